// The fluid's energy budget and speed bound (docs/method.md §7, "The fluid guard"). It reads what
// the step has computed (the velocity scan's energy and largest speed, the markers' forces) and
// walks the cells next to the sides once: no extra sweep of the field.
#include "sim/checks/fluid_guard.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/simulation.hpp"

namespace ibms {

namespace {

// The power side s feeds the fluid. Per face: the viscous stress of the side on the fluid,
// nu (u_b - u_c) / (h_n / 2) (the ghost rule u_g = 2 u_b - u_c), times u_b, and the flux of
// |u_c|^2 / 2 + p_c carried in by the normal face velocity.
double side_power(const Simulation& sim, Side s) {
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const FluidBoundaries& bc = sim.boundaries();
  const SideKind kind = bc.kind(g, s);
  if (kind == SideKind::periodic) return 0.0;
  const double nu = sim.fluid_solver().kinematic_viscosity();
  const bool x_side = s == Side::left || s == Side::right;
  const int n = x_side ? g.ny : g.nx;
  const double h_normal = x_side ? g.dx() : g.dy(), h_along = x_side ? g.dy() : g.dx();
  double power = 0.0;
  for (int k = 0; k < n; ++k) {
    const int i = x_side ? (s == Side::left ? 0 : g.nx - 1) : k;
    const int j = x_side ? k : (s == Side::bottom ? 0 : g.ny - 1);
    const double u = f.velocity_x(i, j), v = f.velocity_y(i, j);
    double inward = 0.0;  // normal face velocity into the box
    switch (s) {
      case Side::left: inward = f.velocity_face_x(0, j); break;
      case Side::right: inward = -f.velocity_face_x(g.nx, j); break;
      case Side::bottom: inward = f.velocity_face_y(i, 0); break;
      case Side::top: inward = -f.velocity_face_y(i, g.ny); break;
    }
    power += inward * (0.5 * (u*u + v*v) + f.pressure(i, j)) * h_along;
    if (kind == SideKind::outflow) continue;
    const double x = x_side ? (s == Side::left ? g.origin_x : g.origin_x + g.length_x) : g.x_centre(i);
    const double y = x_side ? g.y_centre(j) : (s == Side::bottom ? g.origin_y : g.origin_y + g.length_y);
    const auto b = bc.velocity_at(g, s, x, y, f.time);
    power += 2.0 * nu * ((b[0] - u) * b[0] + (b[1] - v) * b[1]) / h_normal * h_along;
  }
  return power;
}

void report_fluid_instability(Simulation& sim, const std::string& what) {
  const FluidState& f = sim.fluid();
  const std::string advice = "; reduce run.cfl or run.time_step (docs/fluid-stability.md)";
  if (sim.scene().run.on_fluid_instability == RunSpec::OnInstability::stop)
    throw BlowUpError(fmt::format("blow-up at step {}, t = {:.6g}: {}{}", f.step, f.time, what, advice));
  if (sim.instability().fluid_guard.warned) return;
  sim.instability().fluid_guard.warned = true;
  std::fprintf(stderr, "ibms: warning at step %ld, t = %.6g: %s%s (run.on_fluid_instability = \"warn\": said once, "
               "the run goes on)\n", f.step, f.time, what.c_str(), advice.c_str());
}

}  // namespace

double boundary_power(const Simulation& sim) {
  double power = 0.0;
  for (Side s : {Side::left, Side::right, Side::bottom, Side::top}) power += side_power(sim, s);
  return power;
}

double body_power(const Simulation& sim) {
  double power = 0.0;
  for (const BodyCoupling& c : sim.markers())
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      power += (c.forcing_sum[l][0] * c.target_velocity[l][0] + c.forcing_sum[l][1] * c.target_velocity[l][1]) *
               c.marker_volume[l];
  return power;
}

void start_fluid_guard(Simulation& sim) {
  const VelocityScan scan = scan_velocity(sim.grid(), sim.fluid());
  FluidGuard& guard = sim.instability().fluid_guard;
  guard.speed_scale = std::max(sim.instability().driving_speed, scan.max_speed);
  guard.initial_energy = scan.kinetic_energy;
  guard.input_work = 0.0;
  guard.boundary_power = boundary_power(sim);
  const double area = sim.grid().length_x * sim.grid().length_y;
  guard.energy_floor = FluidGuard::floor_fraction * 0.5 * guard.speed_scale * guard.speed_scale * area;
  guard.largest_speed_ratio = guard.largest_energy_ratio = 0.0;
}

void account_fluid_input(Simulation& sim, double dt) {
  FluidGuard& guard = sim.instability().fluid_guard;
  const double power = boundary_power(sim);
  // The larger of the powers at both ends of the step: the side work of a flow that speeds up is
  // largest at the start (the wall stress nu (u_b - u_c) / (h/2) falls as u_c nears u_b).
  const double boundary = std::max({0.0, guard.boundary_power, power});
  const double bodies = sim.has_bodies() ? std::max(0.0, body_power(sim)) : 0.0;
  guard.input_work += dt * (boundary + bodies);
  guard.boundary_power = power;
}

void check_fluid_guard(Simulation& sim, const VelocityScan& scan) {
  FluidGuard& guard = sim.instability().fluid_guard;
  const Grid& g = sim.grid();
  const double rho = sim.fluid_density();  // the message speaks the series' units: energy per unit depth
  const double budget = guard.energy_budget();
  guard.largest_speed_ratio = std::max(guard.largest_speed_ratio, scan.max_speed / guard.speed_scale);
  guard.largest_energy_ratio = std::max(guard.largest_energy_ratio, scan.kinetic_energy / budget);
  if (scan.kinetic_energy > budget)
    report_fluid_instability(sim, fmt::format(
        "fluid kinetic energy {:.4g} exceeds its budget {:.4g} = {} E_0 + {} W + floor (E_0 = {:.4g} at the start, "
        "W = {:.4g} the work of the sides and bodies since): the fluid gains energy nothing in the scene supplies",
        rho * scan.kinetic_energy, rho * budget, 1.0 + FluidGuard::initial_margin, 1.0 + FluidGuard::work_margin,
        rho * guard.initial_energy, rho * guard.input_work));
  const double bound = FluidGuard::speed_factor * guard.speed_scale;
  if (scan.max_speed > bound)
    report_fluid_instability(sim, fmt::format(
        "fluid speed {:.4g} in cell ({}, {}) at x = {:.6g}, y = {:.6g} exceeds {} V_f = {:.4g} (V_f = {:.4g} the "
        "scene's speed scale: walls, inflows, bodies, free fall, the initial field)",
        scan.max_speed, scan.speed_i, scan.speed_j, g.x_centre(scan.speed_i), g.y_centre(scan.speed_j),
        FluidGuard::speed_factor, bound, guard.speed_scale));
}

}  // namespace ibms
