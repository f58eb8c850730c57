// Claim (docs/fluid-stability.md): under a uniform flow U the fluid solver multiplies a Fourier
// mode of wave angle theta = k h by the von Neumann factor of AB2 convection + Crank-Nicolson
// diffusion with central differences (fluid/time_scheme_stability.hpp) each step, to round-off.
// Set-up: periodic 16 x 4 box, u = U, v = eps sin(k x). v depends on x only, so every nonlinear
// term but U dv/dx vanishes, the face velocities stay divergence-free and the pressure stays 0:
// the solver's v obeys exactly the 1D model scheme v_t + U v_x = nu v_xx of the analysis.
// Checks docs/method.md §2.2, §2.3: the step is §2.3's AB2 convection with Crank-Nicolson diffusion,
// and §2.2's stability limits of the upwind-biased face values hold (Fromm: CFL 0.49-0.50;
// kappa = 1/3: at least 0.55).
#define BOOST_TEST_MODULE time_scheme_stability
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "core/constants.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/time_scheme_stability.hpp"

using namespace ibms;

namespace {

// Amplitude of the mode sin/cos(k x) in v, per cell.
double mode_amplitude(const Grid& g, const FluidState& s, double k) {
  double sine = 0.0, cosine = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      sine += s.velocity_y(i, j) * std::sin(k * g.x_centre(i));
      cosine += s.velocity_y(i, j) * std::cos(k * g.x_centre(i));
    }
  return std::hypot(sine, cosine) / g.n_cells();
}

// Measured growth per step of the mode with `waves` wavelengths in the box, steps 40 to 80 (the
// parasitic AB2 root, |G_2| <= C/2 here, has died out by step 40).
double measured_factor(double cfl, double viscous_number, int waves,
                       ConvectionScheme convection = ConvectionScheme::central) {
  constexpr int n = 16;
  const double h = 1.0 / n, speed = 1.0, dt = cfl * h / speed, nu = viscous_number * h * h / dt;
  const Grid g(n, 4, 1.0, 4 * h, /*per_x=*/true, /*per_y=*/true);
  FluidBoundaries walls;
  walls.periodic_x = walls.periodic_y = true;
  FluidSchemes schemes;
  schemes.convection = convection;
  FluidSolver solver(g, nu, walls, schemes);
  FluidState s = solver.make_state();
  const double k = 2 * pi * waves;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      s.velocity_x(i, j) = speed;
      s.velocity_y(i, j) = 1e-3 * std::sin(k * g.x_centre(i));
    }
  solver.initialise_faces(s);
  double a40 = 0.0;
  for (int m = 1; m <= 80; ++m) {
    solver.predict_momentum(s, dt, nullptr, nullptr);
    solver.project_smac(s, dt);
    if (m == 40) a40 = mode_amplitude(g, s, k);
  }
  return std::pow(mode_amplitude(g, s, k) / a40, 1.0 / 40);
}

}  // namespace

BOOST_AUTO_TEST_CASE(solver_amplifies_a_fourier_mode_by_the_ab2_cn_factor) {
  struct Case { double cfl, viscous_number; int waves; };
  // Unstable without diffusion (C = 0.25 and 0.5), damped by CN, and unstable at C = 1 with some.
  const Case cases[] = {{0.25, 0.0, 4}, {0.5, 0.0, 4}, {0.5, 0.0, 3}, {0.5, 0.05, 4}, {1.0, 0.25, 3}, {0.75, 2.0, 5}};
  for (const Case& c : cases) {
    const double theta = 2 * pi * c.waves / 16;
    const double measured = measured_factor(c.cfl, c.viscous_number, c.waves);
    const double theory = ab2_cn_amplification(c.cfl, c.viscous_number, theta);
    BOOST_TEST_MESSAGE("C = " << c.cfl << ", D = " << c.viscous_number << ", theta = " << theta << ": measured |G| "
                              << measured << ", theory " << theory);
    BOOST_TEST(std::abs(measured - theory) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(boundary_of_the_python_table_is_the_boundary_here) {
  // reports/fluid_stability_theory.py: D_min(C = 0.5) = 0.012676, D_min(C = 1) = 0.56524.
  for (const auto& [cfl, d_min] : {std::pair{0.5, 0.012676}, std::pair{1.0, 0.56524}}) {
    BOOST_TEST(ab2_cn_max_amplification(cfl, 0.99 * d_min) > 1.0 + 1e-9);
    BOOST_TEST(ab2_cn_max_amplification(cfl, 1.01 * d_min) <= 1.0 + 1e-12);
  }
}

// Fromm's face values (kappa = 0, the cavity scenes' scheme): the solver's growth factor is the
// analysed one with the upwind-biased symbol, and AB2 + CN keeps them stable only up to a CFL
// number of 0.49-0.50 at every cell Reynolds number (docs/fluid-stability.md §1): below it at
// C = 0.45, above it at C = 0.55, also with some diffusion.
BOOST_AUTO_TEST_CASE(fromm_face_values_amplify_by_their_upwind_biased_factor_and_limit_the_cfl_to_one_half) {
  struct Case { double cfl, viscous_number; int waves; bool grows; };
  const Case cases[] = {{0.45, 0.0, 6, false}, {0.55, 0.0, 6, true}, {0.55, 0.05, 5, true}, {0.45, 0.05, 4, false}};
  for (const Case& c : cases) {
    const double theta = 2 * pi * c.waves / 16;
    const double measured = measured_factor(c.cfl, c.viscous_number, c.waves, ConvectionScheme::fromm);
    const double theory = ab2_cn_amplification(c.cfl, c.viscous_number, theta, upwind_kappa(ConvectionScheme::fromm));
    BOOST_TEST_MESSAGE("Fromm, C = " << c.cfl << ", D = " << c.viscous_number << ", theta = " << theta
                                     << ": measured |G| " << measured << ", theory " << theory);
    BOOST_TEST(std::abs(measured - theory) < 1e-9);
    BOOST_TEST((measured > 1.0) == c.grows);
  }
  for (double cell_reynolds : {0.5, 4.0, 16.0, 1e6}) {
    const double limit = ab2_cn_cfl_limit(cell_reynolds, 0.0);
    BOOST_TEST_MESSAGE("Fromm: CFL limit at Re_h = " << cell_reynolds << ": " << limit);
    BOOST_TEST(limit >= 0.49);
    BOOST_TEST(limit <= 0.50);
  }
}

// The third-order upwind-biased face values (kappa = 1/3, the DFG 2D-2 scene's scheme): the
// solver's growth factor is the analysed one, and AB2 + CN keeps them stable up to a CFL number
// of about 0.58 without diffusion, more with it (the scene's run.cfl = 0.5 lies below): below the
// limit at C = 0.5, above it at C = 0.65 without diffusion.
BOOST_AUTO_TEST_CASE(upwind3_face_values_amplify_by_their_upwind_biased_factor_and_allow_cfl_one_half) {
  const double kappa = upwind_kappa(ConvectionScheme::upwind3);
  BOOST_TEST(std::abs(kappa - 1.0 / 3.0) < 1e-15);
  struct Case { double cfl, viscous_number; int waves; bool grows; };
  const Case cases[] = {{0.5, 0.0, 3, false}, {0.65, 0.0, 6, true}, {0.5, 0.05, 3, false}, {0.3, 0.0, 4, false}};
  for (const Case& c : cases) {
    const double theta = 2 * pi * c.waves / 16;
    const double measured = measured_factor(c.cfl, c.viscous_number, c.waves, ConvectionScheme::upwind3);
    const double theory = ab2_cn_amplification(c.cfl, c.viscous_number, theta, kappa);
    BOOST_TEST_MESSAGE("upwind3, C = " << c.cfl << ", D = " << c.viscous_number << ", theta = " << theta
                                       << ": measured |G| " << measured << ", theory " << theory);
    BOOST_TEST(std::abs(measured - theory) < 1e-9);
    BOOST_TEST((measured > 1.0) == c.grows);
  }
  for (double cell_reynolds : {0.5, 4.0, 16.0, 1e6}) {
    const double limit = ab2_cn_cfl_limit(cell_reynolds, kappa);
    BOOST_TEST_MESSAGE("upwind3: CFL limit at Re_h = " << cell_reynolds << ": " << limit);
    BOOST_TEST(limit >= 0.55);
  }
}
