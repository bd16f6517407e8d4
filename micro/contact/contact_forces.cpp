#include "micro/contact/contact_forces.h"
#include "micro/contact/contact_kernel.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace softglass::micro {

void ContactList::clear() {
  i.clear();
  j.clear();
  separation.clear();
  inverse_distance.clear();
  deformation.clear();
  contact_radius.clear();
  force.clear();
  stiffness.clear();
}

void ContactList::resize(std::size_t pairs) {
  i.resize(pairs);
  j.resize(pairs);
  separation.resize(pairs);
  inverse_distance.resize(pairs);
  deformation.resize(pairs);
  contact_radius.resize(pairs);
  force.resize(pairs);
  stiffness.resize(pairs);
}

Eigen::Matrix3d ContactList::virial() const {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
  for (std::size_t k = 0; k < size(); ++k) {
    const Vec3& d = separation[k];
    const Vec3 f = (force[k] * inverse_distance[k]) * d;
    xx += f.x() * d.x(), yy += f.y() * d.y(), zz += f.z() * d.z();
    xy += f.y() * d.x(), xz += f.z() * d.x(), yz += f.z() * d.y();
  }
  Eigen::Matrix3d v;
  v << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return v;
}

void ContactField::Touching::reserve(std::size_t pairs) {
  if (pair.size() >= pairs) return;
  pair.resize(pairs);
  for (std::vector<double>* a : {&dx, &dy, &dz, &distance2, &deformation, &magnitude, &scale,
                                 &normal_stiffness, &norm, &energy, &inverse_distance})
    a->resize(pairs);
}

std::size_t ContactField::memory_bytes() const {
  std::size_t bytes = force.capacity() * sizeof(Vec3) + stiffness_sum.capacity() * sizeof(double);
  for (const auto& f : scratch.forces) bytes += f.capacity() * sizeof(Vec3);
  for (const auto& k : scratch.stiffness) bytes += k.capacity() * sizeof(double);
  const auto list_bytes = [](const ContactList& c) {
    return c.i.capacity() * 8 + c.separation.capacity() * sizeof(Vec3) +
           (c.inverse_distance.capacity() + c.deformation.capacity() + c.contact_radius.capacity() +
            c.force.capacity() + c.stiffness.capacity()) *
               sizeof(double);
  };
  bytes += list_bytes(contacts);
  for (const auto& c : scratch.contacts) bytes += list_bytes(c);
  return bytes;
}

int prepare_kernel(const ForceKernelInput& in, ContactField& out) {
  const std::size_t n = in.x.size();
  const int threads = n >= 2048 ? omp_get_max_threads() : 1;
  auto& scratch = out.scratch;
  out.force.assign(n, Vec3::Zero());
  out.stiffness_sum.assign(n, 0.0);
  scratch.forces.resize(threads - 1);
  scratch.stiffness.resize(threads - 1);
  for (auto& f : scratch.forces) f.assign(n, Vec3::Zero());
  for (auto& k : scratch.stiffness) k.assign(n, 0.0);
  scratch.contacts.resize(threads);
  for (auto& c : scratch.contacts) c.clear();
  scratch.touching.resize(threads);
  return threads;
}

void reduce_accumulators(ContactField& out, std::size_t begin, std::size_t end) {
  for (std::size_t t = 0; t < out.scratch.forces.size(); ++t) {
    const auto& f = out.scratch.forces[t];
    const auto& k = out.scratch.stiffness[t];
    for (std::size_t i = begin; i < end; ++i) {
      out.force[i] += f[i];
      out.stiffness_sum[i] += k[i];
    }
  }
}

void finish_kernel(const ForceKernelInput& in, const std::vector<KernelTotals>& totals,
                   ContactField& out) {
  double v[6] = {};
  out.energy = 0.0;
  out.force_magnitude_sum = 0.0;
  out.contact_count = 0;
  for (const KernelTotals& t : totals) {
    for (int c = 0; c < 6; ++c) v[c] += t.virial[c];
    out.energy += t.energy;
    out.force_magnitude_sum += t.magnitude;
    out.contact_count += t.contacts;
  }
  out.virial << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];

  out.contacts.clear();
  if (!in.request.contacts) return;
  // One thread: its list is the whole list, handed over (the old one goes back
  // to the workspace, to be cleared and refilled with its capacity kept).
  if (out.scratch.contacts.size() == 1) {
    std::swap(out.contacts, out.scratch.contacts[0]);
    return;
  }
  const auto cat = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  for (const ContactList& part : out.scratch.contacts) {
    cat(out.contacts.i, part.i);
    cat(out.contacts.j, part.j);
    cat(out.contacts.separation, part.separation);
    cat(out.contacts.inverse_distance, part.inverse_distance);
    cat(out.contacts.deformation, part.deformation);
    cat(out.contacts.contact_radius, part.contact_radius);
    cat(out.contacts.force, part.force);
    cat(out.contacts.stiffness, part.stiffness);
  }
}

void compute_contact_forces(const ContactLaw& law, const LeesEdwardsBox& box,
                            std::span<const Vec3> x, const NeighbourList& neighbours,
                            const ForceRequest& request, ContactField& out) {
  law.compute_forces({box, x, neighbours, request}, out);
}

}  // namespace softglass::micro
