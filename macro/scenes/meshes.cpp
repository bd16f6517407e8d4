#include "macro/scenes/meshes.h"

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <limits>
#include <set>

#include "common/errors.h"
#include "common/input_file.h"

namespace softglass::macro::meshes {

using namespace dealii;

namespace {

std::vector<double> steps(double length, unsigned cells) {
  return std::vector<double>(cells, length / cells);
}

// Cell counts for the pieces of a segment split at interior points, at least
// one each, in proportion to length.
unsigned cells_for(double piece, double total, unsigned cells) {
  return std::max(1u, static_cast<unsigned>(std::lround(cells * piece / total)));
}

}  // namespace

template <int dim>
MeshExtent extent(const Triangulation<dim>& mesh) {
  MeshExtent e{.dimension = dim, .cells = mesh.n_active_cells()};
  e.smallest_cell = std::numeric_limits<double>::infinity();
  for (const auto& cell : mesh.active_cell_iterators())
    e.smallest_cell = std::min(e.smallest_cell, cell->minimum_vertex_distance());
  const auto [low, high] = GridTools::compute_bounding_box(mesh).get_boundary_points();
  e.largest_extent = low.distance(high);
  e.volume = GridTools::volume(mesh);
  return e;
}

template MeshExtent extent(const Triangulation<1>&);
template MeshExtent extent(const Triangulation<2>&);

void interval(Triangulation<1>& mesh, double a, double b, unsigned cells) {
  GridGenerator::subdivided_hyper_cube(mesh, cells, a, b, true);
}

void rectangle(Triangulation<2>& mesh, double x0, double x1, double y0, double y1, unsigned nx,
               unsigned ny) {
  GridGenerator::subdivided_hyper_rectangle(mesh, {nx, ny}, Point<2>(x0, y0), Point<2>(x1, y1),
                                            true);
}

void disc(Triangulation<2>& mesh, double radius) {
  GridGenerator::hyper_ball_balanced(mesh, Point<2>(), radius);
  mesh.set_all_manifold_ids_on_boundary(0);
  mesh.set_manifold(0, PolarManifold<2>(Point<2>()));
  for (const auto& face : mesh.active_face_iterators())
    if (face->at_boundary()) face->set_boundary_id(0);
}

void gmsh(Triangulation<2>& mesh, const std::filesystem::path& file) {
  std::istringstream in(read_input_text(file, "duct: mesh file"));
  GridIn<2> reader;
  reader.attach_triangulation(mesh);
  try {
    reader.read_msh(in);
  } catch (const std::exception& error) {
    throw InputError(
        fmt::format("duct: mesh file = '{}' is not a readable 2D Gmsh mesh of quadrilaterals: {}",
                    file.string(), error.what()));
  }
  require(mesh.n_active_cells() > 0,
          fmt::format("duct: mesh file = '{}' has no cells", file.string()));
}

void cone_plate(Triangulation<2>& mesh, double radius, double angle, double truncation,
                bool spherical_rim, double fill, unsigned radial, unsigned gap) {
  const double t = std::tan(angle);
  // The sample's extent under the cone (an underfilled sample stops short of
  // the edge) and the collar beyond it (an overfilled one).
  const double covered = std::min(fill, 1.0) * radius;
  const double collar = std::max(fill - 1.0, 0.0) * radius;
  const bool spherical = spherical_rim && collar == 0.0;
  const double r_t = std::min(truncation / t, 0.5 * covered);
  // A vertex column at the edge of the truncation, r_t, where the cone's
  // surface has its kink; the flat part gets cells in proportion, at least 2.
  std::vector<double> r_steps;
  if (r_t > 0.0) {
    const unsigned inner = std::max(2u, cells_for(r_t, radius, radial));
    r_steps = steps(r_t, inner);
  }
  for (double h : steps(covered - r_t, cells_for(covered, radius, radial))) r_steps.push_back(h);
  if (collar > 0.0)
    for (double h : steps(collar, cells_for(collar, radius, radial))) r_steps.push_back(h);
  const double outer = covered + collar;
  GridGenerator::subdivided_hyper_rectangle(mesh, {r_steps, steps(1.0, gap)}, Point<2>(0.0, 0.0),
                                            Point<2>(outer, 1.0), true);
  // The gap under the cone; the collar keeps the height of the cone's edge.
  const auto height = [&](double r) { return std::max(truncation, std::min(r, radius) * t); };
  GridTools::transform(
      [&](const Point<2>& p) {
        const double r = p[0], eta = p[1];
        Point<2> q(r, eta * height(r));
        if (spherical && r > r_t) {
          // Slide the point along the ray from the virtual apex (the origin):
          // points of the plate stay on the plate and points of the cone on
          // the cone, and the rim column lands on |(r, z)| = R. The shift
          // fades in quadratically from the truncation edge.
          const double on_rim = 1.0 / std::sqrt(1.0 + eta * eta * t * t);
          const double blend = std::pow((r - r_t) / (covered - r_t), 2);
          q *= 1.0 + blend * (on_rim - 1.0);
        }
        return q;
      },
      mesh);
  // The collar's top is a free surface, not the cone.
  for (const auto& face : mesh.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == 3 && face->center()[0] > radius)
      face->set_boundary_id(1);
  if (spherical) {
    // Beyond the truncation every boundary is a ray from the apex (cone,
    // plate) or an arc about it (rim): a polar manifold keeps refined
    // vertices on them, so the rim stays spherical instead of keeping the
    // coarse mesh's chords (a torque error of ~1e-4 at 2°).
    for (const auto& cell : mesh.active_cell_iterators())
      if (cell->center()[0] > r_t) cell->set_all_manifold_ids(1);
    mesh.set_manifold(1, PolarManifold<2>(Point<2>()));
  }
}

void couette_with_bottom(Triangulation<2>& mesh, double inner_radius, double outer_radius,
                         double length, double bottom_gap, unsigned gap_cells) {
  const double gap = outer_radius - inner_radius, cell = gap / gap_cells;
  const auto count = [&](double extent) {
    return std::max(1u, unsigned(std::lround(extent / cell)));
  };
  std::vector<double> r_steps = steps(inner_radius, count(inner_radius));
  for (double h : steps(gap, gap_cells)) r_steps.push_back(h);
  std::vector<double> z_steps = steps(bottom_gap, count(bottom_gap));
  // Along the bob the flow hardly changes with z: cells 4 times taller than
  // wide there (the ends are resolved by the bottom's square cells and by
  // adaptive refinement).
  for (double h : steps(length, count(0.25 * length))) z_steps.push_back(h);
  Triangulation<2> box;
  GridGenerator::subdivided_hyper_rectangle(box, {r_steps, z_steps}, Point<2>(0.0, 0.0),
                                            Point<2>(outer_radius, bottom_gap + length), false);
  std::set<Triangulation<2>::active_cell_iterator> bob;
  for (const auto& c : box.active_cell_iterators())
    if (c->center()[0] < inner_radius && c->center()[1] > bottom_gap) bob.insert(c);
  GridGenerator::create_triangulation_with_removed_cells(box, bob, mesh);
  const double tol = 1e-9 * outer_radius;
  for (const auto& face : mesh.active_face_iterators()) {
    if (!face->at_boundary()) continue;
    const Point<2> c = face->center();
    if (std::abs(c[0] - outer_radius) < tol || std::abs(c[1]) < tol) {
      face->set_boundary_id(1);
    } else if (std::abs(c[0]) < tol) {
      face->set_boundary_id(2);
    } else if (std::abs(c[1] - bottom_gap - length) < tol && c[0] > inner_radius) {
      face->set_boundary_id(3);
    } else {
      face->set_boundary_id(0);
    }
  }
}

}  // namespace softglass::macro::meshes
