// Figures of a body's force history used by the DFG cylinder checks (validation/dfg_cylinder_*)
// and by `ibms compare` for those cases: one definition for both.
//  - rim_pressure: the pressure at a point of a body's rim from three probes outside it along the
//    normal, by the quadratic through them evaluated at the rim (the diffuse immersed boundary
//    smears the pressure jump over ~3 cells, so the value at the rim itself is a mixture);
//  - periodic_forces: maxima of c_D and c_L, the Strouhal number from the mean period between
//    upward crossings of c_L - mean(c_L) (with a hysteresis of a tenth of the amplitude), and Delta p half a period after the last lift maximum.
// (Richardson extrapolation over grids: metrics/grid_convergence.hpp.)
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace ibms {

// p at distance 0 from p(d_k), k = 0, 1, 2 (distinct distances) [pressure].
double rim_pressure(const std::array<double, 3>& distance, const std::array<double, 3>& pressure);

// The DFG scenes' probes (validation/dfg_cylinder_*/scene.toml): 0-2 lie 0.01, 0.015, 0.02 in front
// of the cylinder, 3-5 as far behind it.
inline constexpr std::array<double, 3> dfg_probe_distance{0.01, 0.015, 0.02};
// Delta p = p(front point) - p(back point), each extrapolated to the rim from its three probes.
double dfg_pressure_difference(const std::array<double, 6>& probe_pressure);

struct PeriodicForces {
  double drag_max = NAN, lift_max = NAN;  // [-]
  double strouhal = NAN;                  // f L / U [-]
  double pressure_difference_half_period = NAN;  // NaN without a Delta p series [pressure]
  int periods = 0;                        // whole lift periods measured
};

// Over every row with time >= t_from (time increasing, one row per step; the run's last steps share
// the time left, so the last is no small fraction of the one before, docs/method.md §3.7). Throws
// std::runtime_error with fewer than 10 rows or two lift periods in the window.
PeriodicForces periodic_forces(const std::vector<double>& time, const std::vector<double>& drag,
                               const std::vector<double>& lift, const std::vector<double>& pressure_difference,
                               double t_from, double length, double speed);

}  // namespace ibms
