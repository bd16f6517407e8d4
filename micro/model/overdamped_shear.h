// Overdamped particles in simple shear: the paper's equation of motion.
//
// In reduced units (lengths R, time 1/γ̇ so that time is strain, forces E* R²)
//     dx_α/dγ = y_α e_x + v_α,     ζ_α v_α = F^e_α + F^EHD_α(v),
//     ζ_α = γ̃ / m_α = 6π γ̃ R_α / f_r,
// where v is the non-affine velocity (docs/physics.md, "Motion"). This class evaluates the
// right-hand side at the current configuration — elastic forces, the implicit
// EHD velocity solve, the stress, and a bound on the stiffness — and moves the
// particles; integrators (integrator.h) decide the steps.
//
// Under a time-dependent drive (shear_drive.h: oscillatory shear) time t is in
// units of 1/γ̇_ref, γ̃ is that reference rate's, and the affine flow is
// c(t) y e_x: dx_α/dt = c(t) y_α e_x + v_α, the drag seeing the affine relative
// velocity c(t) d_y e_x. Steady shear is c ≡ 1, where time is the strain
// itself. Integrators step in time and move the affine part with the drive's
// exact strain increment (advance_affinely).
//
// Stiffness. Linearised about a configuration, the elastic part of the motion is
// δẋ = −ζ⁻¹ H δx with H the Hessian of the elastic energy. Block Gershgorin
// bounds its fastest rate by  λ = max_α 2 Σ_c ‖K_c‖ / ζ_α  (per unit strain); the
// EHD drag adds friction and only slows relaxation. An explicit step dt is stable
// when dt λ < 2, so the step follows the stiffness and scales like γ̃.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "micro/model/contact_system.h"
#include "micro/model/ehd_drag.h"
#include "micro/model/shear_drive.h"
#include "micro/model/solvent_flow.h"
#include "micro/numerics/vector_clones.h"

namespace softglass::micro {

/// f_r above 1 makes the friction against the affine flow weaker than a free
/// sphere's Stokes drag: the limit in which the films carry the dissipation.
inline constexpr double kMinMobilityFactor = 1e-6, kMaxMobilityFactor = 1e4;

struct ShearModel {
  double gamma_tilde = 1e-5;      // γ̇ η_s / E*
  double mobility_factor = 0.01;  // f_r
  EhdSettings drag;

  void validate() const;
  /// ζ = 6π γ̃ R / f_r, the friction of a particle of radius R against the
  /// affine flow (units E* R² per γ̇ R).
  double friction(double radius) const;
};

/// Stress tensors (units of E*), σ = −(1/V) Σ d ⊗ f over contacts: σ^e of the
/// elastic forces, σ^v of the dissipative ones, and σ^film ⊆ σ^v the part of
/// the EHD films alone (σ^v − σ^film is the Stokes pair dashpots').
struct StressSample {
  Eigen::Matrix3d elastic = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d viscous = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d film = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d total() const { return elastic + viscous; }
};

class OverdampedShear {
 public:
  /// Under `drive` from time `time` (ignored for steady shear, whose time is
  /// the cell's strain).
  OverdampedShear(ContactSystem system, const ShearModel& model,
                  ShearDrive drive = ShearDrive::steady(), double time = 0.0);

  ContactSystem& system() { return system_; }
  const ContactSystem& system() const { return system_; }
  const ShearModel& model() const { return model_; }
  const ShearDrive& drive() const { return drive_; }
  double strain() const { return system_.box().strain(); }
  /// Time (units 1/γ̇_ref); the strain itself in steady shear.
  double time() const { return drive_.is_steady() ? strain() : time_; }
  /// The affine flow's rate c now (1 in steady shear).
  double rate() const { return drive_.rate(time()); }
  /// The strain after a further time `dt`.
  double strain_after(double dt) const { return strain() + strain_increment(dt); }
  double strain_increment(double dt) const { return drive_.strain_increment(time(), dt); }

  /// Forces, velocities and stiffness bound at the current configuration, and
  /// the stress if the strain has reached the one set by `sample_stress_from`.
  void evaluate();
  /// What a step's error estimate compares the new velocities with
  /// (adaptive_euler.cpp): the velocities v⁰ at the step's start and the
  /// step's strain increment Δγ.
  struct VelocityChange {
    std::span<const Vec3> before;
    double strain_step;
  };
  /// evaluate(), returning as well max_α |Δu_α|², the largest change over the
  /// step of a particle's total velocity u = c y e_x + v: Δu_α = v_α − v⁰_α +
  /// Δγ v⁰_α,y e_x (its y moved by dt v⁰_y while the cell sheared by Δγ; the
  /// drive's own change of c moves every particle affinely, which a step
  /// integrates exactly). It is taken in the pass that sets the velocities: a
  /// pass of its own read both velocity arrays again (4 % of an explicit
  /// step's samples at N = 10⁵).
  double evaluate(const VelocityChange& change);
  /// After an implicit step to this configuration: takes `velocity` (the
  /// step's own u/h, which solve its equation of motion with the drag of the
  /// step's start) as the velocities here instead of solving for them — unless
  /// the stress is due here, which gets a full evaluate() warm-started by them.
  /// Between samples nothing reads the forces or the solved velocities, so the
  /// velocity solve would only replace u/h by v(x) in the next step's guess
  /// and error estimate (backward_euler.cpp).
  void accept_step_velocities(std::span<const Vec3> velocity);
  /// Evaluations at times ≥ `time` compute the stress (by default all do); a
  /// run sets its next sample time so that steps between samples skip it.
  void sample_stress_from(double time) { stress_from_ = time; }
  bool evaluated() const { return evaluated_; }
  /// What the reservoir friction acts against (solvent_flow.h): the affine
  /// flow unless set (the wall scene sets the local mean flow).
  void set_solvent_flow(SolventFlow solvent) { solvent_ = std::move(solvent); }
  const SolventFlow& solvent_flow() const { return solvent_; }

  /// Non-affine velocities v of the last evaluation (units γ̇ R).
  std::span<const Vec3> velocities() const { return system_.particles().velocity; }
  double relaxation_rate() const { return relaxation_rate_; }
  double max_speed() const { return max_speed_; }
  /// The stress of the last evaluation; throws std::logic_error if that
  /// evaluation did not compute it.
  StressSample stress() const;
  std::size_t contact_count() const { return system_.forces().contact_count; }
  const VelocitySolveStats& last_solve() const { return last_solve_; }
  std::size_t evaluations() const { return evaluations_; }

  /// Makes the neighbour list valid for an Euler step of `dt` from here. May
  /// reorder particles (velocities move with them).
  void prepare_step(double dt);
  /// The affine part of a step: time += dt, x += Δγ y e_x, the cell's strain
  /// += Δγ. The caller adds the non-affine move (system().move).
  void advance_affinely(double dt);

  /// Everything a step and `evaluate` change, for rejecting a trial step.
  struct Snapshot {
    std::vector<Vec3> position, velocity;
    SolventFlow solvent;
    ContactSystem::Tracking tracking;
    double strain, time, relaxation_rate, max_speed;
    Eigen::Matrix3d elastic_virial;
    DissipativeVirial viscous_virial;
    bool stress_valid;
  };
  /// Copies into `into`'s buffers (no allocation once they have grown).
  void save(Snapshot& into) const;
  /// save(into), then the explicit step x += Δγ y e_x + dt v, time += dt (Δγ
  /// the drive's strain increment over dt, v from the last evaluation), in
  /// one pass over the particles: the positions and their tracking are handed
  /// to `into` by swapping arrays, and the new ones written from them (the
  /// copies and the separate shear and move were 5 % of an explicit Hertz step
  /// at N = 1000). Without drag the velocities are handed over too, since the
  /// next evaluation overwrites them all; until it, velocities() holds stale
  /// values.
  void save_and_step(Snapshot& into, double dt);
  void restore(const Snapshot& from);

 private:
  // evaluate(), with the velocity change if `change` is given (else 0).
  double evaluate_against(const VelocityChange* change);
  // Everything a snapshot holds but the positions and the velocities.
  void save_state(Snapshot& into) const;
  // Whether the velocities are F/ζ (no EHD drag, no Stokes pair dashpots):
  // then nothing implicit starts from the last ones.
  bool free_draining() const;
  /// max_speed_ from the particles' velocities, after setting them to F/ζ if
  /// kFreeDraining, relaxation_rate_ from the stiffness sums if kRate, and
  /// returns max |Δu|² against `change` if kChange (else 0); throws
  /// NumericalError if a velocity is not finite.
  template <bool kFreeDraining, bool kRate, bool kChange>
  SOFTGLASS_VECTOR_CLONES double scan_velocities(std::span<const Vec3> force,
                                                 std::span<const double> stiffness,
                                                 const VelocityChange* change);

  ContactSystem system_;
  ShearModel model_;
  ShearDrive drive_;
  double time_;  // time of a time-dependent drive
  EhdDrag drag_;
  std::vector<double> friction_;  // ζ_α
  std::vector<double> mobility_;  // 1/ζ_α
  SolventFlow solvent_;
  std::vector<Vec3> driving_force_;   // F^e + ζ_r v̄(y) e_x, with a non-affine solvent flow
  std::size_t ordered_at_build_ = 0;  // the list build whose particle order they follow
  bool evaluated_ = false;
  bool stress_valid_ = false;
  double stress_from_ = -std::numeric_limits<double>::infinity();
  double relaxation_rate_ = 0.0;
  double max_speed_ = 0.0;
  Eigen::Matrix3d elastic_virial_ = Eigen::Matrix3d::Zero();
  DissipativeVirial viscous_virial_;
  VelocitySolveStats last_solve_;
  std::size_t evaluations_ = 0;
};

/// σ = σ_yx, N1 = σ_xx − σ_yy, N2 = σ_yy − σ_zz, Π = −tr σ / 3.
struct ShearObservables {
  double shear, n1, n2, pressure;
};
ShearObservables observables(const Eigen::Matrix3d& sigma);

}  // namespace softglass::micro
