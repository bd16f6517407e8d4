// The product of a Hessian made of pair blocks: for particles a and pairs
// k = (i, j) with 3×3 blocks B_k,
//     y_a = s_a x_a + Σ_{k: i_k = a} B_k (x_i − x_j) − Σ_{k: j_k = a} B_k (x_i − x_j),
// the shape of every pair interaction's Hessian (contacts, films, dashpots:
// forces that depend on the relative displacement only) plus a per-particle
// diagonal s (friction, damping). CG spends most of its time here
// (docs/integrators.md, "Where the time goes").
//
// Two implementations:
// - a portable one in Eigen's 3-vectors;
// - on processors with AVX2 and FMA, one that holds a particle's 3-vector in
//   one 4-wide register. Eigen cannot: a 3-vector is no whole number of
//   packets, so each pair cost some thirty scalar loads, multiplications,
//   additions and shuffles. The block's columns and the vectors are read with
//   masked loads (nothing is read past a 3-vector), the sums go into a padded
//   buffer copied out at the end, and B (x_i − x_j) is two fused
//   multiply-adds (measured in place:
//   bench/results/hessian_product_avx2-2026-11-29-zen3.md).
// They differ in the last bits (the fused multiply-adds round once, not
// twice), as the force kernel's clones do (vector_clones.h): a trajectory can
// part from the other's at a plastic event, statistically the same. Summed in
// Eigen's order with separate multiplications and additions the vectorised
// product was bit for bit the portable one, but gained little: the chain of
// dependent additions, not the instruction count, bounds it.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <vector>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

struct PairBlocks {
  std::span<const std::uint32_t> i, j;  // the pairs, grouped by i (runs of equal i)
  std::span<const Eigen::Matrix3d> block;
};

/// out = the product above with s_a = shift + (diagonal empty ? 0 : diagonal[a]).
/// `padded` is scratch (4 doubles per particle), kept by the caller so that no
/// product allocates.
void pair_block_product(const PairBlocks& pairs, std::span<const double> diagonal, double shift,
                        const std::vector<Vec3>& in, std::vector<Vec3>& out,
                        std::vector<double>& padded);

/// The portable implementation alone, which the tests check on every processor.
void pair_block_product_portable(const PairBlocks& pairs, std::span<const double> diagonal,
                                 double shift, const std::vector<Vec3>& in, std::vector<Vec3>& out);

/// True when this processor runs the AVX2 implementation.
bool pair_block_product_vectorised();

}  // namespace softglass::micro
