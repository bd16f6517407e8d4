#include "micro/geometry/neighbour_list.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/errors.h"

namespace softglass::micro {

namespace {
inline int cell_coordinate(double position, double width, int cells) {
  return std::min(static_cast<int>(position / width), cells - 1);
}
inline int periodic(int c, int cells) {
  return c < 0 ? c + cells : (c >= cells ? c - cells : c);
}
}  // namespace

NeighbourList::NeighbourList(double skin) : skin_(skin) {
  require(skin > 0.0 && std::isfinite(skin),
          fmt::format("neighbour skin = {} must be positive", skin));
}

NeighbourList::Grid NeighbourList::grid_for(const LeesEdwardsBox& box, double max_radius) const {
  const double reach = 2.0 * max_radius + skin_;
  const int cells = static_cast<int>(std::floor(box.side() / reach));
  if (cells < 3) {
    throw InputError(fmt::format(
        "the cell (side L = {:.4g} R) is too small for the neighbour grid: it needs L ≥ 3 × "
        "(2 R_max + skin) = {:.4g} R; use more particles or a smaller skin",
        box.side(), 3.0 * reach));
  }
  return {cells, box.side() / cells};
}

std::vector<std::uint32_t> NeighbourList::spatial_order(const LeesEdwardsBox& box,
                                                        std::span<const Vec3> x,
                                                        double max_radius) const {
  const Grid g = grid_for(box, max_radius);
  std::vector<std::uint32_t> cell(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int cx = cell_coordinate(x[i].x(), g.width, g.cells);
    const int cy = cell_coordinate(x[i].y(), g.width, g.cells);
    const int cz = cell_coordinate(x[i].z(), g.width, g.cells);
    cell[i] = static_cast<std::uint32_t>((cz * g.cells + cy) * g.cells + cx);
  }
  std::vector<std::uint32_t> order(x.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return cell[a] < cell[b]; });
  return order;
}

void NeighbourList::build(const LeesEdwardsBox& box, std::span<const Vec3> x,
                          std::span<const double> radius) {
  const std::size_t n = x.size();
  if (n > kMaxParticles) {
    throw InputError(
        fmt::format("{} particles exceed the neighbour list's limit of {}", n, kMaxParticles));
  }
  max_radius_ = n ? *std::max_element(radius.begin(), radius.end()) : 0.0;
  const Grid g = grid_for(box, max_radius_);
  sort_into_cells(g, x);
  const int threads = n >= 4096 ? omp_get_max_threads() : 1;
  find_pairs(box, g, x, radius, threads);
  gather_rows(n);
  compute_constants(radius, threads);
  strain_at_build_ = box.strain();
  images_strain_ = box.strain();
  images_offset_ = box.image_offset();
  built_ = true;
  ++builds_;
}

// Two passes over the wider list's rows: count the pairs kept per row, then
// copy them (and their constants) into place, each thread over its own rows.
void NeighbourList::filter(const NeighbourList& wider, const LeesEdwardsBox& box,
                           std::span<const Vec3> x) {
  const std::size_t n = wider.size();
  const auto shifts = wider.image_shifts(box);
  const auto kept = [&](std::size_t i, std::size_t p) {
    const std::uint32_t entry = wider.neighbours_[p];
    const Vec3 d = x[i] - x[index(entry)] - shifts[image(entry)];
    const double cutoff = wider.constants_[p].contact_distance + skin_;
    return d.squaredNorm() < cutoff * cutoff;
  };
  const int threads = n >= 4096 ? omp_get_max_threads() : 1;
  start_.assign(n + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t count = 0;
    for (std::size_t p = wider.start_[i]; p < wider.start_[i + 1]; ++p) count += kept(i, p);
    start_[i + 1] = count;
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  neighbours_.resize(start_[n]);
  constants_.resize(start_[n]);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t q = start_[i];
    for (std::size_t p = wider.start_[i]; p < wider.start_[i + 1]; ++p) {
      if (!kept(i, p)) continue;
      neighbours_[q] = wider.neighbours_[p];
      constants_[q++] = wider.constants_[p];
    }
  }
  max_radius_ = wider.max_radius_;
  strain_at_build_ = box.strain();
  images_strain_ = wider.images_strain_;
  images_offset_ = wider.images_offset_;
  built_ = true;
  ++builds_;
}

// Counting sort of the particles into the grid's cells.
void NeighbourList::sort_into_cells(const Grid& g, std::span<const Vec3> x) {
  const std::size_t n = x.size();
  const int nc = g.cells;
  const std::size_t ncell = static_cast<std::size_t>(nc) * nc * nc;
  std::vector<std::uint32_t> cell_of(n);
  cell_start_.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = cell_coordinate(x[i].x(), g.width, nc);
    const int cy = cell_coordinate(x[i].y(), g.width, nc);
    const int cz = cell_coordinate(x[i].z(), g.width, nc);
    cell_of[i] = static_cast<std::uint32_t>((cz * nc + cy) * nc + cx);
    ++cell_start_[cell_of[i] + 1];
  }
  std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
  cell_members_.resize(n);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    cell_members_[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
}

// The pairs (i, j > i) within reach, each thread into its own list, with the
// image each pair is seen through; counts_[i] the pairs of i.
void NeighbourList::find_pairs(const LeesEdwardsBox& box, const Grid& g, std::span<const Vec3> x,
                               std::span<const double> radius, int threads) {
  const std::size_t n = x.size();
  const int nc = g.cells;
  const double reach = 2.0 * max_radius_ + skin_;
  const double offset = box.image_offset();
  const double L = box.side();
  counts_.assign(n, 0);
  thread_pairs_.resize(threads);

#pragma omp parallel num_threads(threads)
  {
    std::vector<std::uint32_t>& pairs = thread_pairs_[omp_get_thread_num()];
    pairs.clear();
    // The members of cell c that pair with i, appended to `pairs`.
    const auto scan_cell = [&](std::size_t i, std::size_t c, std::uint32_t& count) {
      const Vec3 xi = x[i];
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t j = cell_members_[k];
        if (j <= i) continue;
        const double cutoff = radius[i] + radius[j] + skin_;
        const Vec3 raw = xi - x[j];
        const Vec3 d = box.minimum_image(raw);
        if (d.squaredNorm() < cutoff * cutoff) {
          // raw − d = (n_x L + n_y δ, n_y L, n_z L)
          const int ny = static_cast<int>(std::lround((raw.y() - d.y()) / L));
          const int nz = static_cast<int>(std::lround((raw.z() - d.z()) / L));
          const int nx = static_cast<int>(std::lround((raw.x() - d.x() - ny * offset) / L));
          const auto code = static_cast<std::uint32_t>((nx + 2) + 5 * (ny + 1) + 15 * (nz + 1));
          pairs.push_back(j | (code << kIndexBits));
          ++count;
        }
      }
    };
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 xi = x[i];
      const int cx = cell_coordinate(xi.x(), g.width, nc);
      const int cy = cell_coordinate(xi.y(), g.width, nc);
      const int cz = cell_coordinate(xi.z(), g.width, nc);
      std::uint32_t count = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        int y = cy + dy;
        // x range of candidate cells; shifted across the Lees–Edwards boundary.
        int x_lo = cx - 1, x_hi = cx + 1;
        if (y < 0 || y >= nc) {
          const double shifted = y < 0 ? xi.x() + offset : xi.x() - offset;
          x_lo = static_cast<int>(std::floor((shifted - reach) / g.width));
          x_hi = static_cast<int>(std::floor((shifted + reach) / g.width));
          y = periodic(y, nc);
        }
        for (int dz = -1; dz <= 1; ++dz) {
          const int z = periodic(cz + dz, nc);
          for (int xc = x_lo; xc <= x_hi; ++xc) {
            const int xw = ((xc % nc) + nc) % nc;
            scan_cell(i, (static_cast<std::size_t>(z) * nc + y) * nc + xw, count);
          }
        }
      }
      counts_[i] = count;
    }
  }
}

// The per-thread lists concatenated into CSR form. With a static schedule the
// threads own consecutive ranges of i, so thread order is index order; the
// neighbours of each i are then sorted by j, a fixed summation order whatever
// the grid.
void NeighbourList::gather_rows(std::size_t n) {
  start_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] = start_[i] + counts_[i];
  neighbours_.clear();
  neighbours_.reserve(start_[n]);
  for (const auto& pairs : thread_pairs_)
    neighbours_.insert(neighbours_.end(), pairs.begin(), pairs.end());
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(neighbours_.begin() + static_cast<std::ptrdiff_t>(start_[i]),
              neighbours_.begin() + static_cast<std::ptrdiff_t>(start_[i + 1]),
              [](std::uint32_t a, std::uint32_t b) { return index(a) < index(b); });
  }
}

// R_i + R_j, R_c and 1/R_c of every pair, for the kernels.
void NeighbourList::compute_constants(std::span<const double> radius, int threads) {
  const std::size_t n = start_.size() - 1;
  constants_.resize(neighbours_.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t p = start_[i]; p < start_[i + 1]; ++p) {
      const double ri = radius[i], rj = radius[index(neighbours_[p])];
      const double sum = ri + rj;
      constants_[p] = {sum, ri * rj / sum, sum / (ri * rj)};
    }
  }
}

std::array<Vec3, NeighbourList::kImages> NeighbourList::image_shifts(
    const LeesEdwardsBox& box) const {
  const double L = box.side();
  const double delta = images_offset_ + L * (box.strain() - images_strain_);
  std::array<Vec3, kImages> shifts;
  for (int nz = -1; nz <= 1; ++nz)
    for (int ny = -1; ny <= 1; ++ny)
      for (int nx = -2; nx <= 2; ++nx) {
        shifts[(nx + 2) + 5 * (ny + 1) + 15 * (nz + 1)] = Vec3(nx * L + ny * delta, ny * L, nz * L);
      }
  return shifts;
}

std::size_t NeighbourList::memory_bytes() const {
  return start_.capacity() * sizeof(std::size_t) + neighbours_.capacity() * sizeof(std::uint32_t) +
         constants_.capacity() * sizeof(PairConstants) +
         (cell_start_.capacity() + cell_members_.capacity() + counts_.capacity()) *
             sizeof(std::uint32_t);
}

}  // namespace softglass::micro
