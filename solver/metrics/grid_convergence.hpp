// Convergence figures, one definition for the verification tests, the validation checks, the
// benches and `ibms compare`:
//  - observed_order: least-squares slope of log(error) against log(h) with its standard error
//    (GSL gsl_fit_linear), over the finest `levels` points;
//  - grid_convergence: observed order, Richardson-extrapolated value and fine-grid GCI of a scalar
//    on three grids with any refinement ratios (Celik et al. 2008, J. Fluids Eng. 130, 078001,
//    eqs. 3a-c by fixed-point iteration, safety factor 1.25), none for a triple whose differences
//    change sign or do not shrink as a positive order requires. Given the scheme's formal order
//    p_f, the GCI follows Roache (1998) as Oberkampf & Roy (2010, §8.6.2) state it: safety factor
//    1.25 with the observed order where that lies within 10 % of p_f, else safety factor 3 with
//    p = min(max(0.5, p_observed), p_f), so that an observed order far above the formal one (a triple
//    in its pre-asymptotic range, or with a cancellation of errors) does not shrink the uncertainty.
#pragma once
#include <cmath>
#include <vector>

namespace ibms {

struct ObservedOrder {
  double order = NAN;           // slope of log e against log h
  double standard_error = NAN;  // of the slope; NaN with fewer than three points (no residual)
  int points = 0;
};
// h and e of one length, e > 0; the finest `levels` entries by position (the last ones, tables
// run coarse to fine); levels <= 0: all. Throws std::invalid_argument on fewer than two points or
// a non-positive h or e.
ObservedOrder observed_order(const std::vector<double>& h, const std::vector<double>& e, int levels = 3);

// The formal orders the validation checks give grid_convergence (docs/method.md §2.4): the fluid
// alone is second order in space; a quantity of a body under the diffuse immersed boundary is first
// order in h.
inline constexpr double fluid_order = 2.0;
inline constexpr double immersed_boundary_order = 1.0;

struct GridConvergence {
  double order = NAN;         // observed order p
  double extrapolated = NAN;  // (r21^p f_fine - f_medium) / (r21^p - 1)
  double gci_fine = NAN;      // F_s |(f_fine - f_medium) / f_fine| / (r21^p_gci - 1), a fraction
  double safety_factor = NAN; // F_s: 1.25, or 3 where the observed order is not within 10 % of the formal one
  double gci_order = NAN;     // p_gci: the observed order, or min(max(0.5, p), p_f) with F_s = 3
  bool monotone = false;      // the two differences have one sign (otherwise order etc. are NaN)
  bool converging = false;    // monotone and some order p > 0 fits: the fine difference is smaller than
                              // the coarse one by more than p -> 0 would give (e32 / e21 > ln r32 /
                              // ln r21; 1 for equal ratios). Otherwise order etc. are NaN: Celik's
                              // iteration takes |...| and returns a large order for a diverging triple.
};
// f_fine on the grid of spacing h_fine, ..., f_coarse on the coarsest (h_fine < h_medium < h_coarse);
// formal_order: the scheme's order for this quantity (NaN: none stated, the GCI takes the observed
// order with F_s = 1.25, Celik et al. 2008).
GridConvergence grid_convergence(double h_fine, double h_medium, double h_coarse, double f_fine, double f_medium,
                                 double f_coarse, double formal_order = NAN);

}  // namespace ibms
