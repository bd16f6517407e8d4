// The contact-force kernel, compiled once per contact law with the law's F(ε)
// inlined (contact/contact_law_impl.h). See contact_forces.h for the physics.
//
// Loop over particles i and their list neighbours j > i (half list): separation
// d through the pair's image (neighbour_list.h), overlap test, then for a contact,
// with R_i + R_j, R_c and 1/R_c from the list,
//     ε = (R_i + R_j − r)/R_c,  |f| = R_c² F(ε),  f = |f| d/r,
// added to i and subtracted from j. Threads write j's share into their own
// accumulators, reduced afterwards in a fixed order, so results do not depend on
// scheduling (for a given thread count).
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "micro/contact/contact_forces.h"

namespace softglass::micro {

/// Per-thread sums besides the per-particle accumulators.
struct KernelTotals {
  double virial[6] = {};  // xx, yy, zz, xy, xz, yz of Σ d ⊗ f (symmetric: f ∥ d)
  double energy = 0.0, magnitude = 0.0;
  std::size_t contacts = 0;
};

/// Sizes the buffers; returns the thread count to use.
int prepare_kernel(const ForceKernelInput& in, ContactField& out);
/// Adds the accumulators of threads 1, 2, … for particles [begin, end) into `out`.
void reduce_accumulators(ContactField& out, std::size_t begin, std::size_t end);
/// Adds the per-thread totals and contact lists into `out`.
void finish_kernel(const ForceKernelInput& in, const std::vector<KernelTotals>& totals,
                   ContactField& out);

/// The kernel proper, with what is requested known at compile time so that the
/// contact loop carries no tests for it.
template <class Law, bool kEnergy, bool kContacts, bool kVirial>
void contact_kernel(const Law& law, const ForceKernelInput& in, ContactField& out) {
  const int threads = prepare_kernel(in, out);
  const std::size_t n = in.x.size();
  const auto shifts = in.neighbours.image_shifts(in.box);
  std::vector<KernelTotals> totals(threads);

#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    Vec3* force = t == 0 ? out.force.data() : out.scratch.forces[t - 1].data();
    double* stiffness = t == 0 ? out.stiffness_sum.data() : out.scratch.stiffness[t - 1].data();
    ContactList& contacts = out.scratch.contacts[t];
    KernelTotals sums;
    double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0, magnitude = 0;
    std::size_t count = 0;

    // Contacts of particle i, compacted without a branch on the overlap test
    // (whose outcome is unpredictable: a quarter of the list pairs do not touch).
    ContactField::Touching& touching = out.scratch.touching[t];
    std::vector<std::uint32_t>& cp = touching.position;
    std::vector<Vec3>& cd = touching.separation;
    std::vector<double>& cr2 = touching.distance2;

#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 xi = in.x[i];
      const auto list = in.neighbours.neighbours(i);
      const auto pairs = in.neighbours.pair_constants(i);
      if (cp.size() < list.size())
        cp.resize(list.size()), cd.resize(list.size()), cr2.resize(list.size());
      std::size_t m = 0;
      for (std::uint32_t p = 0; p < list.size(); ++p) {
        const std::uint32_t entry = list[p];
        const Vec3 d = xi - in.x[NeighbourList::index(entry)] - shifts[NeighbourList::image(entry)];
        const double r2 = d.squaredNorm();
        const double sum = pairs[p].contact_distance;
        cp[m] = p, cd[m] = d, cr2[m] = r2;
        m += r2 < sum * sum;
      }

      double fx = 0, fy = 0, fz = 0, ki = 0;
      for (std::size_t k = 0; k < m; ++k) {
        const std::uint32_t j = NeighbourList::index(list[cp[k]]);
        const auto& pair = pairs[cp[k]];
        const Vec3& d = cd[k];
        const double r = std::sqrt(cr2[k]);
        const double inv_r = 1.0 / r;
        const double rc = pair.contact_radius;
        const double eps = (pair.contact_distance - r) * pair.inverse_contact_radius;
        double F, dF;
        law.force_and_stiffness(eps, F, dF);
        const double fmag = rc * rc * F;
        const double s = fmag * inv_r;  // f = s d
        const double kn = rc * dF;
        const double norm = std::max(kn, s);  // ‖K_c‖ = max(normal stiffness, f/r)
        const double f0 = s * d.x(), f1 = s * d.y(), f2 = s * d.z();
        fx += f0, fy += f1, fz += f2, ki += norm;
        force[j] -= Vec3(f0, f1, f2);
        stiffness[j] += norm;
        if constexpr (kVirial) {
          vxx += f0 * d.x(), vyy += f1 * d.y(), vzz += f2 * d.z();
          vxy += f1 * d.x(), vxz += f2 * d.x(), vyz += f2 * d.y();
        }
        magnitude += fmag;
        if constexpr (kEnergy) sums.energy += rc * rc * rc * law.energy(eps);
        if constexpr (kContacts) {
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
      force[i] += Vec3(fx, fy, fz);
      stiffness[i] += ki;
    }
    double* v = sums.virial;
    v[0] = vxx, v[1] = vyy, v[2] = vzz, v[3] = vxy, v[4] = vxz, v[5] = vyz;
    sums.magnitude = magnitude;
    sums.contacts = count;
    totals[t] = sums;

#pragma omp barrier
    // Threads 1, 2, … add into thread 0's arrays, each over its own range, in a
    // fixed order.
    const std::size_t chunk = (n + threads - 1) / threads;
    reduce_accumulators(out, std::min(n, t * chunk), std::min(n, (t + 1) * chunk));
  }
  finish_kernel(in, totals, out);
}

template <class Law>
void run_contact_kernel(const Law& law, const ForceKernelInput& in, ContactField& out) {
  const ForceRequest& r = in.request;
  const int flags = (r.energy ? 4 : 0) | (r.contacts ? 2 : 0) | (r.virial ? 1 : 0);
  switch (flags) {
    case 0:
      return contact_kernel<Law, false, false, false>(law, in, out);
    case 1:
      return contact_kernel<Law, false, false, true>(law, in, out);
    case 2:
      return contact_kernel<Law, false, true, false>(law, in, out);
    case 3:
      return contact_kernel<Law, false, true, true>(law, in, out);
    case 4:
      return contact_kernel<Law, true, false, false>(law, in, out);
    case 5:
      return contact_kernel<Law, true, false, true>(law, in, out);
    case 6:
      return contact_kernel<Law, true, true, false>(law, in, out);
    default:
      return contact_kernel<Law, true, true, true>(law, in, out);
  }
}

}  // namespace softglass::micro
