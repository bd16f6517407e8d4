// Coarse meshes of the scenes' sections, with the boundary ids the scenes use.
// Refinement (uniform, adaptive) is the solver's business; these only set the
// shape and a grading that suits the flow.
#pragma once

#include <deal.II/grid/tria.h>

#include <filesystem>

#include "macro/scenes/scene.h"

namespace softglass::macro::meshes {

/// The extent of a coarse mesh (dim = 1, 2); its volume is the section's
/// measure.
template <int dim>
MeshExtent extent(const dealii::Triangulation<dim>& mesh);

/// [a, b] in `cells` equal cells; id 0 at a, 1 at b.
void interval(dealii::Triangulation<1>& mesh, double a, double b, unsigned cells);

/// [x0, x1] × [y0, y1] in nx × ny cells; ids 0 left, 1 right, 2 bottom, 3 top.
void rectangle(dealii::Triangulation<2>& mesh, double x0, double x1, double y0, double y1,
               unsigned nx, unsigned ny);

/// Disc of radius R about the origin, curved boundary (id 0) on a polar manifold.
void disc(dealii::Triangulation<2>& mesh, double radius);

/// A Gmsh .msh file (2D); InputError naming the file if it cannot be read.
void gmsh(dealii::Triangulation<2>& mesh, const std::filesystem::path& file);

/// The meridian section (r, z) of the sample in a cone and plate of radius R:
/// plate z = 0 (id 2), cone z = r tan β truncated flat at the gap z = h_t for
/// r < h_t/tan β (id 3), axis r = 0 (id 0) and the free surface (id 1). The
/// sample reaches the radius `fill` R: filled (1), its rim is cylindrical
/// (r = R) or spherical about the cone's virtual apex (|(r, z)| = R);
/// underfilled (< 1), the same at r = fill R under the cone; overfilled (> 1),
/// a collar of the rim's height R tan β out to r = fill R beyond the cone's
/// edge, its top and side free. `radial` cells up to R (in proportion beyond),
/// `gap` cells across the gap.
void cone_plate(dealii::Triangulation<2>& mesh, double radius, double angle, double truncation,
                bool spherical_rim, double fill, unsigned radial, unsigned gap);

/// The meridian section of a Couette cell with its bottom: cup r = R2 and
/// bottom z = 0 (id 1), bob r = R1 and its base z = h_b (id 0), axis (id 2),
/// free surface z = h_b + L (id 3); the material fills the gap to the bob's top.
void couette_with_bottom(dealii::Triangulation<2>& mesh, double inner_radius, double outer_radius,
                         double length, double bottom_gap, unsigned gap_cells);

}  // namespace softglass::macro::meshes
