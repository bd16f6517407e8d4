// Elastic contact forces, their virial and stiffness, from the neighbour list.
//
// Reduced units: lengths R, forces E* R², stresses E*. For each overlapping pair
// (h = R_i + R_j − r > 0) the force on i from j is
//     f = R_c² F(ε) n⊥,   n⊥ = (x_i − x_j)/r,   ε = h/R_c,
// and the pair's Hessian block has the norm max(R_c F'(ε), |f|/r) (normal
// stiffness and the tangential "prestress" term f/r). The per-particle sum of
// these norms bounds the largest eigenvalue of the Hessian (block Gershgorin),
// which sets the stable step of an explicit integrator.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "micro/contact/contact_law.h"
#include "micro/contact/wall_contacts.h"
#include "micro/geometry/lees_edwards_box.h"
#include "micro/geometry/neighbour_list.h"

namespace softglass::micro {

/// The contacts of the current configuration, kept when a velocity-dependent
/// drag or an analysis needs them.
struct ContactList {
  std::vector<std::uint32_t> i, j;
  std::vector<Vec3> separation;          // d = x_i − x_j (nearest image)
  std::vector<double> inverse_distance;  // 1/r = 1/|d|, the kernel's: spares the Hessian's
                                         // assembly a square root and a division per contact
  std::vector<double> deformation;       // ε
  std::vector<double> contact_radius;    // R_c
  std::vector<double> force;             // |f| = R_c² F(ε)
  std::vector<double> stiffness;         // df/dh = R_c F'(ε)

  std::size_t size() const { return i.size(); }
  /// Σ d ⊗ f over the contacts, f = (|f|/r) d: the kernel's virial, from a
  /// list already at hand instead of another pass over the neighbour list.
  Eigen::Matrix3d virial() const;
  void clear();
  void resize(std::size_t pairs);
};

struct ForceRequest {
  bool energy = false;    // Σ R_c³ W(ε): one more law call per contact
  bool contacts = false;  // fill `ContactField::contacts`
  bool virial = true;     // Σ d ⊗ f, for the stress
};

/// What a force evaluation reads.
struct ForceKernelInput {
  const LeesEdwardsBox& box;
  std::span<const Vec3> x;
  const NeighbourList& neighbours;
  ForceRequest request;
};

/// Result of one force evaluation; buffers are reused between evaluations.
struct ContactField {
  std::vector<Vec3> force;            // F^e_i
  std::vector<double> stiffness_sum;  // Σ over contacts of the Hessian block norm
  Eigen::Matrix3d virial =
      Eigen::Matrix3d::Zero();  // Σ_pairs d ⊗ f  (σ^e = −virial/V), if requested
  double energy = 0.0;
  double force_magnitude_sum = 0.0;  // Σ_c |f_c|
  std::size_t contact_count = 0;     // pairs only
  ContactList contacts;
  WallContacts walls;  // with walls (wall_contacts.h): always filled

  std::size_t memory_bytes() const;

  /// The touching pairs of a block of particles, compacted by the kernel
  /// (contact_kernel.h) into one array per quantity, so that the contact law
  /// runs over all of them in a single loop the compiler vectorises: the pair's
  /// place in the block's rows of the list, the separation d and |d|², and what
  /// the law makes of them. `end[b]` is one past the last pair of the block's
  /// b-th particle.
  struct Touching {
    std::vector<std::uint32_t> pair, end;
    std::vector<double> dx, dy, dz, distance2;
    std::vector<double> deformation, magnitude, scale, normal_stiffness, norm, energy;
    std::vector<double> inverse_distance;  // written only when the contacts are asked for
    /// Room for at least `pairs` pairs (contents kept).
    void reserve(std::size_t pairs);
  };
  /// Workspace of the kernel (contact_kernel.h), kept to avoid reallocation:
  /// the force and stiffness accumulators of threads 1, 2, … (thread 0 writes
  /// into `force` and `stiffness_sum` directly), every thread's contacts and
  /// touching pairs.
  struct Scratch {
    std::vector<std::vector<Vec3>> forces;
    std::vector<std::vector<double>> stiffness;
    std::vector<ContactList> contacts;
    std::vector<Touching> touching;
  } scratch;
};

/// Elastic forces with `law` (dispatches once to the law's compiled kernel); the
/// radii enter through the list's pair constants.
void compute_contact_forces(const ContactLaw& law, const LeesEdwardsBox& box,
                            std::span<const Vec3> x, const NeighbourList& neighbours,
                            const ForceRequest& request, ContactField& out);

}  // namespace softglass::micro
