// FFTW real-to-real Poisson/Helmholtz solver (docs/method.md §6; transform kinds and eigenvalues as in
// CaNS src/initsolver_eigenvalues-inc.f90 and src/fft.f90).
#include "fluid/spectral_solver.hpp"
#include "fluid/threads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace ibms {
namespace {

// FFTW transform pair of one direction with the given ends (low, high): same kind at both ends
// (DCT-II/III, DST-II/III, R2HC/HC2R) or mixed (DCT-IV, DST-IV: each its own inverse).
struct Transform {
  fftw_r2r_kind forward, inverse;
};

Transform transform(SpectralBoundary low, SpectralBoundary high) {
  using B = SpectralBoundary;
  if (low == B::periodic) return {FFTW_R2HC, FFTW_HC2R};
  if (low == B::neumann && high == B::neumann) return {FFTW_REDFT10, FFTW_REDFT01};
  if (low == B::dirichlet && high == B::dirichlet) return {FFTW_RODFT10, FFTW_RODFT01};
  if (low == B::neumann) return {FFTW_REDFT11, FFTW_REDFT11};  // q_-1 = q_0, q_n = -q_(n-1)
  return {FFTW_RODFT11, FFTW_RODFT11};                          // q_-1 = -q_0, q_n = q_(n-1)
}

// Eigenvalues of (q_{i-1} - 2 q_i + q_{i+1})/h^2 in the order FFTW stores the transform:
// -4 sin^2(theta_m / 2) / h^2 with theta_m = pi m / n (Neumann), pi (m + 1) / n (Dirichlet),
// pi (m + 1/2) / n (mixed), 2 pi min(m, n - m) / n (periodic).
std::vector<double> eigenvalues(SpectralBoundary low, SpectralBoundary high, int n, double h) {
  using B = SpectralBoundary;
  std::vector<double> lambda(n);
  for (int m = 0; m < n; ++m) {
    double s = 0.0;
    if (low == B::periodic) s = std::sin(pi * (m <= n / 2 ? m : n - m) / n);
    else if (low == B::neumann && high == B::neumann) s = std::sin(pi * m / (2.0 * n));
    else if (low == B::dirichlet && high == B::dirichlet) s = std::sin(pi * (m + 1) / (2.0 * n));
    else s = std::sin(pi * (m + 0.5) / (2.0 * n));
    lambda[m] = -4.0 * s * s / (h * h);
  }
  return lambda;
}

double logical_size(SpectralBoundary b, int n) { return b == SpectralBoundary::periodic ? n : 2.0 * n; }

}  // namespace

SpectralSolver::SpectralSolver(const Grid& grid, SpectralBoundary boundary_x, SpectralBoundary boundary_y,
                               FftPlanning planning)
    : SpectralSolver(grid, boundary_x, boundary_x, boundary_y, boundary_y, planning) {}

SpectralSolver::SpectralSolver(const Grid& grid, SpectralBoundary left, SpectralBoundary right,
                               SpectralBoundary bottom, SpectralBoundary top, FftPlanning planning)
    : nx_(grid.nx), ny_(grid.ny) {
  const auto periodic = [](SpectralBoundary low, SpectralBoundary high) {
    return low == SpectralBoundary::periodic || high == SpectralBoundary::periodic;
  };
  if ((left == SpectralBoundary::periodic) != (right == SpectralBoundary::periodic) ||
      (bottom == SpectralBoundary::periodic) != (top == SpectralBoundary::periodic))
    throw std::invalid_argument("SpectralSolver: periodic at one end of a direction only");
  if (grid.periodic_x != periodic(left, right) || grid.periodic_y != periodic(bottom, top))
    throw std::invalid_argument("SpectralSolver: boundary kind does not match grid periodicity");
  normalisation_ = logical_size(left, nx_) * logical_size(bottom, ny_);
  lambda_x_ = eigenvalues(left, right, nx_, grid.dx());
  lambda_y_ = eigenvalues(bottom, top, ny_, grid.dy());
  buffer_ = fftw_alloc_real(static_cast<std::size_t>(nx_) * ny_);
  prepare_fft_threads();  // plans below use thread_count() threads
  // Row-major (ny, nx): the first FFTW dimension is y.
  const Transform tx = transform(left, right), ty = transform(bottom, top);
  const unsigned flags = planning == FftPlanning::estimate ? FFTW_ESTIMATE : FFTW_MEASURE;
  forward_ = fftw_plan_r2r_2d(ny_, nx_, buffer_, buffer_, ty.forward, tx.forward, flags);
  inverse_ = fftw_plan_r2r_2d(ny_, nx_, buffer_, buffer_, ty.inverse, tx.inverse, flags);
  if (!forward_ || !inverse_) throw std::runtime_error("SpectralSolver: FFTW planning failed");
}

SpectralSolver::~SpectralSolver() {
  fftw_destroy_plan(forward_);
  fftw_destroy_plan(inverse_);
  fftw_free(buffer_);
}

SpectralSolveStats SpectralSolver::solve(double a, double b, const double* rhs, double* solution) {
  return solve(a, b, rhs, solution, lambda_x_, lambda_y_);
}

SpectralSolveStats SpectralSolver::solve(double a, double b, const double* rhs, double* solution,
                                         const std::vector<double>& ex, const std::vector<double>& ey) {
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
      const double diagonal = (a + b * (ex[k] + ey[l])) * normalisation_;
      if (std::abs(a + b * (ex[k] + ey[l])) <= 1e-300 ||
          (a == 0.0 && ex[k] == 0.0 && ey[l] == 0.0)) {
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
  // FFTW knows its threaded solvers, which wisdom made on threads names, only once its threads
  // are set up; before that it refuses such wisdom whole.
  prepare_fft_threads();
  return !wisdom.empty() && fftw_import_wisdom_from_string(wisdom.c_str()) != 0;
}

}  // namespace ibms
