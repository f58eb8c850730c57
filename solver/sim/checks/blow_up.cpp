// Blow-up checks after each step (docs/method.md §7): a non-finite or too fast fluid, body points
// that are non-finite or have left the box, bodies with more energy than the scene can give them,
// contacts deeper than their spheres, and the fluid guard (sim/checks/fluid_guard.hpp).
#include "sim/checks/blow_up.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {
namespace {

// Stops the run (run.on_body_instability = "stop") or warns once ("warn").
void report_body_instability(const Simulation& sim, const std::string& what) {
  const FluidState& f = sim.fluid();
  const std::string advice = "; reduce run.time_step, or do not fix the solid sub-steps";
  if (sim.scene().run.on_body_instability == RunSpec::OnInstability::stop)
    throw BlowUpError(fmt::format("blow-up at step {}, t = {:.6g}: {}{}", f.step, f.time, what, advice));
  if (sim.instability().warned) return;
  sim.instability().warned = true;
  std::fprintf(stderr, "ibms: warning at step %ld, t = %.6g: %s%s (run.on_body_instability = \"warn\": said once, "
               "the run goes on)\n", f.step, f.time, what.c_str(), advice.c_str());
}

// Non-finite body points, or points outside the box in a wall direction (the IB stencil and the
// inner-fluid region need them inside).
void check_bodies_for_blow_up(const Simulation& sim) {
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    for (int p = 0; p < body.n_points(); ++p) {
      const auto& x = body.position[p];
      const auto& u = body.velocity[p];
      const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(u[0]) && std::isfinite(u[1]);
      const bool inside_x = g.periodic_x || (x[0] > g.origin_x && x[0] < g.origin_x + g.length_x);
      const bool inside_y = g.periodic_y || (x[1] > g.origin_y && x[1] < g.origin_y + g.length_y);
      if (finite && inside_x && inside_y) {
        // An open side has no wall for the kernel's mirror images (scene_checks.cpp: bodies start
        // 3 cells away from it): a body that drifts that close stops the run with the side named.
        const double reach = 3.0 * g.dx();
        const double distance[4] = {x[0] - g.origin_x, g.origin_x + g.length_x - x[0], x[1] - g.origin_y,
                                    g.origin_y + g.length_y - x[1]};
        const char* names[4] = {"left", "right", "bottom", "top"};
        for (int s = 0; s < 4; ++s) {
          const SideKind kind = sim.boundaries().kind(g, static_cast<Side>(s));
          if ((kind == SideKind::inflow || kind == SideKind::outflow) && distance[s] < reach)
            throw BlowUpError(fmt::format(
                "stopped at step {}, t = {:.6g}: body {} point {} at x = {:.6g}, y = {:.6g} came within 3 cells of the {} "
                "side ({}): the immersed boundary cannot act across an open side",
                f.step, f.time, b, p, x[0], x[1], names[s], side_kind_name(kind)));
        }
        continue;
      }
      throw BlowUpError(fmt::format(
          "blow-up at step {}, t = {:.6g}: body {} point {} {} at x = {:.6g}, y = {:.6g} (u = {:.3g}, v = {:.3g})",
          f.step, f.time, b, p, finite ? "left the box" : "is non-finite", x[0], x[1], u[0], u[1]));
    }
    // Energy no driver of the scene can supply: an unstable spring or contact
    // that pumps energy into the body while its points stay finite and inside the box.
    if (body.kind == BodyKind::prescribed) continue;
    // Kinetic only: an unstable mode grows in its kinetic and its spring energy alike, while the
    // spring energy alone also holds the load of a swelling step (the natural lengths jump by
    // rate dt at each step's end, ~ k (rate dt)^2 / 2 per spring: 2.2 for the stiff swelling disk).
    const double energy = kinetic_energy(body);
    const double bound = InstabilityBounds::energy_factor * sim.instability().body_energy_scale[b];
    if (energy > bound)
      report_body_instability(sim, fmt::format(
          "body {} has kinetic energy {:.4g}, above the {:.4g} the scene can give it "
          "(4 (M V^2 / 2 + initial spring energy), V = {:.4g} the fastest driver: walls, initial and prescribed "
          "speeds, swelling, buoyant free fall across the box): an unstable spring or contact",
          b, energy, bound, sim.instability().driving_speed));
  }
  // A contact deeper than the contact spheres: the rims pass into each other (docs/method.md §5.5,
  // "Limit"). The overlap is about v0 T_c / pi under the collision-time law, v0 sqrt(m_eff / k)
  // under the linear one; the validation scenes reach at most 13 % of the radius.
  if (sim.has_contacts()) {
    double smallest_radius = HUGE_VAL;
    for (const MassSpringBody& body : sim.bodies())
      smallest_radius = std::min(smallest_radius, sim.contact_model().cds_radius_of(body));
    if (sim.stats().last_contact_stats.max_overlap > smallest_radius)
      report_body_instability(sim, fmt::format(
          "a contact overlap of {:.4g} exceeds the smallest contact-sphere radius {:.4g}: the rims pass into each "
          "other (contact.model = \"collision_time\": the overlap is about v0 T_c / pi, so lower run.max_time_step "
          "or contact.collision_steps; linear law: about v0 sqrt(m / k), so raise contact.stiffness)",
          sim.stats().last_contact_stats.max_overlap, smallest_radius));
  }
  // The contacts have given the bodies more energy than they took: more than a quarter of the
  // energy scale sum_b M_b V^2 / 2 (a stable contact gives back at most what it stored, less its
  // integration error of a few per cent of one collision's energy).
  double energy_scale = 0.0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b)
    if (sim.bodies()[b].kind != BodyKind::prescribed) energy_scale += sim.instability().body_energy_scale[b];
  constexpr double returned_fraction = 0.25;
  if (sim.stats().total_contact_work > returned_fraction * energy_scale)
    report_body_instability(sim, fmt::format(
        "the contacts have returned {:.4g} more energy to the bodies than they received (more than {} of the bodies' "
        "energy scale {:.4g}): an unstable contact",
        sim.stats().total_contact_work, returned_fraction, energy_scale));
}

}  // namespace

void check_for_blow_up(Simulation& sim, double dt, const VelocityScan& scan) {
  account_fluid_input(sim, dt);  // before any stop: the budget counts every step
  if (sim.has_bodies()) check_bodies_for_blow_up(sim);
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const std::string place = fmt::format("cell ({}, {}) at x = {:.6g}, y = {:.6g}", scan.i, scan.j,
                                        g.x_centre(scan.i), g.y_centre(scan.j));
  if (!scan.finite)
    throw BlowUpError(fmt::format("blow-up at step {}, t = {:.6g}: non-finite velocity or pressure in {}",
                                  f.step, f.time, place));
  const double cfl = dt * scan.max_rate;
  if (cfl > sim.scene().run.max_cfl)
    throw BlowUpError(fmt::format(
        "blow-up at step {}, t = {:.6g}: CFL number {:.3g} exceeds run.max_cfl = {:.3g} in {} "
        "(|u| = {:.3g}, |v| = {:.3g}); reduce run.time_step or run.cfl",
        f.step, f.time, cfl, sim.scene().run.max_cfl, place, f.velocity_x(scan.i, scan.j),
        f.velocity_y(scan.i, scan.j)));
  check_fluid_guard(sim, scan);
}

}  // namespace ibms
