// An independent reference for the Newtonian end of the lid-driven cavity
// benchmark (bench/macro_cavity.sh): creeping flow in the unit square, lid
// speed 1, computed without finite elements, from the streamfunction.
//
// With u = ∂ψ/∂y, v = −∂ψ/∂x, Stokes flow is the biharmonic problem
//
//     ∇⁴ψ = 0,   ψ = 0 on the walls,   ∂ψ/∂n = 0 on the fixed walls,
//     ∂ψ/∂y = 1 on the lid (y = 1),
//
// discretised by the 13-point second-order stencil on an N×N grid; the normal
// derivatives enter through ghost values (ψ₋₁ = ψ₁ at a fixed wall,
// ψ_{N+1} = ψ_{N−1} + 2h at the lid). The matrix is symmetric positive
// definite: one sparse Cholesky factorisation. The lid's corners play no
// part (ψ = 0 there): leaky and non-leaky lids are the same problem here.
//
// Prints u_min on the vertical centreline x = 1/2 and its height (parabolic
// interpolation between grid points) for N, 2N, 4N, and the Richardson
// extrapolation of the second-order sequence.
//   usage: stokes_cavity_reference [N = 128]
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

namespace {

struct CentrelineMinimum {
  double u, y;
};

CentrelineMinimum solve(int cells) {
  const int n = cells - 1;  // interior nodes per direction
  const double h = 1.0 / cells;
  const auto index = [n](int i, int j) { return (j - 1) * n + (i - 1); };
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n * n);
  for (int j = 1; j <= n; ++j) {
    for (int i = 1; i <= n; ++i) {
      const int row = index(i, j);
      // Adds c·ψ(a, b) to the row, resolving boundary and ghost values.
      const auto add = [&](int a, int b, double c) {
        if (a == -1) a = 1;  // ∂ψ/∂x = 0 on the side walls
        if (a == cells + 1) a = cells - 1;
        if (b == -1) b = 1;  // ∂ψ/∂y = 0 on the bottom
        if (b == cells + 1) {
          rhs[row] -= c * 2.0 * h;  // ψ_{N+1} = ψ_{N−1} + 2h: u = 1 on the lid
          b = cells - 1;
        }
        if (a == 0 || a == cells || b == 0 || b == cells) return;  // ψ = 0
        entries.emplace_back(row, index(a, b), c);
      };
      add(i, j, 20.0);
      for (const auto& [a, b] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        add(i + a, j + b, -8.0);
        add(i + 2 * a, j + 2 * b, 1.0);
      }
      for (const auto& [a, b] : {std::pair{1, 1}, {1, -1}, {-1, 1}, {-1, -1}})
        add(i + a, j + b, 2.0);
    }
  }
  Eigen::SparseMatrix<double> matrix(n * n, n * n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(matrix);
  if (cholesky.info() != Eigen::Success) {
    std::fprintf(stderr, "stokes_cavity_reference: factorisation failed at N = %d\n", cells);
    std::exit(1);
  }
  const Eigen::VectorXd psi = cholesky.solve(rhs);
  const auto value = [&](int i, int j) {
    return i <= 0 || i >= cells || j <= 0 || j >= cells ? 0.0 : psi[index(i, j)];
  };
  // u = ∂ψ/∂y by central differences on the centreline; minimum by parabola.
  const int centre = cells / 2;
  std::vector<double> u(cells + 1, 0.0);
  int lowest = 1;
  for (int j = 1; j < cells; ++j) {
    u[j] = (value(centre, j + 1) - value(centre, j - 1)) / (2.0 * h);
    if (u[j] < u[lowest]) lowest = j;
  }
  const double below = u[lowest - 1], at = u[lowest], above = u[lowest + 1];
  const double shift = 0.5 * (below - above) / (below - 2.0 * at + above);
  return {at - 0.25 * (below - above) * shift, (lowest + shift) * h};
}

}  // namespace

int main(int argc, char** argv) {
  const int cells = argc > 1 ? std::atoi(argv[1]) : 128;
  if (cells < 8 || cells % 2 != 0) {
    std::fprintf(stderr, "stokes_cavity_reference: N must be even and >= 8\n");
    return 2;
  }
  std::vector<CentrelineMinimum> levels;
  for (int k = 0; k < 3; ++k) {
    levels.push_back(solve(cells << k));
    std::printf("N = %5d: u_min = %.6f at y = %.4f\n", cells << k, levels.back().u,
                levels.back().y);
  }
  // Second order: u_∞ ≈ (4 u_h − u_2h)/3 from the two finest grids.
  const double extrapolated = (4.0 * levels[2].u - levels[1].u) / 3.0;
  const double order = std::log2((levels[1].u - levels[0].u) / (levels[2].u - levels[1].u));
  std::printf("observed order %.2f; extrapolated u_min = %.5f at y = %.3f\n", order, extrapolated,
              levels[2].y);
  return 0;
}
