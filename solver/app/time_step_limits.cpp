// Time-step limits of a scene (time_step_limits.hpp).
#include "app/time_step_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "fluid/time_scheme_stability.hpp"
#include "sim/bodies/body_update.hpp"
#include "sim/time_step_limits.hpp"
#include "solid/spring_dashpot.hpp"
#include "solid/stable_substep.hpp"

namespace ibms {
namespace {

double grid_spacing(const Scene& scene) {
  return std::min(scene.domain.length_x / scene.domain.cells_x, scene.domain.length_y / scene.domain.cells_y);
}

}  // namespace

std::vector<TimeStepLimit> time_step_limits(const Scene& scene, const Simulation& sim) {
  std::vector<TimeStepLimit> limits;
  // The run's own limits at the first step (sim/time_step_limits.hpp), not derived again here.
  const StepLimits run = step_limits(sim, scan_velocity(sim.grid(), sim.fluid()));
  const double h = grid_spacing(scene);
  // Advective: dt max(|u|/dx + |v|/dy) <= 1 is the run's blow-up guard (run.max_cfl); the adaptive
  // step targets run.cfl of it, docs/method.md §2.3.
  limits.push_back({"CFL (advective, |u| dt / h <= 1)", run.rate > 0 ? 1.0 / run.rate : HUGE_VAL, scene.run.cfl, false,
                    run.rate > 0 ? fmt::format("1 / max(|u|/dx + |v|/dy over the cells, U_walls / h) = 1 / {:.4g} "
                                               "at the start", run.rate)
                                 : "no velocity scale before the run (fluid at rest): checked every step"});
  const double nu = scene.fluid.kinematic_viscosity;
  if (scene.run.max_viscous_number > 0)
    limits.push_back({"viscous number (h^2 / nu)", nu > 0 ? h * h / nu : HUGE_VAL, scene.run.max_viscous_number, false,
                      "run.max_viscous_number: the direct forcing's slip grows like (nu dt / h^2) h"});
  else
    limits.push_back({"viscous (explicit bound h^2 / (4 nu))", nu > 0 ? h * h / (4 * nu) : HUGE_VAL, HUGE_VAL, false,
                      sim.has_bodies() ? "not binding (Crank-Nicolson); with bodies consider run.max_viscous_number"
                                       : "not binding: Crank-Nicolson diffusion"});
  if (!sim.has_bodies()) return limits;
  // The speed the run's first step sees: prescribed bodies at their largest over that step.
  const double dx = sim.grid().dx();  // the run's marker travel is in cells of dx (bodies need dx = dy)
  limits.push_back({"marker travel (h / max|U_body|)", run.body_speed > 0 ? dx / run.body_speed : HUGE_VAL,
                    max_marker_travel_cells, false,
                    run.body_speed > 0 ? fmt::format("fastest body point over the first step {:.4g}; adaptive runs "
                                                     "check it every step", run.body_speed)
                                       : "bodies start at rest: checked every step by the adaptive step"});
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    if (body.kind != BodyKind::mass_spring) continue;  // rigid and prescribed bodies have no springs
    const SpectralBounds bounds = spectral_bounds(body);
    const double omega = std::sqrt(bounds.omega_squared_max), gamma = bounds.damping_rate_max;
    // Symplectic Euler, docs/method.md §5.1: undamped dt <= 2 / omega_max (period 2 pi / omega_max),
    // pure dashpot dt <= 2 / gamma_max; together 4 / (gamma + sqrt(gamma^2 + 4 omega^2)), safety 0.5.
    limits.push_back({fmt::format("body {} spring period (2 / omega_max)", b), omega > 0 ? 2 / omega : HUGE_VAL, 0.5,
                      true, fmt::format("omega_max <= {:.4g} [1/time], period 2 pi / omega_max = {:.4g}", omega,
                                        omega > 0 ? 2 * pi / omega : HUGE_VAL)});
    limits.push_back({fmt::format("body {} damping (2 / gamma_max)", b), gamma > 0 ? 2 / gamma : HUGE_VAL, 0.5, true,
                      fmt::format("gamma_max <= {:.4g} [1/time]", gamma)});
    limits.push_back({fmt::format("body {} springs + dashpots together", b), stable_substep(body, /*safety=*/1.0), 0.5,
                      true, "4 / (gamma + sqrt(gamma^2 + 4 omega^2))"});
  }
  if (sim.has_contacts()) {
    // The figures of the run's own bound (contact_substep_bounds), at the first step's dt.
    const ContactModel model = sim.contact_model().for_fluid_step(planned_time_step(sim));
    const ContactSubstepBounds bounds = contact_substep_bounds(model, sim.bodies());
    const bool collision_time = model.law == ContactLawKind::collision_time;
    const bool whole_body = model.effective_mass == ContactEffectiveMass::body;
    limits.push_back({"contact duration t_c (DEM)", bounds.duration, 1.0 / model.steps_per_contact, true,
                      fmt::format("lightest CDS point, {} x {}; the sub-step is also kept below half the dashpot "
                                  "limit: {:.4g}", model.active_pairs_safety,
                                  collision_time ? fmt::format("k = {:.4g} (collision_time: heaviest {}, T_c = {:.4g} "
                                                               "at the first step)", bounds.pair_stiffness,
                                                               whole_body ? "body" : "CDS point", model.collision_time)
                                                 : std::string("k_Dn"),
                                  std::min(bounds.resolution, bounds.dashpot))});
  }
  return limits;
}

std::string describe_time_step_limits(const Scene& scene, const Simulation& sim) {
  const std::vector<TimeStepLimit> limits = time_step_limits(scene, sim);
  const double dt = planned_time_step(sim);
  const bool fixed = scene.run.time_step > 0;
  std::string text = "# time-step limits [time] (stability bound; safe fraction the run keeps to)\n";
  for (const TimeStepLimit& l : limits) {
    text += fmt::format("  {:<44} {:>11}  safe fraction {:<6} {}{}\n", l.name,
                        std::isfinite(l.limit) ? fmt::format("{:.4g}", l.limit) : "none",
                        std::isfinite(l.safe_fraction) ? fmt::format("{:.3g}", l.safe_fraction) : "-",
                        l.sub_stepped ? "(solid sub-step) " : "", l.note);
  }
  text += "\n# time step\n";
  if (fixed) text += fmt::format("fixed dt = {:.4g}\n", dt);
  else {
    text += fmt::format("adaptive: dt = cfl / max(|u|/dx + |v|/dy, U_walls / h), cfl = {:.3g}, "
                        "capped at {:.4g}{}{}\n",
                        scene.run.cfl, scene.run.max_time_step, sim.has_bodies() ? ", marker travel <= 0.5 h" : "",
                        scene.run.max_viscous_number > 0 ? ", nu dt / h^2 <= run.max_viscous_number" : "");
    if (std::isfinite(dt)) text += fmt::format("  first step (as the run takes it): dt = {:.4g}\n", dt);
  }
  const double h = grid_spacing(scene);
  if (std::isfinite(dt))
    text += fmt::format("  viscous number nu dt / h^2 = {:.3g} (Crank-Nicolson: no limit)\n",
                        scene.fluid.kinematic_viscosity * dt / (h * h));
  // AB2 convection is stable only with enough CN diffusion: the CFL limit of a uniform flow along a
  // grid axis at the scene's cell Reynolds number (docs/fluid-stability.md). A note, not a warning:
  // the measured cavity is stable far beyond it, a periodic shear layer to 1.0-1.4 times it.
  const double speed = sim.speed_scale();
  if (speed > 0 && scene.fluid.kinematic_viscosity > 0) {
    const double cell_reynolds = speed * h / scene.fluid.kinematic_viscosity;
    const ConvectionScheme convection = sim.fluid_solver().schemes().convection;
    const double cfl_limit = ab2_cn_cfl_limit(cell_reynolds, upwind_kappa(convection));
    text += fmt::format("  cell Reynolds number U h / nu = {:.3g}: von Neumann limit of AB2 + CN ({}) CFL <= {:.3g}\n",
                        cell_reynolds, convection_name(convection), cfl_limit);
    const double cfl = fixed ? dt * speed / h : scene.run.cfl;
    if (cfl > cfl_limit)
      text += fmt::format("note: CFL {:.3g} is above that limit: a flow carried at speed U along a grid axis may go "
                          "unstable (lower run.{}; docs/fluid-stability.md)\n",
                          cfl, fixed ? "time_step" : "cfl");
  }
  if (sim.has_bodies()) {
    // The springs' sub-step as the run takes it (spring_stepping): bodies whose springs are implicit
    // at this step set none (without a finite step: only those forced implicit).
    double solid_substep = HUGE_VAL;
    SpectralWorkspace scratch;
    for (const MassSpringBody& body : sim.bodies())
      solid_substep = std::min(solid_substep, spring_stepping(body, std::isfinite(dt) ? dt : 0.0, scratch).substep);
    const double contact_limit =
        sim.has_contacts() && std::isfinite(dt) ? contact_substep(sim.contact_model().for_fluid_step(dt), sim.bodies())
                                                : HUGE_VAL;
    text += fmt::format("solid sub-step: springs {}{}\n",
                        std::isfinite(solid_substep) ? fmt::format("{:.4g}", solid_substep) : "none (no explicit springs)",
                        sim.has_contacts() ? fmt::format(", contacts {:.4g} (only while a contact is possible within "
                                                         "the step)", contact_limit)
                                           : "");
    if (std::isfinite(dt) && dt > 0) {
      const bool touching = sim.substep_planner().contact_possible(dt);
      SubstepGroups groups;
      sim.substep_planner().plan(dt, groups);
      SolidStepInputs in;
      in.dt = dt;
      in.max_substep = groups.group_of.empty() ? sim.substep_planner().global_contact_limit(dt) : HUGE_VAL;
      in.fixed_substeps = sim.fixed_substeps();
      const SolidStepCount count = count_substeps(in, groups, sim.bodies());
      const std::size_t n_groups = groups.group_of.empty() ? 1 : groups.max_substep.size();
      text += fmt::format("sub-steps per fluid step at dt = {:.4g}: {} at most, {} summed over the {} bodies "
                          "({} {}{})\n",
                          dt, count.max_substeps, count.body_substeps, sim.bodies().size(),
                          groups.group_of.empty() ? "global:" : fmt::format("per group: {} group(s);", n_groups),
                          sim.has_contacts() ? (touching ? "a contact is possible at t = 0" : "no contact possible at t = 0")
                                             : "no contacts",
                          "");
    }
  }
  // A fixed step above the safe fraction of a limit the fluid step itself must respect is a warning;
  // limits handled by sub-stepping are reported with the sub-steps that handle them.
  if (fixed)
    for (const TimeStepLimit& l : limits) {
      if (!std::isfinite(l.limit) || !std::isfinite(l.safe_fraction) || dt <= l.safe_fraction * l.limit) continue;
      if (l.sub_stepped)
        text += fmt::format("note: fixed dt = {:.4g} is {:.3g} x the {} limit: the solid sub-steps it\n", dt,
                            dt / l.limit, l.name);
      else
        text += fmt::format("WARNING: fixed dt = {:.4g} is {:.3g} x the {} limit {:.4g}, above the safe fraction {:.3g}\n",
                            dt, dt / l.limit, l.name, l.limit, l.safe_fraction);
    }
  return text;
}

}  // namespace ibms
