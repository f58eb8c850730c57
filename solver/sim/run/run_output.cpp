// What a run writes (run_output.hpp): series rows, snapshots, profiles, tables, timing, progress.
#include "sim/run/run_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "fluid/boundary_conditions.hpp"
#include "fluid/operators.hpp"
#include "io/csv_table.hpp"
#include "sim/run/centreline_profiles.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/run/simulation_checkpoint.hpp"
#include "solid/body_geometry.hpp"
#include "solid/spring_forces.hpp"

#ifndef IBMS_VERSION
#define IBMS_VERSION "unknown"
#endif

namespace ibms {

const char* ibms_version() { return IBMS_VERSION; }

void BodyTable::append(double time, const std::vector<SeriesValue>& values) {
  if (headers.empty()) {
    headers.push_back("time [time]");
    for (const SeriesValue& v : values) headers.push_back(v.name + " [" + v.units + "]");
    columns.resize(headers.size());
  }
  columns[0].push_back(time);
  for (std::size_t k = 0; k < values.size(); ++k) columns[k + 1].push_back(values[k].value);
}

namespace {

std::vector<SeriesValue> body_series(const Simulation& sim, const ControlVolumeMonitor& control_volumes);
std::vector<SeriesValue> probe_series(const Simulation& sim);

void write_body_table(const std::string& h5_path, const Simulation& sim, const BodyTable& table) {
  if (table.headers.empty()) return;
  const std::filesystem::path base = std::filesystem::path(h5_path).replace_extension("");
  write_csv(base.string() + "_bodies.csv",
            {"ibms body series: per body centroid of the rim polygon, centre-of-mass velocity, (rigid and",
             "prescribed: angle, angular velocity), hydrodynamic force and torque about the centre, the same force by a",
             "control-volume momentum balance (drag and lift coefficients of both when the body has a reference_speed),",
             "the slip left at the markers, diameter D(t), rim-polygon area, spring energy,",
             "sub-steps of the step; output.probes: pressure and velocity at each probe point; source scene: " +
                 sim.scene().source_file},
            table.headers, table.columns);
}

void write_series(OutputFile& out, const Simulation& sim, const ControlVolumeMonitor& control_volumes, double dt,
                  double cfl, double steady_residual, BodyTable& bodies) {
  const FluidState& f = sim.fluid();
  const ProjectionStats& ps = sim.stats().last_projection;
  std::vector<SeriesValue> row({
      {"time", "time", f.time},
      {"dt", "time", dt},
      {"step", "-", static_cast<double>(f.step)},
      {"kinetic_energy", "mass length^2/time^2 per unit depth",
       sim.fluid_density() * sim.fluid_solver().kinetic_energy(f)},
      {"max_divergence", "1/time", ps.max_divergence_after},
      {"max_divergence_before_projection", "1/time", ps.max_divergence_before},
      {"poisson_removed_mean", "1/time^2", ps.removed_mean},
      {"cfl", "-", cfl},
      {"steady_residual", "1/time", steady_residual},
  });
  if (sim.boundaries().has_open_side(sim.grid())) {
    // Volume fluxes through the open sides: what comes in, and the net (0 to round-off).
    const Grid& g = sim.grid();
    double in = 0.0;
    for (Side s : {Side::left, Side::right, Side::bottom, Side::top})
      if (sim.boundaries().kind(g, s) == SideKind::inflow) in += side_inflow(g, s, f.velocity_face_x, f.velocity_face_y);
    row.push_back({"inflow_flux", "length^2/time", in});
    row.push_back({"net_boundary_flux", "length^2/time", net_inflow(g, f.velocity_face_x, f.velocity_face_y)});
  }
  std::vector<SeriesValue> body_row = body_series(sim, control_volumes);
  for (const SeriesValue& v : probe_series(sim)) body_row.push_back(v);
  if (!body_row.empty()) bodies.append(f.time, body_row);
  for (const SeriesValue& v : body_row) row.push_back(v);
  out.append_series(row);
}

std::string body_name(std::size_t b) { return fmt::format("body_{:03d}", b); }

// output.probes: p (dynamic), u, v at each point, bilinear in the four nearest cell centres; a
// point within half a cell of a side takes the nearest centre line there (no extrapolation).
std::vector<SeriesValue> probe_series(const Simulation& sim) {
  std::vector<SeriesValue> row;
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const auto& probes = sim.scene().output.probes;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const auto axis = [](double x, double origin, double h, int n) {
      const double s = std::clamp((x - origin) / h - 0.5, 0.0, static_cast<double>(n - 1));
      const int i0 = std::min(static_cast<int>(std::floor(s)), n - 2);
      return std::pair<int, double>{i0, s - i0};
    };
    const auto [i, wx] = axis(probes[k][0], g.origin_x, g.dx(), g.nx);
    const auto [j, wy] = axis(probes[k][1], g.origin_y, g.dy(), g.ny);
    const auto at = [&, i = i, j = j, wx = wx, wy = wy](const CellField& q) {
      return (1 - wx) * (1 - wy) * q(i, j) + wx * (1 - wy) * q(i + 1, j) + (1 - wx) * wy * q(i, j + 1) +
             wx * wy * q(i + 1, j + 1);
    };
    const std::string name = fmt::format("probe_{:03d}", k);
    row.push_back({name + "/pressure", "mass/(length time^2)", sim.fluid_density() * at(f.pressure)});
    row.push_back({name + "/velocity_x", "length/time", at(f.velocity_x)});
    row.push_back({name + "/velocity_y", "length/time", at(f.velocity_y)});
  }
  return row;
}

// Per-body series: centroid of the rim polygon, centre-of-mass velocity, the forces of the step
// (immersed-boundary reaction and control-volume balance), the slip left at the markers, diameter
// (the swelling law's D), rim-polygon area, elastic energy and the sub-steps of the latest step.
std::vector<SeriesValue> body_series(const Simulation& sim, const ControlVolumeMonitor& control_volumes) {
  std::vector<SeriesValue> row;
  if (!sim.has_bodies()) return row;
  // Coupling diagnostics of the step: largest fluid velocity component and the Poisson removed
  // mean (compatibility, docs/method.md §1.8), with each body's largest forcing target speed.
  row.push_back({"max_fluid_velocity_component", "length/time", sim.stats().last_projection.max_velocity});
  row.push_back({"poisson_removed_mean_bodies", "1/time^2", sim.stats().last_projection.removed_mean});
  if (sim.coupling().counts_products())
    row.push_back({"coupling_iterations", "-", static_cast<double>(sim.stats().last_coupling_iterations)});
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    const std::string name = body_name(b);
    const auto c = centroid(body);
    const Vec2 velocity = body_velocity(sim, b);  // centre-of-mass velocity (rigid motion: V)
    row.push_back({name + "/centroid_x", "length", c[0]});
    row.push_back({name + "/centroid_y", "length", c[1]});
    row.push_back({name + "/velocity_x", "length/time", velocity[0]});
    row.push_back({name + "/velocity_y", "length/time", velocity[1]});
    if (body.kind != BodyKind::mass_spring) {
      row.push_back({name + "/angle", "rad", sim.rigid()[b].state.angle});
      row.push_back({name + "/angular_velocity", "1/time", sim.rigid()[b].state.angular_velocity});
    }
    // What the fluid does to the body in the step just taken (BodyCoupling::hydrodynamic_force).
    const BodyCoupling& coupling = sim.markers()[b];
    row.push_back({name + "/force_x", "force per unit depth", coupling.hydrodynamic_force[0]});
    row.push_back({name + "/force_y", "force per unit depth", coupling.hydrodynamic_force[1]});
    row.push_back({name + "/torque", "force length per unit depth", coupling.hydrodynamic_torque});
    // The same force from the fluid alone: the control-volume balance of the step (sim/checks/control_volume_monitor.hpp).
    const BodyControlVolume& cv = control_volumes.body(b);
    row.push_back({name + "/cv_force_x", "force per unit depth", cv.force[0]});
    row.push_back({name + "/cv_force_y", "force per unit depth", cv.force[1]});
    row.push_back({name + "/cv_clearance", "length", cv.clearance});
    const BodySpec& spec = sim.scene().bodies[b];
    if (spec.reference_speed > 0.0) {
      // C = F / (rho_f U_ref^2 L_ref / 2); drag along +x, lift along +y.
      const double length = spec.reference_length > 0.0 ? spec.reference_length : spec.diameter;
      const double scale = 0.5 * sim.fluid_density() * spec.reference_speed * spec.reference_speed * length;
      row.push_back({name + "/drag_coefficient", "-", coupling.hydrodynamic_force[0] / scale});
      row.push_back({name + "/lift_coefficient", "-", coupling.hydrodynamic_force[1] / scale});
      row.push_back({name + "/cv_drag_coefficient", "-", cv.force[0] / scale});
      row.push_back({name + "/cv_lift_coefficient", "-", cv.force[1] / scale});
    }
    // The no-slip error left at the end of the step, max and RMS over the markers of
    // |J u^{n+1} - U_target| / U_ref (BodyCoupling::slip_max, slip_rms).
    row.push_back({name + "/slip_max", "-", coupling.slip_max});
    row.push_back({name + "/slip_rms", "-", coupling.slip_rms});
    // The same of the face velocities, |J_f U_f^{n+1} - U_target| / U_ref: what "no_slip" holds
    // under ibm.constrained_velocity = "faces".
    row.push_back({name + "/face_slip_max", "-", coupling.face_slip_max});
    row.push_back({name + "/face_slip_rms", "-", coupling.face_slip_rms});
    row.push_back({name + "/diameter", "length", body.diameter});
    row.push_back({name + "/area", "length^2 per unit depth", polygon_area(body)});
    row.push_back({name + "/deformation", "-", deformation_parameter(body)});
    row.push_back({name + "/spring_energy", "energy per unit depth", spring_energy(body, body.length_scale())});
    row.push_back({name + "/n_substeps", "-", static_cast<double>(sim.substep_planner().body_substeps(b))});
    double max_target = 0.0;
    for (const auto& u : sim.markers()[b].target_velocity) max_target = std::max(max_target, std::hypot(u[0], u[1]));
    row.push_back({name + "/max_target_speed", "length/time", max_target});
  }
  {  // separation: from the walls always, between bodies when there are several
    const Grid& g = sim.grid();
    const BodySeparation sep = body_separation(sim.bodies(), {g.origin_x, g.origin_y},
                                               {g.origin_x + g.length_x, g.origin_y + g.length_y},
                                               {g.periodic_x, g.periodic_y});
    if (!(g.periodic_x && g.periodic_y)) row.push_back({"bodies/min_wall_distance", "length", sep.min_wall_distance});
    if (sim.bodies().size() > 1) {
      row.push_back({"bodies/min_rim_distance", "length", sep.min_rim_distance});
      row.push_back({"bodies/n_points_inside_others", "-", static_cast<double>(sep.n_points_inside_others)});
      row.push_back({"bodies/n_edge_crossings", "-", static_cast<double>(sep.n_edge_crossings)});
    }
  }
  if (sim.has_contacts()) {  // merged over the sub-steps of the step
    const ContactStats& cs = sim.stats().last_contact_stats;
    row.push_back({"contact/n_active_pairs", "-", static_cast<double>(cs.n_active_pairs)});
    row.push_back({"contact/n_wall_contacts", "-", static_cast<double>(cs.n_wall_contacts)});
    row.push_back({"contact/max_overlap", "length", cs.max_overlap});
    if (sim.contact_model().law == ContactLawKind::collision_time)
      row.push_back({"contact/collision_time", "time", sim.contact_model().collision_time});
  }
  return row;
}

void write_snapshot(OutputFile& out, Simulation& sim) {
  const Grid& g = sim.grid();
  FluidState& f = sim.fluid();
  const std::size_t n = g.n_cells();
  std::vector<double> u(n), v(n), p(n), w(n);
  fill_velocity_ghosts(g, sim.boundaries(), f.time, f.velocity_x, f.velocity_y);
  CellField vort(g);
  vorticity(g, f.velocity_x, f.velocity_y, vort);
  f.velocity_x.copy_interior_to(u.data());
  f.velocity_y.copy_interior_to(v.data());
  f.pressure.copy_interior_to(p.data());
  for (double& x : p) x *= sim.fluid_density();  // kinematic -> dynamic pressure
  vort.copy_interior_to(w.data());
  const std::vector<std::size_t> dims{static_cast<std::size_t>(g.ny), static_cast<std::size_t>(g.nx)};
  std::vector<SnapshotArray> arrays{{"u", "length/time", dims, u.data()},
                                    {"v", "length/time", dims, v.data()},
                                    {"p", "mass/(length time^2)", dims, p.data()},
                                    {"vorticity", "1/time", dims, w.data()}};
  // Surface (rim) points of every body: body_NNN/x, y, u, v.
  std::vector<std::vector<double>> body_data;
  body_data.reserve(4 * sim.bodies().size());
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    const std::size_t n_rim = static_cast<std::size_t>(body.n_surface);
    for (int q = 0; q < 4; ++q) {
      std::vector<double>& values = body_data.emplace_back(n_rim);
      for (std::size_t l = 0; l < n_rim; ++l) values[l] = q < 2 ? body.position[l][q] : body.velocity[l][q - 2];
      static const char* names[4] = {"x", "y", "u", "v"};
      arrays.push_back({body_name(b) + "/" + names[q], q < 2 ? "length" : "length/time", {n_rim}, values.data()});
    }
  }
  out.write_snapshot(f.step, f.time, arrays);
}

void write_profiles(const std::string& h5_path, const Simulation& sim) {
  const CentrelineProfiles prof = centreline_profiles(sim);
  const std::filesystem::path base = std::filesystem::path(h5_path).replace_extension("");
  const std::string t = fmt::format("t = {:.10g}, step {}", sim.fluid().time, sim.fluid().step);
  write_csv(base.string() + "_centreline_u.csv",
            {"ibms centre-line profile: u along the vertical line x = mid-width", t,
             "source scene: " + sim.scene().source_file},
            {"y [length]", "u [length/time]"}, {prof.y, prof.u});
  write_csv(base.string() + "_centreline_v.csv",
            {"ibms centre-line profile: v along the horizontal line y = mid-height", t,
             "source scene: " + sim.scene().source_file},
            {"x [length]", "v [length/time]"}, {prof.x, prof.v});
}

// /timing: wall seconds and calls per pipeline stage (contacts run inside bodies), and the whole
// run's wall time with its step count as `run` (calls = steps).
void write_stage_timing(OutputFile& out, const Simulation& sim, double wall_seconds) {
  std::vector<OutputFile::TimingEntry> entries;
  for (int s = 0; s < static_cast<int>(Stage::count); ++s)
    entries.push_back({std::string(stage_names[s]), sim.timers().seconds(static_cast<Stage>(s)),
                       sim.timers().calls(static_cast<Stage>(s))});
  entries.push_back({"run", wall_seconds, sim.fluid().step});
  if (sim.has_bodies()) {  // the solid's work: seconds of the bodies stage, calls = sub-step totals
    entries.push_back({"solid_substeps", sim.timers().seconds(Stage::bodies), sim.stats().total_substeps});
    entries.push_back({"body_substeps", sim.timers().seconds(Stage::bodies), sim.stats().total_body_substeps});
  }
  out.write_timing(entries);
}

std::string format_seconds(double s) {
  if (!std::isfinite(s)) return "?";
  if (s < 120) return fmt::format("{:.0f} s", s);
  if (s < 7200) return fmt::format("{:.1f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}

}  // namespace

RunOutput::RunOutput(const Simulation& sim, const std::string& h5_path)
    : h5_path_(h5_path),
      file_(h5_path, sim.scene().resolved_text, sim.grid(), ibms_version(), ibms_git_commit()) {}

void RunOutput::snapshot(Simulation& sim) {
  auto t = sim.timers().time(Stage::output);
  write_snapshot(file_, sim);
}

void RunOutput::end_step(Simulation& sim, const ControlVolumeMonitor& control_volumes, double dt, double cfl,
                         double steady_residual) {
  last_dt_ = dt;
  last_cfl_ = cfl;
  last_residual_ = steady_residual;
  if (sim.fluid().step % sim.scene().output.series_every != 0) return;
  auto t = sim.timers().time(Stage::output);
  write_series(file_, sim, control_volumes, dt, cfl, steady_residual, body_table_);
  series_step_ = sim.fluid().step;
}

void RunOutput::checkpoint(Simulation& sim, double next_snapshot) {
  auto t = sim.timers().time(Stage::output);
  write_simulation_checkpoint(file_, sim, next_snapshot);
}

void RunOutput::finish(Simulation& sim, const ControlVolumeMonitor& control_volumes, double next_snapshot) {
  auto t = sim.timers().time(Stage::output);
  if (last_dt_ > 0.0 && series_step_ != sim.fluid().step)
    write_series(file_, sim, control_volumes, last_dt_, last_cfl_, last_residual_, body_table_);
  // The checkpoint first: write_snapshot refills the velocity ghost layers.
  write_simulation_checkpoint(file_, sim, next_snapshot);
  write_snapshot(file_, sim);
  if (sim.scene().output.centreline_profiles) write_profiles(h5_path_, sim);
  write_body_table(h5_path_, sim, body_table_);
}

void RunOutput::write_timing(const Simulation& sim, double wall_seconds) { write_stage_timing(file_, sim, wall_seconds); }

void RunOutput::after_blow_up(const Simulation& sim, double wall_seconds) {
  write_body_table(h5_path_, sim, body_table_);
  write_stage_timing(file_, sim, wall_seconds);
  file_.flush();
}

std::string stage_timing_table(const Simulation& sim, double wall_seconds) {
  std::string text = fmt::format("{:<14} {:>10} {:>7} {:>10}\n", "stage", "seconds", "share", "calls");
  for (int s = 0; s < static_cast<int>(Stage::count); ++s) {
    const double seconds = sim.timers().seconds(static_cast<Stage>(s));
    const long calls = sim.timers().calls(static_cast<Stage>(s));
    if (calls == 0) continue;
    text += fmt::format("{:<14} {:>10.3f} {:>6.1f}% {:>10}{}\n", stage_names[s], seconds,
                        wall_seconds > 0 ? 100.0 * seconds / wall_seconds : 0.0, calls,
                        static_cast<Stage>(s) == Stage::contacts ? "  (inside bodies)" : "");
  }
  text += fmt::format("{:<14} {:>10.3f} {:>6.1f}% {:>10}  (steps)\n", "run", wall_seconds, 100.0, sim.fluid().step);
  if (sim.has_bodies())
    text += fmt::format("solid sub-steps: {} (most of any body group, summed over steps), {} summed over bodies\n",
                        sim.stats().total_substeps, sim.stats().total_body_substeps);
  return text;
}

void print_progress(const Simulation& sim, double elapsed_seconds, double dt, double steady_residual) {
  const FluidState& f = sim.fluid();
  const RunSpec& run = sim.scene().run;
  const double rate = f.step / elapsed_seconds, t_rate = f.time / elapsed_seconds;
  std::fprintf(stderr, "step %ld  t = %.6g / %.6g  dt = %.3g  %.0f steps/s  ETA %s%s\n", f.step, f.time,
               run.end_time, dt, rate, format_seconds((run.end_time - f.time) / t_rate).c_str(),
               run.steady_tolerance > 0 ? fmt::format("  steady residual {:.2e}", steady_residual).c_str() : "");
}

}  // namespace ibms
