// Neighbour list under Lees–Edwards: it must hold every pair within
// R_i + R_j + skin, so that the contacts found through it are exactly those of a
// brute-force search over all pairs with the nearest image — at any accumulated
// strain — and it must stay complete for as long as `valid_for` says so.
//
// The brute force (micro_test_support.h) enumerates images explicitly and does
// not use LeesEdwardsBox::minimum_image. Pairs within 1e-9 of a threshold are
// left out of the comparison (they could go either way by rounding; with
// random positions there are none in practice, and the tests check that).
#include <gtest/gtest.h>

#include <random>

#include "common/errors.h"
#include "micro/contact/contact_law.h"
#include "micro/contact/contact_forces.h"
#include "micro/geometry/neighbour_list.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

using testing::brute_force_pairs;
using testing::PairSet;
using testing::random_configuration;

constexpr double kSkin = 0.3;

PairSet list_pairs(const NeighbourList& list) {
  PairSet pairs;
  for (std::uint32_t i = 0; i < list.size(); ++i)
    for (std::uint32_t entry : list.neighbours(i)) {
      const std::uint32_t j = NeighbourList::index(entry);
      EXPECT_GT(j, i) << "the list stores each pair once, j > i";
      pairs.insert({i, j});
    }
  EXPECT_EQ(pairs.size(), list.pair_count()) << "no pair stored twice";
  return pairs;
}

PairSet contact_pairs(const LeesEdwardsBox& box, std::span<const Vec3> x,
                      const NeighbourList& list) {
  const auto hertz = testing::named_law("hertz");
  ContactField field;
  compute_contact_forces(*hertz, box, x, list, {.contacts = true}, field);
  PairSet pairs;
  for (std::size_t k = 0; k < field.contacts.size(); ++k)
    pairs.insert(testing::ordered(field.contacts.i[k], field.contacts.j[k]));
  EXPECT_EQ(pairs.size(), field.contact_count);
  return pairs;
}

class NeighbourListAtStrain : public ::testing::TestWithParam<double> {};

TEST_P(NeighbourListAtStrain, MatchesBruteForce) {
  // 400 particles at φ = 0.7, placed at random (so they overlap a lot): about
  // 1000 contacts, a good share of them across the gradient boundary.
  const double strain = GetParam();
  const auto c = random_configuration(400, 0.7, 2024);
  LeesEdwardsBox box(c.side);
  box.set_strain(strain);
  NeighbourList list(kSkin);
  list.build(box, c.position, c.radius);

  PairSet ambiguous;
  const PairSet expected_list =
      brute_force_pairs(c.position, c.radius, c.side, strain, kSkin, 1e-9, &ambiguous);
  const PairSet expected_contacts =
      brute_force_pairs(c.position, c.radius, c.side, strain, 0.0, 1e-9, &ambiguous);
  ASSERT_TRUE(ambiguous.empty()) << "a pair sits within 1e-9 of a threshold; change the seed";
  ASSERT_GT(expected_contacts.size(), 800u);

  EXPECT_EQ(list_pairs(list), expected_list) << "strain " << strain;
  EXPECT_EQ(contact_pairs(box, c.position, list), expected_contacts) << "strain " << strain;

  // Some of those pairs must cross the y boundary, or the test says little
  // about Lees–Edwards.
  std::size_t across = 0;
  for (const auto& [i, j] : expected_contacts)
    across += std::abs(c.position[i].y() - c.position[j].y()) > c.side / 2;
  EXPECT_GT(across, 25u);
}

// 0: plain periodic; 0.5: offset L/2; 7.3 and 1e4 + 0.37: many box lengths of
// shear, where the offset must be taken from the fractional strain.
INSTANTIATE_TEST_SUITE_P(Strains, NeighbourListAtStrain,
                         ::testing::Values(0.0, 0.5, 7.3, 1e4 + 0.37));

TEST(NeighbourList, StaysCompleteWithinTheValidityBound) {
  // Build at strain 7.3, then move every particle by a random non-affine
  // displacement of length exactly A plus the affine shear Δγ y e_x, with
  //     2A + Δγ (2 R_max + 2A) = 0.95 skin  (inside the bound of neighbour_list.h).
  // The old list must then still hold every contact of the moved configuration.
  // Between builds positions move continuously (the list carries each pair's
  // image); the brute-force reference gets them wrapped into the cell.
  const auto c = random_configuration(400, 0.7, 77);
  const double start = 7.3;
  LeesEdwardsBox box(c.side);
  box.set_strain(start);
  NeighbourList list(kSkin);
  list.build(box, c.position, c.radius);

  const double r_max = *std::max_element(c.radius.begin(), c.radius.end());
  const double a = 0.2 * kSkin;
  const double strain_step = (0.95 * kSkin - 2 * a) / (2 * r_max + 2 * a);
  EXPECT_TRUE(list.valid_for(a, start + strain_step));
  EXPECT_TRUE(list.valid_for(a, start - strain_step));  // either direction of shear

  LeesEdwardsBox moved_box = box;
  moved_box.set_strain(start + strain_step);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  std::vector<Vec3> moved = c.position;
  for (std::size_t i = 0; i < moved.size(); ++i) {
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    moved[i] += a * direction + Vec3(strain_step * c.position[i].y(), 0, 0);
  }
  std::vector<Vec3> wrapped = moved;
  for (Vec3& x : wrapped) moved_box.wrap(x);
  PairSet ambiguous;
  const PairSet expected =
      brute_force_pairs(wrapped, c.radius, c.side, start + strain_step, 0.0, 1e-9, &ambiguous);
  ASSERT_TRUE(ambiguous.empty());
  const PairSet found = contact_pairs(moved_box, moved, list);
  EXPECT_EQ(found, expected);
  // The moves did change the contact network (otherwise nothing was tested).
  const PairSet before = brute_force_pairs(c.position, c.radius, c.side, start, 0.0);
  EXPECT_NE(before, expected);
}

TEST(NeighbourList, FilteredListHoldsThePairsWithinItsSkinAndStaysComplete) {
  // A wide list built at strain 7.3, the particles moved within its bound, a
  // narrow list (a quarter of the skin) filtered from it there: the narrow list
  // holds exactly the pairs within R_i + R_j + skin/4 of the moved
  // configuration, through the wide list's images. Moved again within the
  // narrow list's own bound (from the filtering), it still holds every contact.
  const auto c = random_configuration(400, 0.7, 77);
  const double r_max = *std::max_element(c.radius.begin(), c.radius.end());
  const double start = 7.3, narrow_skin = 0.25 * kSkin;
  LeesEdwardsBox box(c.side);
  box.set_strain(start);
  NeighbourList wide(kSkin), narrow(narrow_skin);
  wide.build(box, c.position, c.radius);

  std::mt19937_64 rng(9);
  std::normal_distribution<double> normal;
  // x + a n + Δγ y e_x with 2a + Δγ (2 R_max + 2a) = `share` of `skin`.
  const auto move = [&](const std::vector<Vec3>& x, double skin, double share, double& strain) {
    const double a = 0.2 * skin;
    const double step = (share * skin - 2 * a) / (2 * r_max + 2 * a);
    std::vector<Vec3> moved = x;
    for (std::size_t i = 0; i < moved.size(); ++i) {
      const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
      moved[i] += a * direction + Vec3(step * x[i].y(), 0, 0);
    }
    strain += step;
    return moved;
  };
  const auto wrapped_at = [&](std::vector<Vec3> x, double strain) {
    LeesEdwardsBox b(c.side);
    b.set_strain(strain);
    for (Vec3& xi : x) b.wrap(xi);
    return x;
  };

  double strain = start;
  const std::vector<Vec3> first = move(c.position, kSkin, 0.5, strain);
  box.set_strain(strain);
  narrow.filter(wide, box, first);
  PairSet ambiguous;
  const PairSet expected = brute_force_pairs(wrapped_at(first, strain), c.radius, c.side, strain,
                                             narrow_skin, 1e-9, &ambiguous);
  ASSERT_TRUE(ambiguous.empty());
  EXPECT_EQ(list_pairs(narrow), expected);
  EXPECT_LT(narrow.pair_count(), wide.pair_count());
  EXPECT_TRUE(narrow.valid_for(0.0, strain));
  const PairSet first_contacts = contact_pairs(box, first, wide);
  EXPECT_EQ(contact_pairs(box, first, narrow), first_contacts);

  const std::vector<Vec3> second = move(first, narrow_skin, 0.95, strain);
  EXPECT_TRUE(narrow.valid_for(0.2 * narrow_skin, strain));
  box.set_strain(strain);
  const PairSet contacts = brute_force_pairs(wrapped_at(second, strain), c.radius, c.side, strain,
                                             0.0, 1e-9, &ambiguous);
  ASSERT_TRUE(ambiguous.empty());
  EXPECT_EQ(contact_pairs(box, second, narrow), contacts);
  EXPECT_NE(contacts, first_contacts) << "the moves changed the contact network";
}

TEST(NeighbourList, ValidityBoundIsTightForNonAffineMoves) {
  // Two unit spheres a distance 2 + 1.001·skin apart: not in the list. Moving
  // each towards the other by A closes the gap by 2A. With 2A = 0.999 skin the
  // bound says "valid" and indeed they do not touch; with 2A = 1.003 skin the
  // bound says "invalid", and indeed they touch while the stale list misses it.
  const double side = 20.0;  // ≥ 3 (2 R_max + skin) for the grid
  LeesEdwardsBox box(side);
  const std::vector<double> radius = {1.0, 1.0};
  const double gap = 1.001 * kSkin;
  const std::vector<Vec3> x = {Vec3(10.0, 10.0, 10.0), Vec3(10.0 + 2.0 + gap, 10.0, 10.0)};
  NeighbourList list(kSkin);
  list.build(box, x, radius);
  EXPECT_EQ(list.pair_count(), 0u);

  for (const double two_a : {0.999 * kSkin, 1.003 * kSkin}) {
    const double a = two_a / 2;
    const std::vector<Vec3> moved = {x[0] + Vec3(a, 0, 0), x[1] - Vec3(a, 0, 0)};
    const bool touching = (moved[1] - moved[0]).norm() < 2.0;
    EXPECT_EQ(list.valid_for(a, 0.0), !touching) << "2A = " << two_a;
    EXPECT_EQ(contact_pairs(box, moved, list).size(), 0u);  // the stale list sees nothing
    EXPECT_EQ(brute_force_pairs(moved, radius, side, 0.0, 0.0).size(), touching ? 1u : 0u);
  }
}

TEST(NeighbourList, ValidForIsFalseBeyondTheBound) {
  const auto c = random_configuration(300, 0.7, 3);
  LeesEdwardsBox box(c.side);
  box.set_strain(0.25);
  NeighbourList list(kSkin);
  EXPECT_FALSE(list.valid_for(0.0, 0.25)) << "an unbuilt list is never valid";
  list.build(box, c.position, c.radius);
  const double r_max = *std::max_element(c.radius.begin(), c.radius.end());

  EXPECT_TRUE(list.valid_for(0.0, 0.25));
  // non-affine only: 2A < skin
  EXPECT_TRUE(list.valid_for(0.499 * kSkin, 0.25));
  EXPECT_FALSE(list.valid_for(0.501 * kSkin, 0.25));
  // affine only: Δγ · 2 R_max < skin, in both directions of strain
  const double limit = kSkin / (2 * r_max);
  EXPECT_TRUE(list.valid_for(0.0, 0.25 + 0.99 * limit));
  EXPECT_FALSE(list.valid_for(0.0, 0.25 + 1.01 * limit));
  EXPECT_TRUE(list.valid_for(0.0, 0.25 - 0.99 * limit));
  EXPECT_FALSE(list.valid_for(0.0, 0.25 - 1.01 * limit));
  // combined: 2A + Δγ (2 R_max + 2A) < skin
  const double a = 0.1 * kSkin;
  const double combined = (kSkin - 2 * a) / (2 * r_max + 2 * a);
  EXPECT_TRUE(list.valid_for(a, 0.25 + 0.99 * combined));
  EXPECT_FALSE(list.valid_for(a, 0.25 + 1.01 * combined));
  // the reach is that bound solved for A: half the skin at the build's strain,
  // a at the combined strain limit, nothing left at the affine-only one
  EXPECT_DOUBLE_EQ(list.nonaffine_reach(0.25), 0.5 * kSkin);
  EXPECT_NEAR(list.nonaffine_reach(0.25 + combined), a, 1e-12);
  EXPECT_NEAR(list.nonaffine_reach(0.25 - limit), 0.0, 1e-12);
}

TEST(NeighbourList, TooSmallCellIsAnInputError) {
  // The grid needs three cells of side 2 R_max + skin per direction.
  LeesEdwardsBox box(3 * (2.0 + kSkin) - 0.01);
  const std::vector<Vec3> x = {Vec3(1, 1, 1), Vec3(4, 4, 4)};
  const std::vector<double> radius = {1.0, 1.0};
  NeighbourList list(kSkin);
  EXPECT_THROW(list.build(box, x, radius), InputError);
  LeesEdwardsBox big(3 * (2.0 + kSkin) + 0.01);
  EXPECT_NO_THROW(list.build(big, x, radius));
}

}  // namespace
}  // namespace softglass::micro
