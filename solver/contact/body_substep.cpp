// Solid sub-step with contacts re-evaluated every sub-step, docs/method.md §5.3.
#include "contact/body_substep.hpp"

#include <stdexcept>

#include "solid/symplectic_euler.hpp"

namespace ibms {

ContactStats advance_bodies_substep(const ContactModel& model, const WallBox& box, double dt_sub,
                                    const std::vector<std::vector<std::array<double, 2>>>& frozen_force_per_body,
                                    std::vector<MassSpringBody>& bodies,
                                    std::vector<ImplicitSpringSystem>* implicit) {
  if (frozen_force_per_body.size() != bodies.size())
    throw std::invalid_argument("advance_bodies_substep: one force vector per body expected");
  std::vector<std::vector<std::array<double, 2>>> force = frozen_force_per_body;
  // All contacts from the same time level x^k, U^k before any body is moved.
  const ContactStats stats = add_contact_forces(model, bodies, box, force);
  if (implicit != nullptr) implicit->resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (implicit != nullptr) (*implicit)[b].advance(bodies[b], dt_sub, force[b]);
    else advance_symplectic_euler(bodies[b], dt_sub, force[b]);
  }
  return stats;
}

ContactSubcycleResult advance_bodies_inner_loop(const ContactModel& model, const WallBox& box, double dt_outer,
                                                int n_inner,
                                                const std::vector<std::vector<std::array<double, 2>>>& frozen_force_per_body,
                                                std::vector<MassSpringBody>& bodies, ContactSubcycler& subcycler,
                                                bool continues) {
  if (frozen_force_per_body.size() != bodies.size())
    throw std::invalid_argument("advance_bodies_inner_loop: one force vector per body expected");
  return subcycler.advance(model, box, dt_outer, n_inner, frozen_force_per_body, {}, bodies, continues);
}

}  // namespace ibms
