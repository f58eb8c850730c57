// Parameters of the DEM contacts between contact-detection spheres (CDS), docs/method.md §1.9 and A8:
// one CDS (circle) per surface mass point, radius absolute or a fraction of the current body
// diameter; linear normal spring k_Dn (or, collision_time, k per contact from a collision time,
// §5.5) with a dashpot from the restitution coefficient e_D;
// no tangential force. Also the walls the CDS touch and the sub-step bound t_c / 20 (A8).
// 2D, per unit depth: stiffness [force/length^2], masses [mass/length]. Knows nothing of the grid.
#pragma once
#include <array>
#include <limits>
#include <vector>

#include "core/options.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

// Which mass enters m_eff of the restitution-damping relation (A8).
//  body:  whole-body masses M_A M_B / (M_A + M_B), wall M_A (A8: "m = rho_s pi r^2", the particle);
//         a stiff body then rebounds with e_D measured on its centre-of-mass velocity.
//  point: the two CDS point masses m_i m_j / (m_i + m_j), wall m_i (docs/method.md §1.9 literal, m_e = M/2
//         with M the point mass); a stiff body then rebounds with far less damping than e_D says.
enum class ContactEffectiveMass { body, point };

// How k (and with it c) of a contact is chosen, ContactLawKind (linear | collision_time), the step
// of the inner loop, InnerStepBound (listed_pairs | lightest_point), and the default of its outer
// step, inner_loop_outer_fraction: core/options.hpp.

struct ContactModel {
  ContactLawKind law = ContactLawKind::linear;
  double stiffness = 0.0;                // k_Dn per CDS pair (linear) [force/length^2 per unit depth]; 0 = off
  double collision_steps = 10.0;         // T_c / dt (collision_time) [-]
  double collision_time = 0.0;           // T_c (collision_time), set each fluid step by for_fluid_step [time]
  double restitution_coefficient = 1.0;  // e_D in (0, 1] [-]
  double cds_radius = 0.0;               // absolute CDS radius [length]; 0: use the fraction
  double cds_radius_fraction = 0.0;      // CDS radius / current body diameter [-]
  bool walls = true;                     // CDS-wall contacts on the non-periodic walls
  // A CDS on each mass-spring body's centre point as well as on its surface points (docs/method.md
  // §1.9): the centre point of a wheel crushed flat cannot then pass through a wall or another body.
  bool centre_point = false;
  ContactEffectiveMass effective_mass = ContactEffectiveMass::body;
  // Departure from docs/method.md §1.9 (on by default): the CDS pairs active between the same two bodies
  // (or a body and a wall) act in parallel, S = sum_p (n_p . N)^2 of them along their mean normal N
  // (S = n_c for parallel pairs); each gets the dashpot built for stiffness k_Dn / S, so the group
  // keeps the damping ratio that gives e_D. Off: every pair gets the single-pair dashpot and the
  // realised damping ratio grows like sqrt(S).
  bool share_damping_among_active_pairs = true;
  // Simultaneously active pairs assumed by the sub-step bound (docs/method.md §1.9: "safety factor ~4").
  double active_pairs_safety = 4.0;      // [-]
  // Sub-steps per contact duration (A8: >= 20, "preferably 50 for accurate e"). Measured for two free
  // CDS points at contact_substep's bound with safety 4 (about 40 steps per real contact): e = 0.1 ->
  // 0.092, 0.5 -> 0.508, 0.9 -> 0.905, 1 -> 0.99997; raise it when e_D < 1 must be met within 1 %.
  // The inner loop's listed_pairs step applies it to the fastest mode of the listed pairs (a single
  // pair: 20 steps per contact).
  double steps_per_contact = 20.0;       // [-]
  InnerStepBound inner_step = InnerStepBound::listed_pairs;
  // The inner loop's outer step as a fraction of the group's springs' stable sub-step, in (0, 1]
  // (core/options.hpp's inner_loop_outer_fraction: the default, and why).
  double outer_step_fraction = inner_loop_outer_fraction;  // [-]

  // std::invalid_argument naming the first inconsistent parameter.
  void check() const;

  // The points 0 .. cds_points(body) - 1 of a body carry a CDS: its surface points, and its centre
  // point (the last) with centre_point on a mass-spring body.
  int cds_points(const MassSpringBody& body) const {
    return centre_point && body.kind == BodyKind::mass_spring ? body.n_points() : body.n_surface;
  }
  bool enabled() const { return stiffness > 0.0 || law == ContactLawKind::collision_time; }
  // The model of a fluid step of length dt: T_c = collision_steps dt (collision_time; linear: unchanged).
  ContactModel for_fluid_step(double dt) const;
  // k of one CDS pair (or CDS and wall) whose effective mass is m_eff (contact_effective_mass)
  // [force/length^2 per unit depth]: k_Dn, or m_eff (pi^2 + ln^2 e_D) / T_c^2.
  double pair_stiffness(double pair_mass) const;
  // CDS radius of the points of this body [length]; follows the current (swollen) diameter.
  double cds_radius_of(const MassSpringBody& body) const;
};

// The bodies a call works on: every body (the default), or a group given by its bodies' indices in
// ascending order (a view of the caller's list, which outlives the call). Loops visit the members
// only, so that a call on a group of k bodies costs O(k) whatever the number of bodies:
//   for (std::size_t i = 0; i < members.count(bodies.size()); ++i) { const std::size_t b = members.at(i); ... }
struct BodySet {
  const int* list = nullptr;  // the group's bodies, ascending (unused for every body)
  std::size_t size = 0;
  bool every = true;
  static BodySet group(const int* first, std::size_t n) { return {first, n, false}; }
  std::size_t count(std::size_t n_bodies) const { return every ? n_bodies : size; }
  std::size_t at(std::size_t i) const { return every ? i : static_cast<std::size_t>(list[i]); }
};

// The box the bodies live in: [origin_x, origin_x + length_x] x [origin_y, origin_y + length_y].
// A periodic direction has no walls and contacts across it use the minimum image.
struct WallBox {
  std::array<double, 2> origin{0.0, 0.0};  // [length]
  std::array<double, 2> length{1.0, 1.0};  // [length]
  std::array<bool, 2> periodic{false, false};
  // Inflow or outflow sides (left, right, bottom, top): no wall there, so no contact.
  std::array<bool, 4> open{false, false, false, false};
  // A wall at side 0 (low) or 1 (high) of direction `axis`.
  bool is_wall(int axis, int side) const { return !periodic[axis] && !open[2 * axis + side]; }
};

// Largest sub-step that resolves a contact with steps_per_contact sub-steps (A8: dt <= t_c / 20)
// and keeps the dashpot of the lightest CDS point stable (docs/method.md §5.1, pure dashpot dt <= 2 m / c, with
// safety 0.5). t_c uses the lightest CDS point mass (m_p / 2 if there are two bodies, m_p with
// walls only) and active_pairs_safety * k_Dn: conservative, because a stiff body's contact lasts
// longer than that of its lightest point. Infinity when contacts are off [time].
// members: the bodies of one contact group (contact_groups below); empty = all bodies.
double contact_substep(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                       const BodySet& members = {});
// The parts of contact_substep, for `ibms info` to print the figures the run uses.
struct ContactSubstepBounds {
  double pair_stiffness = 0.0;  // k of the stiffest pair (k_Dn, or collision_time's for the heaviest m_eff) [force/length^2]
  double duration = std::numeric_limits<double>::infinity();    // t_c of the lightest point in active_pairs_safety such pairs [time]
  double resolution = std::numeric_limits<double>::infinity();  // t_c / steps_per_contact [time]
  double dashpot = std::numeric_limits<double>::infinity();     // dashpot stability, safety 0.5 [time]
};
ContactSubstepBounds contact_substep_bounds(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                                            const BodySet& members = {});
// The dashpot part of contact_substep alone: pure dashpot dt <= 2 m / c of the lightest CDS point
// in active_pairs_safety pairs, safety 0.5. Infinity without damping [time].
double contact_dashpot_substep(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                               const BodySet& members = {});

// Mass a CDS point brings to a contact [mass/length]: its lumped mass, or for a rigid body m/3, the
// smallest effective mass of a rim point of a uniform rigid disk (pushed along its rim tangent,
// 1/m_eff = 1/m + R^2/I = 3/m). Not for prescribed bodies (infinitely heavy).
double cds_point_mass(const MassSpringBody& body, int point);
// The lightest CDS point mass over the bodies that can move, their centre points included where
// they carry a CDS (ContactModel::cds_points; infinity if none) [mass/length].
double lightest_cds_point_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                               const BodySet& members = {});

// Whether a contact can begin or is under way within the next fluid step of length dt (contact
// sub-steps run only while a contact is possible). Each body is bounded by the circle about
// its rim points' mean holding every CDS; two bodies (or a body and a wall) can touch within dt
// when their gap is below the reach 2 (v_a + v_b) dt + e_a + e_b + r_cds / 2, with v the largest
// point speed of each body, a safety factor 2 on the travel, and e_b = reach_extra[b] what the
// caller adds for body b (travel from its acceleration bound, growth of its radius by swelling).
// Prescribed bodies do not touch each other. Periodic directions use the nearest image.
bool contact_possible_within(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                             const WallBox& box, double dt, const std::vector<double>& reach_extra);

// Contact groups for the multi-rate sub-steps: the bodies joined, directly or through
// others, by a pair that may touch within dt (the test of contact_possible_within, pair by pair).
// Bodies of different groups cannot exert a contact force on each other within the step, so each
// group may take its own sub-step; a group that may touch something (a pair inside it or a wall)
// needs the contact sub-step, the others only their springs'. Numbering: by the lowest body index.
struct ContactGroups {
  std::vector<int> group_of;    // group of each body, 0 .. n_groups - 1
  std::vector<char> may_touch;  // per group: a contact (pair or wall) is possible within dt
  int n_groups = 0;
  bool any_contact() const;
  // Scratch of find_contact_groups: each body's circle (centre x, y, radius, speed, CDS radius)
  // and the free bodies' cell keys.
  std::vector<std::array<double, 5>> circles;
  std::vector<std::pair<long, int>> hashed;
};
// Fills groups (its vectors are reused: no allocation once sized). With contacts off every body is
// a group of its own that touches nothing. Linear in the number of bodies: prescribed bodies are
// tested against every body, free bodies against those in neighbouring cells of a hash.
void find_contact_groups(const ContactModel& model, const std::vector<MassSpringBody>& bodies, const WallBox& box,
                         double dt, const std::vector<double>& reach_extra, ContactGroups& groups);

}  // namespace ibms
