// Uses the installed ibms package the way another code would: a delta-kernel moment (sum of the
// weights and first moment of every kernel over marker offsets, docs/method.md §4) and a Poisson solve
// L q = r with homogeneous Dirichlet walls by the FFTW solver, against q = sin(pi x) sin(pi y)
// (second order: error ratio ~4 between 32^2 and 64^2). Exit 0 when both hold, 1 otherwise.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/grid.hpp"
#include "fluid/spectral_solver.hpp"
#include "ibm/delta_kernel.hpp"

namespace {

// max over 1001 offsets x in [0, 1] of |sum_j phi(x-j) - 1| and of |sum_j (x-j) phi(x-j)|.
void kernel_moments(ibms::KernelKind kind, double& zeroth, double& first) {
  zeroth = first = 0.0;
  for (int n = 0; n <= 1000; ++n) {
    const double x = n / 1000.0;
    const ibms::KernelStencil s = ibms::kernel_stencil(kind, x);
    double m0 = 0.0, m1 = 0.0;
    for (int k = 0; k < s.n_nodes; ++k) {
      m0 += s.weight[k];
      m1 += (x - (s.first + k)) * s.weight[k];
    }
    zeroth = std::max(zeroth, std::abs(m0 - 1.0));
    first = std::max(first, std::abs(m1));
  }
}

// max |q - exact| of the Dirichlet Poisson problem on an n x n grid of the unit square.
double poisson_error(int n) {
  const ibms::Grid grid(n, n, 1.0, 1.0);
  ibms::SpectralSolver solver(grid, ibms::SpectralBoundary::dirichlet, ibms::SpectralBoundary::dirichlet);
  std::vector<double> rhs(grid.n_cells()), q(grid.n_cells());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)  // L q = -2 pi^2 sin(pi x) sin(pi y)
      rhs[grid.index(i, j)] = -2 * M_PI * M_PI * std::sin(M_PI * grid.x_centre(i)) * std::sin(M_PI * grid.y_centre(j));
  solver.solve(/*a=*/0.0, /*b=*/1.0, rhs.data(), q.data());
  double error = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      error = std::max(error, std::abs(q[grid.index(i, j)] -
                                       std::sin(M_PI * grid.x_centre(i)) * std::sin(M_PI * grid.y_centre(j))));
  return error;
}

}  // namespace

int main() {
  bool ok = true;
  std::printf("kernel     max|sum phi - 1|   max|sum (x-j) phi|\n");
  for (ibms::KernelKind kind : ibms::all_kernel_kinds) {
    double zeroth = 0, first = 0;
    kernel_moments(kind, zeroth, first);
    std::printf("%-9s  %.3e          %.3e\n", ibms::kernel_name(kind).c_str(), zeroth, first);
    ok = ok && zeroth < 1e-14;                                          // round-off (<= 6 terms)
    if (kind != ibms::KernelKind::cosine4) ok = ok && first < 1e-14;    // cosine4: first moment up to 0.021
  }
  const double e32 = poisson_error(32), e64 = poisson_error(64);
  const double order = std::log2(e32 / e64);
  std::printf("Dirichlet Poisson: max error 32^2 %.3e, 64^2 %.3e, observed order %.3f\n", e32, e64, order);
  ok = ok && e64 < 1e-3 && order > 1.9;  // second-order compact Laplacian (formal order 2, margin 0.1)
  std::printf("%s\n", ok ? "ibms package consumer: pass" : "ibms package consumer: FAIL");
  return ok ? 0 : 1;
}
