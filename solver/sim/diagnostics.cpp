// Blow-up checks, adaptive time step and centre-line profiles (docs/design.md §3 stage 6).
#include "sim/diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "sim/fluid_guard.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {

VelocityScan scan_velocity(const Grid& grid, const FluidState& fluid) {
  VelocityScan scan;
  const double inv_dx = 1.0 / grid.dx(), inv_dy = 1.0 / grid.dy();
  double sum_squares = 0.0, max_square = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double u = fluid.velocity_x(i, j), v = fluid.velocity_y(i, j);
      const double rate = std::abs(u) * inv_dx + std::abs(v) * inv_dy;
      if (!std::isfinite(rate) || !std::isfinite(fluid.pressure(i, j))) {
        return {HUGE_VAL, i, j, false, HUGE_VAL, i, j, HUGE_VAL};
      }
      if (rate > scan.max_rate) { scan.max_rate = rate; scan.i = i; scan.j = j; }
      const double square = u*u + v*v;
      sum_squares += square;
      if (square > max_square) { max_square = square; scan.speed_i = i; scan.speed_j = j; }
    }
  scan.max_speed = std::sqrt(max_square);
  scan.kinetic_energy = 0.5 * sum_squares * grid.cell_area();
  return scan;
}

double max_body_point_speed(const Simulation& sim) {
  double speed = 0.0;
  for (const MassSpringBody& body : sim.bodies())
    for (const auto& u : body.velocity) speed = std::max(speed, std::hypot(u[0], u[1]));
  return speed;
}

double speed_scale(const Simulation& sim) {
  return std::max(boundary_speed_scale(sim.scene().walls), max_body_point_speed(sim));
}

namespace {

// Stops the run (run.on_body_instability = "stop") or warns once ("warn").
void report_body_instability(const Simulation& sim, const std::string& what) {
  const FluidState& f = sim.fluid();
  const std::string advice = "; reduce run.time_step, or do not fix the solid sub-steps";
  if (sim.scene().run.on_body_instability == RunSpec::OnInstability::stop)
    throw BlowUpError(fmt::format("blow-up at step {}, t = {:.6g}: {}{}", f.step, f.time, what, advice));
  if (sim.instability.warned) return;
  sim.instability.warned = true;
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
    const double bound = InstabilityBounds::energy_factor * sim.instability.body_energy_scale[b];
    if (energy > bound)
      report_body_instability(sim, fmt::format(
          "body {} has kinetic energy {:.4g}, above the {:.4g} the scene can give it "
          "(4 (M V^2 / 2 + initial spring energy), V = {:.4g} the fastest driver: walls, initial and prescribed "
          "speeds, swelling, buoyant free fall across the box): an unstable spring or contact",
          b, energy, bound, sim.instability.driving_speed));
  }
  // A contact deeper than the contact spheres: the rims pass into each other (docs/method.md §5.5,
  // "Limit"). The overlap is about v0 T_c / pi under the collision-time law, v0 sqrt(m_eff / k)
  // under the linear one; the validation scenes reach at most 13 % of the radius.
  if (sim.has_contacts()) {
    double smallest_radius = HUGE_VAL;
    for (const MassSpringBody& body : sim.bodies())
      smallest_radius = std::min(smallest_radius, sim.contact_model().cds_radius_of(body));
    if (sim.stats.last_contact_stats.max_overlap > smallest_radius)
      report_body_instability(sim, fmt::format(
          "a contact overlap of {:.4g} exceeds the smallest contact-sphere radius {:.4g}: the rims pass into each "
          "other (contact.model = \"collision_time\": the overlap is about v0 T_c / pi, so lower run.max_time_step "
          "or contact.collision_steps; linear law: about v0 sqrt(m / k), so raise contact.stiffness)",
          sim.stats.last_contact_stats.max_overlap, smallest_radius));
  }
  // The contacts have given the bodies more energy than they took: more than a quarter of the
  // energy scale sum_b M_b V^2 / 2 (a stable contact gives back at most what it stored, less its
  // integration error of a few per cent of one collision's energy).
  double energy_scale = 0.0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b)
    if (sim.bodies()[b].kind != BodyKind::prescribed) energy_scale += sim.instability.body_energy_scale[b];
  constexpr double returned_fraction = 0.25;
  if (sim.stats.total_contact_work > returned_fraction * energy_scale)
    report_body_instability(sim, fmt::format(
        "the contacts have returned {:.4g} more energy to the bodies than they received (more than {} of the bodies' "
        "energy scale {:.4g}): an unstable contact",
        sim.stats.total_contact_work, returned_fraction, energy_scale));
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

// The approach to end_time (docs/method.md §7.2). A step that differs from its predecessor by a
// fraction x makes the body forces spike by about x times the face term of the momentum
// interpolation, dt (mean(G_c) - G_f) p, over dt: 7.5 % of c_D per unit x on DFG 2D-2 at D/h = 10,
// decaying in three steps. So the step never jumps near the end: once end_time is within
// end_approach_steps steps, the time left is split into the fewest whole steps of at most the step
// asked for (a change of at most 1 / end_approach_steps), and that step is kept to the end while it
// is at most end_overshoot above the step asked for (an adaptive limit drifts while the plan runs);
// beyond that the plan is made anew. A time left that is a whole number of steps keeps its step.
constexpr double end_approach_steps = 100.0;
constexpr double end_overshoot = 0.05;

// The whole number of steps of `step` in `time_left` (relative tolerance 1e-9), or 0.
static double whole_steps(double time_left, double step) {
  const double steps = time_left / step;
  const double n = std::round(steps);
  return n >= 1.0 && std::abs(steps - n) <= 1e-9 * steps ? n : 0.0;
}

static double step_to_end(double limit, double previous, double time_left) {
  if (!(time_left < end_approach_steps * limit)) return limit;
  for (const double step : {previous, limit}) {
    if (!(step > 0.0) || step > (1.0 + end_overshoot) * limit) continue;
    const double n = whole_steps(time_left, step);
    if (n > 0.0) return n == 1.0 ? time_left : step;
  }
  return time_left / std::ceil(time_left / limit);
}

double next_time_step(const Simulation& sim, const VelocityScan& scan) {
  const RunSpec& run = sim.scene().run;
  const double time_left = run.end_time - sim.fluid().time;
  const double previous = sim.fluid().time_step_prev;
  if (run.time_step > 0.0) return step_to_end(run.time_step, previous, time_left);
  // Moving walls and inflows set the velocity scale of a fluid at rest (lid-driven start).
  const double wall_speed = boundary_speed_scale(sim.scene().walls);
  const double rate = std::max(scan.max_rate, wall_speed / std::min(sim.grid().dx(), sim.grid().dy()));
  double dt = rate > 0.0 ? run.cfl / rate : run.max_time_step;
  if (sim.has_bodies()) {
    const double body_speed = max_body_point_speed(sim);
    if (body_speed > 0.0) dt = std::min(dt, max_marker_travel_cells * sim.grid().dx() / body_speed);
  }
  const double h = std::min(sim.grid().dx(), sim.grid().dy());
  dt = std::min(dt, viscous_time_step_limit(run, h, sim.fluid_solver().kinematic_viscosity()));
  return step_to_end(std::min(dt, run.max_time_step), previous, time_left);
}

double planned_time_step(const Simulation& sim) {
  return next_time_step(sim, scan_velocity(sim.grid(), sim.fluid()));
}

double viscous_time_step_limit(const RunSpec& run, double h, double kinematic_viscosity) {
  return run.max_viscous_number > 0.0 ? run.max_viscous_number * h * h / kinematic_viscosity : HUGE_VAL;
}

CentrelineProfiles centreline_profiles(const Simulation& sim) {
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const double t = f.time;
  const FluidBoundaries& bc = sim.boundaries();
  CentrelineProfiles p;
  // Vertical line x = mid: cells i0, i0 + 1 around it, weight w on i0 + 1.
  const double x_mid = g.origin_x + 0.5 * g.length_x, y_mid = g.origin_y + 0.5 * g.length_y;
  const double si = (x_mid - g.origin_x) / g.dx() - 0.5, sj = (y_mid - g.origin_y) / g.dy() - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(si)), 0, g.nx - 2);
  const int j0 = std::clamp(static_cast<int>(std::floor(sj)), 0, g.ny - 2);
  const double wi = si - i0, wj = sj - j0;
  // End points on the sides where the velocity is given (walls, inflows); none at an outflow.
  const double x1 = g.origin_x + g.length_x, y1 = g.origin_y + g.length_y;
  const auto given = [&](Side s) { return bc.kind(g, s) == SideKind::wall || bc.kind(g, s) == SideKind::inflow; };
  if (given(Side::bottom)) { p.y.push_back(g.origin_y); p.u.push_back(bc.velocity_at(g, Side::bottom, x_mid, g.origin_y, t)[0]); }
  for (int j = 0; j < g.ny; ++j) {
    p.y.push_back(g.y_centre(j));
    p.u.push_back((1 - wi) * f.velocity_x(i0, j) + wi * f.velocity_x(i0 + 1, j));
  }
  if (given(Side::top)) { p.y.push_back(y1); p.u.push_back(bc.velocity_at(g, Side::top, x_mid, y1, t)[0]); }
  if (given(Side::left)) { p.x.push_back(g.origin_x); p.v.push_back(bc.velocity_at(g, Side::left, g.origin_x, y_mid, t)[1]); }
  for (int i = 0; i < g.nx; ++i) {
    p.x.push_back(g.x_centre(i));
    p.v.push_back((1 - wj) * f.velocity_y(i, j0) + wj * f.velocity_y(i, j0 + 1));
  }
  if (given(Side::right)) { p.x.push_back(x1); p.v.push_back(bc.velocity_at(g, Side::right, x1, y_mid, t)[1]); }
  return p;
}

}  // namespace ibms
