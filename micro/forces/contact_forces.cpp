#include "micro/forces/contact_forces.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace softglass::micro {

void ContactList::clear() {
  i.clear();
  j.clear();
  separation.clear();
  deformation.clear();
  contact_radius.clear();
  force.clear();
  stiffness.clear();
}

std::size_t ContactField::memory_bytes() const {
  std::size_t bytes = force.capacity() * sizeof(Vec3) + stiffness_sum.capacity() * sizeof(double);
  for (const auto& b : thread_buffers_) bytes += b.capacity() * sizeof(double);
  const auto list_bytes = [](const ContactList& c) {
    return c.i.capacity() * 8 + c.separation.capacity() * sizeof(Vec3) +
           (c.deformation.capacity() + c.contact_radius.capacity() + c.force.capacity() +
            c.stiffness.capacity()) * sizeof(double);
  };
  bytes += list_bytes(contacts);
  for (const auto& c : thread_contacts_) bytes += list_bytes(c);
  return bytes;
}

namespace {

// Contacts of one particle with its list neighbours, gathered so that the law is
// evaluated once per particle (one virtual call per particle, not per contact).
constexpr std::size_t kBatch = 32;
struct Batch {
  std::size_t n = 0;
  std::array<std::uint32_t, kBatch> j;
  std::array<Vec3, kBatch> d;
  std::array<double, kBatch> r2, rj, eps, rc, r, F, dF;
};

// What one thread accumulates besides the per-particle forces.
struct ThreadTotals {
  double virial[6] = {};  // xx, yy, zz, xy, xz, yz of Σ d ⊗ f (symmetric: f ∥ d)
  double energy = 0.0, magnitude = 0.0;
  std::size_t contacts = 0;
};

void append(ContactList& list, std::uint32_t i, std::uint32_t j, const Vec3& d, double eps,
            double rc, double f, double k) {
  list.i.push_back(i);
  list.j.push_back(j);
  list.separation.push_back(d);
  list.deformation.push_back(eps);
  list.contact_radius.push_back(rc);
  list.force.push_back(f);
  list.stiffness.push_back(k);
}

// Forces of the batched contacts of particle i: f = R_c² F(ε) d/r on i, −f on j.
void flush(std::size_t i, double ri, Batch& b, const ContactLaw& law, const ForceRequest& request,
           double* acc, ThreadTotals& totals, ContactList& contacts) {
  for (std::size_t k = 0; k < b.n; ++k) {
    b.r[k] = std::sqrt(b.r2[k]);
    const double sum = ri + b.rj[k];
    b.rc[k] = ri * b.rj[k] / sum;
    b.eps[k] = (sum - b.r[k]) * (1.0 / ri + 1.0 / b.rj[k]);  // h / R_c
  }
  law.evaluate({b.eps.data(), b.n}, {b.F.data(), b.n}, {b.dF.data(), b.n});

  double fx = 0, fy = 0, fz = 0, ki = 0, magnitude = 0;
  double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0;
  for (std::size_t k = 0; k < b.n; ++k) {
    const double rc = b.rc[k];
    const double fmag = rc * rc * b.F[k];
    const double s = fmag / b.r[k];  // f = s d
    const double dx = b.d[k].x(), dy = b.d[k].y(), dz = b.d[k].z();
    const double kn = rc * b.dF[k];
    const double norm = std::max(kn, s);  // ‖K_c‖ = max(normal stiffness, f/r)
    fx += s * dx, fy += s * dy, fz += s * dz;
    ki += norm;
    magnitude += fmag;
    double* aj = acc + 4 * b.j[k];
    aj[0] -= s * dx, aj[1] -= s * dy, aj[2] -= s * dz, aj[3] += norm;
    vxx += s * dx * dx, vyy += s * dy * dy, vzz += s * dz * dz;
    vxy += s * dx * dy, vxz += s * dx * dz, vyz += s * dy * dz;
    if (request.energy) totals.energy += rc * rc * rc * law.energy(b.eps[k]);
    if (request.contacts) {
      append(contacts, static_cast<std::uint32_t>(i), b.j[k], b.d[k], b.eps[k], rc, fmag, kn);
    }
  }
  double* ai = acc + 4 * i;
  ai[0] += fx, ai[1] += fy, ai[2] += fz, ai[3] += ki;
  double* v = totals.virial;
  v[0] += vxx, v[1] += vyy, v[2] += vzz, v[3] += vxy, v[4] += vxz, v[5] += vyz;
  totals.magnitude += magnitude;
  totals.contacts += b.n;
  b.n = 0;
}

}  // namespace

void compute_contact_forces(const ContactLaw& law, const LeesEdwardsBox& box,
                            std::span<const Vec3> x, std::span<const double> radius,
                            const NeighbourList& neighbours, const ForceRequest& request,
                            ContactField& out) {
  const std::size_t n = x.size();
  const int threads = n >= 2048 ? omp_get_max_threads() : 1;
  out.thread_buffers_.resize(threads);
  out.thread_contacts_.resize(threads);
  out.force.resize(n);
  out.stiffness_sum.resize(n);
  std::vector<ThreadTotals> totals(threads);

#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    std::vector<double>& acc = out.thread_buffers_[t];
    acc.assign(4 * n, 0.0);
    ContactList& mine = out.thread_contacts_[t];
    mine.clear();
    ThreadTotals sums;
    Batch b;

#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 xi = x[i];
      const double ri = radius[i];
      for (const std::uint32_t j : neighbours.neighbours(i)) {
        const Vec3 d = box.minimum_image(xi - x[j]);
        const double sum = ri + radius[j];
        const double r2 = d.squaredNorm();
        if (r2 >= sum * sum) continue;
        b.j[b.n] = j;
        b.d[b.n] = d;
        b.r2[b.n] = r2;
        b.rj[b.n] = radius[j];
        if (++b.n == kBatch) flush(i, ri, b, law, request, acc.data(), sums, mine);
      }
      if (b.n) flush(i, ri, b, law, request, acc.data(), sums, mine);
    }
    totals[t] = sums;

    // Reduce the per-thread accumulators in a fixed thread order.
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double f0 = 0, f1 = 0, f2 = 0, k = 0;
      for (int s = 0; s < threads; ++s) {
        const double* a = &out.thread_buffers_[s][4 * i];
        f0 += a[0], f1 += a[1], f2 += a[2], k += a[3];
      }
      out.force[i] = Vec3(f0, f1, f2);
      out.stiffness_sum[i] = k;
    }
  }

  double v[6] = {};
  out.energy = 0.0;
  out.force_magnitude_sum = 0.0;
  out.contact_count = 0;
  for (const ThreadTotals& t : totals) {
    for (int c = 0; c < 6; ++c) v[c] += t.virial[c];
    out.energy += t.energy;
    out.force_magnitude_sum += t.magnitude;
    out.contact_count += t.contacts;
  }
  out.virial << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];

  out.contacts.clear();
  if (request.contacts) {
    const auto cat = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    for (const ContactList& part : out.thread_contacts_) {
      cat(out.contacts.i, part.i);
      cat(out.contacts.j, part.j);
      cat(out.contacts.separation, part.separation);
      cat(out.contacts.deformation, part.deformation);
      cat(out.contacts.contact_radius, part.contact_radius);
      cat(out.contacts.force, part.force);
      cat(out.contacts.stiffness, part.stiffness);
    }
  }
}

}  // namespace softglass::micro
