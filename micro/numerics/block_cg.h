// Preconditioned conjugate gradients for the Newton systems of the engine,
// H x = −g with one 3-vector per particle: the EHD velocity solve
// (model/ehd_drag.cpp) and the implicit step's minimisation
// (dynamics/incremental_minimiser.cpp). H is applied matrix-free; the
// preconditioner is the inverse of H's diagonal (3×3 blocks or scalars).
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

inline double dot(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  double sum = 0.0;
  for (std::size_t a = 0; a < x.size(); ++a) sum += x[a].dot(y[a]);
  return sum;
}

/// The vectors CG works on, kept between solves so that no solve allocates.
struct CgWorkspace {
  std::vector<Vec3> r, z, p, hp;
};

struct CgOutcome {
  int iterations = 0;
  bool negative_curvature = false;
};

/// x ← the CG approximation of −H⁻¹ g. `hessian_times(in, out)` sets out = H in;
/// `precondition(a, v)` returns the preconditioned v of particle a.
template <class HessianTimes, class Precondition>
CgOutcome solve_newton_system(const std::vector<Vec3>& gradient, HessianTimes&& hessian_times,
                              Precondition&& precondition, double eta, int limit, bool truncate,
                              std::vector<Vec3>& x, CgWorkspace& w) {
  const std::size_t n = gradient.size();
  for (auto* v : {&w.r, &w.z, &w.p, &w.hp, &x}) v->resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    x[a].setZero();
    w.r[a] = -gradient[a];
    w.z[a] = precondition(a, w.r[a]);
    w.p[a] = w.z[a];
  }
  const double target2 = eta * eta * dot(gradient, gradient);
  double rz = dot(w.r, w.z);
  CgOutcome outcome;
  while (outcome.iterations < limit) {
    hessian_times(w.p, w.hp);
    const double curvature = dot(w.p, w.hp);
    if (truncate && curvature <= 0.0) {
      if (outcome.iterations == 0) x = w.z;
      outcome.negative_curvature = true;
      break;
    }
    const double alpha = rz / curvature;
    for (std::size_t a = 0; a < n; ++a) {
      x[a] += alpha * w.p[a];
      w.r[a] -= alpha * w.hp[a];
    }
    ++outcome.iterations;
    if (dot(w.r, w.r) <= target2) break;
    for (std::size_t a = 0; a < n; ++a) w.z[a] = precondition(a, w.r[a]);
    const double rz_next = dot(w.r, w.z);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t a = 0; a < n; ++a) w.p[a] = w.z[a] + beta * w.p[a];
  }
  return outcome;
}

}  // namespace softglass::micro
