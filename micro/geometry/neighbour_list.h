// Verlet neighbour list for a Lees–Edwards cell, built in O(N) from a cell grid.
//
// The list holds every pair (i < j) closer than R_i + R_j + skin at build time,
// with the periodic image through which the pair is near. Positions are wrapped
// into the cell only when the list is built and move continuously in between,
// so each pair keeps its image: the separation is d = x_i − x_j − s, with s one
// of a few image shifts (image_shifts) in which the Lees–Edwards offset is
// continued from its value at the build, δ_build + L Δγ. The pair loop then
// needs no nearest-image search.
// Cells are cubes of side ≥ 2 R_max + skin in the lab frame. Across the gradient
// (y) boundary the images are shifted by the Lees–Edwards offset, so for a
// particle in the bottom (top) cell layer the x range of candidate cells in the
// top (bottom) layer is taken from the particle's own x shifted by the offset:
// still three cells, and correct at any accumulated strain.
//
// Validity. Between builds a particle moves with the affine flow plus a
// non-affine displacement a_i. For a pair to come into contact (r < R_i + R_j)
// from beyond the list radius it must close a gap of `skin`; its separation can
// change by at most 2A + Δγ (2 R_max + 2A), with A = max_i |a_i| and Δγ the strain
// since the build (the affine part moves a pair by Δγ times its y separation,
// which is at most 2 R_max + 2A for pairs that end up in contact). The list is
// valid while that bound stays below the skin.
//
// A list can also be filtered from another of a larger skin (filter): the
// pairs of the wider list closer than R_i + R_j + skin now, with their images.
// Between the wider list's builds a narrow list is refreshed in one pass over
// the wider one's pairs, so the contact kernel loops over fewer non-touching
// pairs (ContactSystem). The bound above holds for it with its own skin, the
// strain and the non-affine displacement since the filtering.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

class NeighbourList {
 public:
  explicit NeighbourList(double skin);

  double skin() const { return skin_; }

  /// Permutation (new index → old index) that orders particles cell by cell, so
  /// that particles close in space are close in memory.
  std::vector<std::uint32_t> spatial_order(const LeesEdwardsBox& box, std::span<const Vec3> x,
                                           double max_radius) const;

  /// Builds the list; throws InputError if the cell is too small for the grid
  /// (fewer than three cells of side 2 R_max + skin per direction).
  void build(const LeesEdwardsBox& box, std::span<const Vec3> x, std::span<const double> radius);
  /// Builds the list as the pairs of `wider` (a list of a larger skin that
  /// holds every pair within this one's reach at x) closer than
  /// R_i + R_j + skin at x, in the same order and seen through the same images.
  void filter(const NeighbourList& wider, const LeesEdwardsBox& box, std::span<const Vec3> x);

  /// The list's reach at `strain`: the bound above solved for A, i.e. the
  /// non-affine displacement below which it still holds every contact
  /// (negative when the strain alone has used up the skin).
  double nonaffine_reach(double strain) const {
    return reach_after(std::abs(strain - strain_at_build_));
  }
  /// The reach of the list once the strain has changed by `shear` since it
  /// was built.
  double reach_after(double shear) const {
    return (skin_ - 2.0 * shear * max_radius_) / (2.0 + 2.0 * shear);
  }

  /// Whether the list still holds every contact after particles have moved
  /// non-affinely by at most `max_nonaffine` and the strain has reached `strain`.
  bool valid_for(double max_nonaffine, double strain) const {
    return built_ && max_nonaffine < nonaffine_reach(strain);
  }

  /// Neighbours j > i of particle i, each entry packing j and the pair's image.
  std::span<const std::uint32_t> neighbours(std::size_t i) const {
    return {neighbours_.data() + start_[i], start_[i + 1] - start_[i]};
  }
  static std::uint32_t index(std::uint32_t entry) { return entry & kIndexMask; }
  static std::uint32_t image(std::uint32_t entry) { return entry >> kIndexBits; }

  /// What a pair's contact needs that depends only on the two radii, computed
  /// once per build: R_i + R_j, R_c = R_i R_j/(R_i + R_j) and 1/R_c.
  struct PairConstants {
    double contact_distance, contact_radius, inverse_contact_radius;
  };
  /// Constants of the pairs of particle i, aligned with neighbours(i).
  std::span<const PairConstants> pair_constants(std::size_t i) const {
    return {constants_.data() + start_[i], start_[i + 1] - start_[i]};
  }
  /// The rows of particles first … last − 1, stored one after the other, and
  /// their pairs' constants.
  std::span<const std::uint32_t> neighbours(std::size_t first, std::size_t last) const {
    return {neighbours_.data() + start_[first], start_[last] - start_[first]};
  }
  std::span<const PairConstants> pair_constants(std::size_t first, std::size_t last) const {
    return {constants_.data() + start_[first], start_[last] - start_[first]};
  }

  /// Image shift s by image code: (n_x L + n_y δ, n_y L, n_z L) with
  /// n_x ∈ {−2 … 2}, n_y, n_z ∈ {−1, 0, 1} and δ the continued offset.
  static constexpr std::size_t kImages = 45;
  std::array<Vec3, kImages> image_shifts(const LeesEdwardsBox& box) const;

  /// Largest number of particles the packed entries can index.
  static constexpr std::size_t kMaxParticles = std::size_t{1} << 26;

  std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t pair_count() const { return neighbours_.size(); }
  std::size_t builds() const { return builds_; }
  std::size_t memory_bytes() const;

 private:
  struct Grid {
    int cells;  // per direction
    double width;
  };
  Grid grid_for(const LeesEdwardsBox& box, double max_radius) const;
  // The steps of build().
  void sort_into_cells(const Grid& g, std::span<const Vec3> x);
  void find_pairs(const LeesEdwardsBox& box, const Grid& g, std::span<const Vec3> x,
                  std::span<const double> radius, int threads);
  void gather_rows(std::size_t n);
  void compute_constants(std::span<const double> radius, int threads);

  static constexpr unsigned kIndexBits = 26;
  static constexpr std::uint32_t kIndexMask = (1u << kIndexBits) - 1;

  double skin_;
  bool built_ = false;
  double strain_at_build_ = 0.0;  // of the bound above
  // The Lees–Edwards offset δ at strain γ_images, from which image_shifts
  // continues it: the grid build's (a filtered list keeps the wider one's).
  double images_strain_ = 0.0;
  double images_offset_ = 0.0;
  double max_radius_ = 0.0;
  std::size_t builds_ = 0;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> neighbours_;
  std::vector<PairConstants> constants_;
  // scratch reused between builds
  std::vector<std::uint32_t> cell_start_, cell_members_;
  std::vector<std::vector<std::uint32_t>> thread_pairs_;
  std::vector<std::uint32_t> counts_;
};

}  // namespace softglass::micro
