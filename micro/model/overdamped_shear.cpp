#include "micro/model/overdamped_shear.h"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "common/errors.h"
#include "micro/numerics/vector_clones.h"

namespace softglass::micro {

void ShearModel::validate() const {
  require(std::isfinite(gamma_tilde) && gamma_tilde >= 1e-14 && gamma_tilde <= 1e-1,
          fmt::format("dimensionless shear rate γ̃ = {} is outside [1e-14, 1e-1]", gamma_tilde));
  require(std::isfinite(mobility_factor) && mobility_factor >= kMinMobilityFactor &&
              mobility_factor <= kMaxMobilityFactor,
          fmt::format("mobility factor f_r = {} is outside [{:g}, {:g}]", mobility_factor,
                      kMinMobilityFactor, kMaxMobilityFactor));
  drag.validate();
}

double ShearModel::friction(double radius) const {
  return 6.0 * std::numbers::pi * gamma_tilde * radius / mobility_factor;
}

ShearObservables observables(const Eigen::Matrix3d& s) {
  return {s(1, 0), s(0, 0) - s(1, 1), s(1, 1) - s(2, 2), -s.trace() / 3.0};
}

OverdampedShear::OverdampedShear(ContactSystem system, const ShearModel& model, ShearDrive drive,
                                 double time)
    : system_(std::move(system)), model_(model), drive_(drive), time_(time), drag_(model.drag) {
  model_.validate();
}

bool OverdampedShear::free_draining() const {
  return !model_.drag.enabled && !model_.drag.stokes.has_pairs();
}

void OverdampedShear::evaluate() {
  evaluate_against(nullptr);
}

double OverdampedShear::evaluate(const VelocityChange& change) {
  return evaluate_against(&change);
}

double OverdampedShear::evaluate_against(const VelocityChange* change) {
  // The velocities are implicit with the EHD drag or the Stokes pair dashpots.
  const bool with_drag = !free_draining();
  stress_valid_ = time() >= stress_from_;
  const ContactField& field =
      system_.compute_forces({.energy = false, .contacts = with_drag, .virial = stress_valid_});
  Particles& p = system_.particles();
  const std::size_t n = p.size();
  // ζ and 1/ζ change only when the particles are reordered (at list builds).
  if (friction_.size() != n || ordered_at_build_ != system_.neighbours().builds()) {
    friction_.resize(n);
    mobility_.resize(n);
    for (std::size_t a = 0; a < n; ++a) {
      friction_[a] = model_.friction(p.radius[a]);
      mobility_[a] = 1.0 / friction_[a];
    }
    ordered_at_build_ = system_.neighbours().builds();
  }

  // A solvent flowing with v̄(y) instead of affinely: −ζ_r (v − v̄ e_x) is the
  // reservoir friction of the affine case plus the fixed force ζ_r v̄ e_x.
  const double c = rate();
  std::span<const Vec3> force = field.force;
  if (!solvent_.affine()) {
    driving_force_.assign(field.force.begin(), field.force.end());
    for (std::size_t a = 0; a < n; ++a)
      driving_force_[a].x() +=
          model_.drag.stokes.reservoir(friction_[a]) * solvent_.velocity(p.position[a].y(), c);
    force = driving_force_;
  }

  double velocity_change;
  if (with_drag) {
    last_solve_ = drag_.solve(field.contacts, model_.gamma_tilde, c, friction_, force, p.velocity,
                              field.walls);
    if (stress_valid_)
      viscous_virial_ =
          drag_.virial(field.contacts, model_.gamma_tilde, c, p.velocity, {}, friction_);
    velocity_change = change ? scan_velocities<false, true, true>({}, field.stiffness_sum, change)
                             : scan_velocities<false, true, false>({}, field.stiffness_sum, {});
  } else {
    viscous_virial_ = {};
    velocity_change = change ? scan_velocities<true, true, true>(force, field.stiffness_sum, change)
                             : scan_velocities<true, true, false>(force, field.stiffness_sum, {});
  }
  solvent_.update(p.position, p.velocity, friction_, c);
  elastic_virial_ = field.virial;
  evaluated_ = true;
  ++evaluations_;
  return velocity_change;
}

void OverdampedShear::accept_step_velocities(std::span<const Vec3> velocity) {
  std::copy(velocity.begin(), velocity.end(), system_.particles().velocity.begin());
  if (time() >= stress_from_) {
    evaluate();
    return;
  }
  scan_velocities<false, false, false>({}, {}, {});
  stress_valid_ = false;
  last_solve_ = {};
  evaluated_ = true;
}

// One pass over the particles after the forces (each loop of its own was a
// few per cent of a Hertz step at N = 1000): v = F/ζ when the drag is free
// draining, the relaxation rate's bound λ = max 2 Σ_j k_ij / ζ_α from the
// stiffness sums, and the largest speed. The maxima are exact in any order, so
// the loop is vectorised (a single chain of comparisons would bound it by its
// latency). The maximum alone would let a NaN through (max(s, NaN) is s); the
// sum of the squares carries it, and an infinity, to the test. The velocity
// change is taken componentwise: a Vec3 built and then changed in one
// component goes through memory, and its reload stalled the loop.
template <bool kFreeDraining, bool kRate, bool kChange>
SOFTGLASS_VECTOR_CLONES double OverdampedShear::scan_velocities(std::span<const Vec3> force,
                                                                std::span<const double> stiffness,
                                                                const VelocityChange* change) {
  Vec3* const velocity = system_.particles().velocity.data();
  const double* const mobility = mobility_.data();
  const Vec3* const before = kChange ? change->before.data() : nullptr;
  const double strain_step = kChange ? change->strain_step : 0.0;
  const std::size_t n = system_.size();
  double rate = 0.0, speed2 = 0.0, sum = 0.0, change2 = 0.0;
#pragma omp simd reduction(max : rate, speed2, change2) reduction(+ : sum)
  for (std::size_t a = 0; a < n; ++a) {
    if constexpr (kFreeDraining) velocity[a] = mobility[a] * force[a];
    if constexpr (kRate) rate = std::max(rate, 2.0 * stiffness[a] * mobility[a]);
    const double s = velocity[a].squaredNorm();
    speed2 = std::max(speed2, s);
    sum += s;
    if constexpr (kChange) {
      const Vec3& v0 = before[a];
      const Vec3& v = velocity[a];
      const double cx = v.x() - v0.x() + strain_step * v0.y();
      const double cy = v.y() - v0.y(), cz = v.z() - v0.z();
      change2 = std::max(change2, cx * cx + cy * cy + cz * cz);
    }
  }
  if constexpr (kRate) relaxation_rate_ = rate;
  max_speed_ = std::sqrt(speed2);
  if (!std::isfinite(sum)) {
    throw NumericalError(fmt::format("non-finite particle velocity at strain {}", strain()));
  }
  return change2;
}

StressSample OverdampedShear::stress() const {
  if (!stress_valid_) throw std::logic_error("stress requested at an evaluation that skipped it");
  const double volume = system_.box().volume();
  return {-elastic_virial_ / volume, -viscous_virial_.total() / volume,
          -viscous_virial_.film / volume};
}

void OverdampedShear::prepare_step(double dt) {
  // A rebuild reorders the particles; velocities move with them, and the step
  // needs nothing else from the last evaluation.
  system_.ensure_neighbours(dt * max_speed_, strain_after(dt));
}

void OverdampedShear::advance_affinely(double dt) {
  system_.shear(strain_increment(dt));
  time_ += dt;
  evaluated_ = false;
}

void OverdampedShear::save(Snapshot& into) const {
  const Particles& p = system_.particles();
  into.position.assign(p.position.begin(), p.position.end());
  into.velocity.assign(p.velocity.begin(), p.velocity.end());
  system_.save_tracking(into.tracking);
  save_state(into);
}

void OverdampedShear::save_and_step(Snapshot& into, double dt) {
  // The velocities are copied when the drag's solve starts from them, else
  // handed over: the next evaluation sets every one.
  std::vector<Vec3>& velocity = system_.particles().velocity;
  if (free_draining()) {
    std::swap(velocity, into.velocity);
    velocity.resize(into.velocity.size());
  } else {
    into.velocity.assign(velocity.begin(), velocity.end());
  }
  save_state(into);
  const double increment = strain_increment(dt);
  time_ += dt;
  evaluated_ = false;
  system_.shear_and_move(increment, dt, into.velocity, into.position, into.tracking);
}

void OverdampedShear::save_state(Snapshot& into) const {
  into.solvent = solvent_;
  into.strain = strain();
  into.time = time_;
  into.relaxation_rate = relaxation_rate_;
  into.max_speed = max_speed_;
  into.elastic_virial = elastic_virial_;
  into.viscous_virial = viscous_virial_;
  into.stress_valid = stress_valid_;
}

void OverdampedShear::restore(const Snapshot& s) {
  system_.restore_positions(s.position, s.strain);
  time_ = s.time;
  system_.particles().velocity.assign(s.velocity.begin(), s.velocity.end());
  solvent_ = s.solvent;
  system_.restore_tracking(s.tracking);
  relaxation_rate_ = s.relaxation_rate;
  max_speed_ = s.max_speed;
  elastic_virial_ = s.elastic_virial;
  viscous_virial_ = s.viscous_virial;
  stress_valid_ = s.stress_valid;
  evaluated_ = true;
}

}  // namespace softglass::micro
