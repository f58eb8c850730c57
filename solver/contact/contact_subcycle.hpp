// Multiple time stepping of the DEM contacts (Tuckerman, Berne & Martyna 1992, r-RESPA, with the
// slow force held constant over the outer step instead of applied as impulses): the contact law
// of contact_forces.hpp, unchanged (linear spring-dashpot on the CDS at k_Dn, dashpot from e_D,
// shared among parallel pairs), advanced in an inner loop of short steps over the points near a
// contact only, while the slow forces on every point (springs and their dashpots; the frozen
// fluid reaction, inner-fluid term and buoyant gravity) are evaluated once per outer step.
//
// One outer step of length dt = n dt_i from x^k, U^k, with a = F_slow(x^k, U^k) / m per point
// (plus r t, r the rate of change of F_slow / m between the previous outer step's start and this
// one's within the fluid step, 0 in its first: the slow force is continuous across outer steps to
// second order, so it sets no undamped resting contact ringing; left out of the formulas below):
//   1. neighbour list: the CDS pairs of different bodies (and the CDS-wall pairs) closer than a
//      skin s = 3 (V T + A T^2 / 2), T the time left, V and A the largest point speed and slow
//      acceleration of the members (s >= a tenth of the smallest CDS radius); their points are
//      the candidates;
//   2. inner steps dt_i, on the candidates only: F_c at the current x, U; U += dt_i (a + F_c / m);
//      x += dt_i (U - dt_i a / 2) (symplectic Euler for the contact, the held slow force exact).
//      dt_i (ContactModel::inner_step): listed_pairs, the time left divided into equal steps of at
//      most t_c / steps_per_contact, t_c = pi / |lambda| of the fastest contact mode the listed
//      pairs and walls can form (|lambda| <= sqrt(rho_K) + rho_C, the spectral radii of M^-1/2 K M^-1/2
//      and M^-1/2 C M^-1/2 bounded from above by Collatz-Wielandt on their block-norm matrices; one
//      undamped pair: A8's t_c exactly), and at most the dashpot's stable
//      step; chosen again for the time left whenever the list is rebuilt. lightest_point: the
//      caller's n steps of dt / n (the group's bound, the lightest CDS point in four pairs);
//   3. every other point moves as a candidate would without contact, in closed form:
//      x += dt U^k + dt^2 a / 2, U += dt a;
//   4. the springs again at the new x and the predicted U: U += dt (F_s^{k+1} - F_s^k) / (2 m)
//      (less dt^2 r / 2: the velocity change over the step is dt (F^k + F^{k+1}) / (2 m)).
// The CDS radii of swelling bodies grow linearly over the inner steps (a step in the radius per
// outer step, about a third of the static overlap in the swelling cavity at k_Dn = 1e4, set its
// e_D = 1 resting contacts ringing: 34 instead of 45 touching CDS pairs on average).
//      Without contact, 3. and 4. are velocity Verlet for the slow forces: symplectic, second
//      order, stable for omega dt < 2 as symplectic Euler.
// The slow force acts on a contact as a steady force, not as an impulse dt F / m per outer step:
// an impulse method bounces a resting point by dt F / sqrt(m k_Dn), dt omega_c times the static
// overlap F / k_Dn (measured on soft wheels pressed together: largest overlaps up to 30 % above the
// shared sub-step's with impulses, test_contact_inner_loop).
// A point off the list meets no contact force, so the list stays valid while twice the largest
// displacement since it was built (candidates measured, the others bounded by V t + A t (t + dt_i) / 2)
// is below s; otherwise every point is brought to the current inner step and the list is rebuilt:
// no contact is missed, whatever the rebound speeds.
// Within the list, an inner step examines only the pairs whose gap when the list was built is below
// twice the closing it can have had since (twice the largest candidate displacement plus the radii's
// growth, doubled when passed): a pair left out cannot touch, so the forces are those of the whole list.
// Only mass_spring bodies with explicit springs take part (the caller's choice: a rigid or
// prescribed body moves all its points at once, implicit springs are not slow).
#pragma once
#include <array>
#include <vector>

#include "contact/cds_pair_search.hpp"
#include "contact/contact_forces.hpp"
#include "contact/contact_model.hpp"
#include "contact/normal_contact_law.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

struct ContactSubcycleResult {
  ContactStats stats;      // merged over the inner steps, as over shared sub-steps
  double work = 0.0;       // sum over inner steps of F_c . U dt_inner, all points [energy/length]
  long inner_steps = 0;    // inner steps taken (0: no point was near a contact in the step) [-]
  int list_builds = 0;     // neighbour lists built (1 + rebuilds) [-]
};

// Scratch and neighbour list of the inner loop: kept by the caller (one per thread), so that no
// allocation happens once its vectors have grown.
class ContactSubcycler {
 public:
  // Advances the points of the member bodies (members; empty = all) over dt_outer in inner steps as
  // described above (n_inner of them with InnerStepBound::lightest_point; its own with listed_pairs). external_force: the frozen force on every point other than springs
  // and contacts, one vector of n_points per body (only members read) [force/length].
  // continues: this step follows the previous call's step for the same members within one fluid
  // step; the slow force then varies linearly over the step at the rate between the two steps'
  // starts (continuous across outer steps to second order; held when false).
  // diameter_rate: dD/dt of each body (empty: none): the CDS radii grow continuously over the
  // inner steps (a swelling step in the radius would set an undamped resting contact ringing).
  ContactSubcycleResult advance(const ContactModel& model, const WallBox& box, double dt_outer, int n_inner,
                                const std::vector<std::vector<std::array<double, 2>>>& external_force,
                                const BodySet& members, std::vector<MassSpringBody>& bodies, bool continues = false,
                                const std::vector<double>& diameter_rate = {});

 private:
  using Vec = std::array<double, 2>;
  // The candidate points, their state copied here for the inner loop, one contiguous array per
  // quantity (the inner loop's kick-and-drift runs over them all every inner step).
  struct Candidates {
    std::vector<int> body, point;
    std::vector<double> inverse_mass;
    std::vector<double> x, y;                // position [length]
    std::vector<double> u, v;                // velocity [length/time]
    std::vector<double> force_x, force_y;    // contact force of the current inner step (0 between steps)
    std::vector<double> anchor_x, anchor_y;  // position when the list was built
    std::vector<double> slow_x, slow_y;      // a = F_slow / m at the step's start [length/time^2]
    std::vector<double> rate_x, rate_y;      // its rate of change over the step [length/time^3]

    int size() const { return static_cast<int>(x.size()); }
    bool empty() const { return x.empty(); }
    void clear();
    void reserve(std::size_t n);
  };
  struct Pair {      // two candidate points of different bodies
    int a = 0, b = 0;
    Vec shift{};              // periodic image: x_b - x_a + shift is the separation
    double radius_sum = 0.0;  // r_a + r_b at the list's inner time [length]
    double radius_rate = 0.0; // d(r_a + r_b)/dt [length/time]
    double stiffness = 0.0;   // k of the pair (ContactModel::pair_stiffness) [force/length^2]
    double damping = 0.0;     // 2 zeta sqrt(m_eff k): the dashpot of one pair, before sharing
    int share = 0;            // the pairs of one body pair (or body and wall) share a dashpot
  };
  struct Wall {      // a candidate point and one wall
    int a = 0, axis = 0, side = 0;
    double radius = 0.0, coordinate = 0.0, stiffness = 0.0, damping = 0.0;
    double radius_rate = 0.0;  // dr/dt [length/time]
    int share = 0;
  };
  struct Active {    // one touching pair or wall in the current inner step, with its law
    int a = 0, b = -1;  // candidates (b = -1: a wall)
    int share = 0;
    double stiffness = 0.0, damping = 0.0;
    double overlap = 0.0;
    Vec normal{};
  };

  void build_list(const ContactModel& model, const WallBox& box, double skin, const BodySet& members,
                  const std::vector<MassSpringBody>& bodies, double time);
  void release_list(std::vector<MassSpringBody>& bodies);  // candidates' state back into the bodies
  int candidate(int body, int point, const std::vector<MassSpringBody>& bodies);
  // moved: the largest displacement of a candidate since the list was built [length].
  void contact_forces(const ContactModel& model, double time, double moved, ContactStats& stats);
  // A touching pair or wall into this inner step's list, its normal into its share's sum.
  void activate(const Active& a);
  // One inner step of the candidates; clears their contact forces for the next step and returns
  // the largest squared displacement of a candidate since the list was built.
  double kick_and_drift(double dt, double time, double& work);
  // Off-list points from inner time `start` over `span` in closed form (step 3 above).
  void move_off_list(const BodySet& members, std::vector<MassSpringBody>& bodies, double start, double span);
  // Inner step that gives steps_per_contact steps per contact duration of the fastest mode the
  // listed pairs and walls can form (InnerStepBound::listed_pairs) [time]; infinity with none.
  double listed_pairs_step(const ContactModel& model);
  // Largest speed and slow acceleration of the members' points (off_list_only: of the points off the list).
  std::array<double, 2> fastest(const BodySet& members, const std::vector<MassSpringBody>& bodies,
                                bool off_list_only) const;

  Candidates points_;
  std::vector<double> moved_;     // per candidate: squared displacement since the list was built
  std::vector<double> stiffness_sum_, damping_sum_;  // per candidate: diagonal k / m (c / m) of its pairs and walls
  std::vector<double> perron_x_, perron_y_;          // power-iteration scratch of listed_pairs_step
  std::vector<int> forced_;       // candidates with a contact force in the current inner step
  std::vector<int> touched_;      // shares with an active pair in the current inner step
  std::vector<Pair> pairs_;
  std::vector<double> gap_;       // per pair: |x_b - x_a| - (r_a + r_b) when the list was built [length]
  std::vector<int> near_;         // pairs whose gap is within near_reach_ (in list order)
  double near_reach_ = -1.0;      // [length]
  double near_reach_floor_ = 0.0; // smallest near_reach_ picked (a sixteenth of the skin) [length]
  double radius_rate_max_ = 0.0;  // largest |d(r_a + r_b)/dt| of the pairs [length/time]
  std::vector<Wall> walls_;
  DashpotGroups shares_;               // per body pair or body and wall in the list: its S (normal_contact_law.hpp)
  std::vector<double> share_factor_;   // per share: 1 / sqrt(S) in the current inner step
  std::vector<Active> active_;
  std::vector<int> slot_;         // per body and point (offset_[b] + p): candidate index or -1
  std::vector<int> offset_;
  std::vector<std::vector<Vec>> slow_;    // per body and point: F_slow = external + springs at x^k, U^k
  std::vector<std::vector<Vec>> spring_;  // per body and point: springs at x^{k+1}, predicted U
  std::vector<std::vector<Vec>> rate_;    // per body and point: dF_slow/dt over the step (0: held)
  std::vector<std::vector<Vec>> previous_slow_;  // F_slow at the previous call's start
  double previous_dt_ = 0.0;
  std::vector<double> radius_rate_;  // per body: dr_cds/dt over this step [length/time]
  double time_built_ = 0.0;          // inner time of the list: radii in the list belong to it
  ContactSpheres spheres_;
  PairSearchResult search_;
  // The pairs within a wider reach than the list needs, kept across lists and calls while no sphere
  // centre has moved half the difference (find_list_pairs): a resting bed rebuilds its list at
  // every outer step, and filtering these is cheaper than a new search, with the same result.
  struct PairSuperset {
    PairSearchResult search;
    std::vector<std::array<double, 2>> anchor;  // the sphere centres when it was made [length]
    std::vector<int> body, point;               // which spheres, in order
    double reach = 0.0;                          // the skin it was made with [length]
    bool valid = false;
  };
  PairSuperset superset_;
  std::vector<double> kept_radius_;  // the spheres' radii while the superset's search grows them
  // search_ = the pairs of spheres_ (radii grown by half the skin) that touch, as
  // find_touching_pairs_body_bounds gives them, from superset_ where it still holds them all.
  void find_list_pairs(const WallBox& box, double skin, bool growing);
  long pair_checks_ = 0;
};

}  // namespace ibms
