// Convergence figures, one definition for the verification tests, the validation checks, the
// benches and `ibms compare`:
//  - observed_order: least-squares slope of log(error) against log(h) with its standard error
//    (GSL gsl_fit_linear), over the finest `levels` points;
//  - grid_convergence: observed order, Richardson-extrapolated value and fine-grid GCI of a scalar
//    on three grids with any refinement ratios (Celik et al. 2008, J. Fluids Eng. 130, 078001,
//    eqs. 3a-c by fixed-point iteration, safety factor 1.25), none for a triple whose differences
//    change sign or do not shrink as a positive order requires.
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

struct GridConvergence {
  double order = NAN;         // observed order p
  double extrapolated = NAN;  // (r21^p f_fine - f_medium) / (r21^p - 1)
  double gci_fine = NAN;      // 1.25 |(f_fine - f_medium) / f_fine| / (r21^p - 1), a fraction
  bool monotone = false;      // the two differences have one sign (otherwise order etc. are NaN)
  bool converging = false;    // monotone and some order p > 0 fits: the fine difference is smaller than
                              // the coarse one by more than p -> 0 would give (e32 / e21 > ln r32 /
                              // ln r21; 1 for equal ratios). Otherwise order etc. are NaN: Celik's
                              // iteration takes |...| and returns a large order for a diverging triple.
};
// f_fine on the grid of spacing h_fine, ..., f_coarse on the coarsest (h_fine < h_medium < h_coarse).
GridConvergence grid_convergence(double h_fine, double h_medium, double h_coarse, double f_fine, double f_medium,
                                 double f_coarse);

}  // namespace ibms
