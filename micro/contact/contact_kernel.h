// The contact-force kernel, compiled once per contact law with the law's F(ε)
// inlined (contact/contact_law_impl.h), and for each instruction set
// (numerics/vector_clones.h). See contact_forces.h for the physics.
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
#include <array>
#include <cmath>

#include "micro/contact/contact_forces.h"
#include "micro/numerics/thread_range.h"
#include "micro/numerics/vector_clones.h"

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

/// Particles per block of the kernel: their touching pairs (≈ 5 each in a
/// glass) fill the law's vectorised loop, and the block's arrays (≈ 15 doubles
/// per list pair) stay in the first-level cache.
inline constexpr std::size_t kKernelBlock = 32;

/// The kernel proper, over the blocks [first_block, last_block) of one thread,
/// with what is requested known at compile time so that the contact loop
/// carries no tests for it; `force` and `stiffness` are the thread's
/// accumulators. Compiled for several instruction sets (vector_clones.h). Per
/// block of particles, three passes:
///  1. compact the block's list pairs that touch, without a branch on the
///     overlap test (whose outcome is unpredictable: a quarter of the list pairs
///     do not touch);
///  2. evaluate the law on all of them in one loop of independent iterations,
///     which the compiler vectorises (square root, division and the law's power);
///  3. add the forces to both particles, in the order of the list.
template <class Law, bool kEnergy, bool kContacts, bool kVirial>
SOFTGLASS_VECTOR_CLONES KernelTotals
contact_blocks(const Law& law, const ForceKernelInput& in,
               const std::array<Vec3, NeighbourList::kImages>& shifts, std::size_t first_block,
               std::size_t last_block, Vec3* force, double* stiffness,
               ContactField::Touching& touching, ContactList& contacts) {
  const std::size_t n = in.x.size();
  touching.end.resize(kKernelBlock);
  double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0, magnitude = 0, energy = 0;
  std::size_t count = 0;
  for (std::size_t block = first_block; block < last_block; ++block) {
    const std::size_t first = block * kKernelBlock, last = std::min(n, first + kKernelBlock);
    const auto rows = in.neighbours.neighbours(first, last);
    const auto constants = in.neighbours.pair_constants(first, last);
    touching.reserve(rows.size());
    // Local pointers: the stores below could alias the vectors' own members
    // for all the compiler knows.
    std::uint32_t* const pair = touching.pair.data();
    std::uint32_t* const end = touching.end.data();
    double *const dx = touching.dx.data(), *const dy = touching.dy.data(),
                  *const dz = touching.dz.data(), *const r2 = touching.distance2.data();
    double* const deformation = touching.deformation.data();
    double* const pair_force = touching.magnitude.data();
    double* const scale = touching.scale.data();
    double* const normal_stiffness = touching.normal_stiffness.data();
    double* const norm = touching.norm.data();
    double* const pair_energy = touching.energy.data();
    double* const inverse_distance = touching.inverse_distance.data();

    // 1. ε > 0 ⇔ r < R_i + R_j: the pair is written in any case, kept by
    //    advancing m.
    std::size_t m = 0;
    std::uint32_t q = 0;  // place in the block's rows
    for (std::size_t i = first; i < last; ++i) {
      const Vec3 xi = in.x[i];
      const std::uint32_t row_end = q + in.neighbours.neighbours(i).size();
      for (; q < row_end; ++q) {
        const std::uint32_t entry = rows[q];
        const Vec3 d = xi - in.x[NeighbourList::index(entry)] - shifts[NeighbourList::image(entry)];
        const double distance2 = d.squaredNorm();
        const double sum = constants[q].contact_distance;
        pair[m] = q, dx[m] = d.x(), dy[m] = d.y(), dz[m] = d.z(), r2[m] = distance2;
        m += distance2 < sum * sum;
      }
      end[i - first] = static_cast<std::uint32_t>(m);
    }

    // 2. ε = (R_i + R_j − r)/R_c,  |f| = R_c² F(ε),  f = s d with s = |f|/r,
    //    and the Hessian block norm max(R_c F'(ε), |f|/r).
#pragma omp simd
    for (std::size_t k = 0; k < m; ++k) {
      const double r = std::sqrt(r2[k]);
      const double inv_r = 1.0 / r;
      const NeighbourList::PairConstants& c = constants[pair[k]];
      const double rc = c.contact_radius;
      const double eps = (c.contact_distance - r) * c.inverse_contact_radius;
      double F, dF;
      law.force_and_stiffness(eps, F, dF);
      const double fmag = rc * rc * F;
      const double kn = rc * dF;
      deformation[k] = eps;
      pair_force[k] = fmag;
      scale[k] = fmag * inv_r;
      normal_stiffness[k] = kn;
      norm[k] = std::max(kn, fmag * inv_r);
      if constexpr (kEnergy) pair_energy[k] = rc * rc * rc * law.energy(eps);
      if constexpr (kContacts) inverse_distance[k] = inv_r;
    }

    // 3. +f on i (summed in registers), −f on j; the contacts, if asked for,
    //    written in place (appended one by one, each of the seven arrays went
    //    through a call to grow it per contact).
    const std::size_t listed = contacts.size();
    if constexpr (kContacts) contacts.resize(listed + m);
    std::size_t k = 0;
    for (std::size_t i = first; i < last; ++i) {
      double fx = 0, fy = 0, fz = 0, ki = 0;
      for (const std::size_t stop = end[i - first]; k < stop; ++k) {
        const std::uint32_t j = NeighbourList::index(rows[pair[k]]);
        const double s = scale[k];
        const double f0 = s * dx[k], f1 = s * dy[k], f2 = s * dz[k];
        fx += f0, fy += f1, fz += f2, ki += norm[k];
        force[j] -= Vec3(f0, f1, f2);
        stiffness[j] += norm[k];
        if constexpr (kVirial) {
          vxx += f0 * dx[k], vyy += f1 * dy[k], vzz += f2 * dz[k];
          vxy += f1 * dx[k], vxz += f2 * dx[k], vyz += f2 * dy[k];
        }
        magnitude += pair_force[k];
        if constexpr (kEnergy) energy += pair_energy[k];
        if constexpr (kContacts) {
          const std::size_t c = listed + k;
          contacts.i[c] = static_cast<std::uint32_t>(i);
          contacts.j[c] = j;
          contacts.separation[c] = Vec3(dx[k], dy[k], dz[k]);
          contacts.inverse_distance[c] = inverse_distance[k];
          contacts.deformation[c] = deformation[k];
          contacts.contact_radius[c] = constants[pair[k]].contact_radius;
          contacts.force[c] = pair_force[k];
          contacts.stiffness[c] = normal_stiffness[k];
        }
      }
      force[i] += Vec3(fx, fy, fz);
      stiffness[i] += ki;
    }
    count += m;
  }
  KernelTotals sums;
  double* v = sums.virial;
  v[0] = vxx, v[1] = vyy, v[2] = vzz, v[3] = vxy, v[4] = vxz, v[5] = vyz;
  sums.magnitude = magnitude;
  sums.energy = energy;
  sums.contacts = count;
  return sums;
}

/// Runs contact_blocks on each thread's share of the blocks, then reduces.
template <class Law, bool kEnergy, bool kContacts, bool kVirial>
void contact_kernel(const Law& law, const ForceKernelInput& in, ContactField& out) {
  const int threads = prepare_kernel(in, out);
  const std::size_t n = in.x.size();
  const std::size_t blocks = (n + kKernelBlock - 1) / kKernelBlock;
  const auto shifts = in.neighbours.image_shifts(in.box);
  std::vector<KernelTotals> totals(threads);

  // One thread (the usual case below 2048 particles) runs the body directly:
  // entering a parallel region, its loop schedule and barrier cost libgomp
  // calls per force evaluation even for a team of one.
  const auto body = [&](const int t, const bool team) {
    Vec3* force = t == 0 ? out.force.data() : out.scratch.forces[t - 1].data();
    double* stiffness = t == 0 ? out.stiffness_sum.data() : out.scratch.stiffness[t - 1].data();
    const auto [first_block, last_block] = thread_range(blocks, threads, t);
    totals[t] = contact_blocks<Law, kEnergy, kContacts, kVirial>(
        law, in, shifts, first_block, last_block, force, stiffness, out.scratch.touching[t],
        out.scratch.contacts[t]);

    if (!team) return;
#pragma omp barrier
    // Threads 1, 2, … add into thread 0's arrays, each over its own range, in a
    // fixed order.
    const auto [begin, end] = thread_range(n, threads, t);
    reduce_accumulators(out, begin, end);
  };
  if (threads == 1) {
    body(0, false);
  } else {
#pragma omp parallel num_threads(threads)
    body(omp_get_thread_num(), true);
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
