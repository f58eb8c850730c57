// DEM contact forces between CDS and with walls, docs/method.md §1.9, A8.
#include "contact/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

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
  std::pair<int, int> group;  // the two bodies, or the body and -1 - wall: pairs sharing a dashpot
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
    contact.group = std::minmax(contact.body_a, contact.body_b);
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
    for (int k = 0; k < bodies[b].n_surface; ++k) {
      for (int c = 0; c < 2; ++c) {
        if (box.periodic[c]) continue;
        const double x = bodies[b].position[k][c];
        const double wall_distance[2] = {x - box.origin[c], box.origin[c] + box.length[c] - x};
        for (int side = 0; side < 2; ++side) {
          if (!box.is_wall(c, side)) continue;
          // delta = r_c - d_wall (docs/method.md §1.9); n points out of the box, towards the wall.
          const double overlap = radius - wall_distance[side];
          if (!(overlap > 0.0)) continue;
          ActiveContact contact;
          contact.body_a = b;
          contact.point_a = k;
          contact.group = {b, -1 - (2*c + side)};
          contact.overlap = overlap;
          contact.normal[c] = side == 0 ? -1.0 : 1.0;
          contacts.push_back(contact);
          ++stats.n_wall_contacts;
        }
      }
    }
  }
}

double effective_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                      const ActiveContact& contact) {
  return contact_effective_mass(model, bodies, contact.body_a, contact.point_a,
                                contact.body_b == wall_partner ? -1 : contact.body_b, contact.point_b);
}

// S = sum_p (n_p . N)^2 per group, N the unit mean normal of its pairs: the number of pairs acting
// along N. For a rigid approach along N each pair has delta_p = delta_N (n_p . N), so the group is
// one spring S k with dashpot S c; S = n_c when the pairs are parallel, 1 for a single pair.
struct GroupSum {
  std::pair<int, int> group;
  std::array<double, 2> normal_sum{0.0, 0.0};
  int n_pairs = 0;
  double length = 0.0;    // mean_normal_length of the group
  double parallel = 0.0;  // S
};

// S of every contact's group into `sharing` (one entry per contact); `groups` is scratch. Groups are
// few (pairs of bodies in touch), so a linear look-up in a reused vector replaces the maps.
void count_parallel_pairs(const std::vector<ActiveContact>& contacts, std::vector<GroupSum>& groups,
                          std::vector<int>& group_of, std::vector<double>& sharing) {
  groups.clear();
  group_of.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ActiveContact& contact = contacts[k];
    std::size_t g = 0;
    while (g < groups.size() && groups[g].group != contact.group) ++g;
    if (g == groups.size()) groups.push_back({contact.group});
    groups[g].normal_sum[0] += contact.normal[0];
    groups[g].normal_sum[1] += contact.normal[1];
    ++groups[g].n_pairs;
    group_of[k] = static_cast<int>(g);
  }
  for (GroupSum& g : groups) {
    g.length = mean_normal_length(g.normal_sum, g.n_pairs);
    if (g.length == 0.0) g.parallel = g.n_pairs;  // normals that cancel have no common direction: count them
  }
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    GroupSum& g = groups[group_of[k]];
    if (g.length != 0.0) g.parallel += parallel_share(contacts[k].normal, g.normal_sum, g.length);
  }
  sharing.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) sharing[k] = groups[group_of[k]].parallel;
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
  thread_local std::vector<GroupSum> groups;
  thread_local std::vector<int> group_of;
  thread_local std::vector<double> parallel_pairs;
  contacts.clear();
  // One body has no partner: skip the pair search entirely, walls only.
  if (members.count(bodies.size()) > 1) collect_pair_contacts(model, bodies, members, box, contacts, stats);
  if (model.walls) collect_wall_contacts(model, bodies, members, box, contacts, stats);

  count_parallel_pairs(contacts, groups, group_of, parallel_pairs);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ActiveContact& contact = contacts[k];
    stats.max_overlap = std::max(stats.max_overlap, contact.overlap);
    // The pairs of one group act in parallel, S of them along their mean normal (stiffness S k):
    // the dashpot of k / S for each keeps the damping ratio of e_D for the group (ContactModel).
    // k is k_Dn, or chosen from this pair's m_eff so that it lasts T_c (collision_time).
    const double sharing = model.share_damping_among_active_pairs ? parallel_pairs[k] : 1.0;
    const double m_eff = effective_mass(model, bodies, contact);
    const double stiffness = model.pair_stiffness(m_eff);
    const ContactLaw law{stiffness,
                         damping_from_restitution(model.restitution_coefficient, m_eff, stiffness / sharing)};
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
