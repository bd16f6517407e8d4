// The pair blocks' product (micro/numerics/pair_block_product.h): the operator
// it applies, against the dense matrix it stands for, in both of its
// implementations.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "micro/numerics/pair_block_product.h"

namespace softglass::micro {
namespace {

// A contact-network-like set of pairs: particle by particle, each with a few
// neighbours, then some pairs appended out of order (the drag pairs without an
// elastic block, incremental_minimiser.cpp's add_drag), blocks of every sign.
struct RandomPairs {
  std::vector<std::uint32_t> i, j;
  std::vector<Eigen::Matrix3d> block;
  PairBlocks view() const { return {i, j, block}; }
};

RandomPairs random_pairs(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::uniform_int_distribution<std::uint32_t> other(0, static_cast<std::uint32_t>(n - 1));
  RandomPairs p;
  const auto add = [&](std::uint32_t a, std::uint32_t b) {
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = entry(rng);
    p.i.push_back(a), p.j.push_back(b), p.block.push_back(m);
  };
  for (std::uint32_t a = 0; a < n; ++a)
    for (int c = 0; c < 4; ++c)
      if (const std::uint32_t b = other(rng); b != a) add(a, b);
  for (int c = 0; c < 50; ++c)
    if (const std::uint32_t a = other(rng), b = other(rng); a != b) add(a, b);
  return p;
}

std::vector<Vec3> random_vectors(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<Vec3> x(n);
  for (Vec3& v : x) v = Vec3(entry(rng), entry(rng), entry(rng));
  return x;
}

TEST(PairBlockProduct, AppliesTheDenseOperatorItStandsFor) {
  std::mt19937 rng(7);
  const std::size_t n = 60;
  const RandomPairs pairs = random_pairs(n, rng);
  const std::vector<Vec3> x = random_vectors(n, rng);
  std::vector<double> diagonal(n);
  for (double& d : diagonal) d = std::uniform_real_distribution<double>(0.5, 2.0)(rng);
  const double shift = 0.25;

  // H = diag(s) ⊗ I + Σ_k B_k on (i,i), −B_k on (i,j), −B_k on (j,i), B_k on (j,j):
  // the Hessian of Σ_k ½ (x_i − x_j)·B_k (x_i − x_j) for symmetric B_k, and
  // for any B_k the map of the header.
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (std::size_t a = 0; a < n; ++a)
    h.block<3, 3>(3 * a, 3 * a) += (diagonal[a] + shift) * Eigen::Matrix3d::Identity();
  for (std::size_t k = 0; k < pairs.block.size(); ++k) {
    const std::size_t a = pairs.i[k], b = pairs.j[k];
    h.block<3, 3>(3 * a, 3 * a) += pairs.block[k];
    h.block<3, 3>(3 * a, 3 * b) -= pairs.block[k];
    h.block<3, 3>(3 * b, 3 * a) -= pairs.block[k];
    h.block<3, 3>(3 * b, 3 * b) += pairs.block[k];
  }
  Eigen::VectorXd flat(3 * n);
  for (std::size_t a = 0; a < n; ++a) flat.segment<3>(3 * a) = x[a];
  const Eigen::VectorXd expected = h * flat;

  // Rounding: each entry sums some 30 products of numbers below 2.
  const auto expect_near = [&](const std::vector<Vec3>& y, bool with_diagonal, const char* which) {
    for (std::size_t a = 0; a < n; ++a) {
      const Vec3 want = expected.segment<3>(3 * a) - (with_diagonal ? 0.0 : diagonal[a]) * x[a];
      EXPECT_LT((y[a] - want).cwiseAbs().maxCoeff(), 1e-13) << which << ", particle " << a;
    }
  };
  std::vector<Vec3> y(n);
  std::vector<double> padded;
  pair_block_product(pairs.view(), diagonal, shift, x, y, padded);
  expect_near(y, true, pair_block_product_vectorised() ? "vectorised" : "portable");
  pair_block_product_portable(pairs.view(), diagonal, shift, x, y);
  expect_near(y, true, "portable");
  // Without a diagonal the shift alone stays on it.
  pair_block_product(pairs.view(), {}, shift, x, y, padded);
  expect_near(y, false, "no diagonal");
}

TEST(PairBlockProduct, WithoutPairsOnlyTheDiagonalActs) {
  // A packing below jamming has no contacts: the product is the diagonal's.
  const std::vector<Vec3> x = {Vec3(1.0, -2.0, 3.0), Vec3(0.5, 0.25, -4.0)};
  const std::vector<double> diagonal = {2.0, 3.0};
  std::vector<Vec3> y(2);
  std::vector<double> padded;
  pair_block_product({}, diagonal, 0.5, x, y, padded);
  EXPECT_EQ(y[0], Vec3(2.5, -5.0, 7.5));  // exact: products of binary fractions
  EXPECT_EQ(y[1], Vec3(1.75, 0.875, -14.0));
}

}  // namespace
}  // namespace softglass::micro
