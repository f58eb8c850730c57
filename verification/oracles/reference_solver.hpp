// Iterative reference for the fast solvers: assembles (a I + b L) with the same ghost rules as
// SpectralSolver (sparse, Eigen) and solves it by conjugate gradients. Slow on purpose: it shares
// no code with the transforms, so verification can compare the two.
#pragma once
#include <vector>

#include "core/grid.hpp"
#include "fluid/spectral_solver.hpp"

namespace ibms {

struct ReferenceSolveStats {
  int iterations = 0;
  double relative_residual = 0.0;
};

// rhs and solution contiguous (ny, nx). A singular system (pure Neumann/periodic Poisson) is
// solved for the zero-mean solution after the rhs mean is removed.
ReferenceSolveStats solve_reference(const Grid& grid, SpectralBoundary boundary_x,
                                    SpectralBoundary boundary_y, double a, double b,
                                    const std::vector<double>& rhs, std::vector<double>& solution,
                                    double tolerance = 1e-14);

// Apply (a I + b L) with the same ghost rules (for residual checks).
std::vector<double> apply_operator(const Grid& grid, SpectralBoundary boundary_x,
                                   SpectralBoundary boundary_y, double a, double b,
                                   const std::vector<double>& q);

}  // namespace ibms
