// Test oracle: every pair of contact-detection spheres examined, O(n^2), for comparison with the
// pair searches of solver/contact/cds_pair_search (cell list, body-box broad phase). It shares
// only the minimum-image separation with them; the touching rule (different bodies,
// |x_j - x_i| < r_i + r_j) and the sort are written out here again on purpose.
#pragma once
#include "contact/cds_pair_search.hpp"

namespace ibms::oracles {

PairSearchResult find_touching_pairs_brute_force(const ContactSpheres& spheres, const WallBox& box);

}  // namespace ibms::oracles
