// Eigen sparse assembly of the 5-point operator with ghost rules (docs/method.md §2.5, §6) and CG.
#include "oracles/reference_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

namespace ibms {
namespace {

// Neighbour of cell `i` across a face in one direction: returns the index (or -1 for a ghost)
// and the ghost factor: Neumann ghost q_g = q_int (+1), Dirichlet q_g = -q_int (-1).
struct Neighbour { int index; double factor; };

Neighbour neighbour(int i, int n, SpectralBoundary b) {
  if (i >= 0 && i < n) return {i, 1.0};
  if (b == SpectralBoundary::periodic) return {(i + n) % n, 1.0};
  const int mirror = i < 0 ? 0 : n - 1;
  return {mirror, b == SpectralBoundary::neumann ? 1.0 : -1.0};
}

Eigen::SparseMatrix<double> assemble(const Grid& g, SpectralBoundary bx, SpectralBoundary by,
                                     double a, double b) {
  std::vector<Eigen::Triplet<double>> entries;
  const double cx = b / (g.dx() * g.dx()), cy = b / (g.dy() * g.dy());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int row = static_cast<int>(g.index(i, j));
      entries.emplace_back(row, row, a - 2.0 * cx - 2.0 * cy);
      for (int d : {-1, 1}) {
        const Neighbour nx = neighbour(i + d, g.nx, bx);
        entries.emplace_back(row, static_cast<int>(g.index(nx.index, j)), cx * nx.factor);
        const Neighbour ny = neighbour(j + d, g.ny, by);
        entries.emplace_back(row, static_cast<int>(g.index(i, ny.index)), cy * ny.factor);
      }
    }
  Eigen::SparseMatrix<double> m(static_cast<int>(g.n_cells()), static_cast<int>(g.n_cells()));
  m.setFromTriplets(entries.begin(), entries.end());  // duplicates (ghost folds) are summed
  return m;
}

bool is_singular(SpectralBoundary bx, SpectralBoundary by, double a) {
  return a == 0.0 && bx != SpectralBoundary::dirichlet && by != SpectralBoundary::dirichlet;
}

}  // namespace

ReferenceSolveStats solve_reference(const Grid& grid, SpectralBoundary boundary_x,
                                    SpectralBoundary boundary_y, double a, double b,
                                    const std::vector<double>& rhs, std::vector<double>& solution,
                                    double tolerance) {
  Eigen::SparseMatrix<double> m = assemble(grid, boundary_x, boundary_y, a, b);
  Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(rhs.data(), static_cast<int>(rhs.size()));
  const bool singular = is_singular(boundary_x, boundary_y, a);
  if (singular) r.array() -= r.mean();
  // CG needs a positive (semi-)definite matrix: flip the sign when the diagonal is negative.
  const double sign = m.coeff(0, 0) < 0.0 ? -1.0 : 1.0;
  m *= sign;
  r *= sign;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(20 * static_cast<int>(grid.n_cells()));
  cg.compute(m);
  Eigen::VectorXd q = cg.solve(r);
  if (singular) q.array() -= q.mean();
  solution.assign(q.data(), q.data() + q.size());
  return {static_cast<int>(cg.iterations()), cg.error()};
}

std::vector<double> apply_operator(const Grid& grid, SpectralBoundary boundary_x,
                                   SpectralBoundary boundary_y, double a, double b,
                                   const std::vector<double>& q) {
  const Eigen::SparseMatrix<double> m = assemble(grid, boundary_x, boundary_y, a, b);
  const Eigen::VectorXd result = m * Eigen::Map<const Eigen::VectorXd>(q.data(), static_cast<int>(q.size()));
  return {result.data(), result.data() + result.size()};
}

}  // namespace ibms
