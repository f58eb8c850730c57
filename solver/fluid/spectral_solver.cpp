// FFTW real-to-real Poisson/Helmholtz solver (METHOD.md §6; transform kinds and eigenvalues as in
// CaNS src/initsolver_eigenvalues-inc.f90 and src/fft.f90).
#include "fluid/spectral_solver.hpp"
#include "fluid/threads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ibms {
namespace {

constexpr double pi = 3.14159265358979323846;

fftw_r2r_kind forward_kind(SpectralBoundary b) {
  switch (b) {
    case SpectralBoundary::periodic: return FFTW_R2HC;
    case SpectralBoundary::neumann: return FFTW_REDFT10;   // DCT-II
    case SpectralBoundary::dirichlet: return FFTW_RODFT10; // DST-II
  }
  return FFTW_R2HC;
}

fftw_r2r_kind inverse_kind(SpectralBoundary b) {
  switch (b) {
    case SpectralBoundary::periodic: return FFTW_HC2R;
    case SpectralBoundary::neumann: return FFTW_REDFT01;   // DCT-III
    case SpectralBoundary::dirichlet: return FFTW_RODFT01; // DST-III
  }
  return FFTW_HC2R;
}

// Eigenvalues of (q_{i-1} - 2 q_i + q_{i+1})/h^2 in the order FFTW stores the transform.
std::vector<double> eigenvalues(SpectralBoundary b, int n, double h) {
  std::vector<double> lambda(n);
  for (int m = 0; m < n; ++m) {
    double s = 0.0;
    if (b == SpectralBoundary::neumann) s = std::sin(pi * m / (2.0 * n));
    if (b == SpectralBoundary::dirichlet) s = std::sin(pi * (m + 1) / (2.0 * n));
    if (b == SpectralBoundary::periodic) s = std::sin(pi * (m <= n / 2 ? m : n - m) / n);
    lambda[m] = -4.0 * s * s / (h * h);
  }
  return lambda;
}

double logical_size(SpectralBoundary b, int n) { return b == SpectralBoundary::periodic ? n : 2.0 * n; }

}  // namespace

SpectralSolver::SpectralSolver(const Grid& grid, SpectralBoundary boundary_x, SpectralBoundary boundary_y)
    : nx_(grid.nx), ny_(grid.ny) {
  if (grid.periodic_x != (boundary_x == SpectralBoundary::periodic) ||
      grid.periodic_y != (boundary_y == SpectralBoundary::periodic))
    throw std::invalid_argument("SpectralSolver: boundary kind does not match grid periodicity");
  normalisation_ = logical_size(boundary_x, nx_) * logical_size(boundary_y, ny_);
  lambda_x_ = eigenvalues(boundary_x, nx_, grid.dx());
  lambda_y_ = eigenvalues(boundary_y, ny_, grid.dy());
  buffer_ = fftw_alloc_real(static_cast<std::size_t>(nx_) * ny_);
  prepare_fft_threads();  // plans below use thread_count() threads
  // Row-major (ny, nx): the first FFTW dimension is y.
  forward_ = fftw_plan_r2r_2d(ny_, nx_, buffer_, buffer_, forward_kind(boundary_y),
                              forward_kind(boundary_x), FFTW_MEASURE);
  inverse_ = fftw_plan_r2r_2d(ny_, nx_, buffer_, buffer_, inverse_kind(boundary_y),
                              inverse_kind(boundary_x), FFTW_MEASURE);
  if (!forward_ || !inverse_) throw std::runtime_error("SpectralSolver: FFTW planning failed");
}

SpectralSolver::~SpectralSolver() {
  fftw_destroy_plan(forward_);
  fftw_destroy_plan(inverse_);
  fftw_free(buffer_);
}

SpectralSolveStats SpectralSolver::solve(double a, double b, const double* rhs, double* solution) {
  SpectralSolveStats stats;
  const std::size_t n = static_cast<std::size_t>(nx_) * ny_;
  std::copy(rhs, rhs + n, buffer_);
  fftw_execute(forward_);
  // Diagonal solve; the normalisation of the transform pair is folded into the divisor. The one
  // singular (constant) mode is in row 0, so the rows are shared among threads without a race.
  IBMS_PARALLEL_ROWS
  for (int l = 0; l < ny_; ++l) {
    double* row = buffer_ + static_cast<std::size_t>(nx_) * l;
    for (int k = 0; k < nx_; ++k) {
      const double diagonal = (a + b * (lambda_x_[k] + lambda_y_[l])) * normalisation_;
      if (std::abs(a + b * (lambda_x_[k] + lambda_y_[l])) <= 1e-300 ||
          (a == 0.0 && lambda_x_[k] == 0.0 && lambda_y_[l] == 0.0)) {
        // Constant mode of the singular problem: the forward transform of the constant mode is
        // the rhs sum times the transform's weight, i.e. mean * normalisation.
        stats.removed_mean = row[k] / normalisation_;
        row[k] = 0.0;
      } else {
        row[k] /= diagonal;
      }
    }
  }
  fftw_execute(inverse_);
  std::copy(buffer_, buffer_ + n, solution);
  return stats;
}

std::string fft_planner_wisdom() {
  char* text = fftw_export_wisdom_to_string();
  if (text == nullptr) return {};
  std::string wisdom(text);
  fftw_free(text);
  return wisdom;
}

bool import_fft_planner_wisdom(const std::string& wisdom) {
  return !wisdom.empty() && fftw_import_wisdom_from_string(wisdom.c_str()) != 0;
}

}  // namespace ibms
