// Direct solver of (a I + b L) q = r on the cell-centred grid by FFTW real-to-real transforms
// (docs/method.md §6): DCT-II/III for Neumann at both ends of a direction, DST-II/III for homogeneous
// Dirichlet at both ends, DCT-IV (REDFT11) for Neumann at the low end and Dirichlet at the high one,
// DST-IV (RODFT11) for the reverse (open channels), R2HC/HC2R for periodic directions. L is the compact 5-point Laplacian with the ghost rules of
// fluid/boundary_conditions.hpp. Plans are made once (FftPlanning); solve() allocates nothing.
#pragma once
#include <fftw3.h>

#include <vector>

#include "core/grid.hpp"
#include "core/options.hpp"

#include <string>

namespace ibms {

enum class SpectralBoundary { periodic, neumann, dirichlet };

// FftPlanning (measure | estimate): core/options.hpp.

struct SpectralSolveStats {
  double removed_mean = 0.0;  // mean of r projected out when a I + b L is singular [units of r]
};

class SpectralSolver {
 public:
  // Boundary kind per direction; a periodic grid direction must be `periodic`.
  SpectralSolver(const Grid& grid, SpectralBoundary boundary_x, SpectralBoundary boundary_y,
                 FftPlanning planning = FftPlanning::measure);
  // Boundary kind per side (low and high end of each direction); periodic only at both ends.
  SpectralSolver(const Grid& grid, SpectralBoundary left, SpectralBoundary right, SpectralBoundary bottom,
                 SpectralBoundary top, FftPlanning planning = FftPlanning::measure);
  ~SpectralSolver();
  SpectralSolver(const SpectralSolver&) = delete;
  SpectralSolver& operator=(const SpectralSolver&) = delete;

  // rhs and solution: contiguous (ny, nx), x fastest; may alias. If a + b(lambda_x + lambda_y)
  // vanishes (the constant mode of a pure Neumann/periodic Poisson problem) that mode of the
  // solution is set to 0 (zero mean) and the rhs mean is reported as removed.
  SpectralSolveStats solve(double a, double b, const double* rhs, double* solution);
  // The same with the 1D eigenvalues given (ex: nx values, ey: ny values, transform order) in place
  // of the compact Laplacian's: a + b (ex_k + ey_l). Any operator the transforms diagonalise.
  SpectralSolveStats solve(double a, double b, const double* rhs, double* solution, const std::vector<double>& ex,
                           const std::vector<double>& ey);

  // Eigenvalues of the 1D operators in transform order [1/length^2].
  const std::vector<double>& eigenvalues_x() const { return lambda_x_; }
  const std::vector<double>& eigenvalues_y() const { return lambda_y_; }

 private:
  int nx_, ny_;
  double normalisation_;  // product of the per-direction logical sizes
  std::vector<double> lambda_x_, lambda_y_;
  double* buffer_ = nullptr;  // fftw_malloc'ed, nx*ny
  fftw_plan forward_ = nullptr, inverse_ = nullptr;
};

// FFTW planner state ("wisdom"). Measured plans may differ between processes (FftPlanning); a
// restart imports the original run's wisdom before its plans are made so that it continues
// bit-identically.
std::string fft_planner_wisdom();
// false if FFTW rejects the text (then planning simply measures afresh).
bool import_fft_planner_wisdom(const std::string& wisdom);

}  // namespace ibms
