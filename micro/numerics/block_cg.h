// Preconditioned conjugate gradients for the Newton systems of the engine,
// H x = −g with one 3-vector per particle: the EHD velocity solve
// (model/ehd_drag.cpp) and the implicit step's minimisation
// (dynamics/incremental_minimiser.cpp). H is applied matrix-free; the
// preconditioner is the inverse of H's diagonal (3×3 blocks or scalars) plus a
// coarse correction along the uniform translations.
//
// Why the coarse correction. Pair terms (contacts, films, Stokes pair dashpots)
// resist only relative motion, so a uniform translation of all particles meets
// the per-particle terms alone (the friction against the affine flow, a
// proximal term): H's smallest eigenvalue lies along it. With the friction
// against the neighbours (StokesFriction) only a share κ = 0.01 of the
// friction stays per particle, and block Jacobi leaves that mode ~κ times
// below the rest. The two-level preconditioner
//     M⁻¹ r = D⁻¹ r + P (PᵀHP)⁻¹ Pᵀ r,   P = [1⊗e_x, 1⊗e_y, 1⊗e_z],
// solves that space exactly: PᵀHP = c I, c = Σ_α of the per-particle terms, so
// the correction is the total residual force over c, one pass. M⁻¹ stays
// symmetric positive definite (an SPD plus a PSD operator); it saves CG
// iterations and time (bench/results/implicit_softglass_speedups-2026-11-25.md).
// Piecewise-uniform translations over 2³…4³ boxes of the cell cut the
// iterations further but cost more time than they saved: what is left
// is the elastic Hessian's own soft modes, not long waves of the friction.
//
// CG stops at ‖r‖ ≤ η‖g‖ (an inexact Newton step), after `limit` iterations,
// or — with `truncate` — at the first direction of non-positive curvature
// (Steihaug): the iterate so far, or the preconditioned gradient on the first
// iteration, is then still a descent direction.
#pragma once

#include <cstddef>
#include <vector>

#include "micro/geometry/particles.h"

namespace softglass::micro {

/// Σ_a term(a) over the particles a = 0 … n − 1, calling term in that order,
/// summed in four partial sums (particle a into sum a mod 4, the last n mod 4
/// into the first) added as (s₀ + s₁) + (s₂ + s₃). One running sum made
/// every pass of CG wait, particle after particle, for the addition before;
/// four are four independent chains. The order is fixed, so the sum does not
/// depend on the machine or on the compiler's vector width.
template <class Term>
double sum_over_particles(std::size_t n, Term&& term) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t a = 0;
  for (; a + 4 <= n; a += 4) {
    s0 += term(a);
    s1 += term(a + 1);
    s2 += term(a + 2);
    s3 += term(a + 3);
  }
  for (; a < n; ++a) s0 += term(a);
  return (s0 + s1) + (s2 + s3);
}

inline double dot(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  const Vec3* u = x.data();
  const Vec3* v = y.data();
  return sum_over_particles(x.size(), [&](std::size_t a) { return u[a].dot(v[a]); });
}

/// The vectors CG works on, kept between solves so that no solve allocates.
struct CgWorkspace {
  std::vector<Vec3> r, z, p, hp;
};

struct CgOutcome {
  int iterations = 0;
  bool negative_curvature = false;
};

/// z = D⁻¹ r (`precondition(a, v)` per particle) plus, when
/// `translation_stiffness` c > 0, the coarse correction (Σ_α r_α)/c on every
/// particle; returns r·z. The dot product is summed in the pass that finishes
/// z, in the order of `dot`: one pass over the vectors fewer, the same sum to
/// the last bit.
///
/// The loops here and in solve_newton_system run on raw pointers held in
/// locals: Eigen stores its packets through may-alias types, so with the
/// vectors themselves the compiler reloaded their data pointers after every
/// store.
template <class Precondition>
double two_level_precondition(Precondition& precondition, double translation_stiffness,
                              const std::vector<Vec3>& residual,
                              std::vector<Vec3>& preconditioned) {
  const std::size_t n = residual.size();
  const Vec3* r = residual.data();
  Vec3* z = preconditioned.data();
  const bool coarse_correction = translation_stiffness > 0.0;
  if (!coarse_correction) {
    return sum_over_particles(n, [&](std::size_t a) {
      z[a] = precondition(a, r[a]);
      return r[a].dot(z[a]);
    });
  }
  Vec3 total = Vec3::Zero();
  for (std::size_t a = 0; a < n; ++a) {
    z[a] = precondition(a, r[a]);
    total += r[a];
  }
  const Vec3 coarse = total / translation_stiffness;
  return sum_over_particles(n, [&](std::size_t a) {
    z[a] += coarse;
    return r[a].dot(z[a]);
  });
}

/// x ← the CG approximation of −H⁻¹ g. `hessian_times(in, out)` sets out = H in;
/// `precondition(a, v)` returns the block-Jacobi preconditioned v of particle
/// a; `translation_stiffness` is H's stiffness against a uniform unit
/// translation along one axis, Σ_α of its per-particle terms (0: no coarse
/// correction, for an H without such terms, whose gradient has no part along
/// the translations).
template <class HessianTimes, class Precondition>
CgOutcome solve_newton_system(const std::vector<Vec3>& gradient, HessianTimes&& hessian_times,
                              Precondition&& precondition, double translation_stiffness,
                              double eta, int limit, bool truncate, std::vector<Vec3>& x,
                              CgWorkspace& w) {
  const std::size_t n = gradient.size();
  for (auto* v : {&w.r, &w.z, &w.p, &w.hp, &x}) v->resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    x[a].setZero();
    w.r[a] = -gradient[a];
  }
  double rz = two_level_precondition(precondition, translation_stiffness, w.r, w.z);
  w.p = w.z;
  const double target2 = eta * eta * dot(gradient, gradient);
  CgOutcome outcome;
  while (outcome.iterations < limit) {
    hessian_times(w.p, w.hp);
    const double curvature = dot(w.p, w.hp);
    if (truncate && curvature <= 0.0) {
      if (outcome.iterations == 0) x = w.z;
      outcome.negative_curvature = true;
      break;
    }
    // The update and ‖r‖² in one pass (the sum in `dot`'s order).
    const double alpha = rz / curvature;
    Vec3* xa = x.data();
    Vec3* r = w.r.data();
    const Vec3* p = w.p.data();
    const Vec3* hp = w.hp.data();
    const double rr = sum_over_particles(n, [&](std::size_t a) {
      xa[a] += alpha * p[a];
      r[a] -= alpha * hp[a];
      return r[a].dot(r[a]);
    });
    ++outcome.iterations;
    if (rr <= target2) break;
    const double rz_next = two_level_precondition(precondition, translation_stiffness, w.r, w.z);
    const double beta = rz_next / rz;
    rz = rz_next;
    Vec3* direction = w.p.data();
    const Vec3* z = w.z.data();
    for (std::size_t a = 0; a < n; ++a) direction[a] = z[a] + beta * direction[a];
  }
  return outcome;
}

}  // namespace softglass::micro
