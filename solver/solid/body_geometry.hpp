// Geometric diagnostics of mass-spring bodies for the time series and the cavity checks:
// a deformation measure of one body and the separation of several bodies from each other and
// from the walls (interpenetration detection). Pure functions of the rim points.
#pragma once
#include <array>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

// Deformation parameter (r_max - r_min) / (r_max + r_min) of the rim distances r_l = |X_l - C|
// from the rim polygon's area centroid C: 0 for a regular polygon, ~ Taylor's (L - B)/(L + B)
// for an ellipse-like shape [-].
double deformation_parameter(const MassSpringBody& body);

struct BodySeparation {
  double min_rim_distance = 0.0;  // smallest distance between rim points of different bodies [length]
  int n_points_inside_others = 0; // rim points of one body inside another's rim polygon [-]
  int n_edge_crossings = 0;       // pairs of rim edges of different bodies that cross [-]
  // Pairs of non-adjacent edges of one mass-spring rim that cross: a rim folded through itself. The
  // papers' model has no self-contact (CDS act between different bodies), so nothing stops a soft
  // rim from folding; a folded rim is outside the model's validity (its area and volume weights
  // lose their meaning) [-].
  int n_self_crossings = 0;
  double min_wall_distance = 0.0; // smallest distance from any rim point to a wall [length]
};

// Walls at x = lower[0], upper[0] (unless periodic[0]) and y = lower[1], upper[1] (unless
// periodic[1]); periodic directions use the minimum image between bodies. A rim point outside
// the box has a negative wall distance; without walls (fully periodic) and with one body the
// respective minimum is +infinity. Linear in the number of bodies: pairs come from a hash of the
// rim boxes (cells of twice the largest box side), the points of a pair compared only where they
// lie within the current minimum of the other's box, interpenetration looked for only in
// overlapping boxes; a scene whose nearest bodies are farther apart than the largest box visits
// every pair's boxes once (O(N^2) box gaps, no point pairs beyond the nearest).
BodySeparation body_separation(const std::vector<MassSpringBody>& bodies, std::array<double, 2> lower,
                               std::array<double, 2> upper, std::array<bool, 2> periodic);

}  // namespace ibms
