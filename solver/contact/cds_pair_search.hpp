// Pair search between contact-detection spheres (CDS) of different bodies, docs/method.md §1.9: a cell
// list with bins of at least 2 r_max (so touching spheres sit in the same or adjacent bins), and a
// body-box broad phase; the brute-force O(n^2) reference the tests compare them with is in
// verification/oracles/. Spheres touch when |x_j - x_i| < r_i + r_j; periodic directions
// of the box use the minimum image. Positions [length]; no grid, plain data. All searches return
// the same pairs, sorted, so contact forces do not depend on which one ran.
#pragma once
#include <array>
#include <vector>

#include "contact/contact_model.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

// All CDS of a scene, flattened: sphere s sits on surface point point[s] of body body[s].
struct ContactSpheres {
  std::vector<std::array<double, 2>> centre;  // [length]
  std::vector<double> radius;                 // [length]
  std::vector<int> body;
  std::vector<int> point;

  int n_spheres() const { return static_cast<int>(centre.size()); }
};

ContactSpheres gather_contact_spheres(const ContactModel& model,
                                      const std::vector<MassSpringBody>& bodies);
// The same into `out` (cleared; its capacity is reused, so no allocation once it has grown), for
// the selected bodies only (members; empty = all).
void gather_contact_spheres(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                            ContactSpheres& out, const BodySet& members = {});

// Two touching spheres of different bodies, first < second (indices into ContactSpheres).
struct SpherePair {
  int first = 0, second = 0;
  bool operator==(const SpherePair& other) const {
    return first == other.first && second == other.second;
  }
};

struct PairSearchResult {
  std::vector<SpherePair> pairs;  // sorted by (first, second)
  long n_pair_checks = 0;         // candidate sphere pairs whose distance was examined, plus the
                                  // body-box tests of the body-bounds search [-]
};

PairSearchResult find_touching_pairs_cell_list(const ContactSpheres& spheres, const WallBox& box);
// Broad phase on the bodies' bounding boxes (of their spheres; pairs of boxes from a hash of their
// centres, core/cell_hash.hpp, no all-pairs loop), then, for each pair of bodies whose boxes
// overlap, the sphere pairs of the spheres of each that meet the boxes' common part: for bodies of
// many spheres each, far fewer distance checks than the cell list, whose bins are mostly filled
// with spheres of one body. n_pair_checks counts the body-box tests too. Periodic boxes use the
// cell list. Each body's spheres are expected together (as gather_contact_spheres lists them): the
// boxes are those of runs of one body's spheres, so a body split over several runs is still searched
// right, but at the cost of the tests between its runs.
PairSearchResult find_touching_pairs_body_bounds(const ContactSpheres& spheres, const WallBox& box);
// The same into `out` (cleared, capacity reused) for walled boxes; periodic boxes: the cell list.
void find_touching_pairs_body_bounds(const ContactSpheres& spheres, const WallBox& box, PairSearchResult& out);

// The pairs of `candidates` (sorted, as a search returns them) that touch now, by the searches' own
// test, into `out` (cleared; sorted): where the candidates hold every pair that can touch (a search
// with larger spheres, made while the centres were closer to where they are than its margin), the
// same pairs in the same order as a new search. n_pair_checks counts the candidates.
void keep_touching_pairs(const ContactSpheres& spheres, const WallBox& box, const std::vector<SpherePair>& candidates,
                         PairSearchResult& out);

// x_to - x_from, minimum image in the periodic directions of the box [length].
std::array<double, 2> separation(const std::array<double, 2>& from, const std::array<double, 2>& to,
                                 const WallBox& box);

}  // namespace ibms
