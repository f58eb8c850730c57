// DEM contact forces on the surface mass points of a set of bodies, docs/method.md §1.9 and A8:
// CDS-CDS pairs of different bodies (cell-list search, skipped when there is one body) and CDS-wall
// contacts on the non-periodic walls of the box, each a linear normal spring-dashpot
// (normal_contact_law.hpp) with k_Dn (or the collision-time k, ContactModel::pair_stiffness) and c
// from e_D and m_eff (A8, see ContactEffectiveMass).
// Forces per unit depth [force/length], at the current positions and velocities (one time level).
#pragma once
#include <array>
#include <vector>

#include "contact/contact_model.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

// What one evaluation found (for the contact time series).
struct ContactStats {
  int n_active_pairs = 0;   // touching CDS pairs of different bodies [-]
  int n_wall_contacts = 0;  // CDS touching a wall [-]
  double max_overlap = 0.0; // largest delta over pairs and walls [length]
  long n_pair_checks = 0;   // candidate CDS pairs examined by the pair search [-]

  // Merges the stats of a later sub-step: largest counts and overlap, summed checks.
  void include(const ContactStats& later);
};

// m_eff of A8 for the CDS of point_a of body_a touching point_b of body_b, or a wall (body_b < 0):
// whole-body or point masses (ContactModel::effective_mass), m_a m_b / (m_a + m_b); a prescribed
// partner counts as infinitely heavy [mass/length].
double contact_effective_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies, int body_a,
                              int point_a, int body_b, int point_b);

// Adds the contact forces to force_per_body (one vector of n_points per body; not cleared; the
// centre points receive nothing). Does nothing when the model is off. members: only contacts among
// these bodies and of these bodies with the walls (a contact group, contact_model.hpp); empty = all.
ContactStats add_contact_forces(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                                const WallBox& box,
                                std::vector<std::vector<std::array<double, 2>>>& force_per_body,
                                const BodySet& members = {});

}  // namespace ibms
