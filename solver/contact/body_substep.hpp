// One solid sub-step of all bodies with contacts, docs/method.md §5.3: at x^k, U^k evaluate the DEM
// contact forces of every body (before any body moves, so pair forces stay equal and opposite),
// add the frozen external forces (fluid reaction, internal-fluid term, gravity [force/length]),
// then advance each body by symplectic Euler with its springs and dashpots re-evaluated (§5.1).
// The caller chooses dt_sub <= min(stable_substep(body), contact_substep(model, bodies)).
#pragma once
#include <array>
#include <vector>

#include "contact/contact_forces.hpp"
#include "contact/contact_model.hpp"
#include "contact/contact_subcycle.hpp"
#include "solid/implicit_euler.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

// frozen_force_per_body: one vector of n_points per body, held over the fluid step. implicit: if
// given (one per body), the springs take the linearly implicit Euler step (solid/implicit_euler.hpp).
ContactStats advance_bodies_substep(const ContactModel& model, const WallBox& box, double dt_sub,
                                    const std::vector<std::vector<std::array<double, 2>>>& frozen_force_per_body,
                                    std::vector<MassSpringBody>& bodies,
                                    std::vector<ImplicitSpringSystem>* implicit = nullptr);

// One outer sub-step of all bodies (mass_spring, explicit springs) with the contacts in the inner
// loop of contact_subcycle.hpp: n_inner inner contact steps of dt_outer / n_inner on the points
// near a contact, the springs and the frozen force on every point held over dt_outer.
ContactSubcycleResult advance_bodies_inner_loop(const ContactModel& model, const WallBox& box, double dt_outer,
                                                int n_inner,
                                                const std::vector<std::vector<std::array<double, 2>>>& frozen_force_per_body,
                                                std::vector<MassSpringBody>& bodies, ContactSubcycler& subcycler,
                                                bool continues = false);

}  // namespace ibms
