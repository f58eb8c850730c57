// The solid part of the step (METHOD.md §5.3, §7 step 6): n_sub = ceil(dt / dt_s) symplectic-Euler
// sub-steps of all bodies together, dt_s the smallest stable sub-step of any body (§5.1, safety
// 0.5), with springs and dashpots, buoyancy-corrected gravity F_e = M (1 - rho_f/rho_s) g (§1.7
// step 5, §2.6), contact forces (the hook below) and the swelling law (natural lengths and
// masses, §1.8) re-evaluated every sub-step, while the fluid reaction F_f and the inner-fluid
// force F_int stay frozen at their values from the projection.
#pragma once
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "sim/body_coupling.hpp"
#include "solid/rigid_motion.hpp"
#include "solid/stable_substep.hpp"

namespace ibms {

// Contact seam: adds the contact force on every point of every body [force/length] at `time`
// (forces[b][p], sized like the bodies, zeroed by the caller). Called once per sub-step.
// The default is no_contact_forces; solver/contact provides the DEM version.
using ContactForces = std::function<void(const std::vector<MassSpringBody>& bodies, double time,
                                         std::vector<std::vector<Vec2>>& forces)>;
void no_contact_forces(const std::vector<MassSpringBody>& bodies, double time,
                       std::vector<std::vector<Vec2>>& forces);

// Sets every body's diameter (natural lengths) and masses (constant density) to D(time).
void apply_swelling_schedules(const std::vector<SwellingSchedule>& swelling, double time,
                              std::vector<MassSpringBody>& bodies);

// Number of sub-steps the next fluid step of length dt needs, from stable_substep (§5.3).
// work: scratch of the spectral bounds (null: a local one, which allocates).
int substeps_for(const std::vector<MassSpringBody>& bodies, double dt, double max_substep = HUGE_VAL,
                 SpectralWorkspace* work = nullptr);

struct SolidStepInputs {
  double time = 0.0;                 // t^n [time]
  double dt = 0.0;                   // fluid step [time]
  double fluid_density = 0.0;        // rho_f [mass/length^3]
  Vec2 gravity{0.0, 0.0};            // g [length/time^2]
  double max_substep = HUGE_VAL;     // further sub-step bound, e.g. the contact duration / 20 [time]
  int fixed_substeps = 0;            // > 0: exactly this many sub-steps, no stability bound (stability studies)
  SpectralWorkspace* spectral_workspace = nullptr;  // scratch of the sub-step bound (null: allocates)
};

// Advances all bodies from t^n to t^n + dt; returns the number of sub-steps taken. Each sub-step
// moves each body by its kind (DESIGN.md §11): mass_spring by symplectic Euler of its points;
// rigid by Newton-Euler with the total hydrodynamic force and torque (frozen over the step),
// the contact forces summed to force and torque about X_c, and m (1 - rho_f/rho_s) g; prescribed
// to its scene motion at the sub-step's end. rigid[b] holds the motion of rigid and prescribed
// bodies (unused for mass_spring). contact_work is scratch (resized once).
int advance_bodies(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                   const ContactForces& contact_forces, std::vector<BodyCoupling>& coupling,
                   std::vector<std::vector<Vec2>>& contact_work, std::vector<RigidBody>& rigid,
                   std::vector<MassSpringBody>& bodies);

}  // namespace ibms
