// The contact-force kernel, compiled once per contact law with the law's F(ε)
// inlined (contact/contact_law_impl.h). See contact_forces.h for the physics.
//
// Loop over particles i and their list neighbours j > i (half list): nearest
// image d, overlap test, then for a contact
//     1/R_c = 1/R_i + 1/R_j,  ε = (R_i + R_j − r)/R_c,  |f| = R_c² F(ε),  f = |f| d/r,
// added to i and subtracted from j. Threads write j's share into their own
// accumulators, reduced afterwards in a fixed order, so results do not depend on
// scheduling (for a given thread count).
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "micro/forces/contact_forces.h"

namespace softglass::micro {

/// Per-thread sums besides the per-particle accumulators.
struct KernelTotals {
  double virial[6] = {};  // xx, yy, zz, xy, xz, yz of Σ d ⊗ f (symmetric: f ∥ d)
  double energy = 0.0, magnitude = 0.0;
  std::size_t contacts = 0;
};

/// Sizes the buffers; returns the thread count to use.
int prepare_kernel(const ForceKernelInput& in, ContactField& out);
/// Reduces the per-thread accumulators of particles [begin, end) into `out`.
void reduce_accumulators(ContactField& out, std::size_t begin, std::size_t end);
/// Adds the per-thread totals and contact lists into `out`.
void finish_kernel(const ForceKernelInput& in, const std::vector<KernelTotals>& totals, ContactField& out);

template <class Law>
void run_contact_kernel(const Law& law, const ForceKernelInput& in, ContactField& out) {
  const int threads = prepare_kernel(in, out);
  const std::size_t n = in.x.size();
  const double* inverse_radius = out.scratch.inverse_radius.data();
  std::vector<KernelTotals> totals(threads);

#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    double* acc = out.scratch.accumulators[t].data();
    ContactList& contacts = out.scratch.contacts[t];
    KernelTotals sums;
    double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0, magnitude = 0;
    std::size_t count = 0;

    // Contacts of particle i, compacted without a branch on the overlap test
    // (whose outcome is unpredictable: a quarter of the list pairs do not touch).
    std::vector<std::uint32_t> cj;
    std::vector<Vec3> cd;
    std::vector<double> cr2, csum;

#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 xi = in.x[i];
      const double ri = in.radius[i], inv_ri = inverse_radius[i];
      const auto list = in.neighbours.neighbours(i);
      if (cj.size() < list.size()) {
        cj.resize(list.size()), cd.resize(list.size()), cr2.resize(list.size()), csum.resize(list.size());
      }
      std::size_t m = 0;
      for (const std::uint32_t j : list) {
        const Vec3 d = in.box.minimum_image(xi - in.x[j]);
        const double sum = ri + in.radius[j];
        const double r2 = d.squaredNorm();
        cj[m] = j, cd[m] = d, cr2[m] = r2, csum[m] = sum;
        m += r2 < sum * sum;
      }

      double fx = 0, fy = 0, fz = 0, ki = 0;
      for (std::size_t k = 0; k < m; ++k) {
        const std::uint32_t j = cj[k];
        const Vec3& d = cd[k];
        const double r = std::sqrt(cr2[k]);
        const double inv_r = 1.0 / r;
        const double inv_rc = inv_ri + inverse_radius[j];
        const double rc = 1.0 / inv_rc;
        const double eps = (csum[k] - r) * inv_rc;
        double F, dF;
        law.force_and_stiffness(eps, F, dF);
        const double fmag = rc * rc * F;
        const double s = fmag * inv_r;  // f = s d
        const double kn = rc * dF;
        const double norm = std::max(kn, s);  // ‖K_c‖ = max(normal stiffness, f/r)
        const double f0 = s * d.x(), f1 = s * d.y(), f2 = s * d.z();
        fx += f0, fy += f1, fz += f2, ki += norm;
        double* aj = acc + 4 * j;
        aj[0] -= f0, aj[1] -= f1, aj[2] -= f2, aj[3] += norm;
        vxx += f0 * d.x(), vyy += f1 * d.y(), vzz += f2 * d.z();
        vxy += f1 * d.x(), vxz += f2 * d.x(), vyz += f2 * d.y();
        magnitude += fmag;
        if (in.request.energy) sums.energy += rc * rc * rc * law.energy(eps);
        if (in.request.contacts) {
          contacts.i.push_back(static_cast<std::uint32_t>(i));
          contacts.j.push_back(j);
          contacts.separation.push_back(d);
          contacts.deformation.push_back(eps);
          contacts.contact_radius.push_back(rc);
          contacts.force.push_back(fmag);
          contacts.stiffness.push_back(kn);
        }
      }
      count += m;
      double* ai = acc + 4 * i;
      ai[0] += fx, ai[1] += fy, ai[2] += fz, ai[3] += ki;
    }
    double* v = sums.virial;
    v[0] = vxx, v[1] = vyy, v[2] = vzz, v[3] = vxy, v[4] = vxz, v[5] = vyz;
    sums.magnitude = magnitude;
    sums.contacts = count;
    totals[t] = sums;

#pragma omp barrier
    // The same static partition as above: each thread reduces its own range.
    const std::size_t chunk = (n + threads - 1) / threads;
    reduce_accumulators(out, std::min(n, t * chunk), std::min(n, (t + 1) * chunk));
  }
  finish_kernel(in, totals, out);
}

}  // namespace softglass::micro
