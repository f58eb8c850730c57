// Run loop, output and progress (docs/design.md §3 stage 6, §5).
#include "sim/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/errors.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/operators.hpp"
#include "fluid/threads.hpp"
#include "io/csv_table.hpp"
#include "io/checkpoint.hpp"
#include "io/output_file.hpp"
#include "sim/control_volume_monitor.hpp"
#include "sim/diagnostics.hpp"
#include "sim/fluid_guard.hpp"
#include "sim/simulation_checkpoint.hpp"
#include "solid/body_geometry.hpp"
#include "solid/spring_forces.hpp"

#ifndef IBMS_VERSION
#define IBMS_VERSION "unknown"
#endif

namespace ibms {
namespace {

std::vector<SeriesValue> body_series(const Simulation& sim, const ControlVolumeMonitor& control_volumes);
std::vector<SeriesValue> probe_series(const Simulation& sim);

// Body series kept in memory for <stem>_bodies.csv (one column per series, time first).
struct BodyTable {
  std::vector<std::string> headers;
  std::vector<std::vector<double>> columns;
  void append(double time, const std::vector<SeriesValue>& values) {
    if (headers.empty()) {
      headers.push_back("time [time]");
      for (const SeriesValue& v : values) headers.push_back(v.name + " [" + v.units + "]");
      columns.resize(headers.size());
    }
    columns[0].push_back(time);
    for (std::size_t k = 0; k < values.size(); ++k) columns[k + 1].push_back(values[k].value);
  }
};

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
  const ProjectionStats& ps = sim.last_projection;
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
  row.push_back({"max_fluid_velocity_component", "length/time", sim.last_projection.max_velocity});
  row.push_back({"poisson_removed_mean_bodies", "1/time^2", sim.last_projection.removed_mean});
  if (sim.enforces_no_slip())
    row.push_back({"coupling_iterations", "-", static_cast<double>(sim.last_coupling_iterations)});
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
    const BodyCoupling& coupling = sim.coupling()[b];
    row.push_back({name + "/force_x", "force per unit depth", coupling.hydrodynamic_force[0]});
    row.push_back({name + "/force_y", "force per unit depth", coupling.hydrodynamic_force[1]});
    row.push_back({name + "/torque", "force length per unit depth", coupling.hydrodynamic_torque});
    // The same force from the fluid alone: the control-volume balance of the step (sim/control_volume_monitor.hpp).
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
    row.push_back({name + "/n_substeps", "-", static_cast<double>(sim.body_substeps(b))});
    double max_target = 0.0;
    for (const auto& u : sim.coupling()[b].target_velocity) max_target = std::max(max_target, std::hypot(u[0], u[1]));
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
    const ContactStats& cs = sim.last_contact_stats;
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
void write_timing(OutputFile& out, const Simulation& sim, double wall_seconds) {
  std::vector<OutputFile::TimingEntry> entries;
  for (int s = 0; s < static_cast<int>(Stage::count); ++s)
    entries.push_back({std::string(stage_names[s]), sim.timers().seconds(static_cast<Stage>(s)),
                       sim.timers().calls(static_cast<Stage>(s))});
  entries.push_back({"run", wall_seconds, sim.fluid().step});
  if (sim.has_bodies()) {  // the solid's work: seconds of the bodies stage, calls = sub-step totals
    entries.push_back({"solid_substeps", sim.timers().seconds(Stage::bodies), sim.total_substeps});
    entries.push_back({"body_substeps", sim.timers().seconds(Stage::bodies), sim.total_body_substeps});
  }
  out.write_timing(entries);
}

}  // namespace

const char* ibms_version() { return IBMS_VERSION; }

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
                        sim.total_substeps, sim.total_body_substeps);
  return text;
}

namespace {

std::string format_seconds(double s) {
  if (!std::isfinite(s)) return "?";
  if (s < 120) return fmt::format("{:.0f} s", s);
  if (s < 7200) return fmt::format("{:.1f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}

}  // namespace

RunSummary run_simulation(Simulation& sim, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const Scene& scene = sim.scene();
  const RunSpec& run = scene.run;
  RunSummary summary;
  summary.output_path = options.output_path.empty() ? scene.output.file : options.output_path;
  double next_snapshot = scene.output.snapshot_interval > 0 ? sim.fluid().time : HUGE_VAL;
  if (!options.restart_file.empty()) {  // before the output file exists: a bad restart writes nothing
    std::error_code error;
    if (std::filesystem::equivalent(options.restart_file, summary.output_path, error))
      throw InputError(options.restart_file + ": --restart: the output file would overwrite the checkpoint "
                       "being restarted from; give another output file with -o");
    next_snapshot = restore_simulation(read_checkpoint(options.restart_file), options.restart_file, sim);
  } else {
    start_fluid_guard(sim);  // from the field the run starts with (one set from C++ counts as initial)
  }
  OutputFile out(summary.output_path, scene.resolved_text, sim.grid(), ibms_version(), ibms_git_commit());

  const auto start = clock::now();
  auto last_progress = start;
  const bool progress = scene.output.progress && !options.quiet;
  FluidState& f = sim.fluid();
  BodyTable body_table;
  ControlVolumeMonitor control_volumes(sim);  // after the restore: it starts from the restored fields
  if (sim.has_bodies()) control_volumes.begin_step(sim);
  VelocityScan scan = scan_velocity(sim.grid(), f);
  const int full_count = thread_count();
  ThreadGovernor governor(options.govern_threads ? full_count : 1);
  set_loop_threads(governor.active() ? governor.count() : full_count);
  summary.stop_reason = "end_time";
  const double time_tolerance = 1e-12 * std::max(1.0, std::abs(run.end_time));
  // The final step's series row is written even when output.series_every does not divide its step.
  long series_step = -1;
  double last_dt = 0.0, last_cfl = 0.0, last_residual = 0.0;
  try {
    if (!(next_time_step(sim, scan) > 0.0) && f.time < run.end_time)
      throw InputError(scene.source_file + ": run.max_time_step: the adaptive time step has no velocity scale "
                       "(fluid at rest, no moving wall): set run.max_time_step or run.time_step");
    while (f.time < run.end_time - time_tolerance) {
      if (run.max_steps > 0 && f.step >= run.max_steps) { summary.stop_reason = "max_steps"; break; }
      if (options.stop_requested != nullptr && *options.stop_requested != 0) {
        summary.interrupted = true;
        summary.stop_reason = fmt::format("interrupted by signal {}", static_cast<int>(*options.stop_requested));
        break;
      }
      if (f.time >= next_snapshot - time_tolerance) {
        auto t = sim.timers().time(Stage::output);
        write_snapshot(out, sim);
        next_snapshot += scene.output.snapshot_interval;
      }
      const double dt = next_time_step(sim, scan);
      const auto step_start = clock::now();
      advance_one_step(sim, dt);
      {
        auto t = sim.timers().time(Stage::diagnostics);
        scan = scan_velocity(sim.grid(), f);
        check_for_blow_up(sim, dt, scan);
        if (sim.has_bodies()) {  // the control-volume force of the step, and the start of the next one
          control_volumes.end_step(sim, dt);
          control_volumes.begin_step(sim);
        }
      }
      if (governor.active()) {
        set_loop_threads(governor.after_step(std::chrono::duration<double>(clock::now() - step_start).count()));
      }
      const ProjectionStats& ps = sim.last_projection;
      const double steady_residual = ps.max_velocity > 0 ? ps.max_velocity_change / (dt * ps.max_velocity) : 0.0;
      last_dt = dt;
      last_cfl = dt * scan.max_rate;
      last_residual = steady_residual;
      if (f.step % scene.output.series_every == 0) {
        auto t = sim.timers().time(Stage::output);
        write_series(out, sim, control_volumes, dt, last_cfl, steady_residual, body_table);
        series_step = f.step;
      }
      if (scene.output.checkpoint_every > 0 && f.step % scene.output.checkpoint_every == 0) {
        auto t = sim.timers().time(Stage::output);
        write_simulation_checkpoint(out, sim, next_snapshot);
      }
      if (run.steady_tolerance > 0 && steady_residual < run.steady_tolerance) {
        summary.reached_steady_state = true;
        summary.stop_reason = "steady state";
        break;
      }
      const auto now = clock::now();
      if (progress && now - last_progress > std::chrono::seconds(5)) {
        last_progress = now;
        const double elapsed = std::chrono::duration<double>(now - start).count();
        const double rate = f.step / elapsed, t_rate = f.time / elapsed;
        std::fprintf(stderr, "step %ld  t = %.6g / %.6g  dt = %.3g  %.0f steps/s  ETA %s%s\n", f.step, f.time,
                     run.end_time, dt, rate, format_seconds((run.end_time - f.time) / t_rate).c_str(),
                     run.steady_tolerance > 0 ? fmt::format("  steady residual {:.2e}", steady_residual).c_str() : "");
      }
    }
  } catch (const BlowUpError&) {
    set_loop_threads(full_count);
    write_body_table(summary.output_path, sim, body_table);
    write_timing(out, sim, std::chrono::duration<double>(clock::now() - start).count());
    out.flush();  // everything written so far stays readable
    throw;
  }
  {
    auto t = sim.timers().time(Stage::output);
    if (last_dt > 0.0 && series_step != f.step) write_series(out, sim, control_volumes, last_dt, last_cfl, last_residual, body_table);
    // The checkpoint first: write_snapshot refills the velocity ghost layers.
    write_simulation_checkpoint(out, sim, next_snapshot);
    write_snapshot(out, sim);
    if (scene.output.centreline_profiles) write_profiles(summary.output_path, sim);
    write_body_table(summary.output_path, sim, body_table);
  }
  write_timing(out, sim, std::chrono::duration<double>(clock::now() - start).count());
  summary.steps = f.step;
  summary.time = f.time;
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.steps_at_one_thread = governor.steps_at_one();
  set_loop_threads(full_count);
  return summary;
}

}  // namespace ibms
