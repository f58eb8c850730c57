// Claims: the FFTW Poisson/Helmholtz solver agrees with the Eigen CG reference and reproduces
// discrete manufactured solutions to round-off for wall, periodic and mixed boundaries, and the
// moving-lid (inhomogeneous Dirichlet) shift of docs/method.md §6 is exact.
#define BOOST_TEST_MODULE spectral_solver
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "fluid/boundary_conditions.hpp"
#include "fluid/operators.hpp"
#include "oracles/reference_solver.hpp"
#include "fluid/spectral_solver.hpp"

using namespace ibms;

namespace {

struct Case { const char* name; SpectralBoundary bx, by; double a, b; };

Grid grid_for(const Case& c) {
  return Grid(24, 17, 1.3, 0.9, c.bx == SpectralBoundary::periodic, c.by == SpectralBoundary::periodic);
}

std::vector<double> random_field(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::vector<double> v(n);
  for (auto& x : v) x = dist(gen);
  return v;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

bool singular(const Case& c) {
  return c.a == 0.0 && c.bx != SpectralBoundary::dirichlet && c.by != SpectralBoundary::dirichlet;
}

void remove_mean(std::vector<double>& v) {
  double mean = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double& x : v) x -= mean;
}

const Case cases[] = {
    {"Poisson, Neumann walls (pressure)", SpectralBoundary::neumann, SpectralBoundary::neumann, 0.0, 1.0},
    {"Poisson, periodic box", SpectralBoundary::periodic, SpectralBoundary::periodic, 0.0, 1.0},
    {"Poisson, periodic x, Neumann y", SpectralBoundary::periodic, SpectralBoundary::neumann, 0.0, 1.0},
    {"Helmholtz, Dirichlet walls (CN velocity)", SpectralBoundary::dirichlet, SpectralBoundary::dirichlet, 1.0, -0.01},
    {"Helmholtz, periodic box", SpectralBoundary::periodic, SpectralBoundary::periodic, 1.0, -0.01},
    {"Helmholtz, periodic x, Dirichlet y", SpectralBoundary::periodic, SpectralBoundary::dirichlet, 1.0, -0.01},
    {"Poisson, Dirichlet walls", SpectralBoundary::dirichlet, SpectralBoundary::dirichlet, 0.0, 1.0},
};

}  // namespace

// Discrete manufactured solution: r = A q for a random q, solve, recover q.
BOOST_AUTO_TEST_CASE(fast_solver_reproduces_discrete_manufactured_solution_to_round_off) {
  for (const Case& c : cases) {
    const Grid g = grid_for(c);
    std::vector<double> q = random_field(g.n_cells(), 7);
    if (singular(c)) remove_mean(q);
    const std::vector<double> r = apply_operator(g, c.bx, c.by, c.a, c.b, q);
    SpectralSolver solver(g, c.bx, c.by);
    std::vector<double> solution(g.n_cells());
    const SpectralSolveStats stats = solver.solve(c.a, c.b, r.data(), solution.data());
    double error = 0;
    for (std::size_t k = 0; k < q.size(); ++k) error = std::max(error, std::abs(solution[k] - q[k]));
    BOOST_TEST_MESSAGE(c.name << ": max |q - q_exact| / max|q| = " << error / max_abs(q)
                              << ", removed rhs mean = " << stats.removed_mean);
    // Round-off of two O(N log N) transforms on ~400 values with condition number ~1e3: 1e-12.
    BOOST_TEST(error / max_abs(q) < 1e-12);
    BOOST_TEST(std::abs(stats.removed_mean) < 1e-12 * max_abs(r));
  }
}

// Same operator, independent solver: FFTW vs Eigen conjugate gradients on a random rhs.
BOOST_AUTO_TEST_CASE(fast_solver_agrees_with_eigen_reference) {
  for (const Case& c : cases) {
    const Grid g = grid_for(c);
    std::vector<double> r = random_field(g.n_cells(), 11);
    if (singular(c)) remove_mean(r);
    SpectralSolver solver(g, c.bx, c.by);
    std::vector<double> fast(g.n_cells()), reference;
    solver.solve(c.a, c.b, r.data(), fast.data());
    const ReferenceSolveStats ref = solve_reference(g, c.bx, c.by, c.a, c.b, r, reference, 1e-15);
    double diff = 0;
    for (std::size_t k = 0; k < r.size(); ++k) diff = std::max(diff, std::abs(fast[k] - reference[k]));
    BOOST_TEST_MESSAGE(c.name << ": max |fast - reference| / max|reference| = " << diff / max_abs(reference)
                              << " (CG iterations " << ref.iterations << ")");
    // CG stopped at a relative residual 1e-15 of a system with condition number <= ~1e4: 1e-10.
    BOOST_TEST(diff / max_abs(reference) < 1e-10);
  }
}

// A singular (pure Neumann) rhs with a non-zero mean: the mean is reported and removed.
BOOST_AUTO_TEST_CASE(singular_poisson_reports_the_removed_rhs_mean) {
  const Grid g(16, 16, 1.0, 1.0);
  std::vector<double> r(g.n_cells(), 0.25);
  SpectralSolver solver(g, SpectralBoundary::neumann, SpectralBoundary::neumann);
  std::vector<double> q(g.n_cells());
  const SpectralSolveStats stats = solver.solve(0.0, 1.0, r.data(), q.data());
  BOOST_TEST(std::abs(stats.removed_mean - 0.25) < 1e-14);
  BOOST_TEST(max_abs(q) < 1e-14);
}

// Moving lid: with the ghost rule q_g = 2 u_w - q_int the operator is the homogeneous one plus
// 2 u_w / h^2 in the wall row (docs/method.md §6); moving that to the rhs gives the exact solution.
BOOST_AUTO_TEST_CASE(moving_lid_shift_reproduces_inhomogeneous_dirichlet_solution) {
  const Grid g(20, 20, 1.0, 1.0);
  FluidBoundaries bc;
  bc.top.speed = 1.0;     // lid +x on y = 1
  bc.bottom.speed = -0.5; // two-sided
  bc.left.speed = 0.25;   // tangential v on x = 0
  const double a = 1.0, b = -0.003;
  CellField u(g), v(g), lu(g), lv(g);
  const std::vector<double> qu = random_field(g.n_cells(), 3), qv = random_field(g.n_cells(), 5);
  u.copy_interior_from(qu.data());
  v.copy_interior_from(qv.data());
  fill_velocity_ghosts(g, bc, 0.0, u, v);
  laplacian(g, u, lu);
  laplacian(g, v, lv);
  for (int comp = 0; comp < 2; ++comp) {
    const CellField& q = comp == 0 ? u : v;
    const CellField& lq = comp == 0 ? lu : lv;
    std::vector<double> r(g.n_cells());
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) r[g.index(i, j)] = a * q(i, j) + b * lq(i, j);
    // Shift: r -= b * 2 u_w / h^2 in the wall rows/columns of the tangential component.
    for (int k = 0; k < g.nx && comp == 0; ++k) {
      r[g.index(k, g.ny - 1)] -= b * 2.0 * bc.top.speed / (g.dy() * g.dy());
      r[g.index(k, 0)] -= b * 2.0 * bc.bottom.speed / (g.dy() * g.dy());
    }
    for (int k = 0; k < g.ny && comp == 1; ++k) r[g.index(0, k)] -= b * 2.0 * bc.left.speed / (g.dx() * g.dx());
    SpectralSolver solver(g, SpectralBoundary::dirichlet, SpectralBoundary::dirichlet);
    std::vector<double> solution(g.n_cells());
    solver.solve(a, b, r.data(), solution.data());
    const std::vector<double>& exact = comp == 0 ? qu : qv;
    double error = 0;
    for (std::size_t k = 0; k < exact.size(); ++k) error = std::max(error, std::abs(solution[k] - exact[k]));
    BOOST_TEST_MESSAGE("component " << comp << ": max error with moving walls = " << error);
    BOOST_TEST(error < 1e-12);  // round-off of the transforms (values O(1))
  }
}
