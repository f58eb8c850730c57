// DEM contact forces between CDS and with walls, docs/method.md §1.9, A8.
#include "contact/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/cds_pair_search.hpp"
#include "contact/normal_contact_law.hpp"
#include "solid/spring_dashpot.hpp"

namespace ibms {

double contact_effective_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies, int body_a,
                              int point_a, int body_b, int point_b) {
  const bool whole_body = model.effective_mass == ContactEffectiveMass::body;
  const MassSpringBody& a = bodies[body_a];
  const double m_a = whole_body ? a.total_mass() : cds_point_mass(a, point_a);
  if (body_b < 0) return m_a;
  const MassSpringBody& b = bodies[body_b];
  const double m_b = whole_body ? b.total_mass() : cds_point_mass(b, point_b);
  // A prescribed body does not yield: it acts like a wall (infinite mass) on its partner.
  if (b.kind == BodyKind::prescribed) return m_a;
  if (a.kind == BodyKind::prescribed) return m_b;
  return m_a * m_b / (m_a + m_b);
}

void ContactStats::include(const ContactStats& later) {
  n_active_pairs = std::max(n_active_pairs, later.n_active_pairs);
  n_wall_contacts = std::max(n_wall_contacts, later.n_wall_contacts);
  max_overlap = std::max(max_overlap, later.max_overlap);
  n_pair_checks += later.n_pair_checks;
}

namespace {

constexpr int wall_partner = -1;  // body_b of a wall contact

// One touching CDS and its partner (a CDS of another body, or a wall).
struct ActiveContact {
  int body_a = 0, point_a = 0;
  int body_b = wall_partner, point_b = 0;
  std::array<int, 2> group{};  // contact_group_key / wall_group_key: pairs sharing a dashpot
  double overlap = 0.0;       // delta [length]
  std::array<double, 2> normal{0.0, 0.0};  // from CDS a towards its partner
};

void collect_pair_contacts(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                           const BodySet& members, const WallBox& box, std::vector<ActiveContact>& contacts,
                           ContactStats& stats) {
  // Scratch kept across calls (as the pair search's own bins): no allocation once grown.
  thread_local ContactSpheres spheres;
  thread_local PairSearchResult search;
  gather_contact_spheres(model, bodies, spheres, members);
  find_touching_pairs_body_bounds(spheres, box, search);
  stats.n_pair_checks = search.n_pair_checks;
  for (const SpherePair& pair : search.pairs) {
    const int s = pair.first, t = pair.second;
    // Two prescribed bodies (e.g. nested cylinders) move as the scene says: no contact force.
    if (bodies[spheres.body[s]].kind == BodyKind::prescribed && bodies[spheres.body[t]].kind == BodyKind::prescribed)
      continue;
    const std::array<double, 2> d = separation(spheres.centre[s], spheres.centre[t], box);
    const double distance = std::hypot(d[0], d[1]);
    if (!(distance > 0.0)) throw std::runtime_error("contact: two CDS centres coincide");
    ActiveContact contact;
    contact.body_a = spheres.body[s];
    contact.point_a = spheres.point[s];
    contact.body_b = spheres.body[t];
    contact.point_b = spheres.point[t];
    contact.group = contact_group_key(contact.body_a, contact.body_b);
    // delta = r_i + r_j - |x_j - x_i|, n = (x_j - x_i)/|x_j - x_i| (docs/method.md §1.9).
    contact.overlap = spheres.radius[s] + spheres.radius[t] - distance;
    contact.normal = {d[0] / distance, d[1] / distance};
    contacts.push_back(contact);
  }
  stats.n_active_pairs = static_cast<int>(contacts.size());
}

// Walls 0..3: x = x0, x = x0 + Lx, y = y0, y = y0 + Ly; only in non-periodic directions.
void collect_wall_contacts(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                           const BodySet& members, const WallBox& box, std::vector<ActiveContact>& contacts,
                           ContactStats& stats) {
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const int b = static_cast<int>(members.at(i));
    if (bodies[b].kind == BodyKind::prescribed) continue;  // its motion is given, walls cannot push it
    const double radius = model.cds_radius_of(bodies[b]);
    for_each_point_near_walls(bodies[b].position, model.cds_points(bodies[b]), box, radius, 0.0,
                              [&](int k, int c, int side, double distance) {
                                // delta = r_c - d_wall (docs/method.md §1.9); n points out of the box, towards the wall.
                                ActiveContact contact;
                                contact.body_a = b;
                                contact.point_a = k;
                                contact.group = wall_group_key(b, 2 * c + side);
                                contact.overlap = radius - distance;
                                contact.normal[c] = side == 0 ? -1.0 : 1.0;
                                contacts.push_back(contact);
                                ++stats.n_wall_contacts;
                              });
  }
}

double effective_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                      const ActiveContact& contact) {
  return contact_effective_mass(model, bodies, contact.body_a, contact.point_a,
                                contact.body_b == wall_partner ? -1 : contact.body_b, contact.point_b);
}

// S of every contact's group (normal_contact_law.hpp) into `sharing` (one entry per contact).
void count_parallel_pairs(const std::vector<ActiveContact>& contacts, DashpotGroups& groups,
                          std::vector<int>& group_of, std::vector<double>& sharing) {
  groups.clear();
  group_of.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    group_of[k] = groups.index(contacts[k].group);
    groups[group_of[k]].add(contacts[k].normal);
  }
  for (int g = 0; g < groups.size(); ++g) groups[g].close();
  for (std::size_t k = 0; k < contacts.size(); ++k) groups[group_of[k]].add_share(contacts[k].normal);
  sharing.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) sharing[k] = groups[group_of[k]].damping_factor();
}

}  // namespace

ContactStats add_contact_forces(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                                const WallBox& box,
                                std::vector<std::vector<std::array<double, 2>>>& force_per_body,
                                const BodySet& members) {
  ContactStats stats;
  if (!model.enabled()) return stats;
  if (force_per_body.size() != bodies.size())
    throw std::invalid_argument("add_contact_forces: force_per_body has the wrong size");
  // Scratch kept across calls (called every solid sub-step): no allocation once grown.
  thread_local std::vector<ActiveContact> contacts;
  thread_local DashpotGroups groups;
  thread_local std::vector<int> group_of;
  thread_local std::vector<double> damping_factor;
  contacts.clear();
  // One body has no partner: skip the pair search entirely, walls only.
  if (members.count(bodies.size()) > 1) collect_pair_contacts(model, bodies, members, box, contacts, stats);
  if (model.walls) collect_wall_contacts(model, bodies, members, box, contacts, stats);
  // Room for twice the contacts of the busiest step so far: a few more contacts in a later step
  // (another trajectory of the same scene) then do not reallocate the scratch.
  if (const std::size_t room = 2 * contacts.size() + 16; group_of.capacity() < 2 * contacts.size()) {
    contacts.reserve(room);
    groups.reserve(room);
    group_of.reserve(room);
    damping_factor.reserve(room);
  }

  if (model.share_damping_among_active_pairs) count_parallel_pairs(contacts, groups, group_of, damping_factor);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ActiveContact& contact = contacts[k];
    stats.max_overlap = std::max(stats.max_overlap, contact.overlap);
    // The pairs of one group act in parallel, S of them along their mean normal: each pair's
    // dashpot divided by sqrt(S) keeps the damping ratio of e_D for the group (normal_contact_law.hpp).
    // k is k_Dn, or chosen from this pair's m_eff so that it lasts T_c (collision_time).
    const double m_eff = effective_mass(model, bodies, contact);
    const double stiffness = model.pair_stiffness(m_eff);
    double damping = damping_from_restitution(model.restitution_coefficient, m_eff, stiffness);
    if (model.share_damping_among_active_pairs) damping *= damping_factor[k];
    const ContactLaw law{stiffness, damping};
    const auto& velocity_a = bodies[contact.body_a].velocity[contact.point_a];
    std::array<double, 2> velocity_b{0.0, 0.0};  // walls do not move normal to themselves
    if (contact.body_b != wall_partner) velocity_b = bodies[contact.body_b].velocity[contact.point_b];
    const ContactKinematics kinematics{
        contact.overlap, contact.normal,
        {velocity_b[0] - velocity_a[0], velocity_b[1] - velocity_a[1]}};
    const std::array<double, 2> force = contact_force_on_first(law, kinematics);
    auto& on_a = force_per_body[contact.body_a][contact.point_a];
    on_a[0] += force[0];
    on_a[1] += force[1];
    if (contact.body_b != wall_partner) {  // F_j = -F_i
      auto& on_b = force_per_body[contact.body_b][contact.point_b];
      on_b[0] -= force[0];
      on_b[1] -= force[1];
    }
  }
  return stats;
}

}  // namespace ibms
