// What a run writes (run_output.hpp): series rows, snapshots, profiles, tables, timing, progress.
#include "sim/run/run_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

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

void BodyTable::append(double time, const std::vector<SeriesValue>& leading, const std::vector<SeriesColumns>& per_body,
                       const std::vector<char>& present, const std::vector<SeriesValue>& trailing) {
  const std::size_t n_bodies = per_body.empty() ? 0 : per_body[0].values.size();
  if (headers.empty()) {
    headers.push_back("time [time]");
    for (const SeriesValue& v : leading) headers.push_back(v.name + " [" + v.units + "]");
    for (std::size_t b = 0; b < n_bodies; ++b)
      for (std::size_t q = 0; q < per_body.size(); ++q)
        if (present[b * per_body.size() + q])
          headers.push_back(fmt::format("body_{:03d}/{} [{}]", b, per_body[q].name, per_body[q].units));
    for (const SeriesValue& v : trailing) headers.push_back(v.name + " [" + v.units + "]");
    columns.resize(headers.size());
  }
  std::size_t k = 0;
  columns[k++].push_back(time);
  for (const SeriesValue& v : leading) columns[k++].push_back(v.value);
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (std::size_t q = 0; q < per_body.size(); ++q)
      if (present[b * per_body.size() + q]) columns[k++].push_back(per_body[q].values[b]);
  for (const SeriesValue& v : trailing) columns[k++].push_back(v.value);
}

namespace {

struct BodyRow {
  std::vector<SeriesValue> leading, trailing;  // scalars before and after the bodies' columns
};
BodyRow body_series(const Simulation& sim, const ControlVolumeMonitor& control_volumes,
                    std::vector<SeriesColumns>& per_body, std::vector<char>& present);
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
                  double cfl, double steady_residual, BodyTable& bodies, std::vector<SeriesColumns>& per_body,
                  std::vector<char>& present) {
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
  BodyRow body_row = body_series(sim, control_volumes, per_body, present);
  for (const SeriesValue& v : probe_series(sim)) body_row.trailing.push_back(v);
  if (!body_row.leading.empty() || !per_body.empty() || !body_row.trailing.empty())
    bodies.append(f.time, body_row.leading, per_body, present, body_row.trailing);
  for (const SeriesValue& v : body_row.leading) row.push_back(v);
  for (const SeriesValue& v : body_row.trailing) row.push_back(v);
  out.append_series(row, per_body);
}


// The quantities of every body in a series row, in /series/per_body/<name> and the body table.
struct BodyQuantity {
  const char* name;
  const char* units;
};
constexpr BodyQuantity body_quantities[] = {
    {"centroid_x", "length"},
    {"centroid_y", "length"},
    {"velocity_x", "length/time"},
    {"velocity_y", "length/time"},
    {"angle", "rad"},               // rigid and prescribed bodies
    {"angular_velocity", "1/time"},  // rigid and prescribed bodies
    {"force_x", "force per unit depth"},
    {"force_y", "force per unit depth"},
    {"torque", "force length per unit depth"},
    {"cv_force_x", "force per unit depth"},
    {"cv_force_y", "force per unit depth"},
    {"cv_clearance", "length"},
    {"drag_coefficient", "-"},  // the four coefficients: bodies with a reference_speed
    {"lift_coefficient", "-"},
    {"cv_drag_coefficient", "-"},
    {"cv_lift_coefficient", "-"},
    {"slip_max", "-"},
    {"slip_rms", "-"},
    {"face_slip_max", "-"},
    {"face_slip_rms", "-"},
    {"diameter", "length"},
    {"area", "length^2 per unit depth"},
    {"deformation", "-"},
    {"spring_energy", "energy per unit depth"},
    {"n_substeps", "-"},
    {"max_target_speed", "length/time"},
};
constexpr std::size_t n_body_quantities = sizeof body_quantities / sizeof body_quantities[0];

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
// (the swelling law's D), rim-polygon area, elastic energy and the sub-steps of the latest step;
// the scalars of the coupling, the bodies' separation and the contacts around them.
BodyRow body_series(const Simulation& sim, const ControlVolumeMonitor& control_volumes,
                    std::vector<SeriesColumns>& per_body, std::vector<char>& present) {
  BodyRow row;
  if (!sim.has_bodies()) return row;
  // Coupling diagnostics of the step: largest fluid velocity component and the Poisson removed
  // mean (compatibility, docs/method.md §1.8), with each body's largest forcing target speed.
  row.leading.push_back({"max_fluid_velocity_component", "length/time", sim.stats().last_projection.max_velocity});
  row.leading.push_back({"poisson_removed_mean_bodies", "1/time^2", sim.stats().last_projection.removed_mean});
  if (sim.coupling().counts_products())
    row.leading.push_back({"coupling_iterations", "-", static_cast<double>(sim.stats().last_coupling_iterations)});
  const std::size_t n_bodies = sim.bodies().size();
  if (per_body.empty()) {  // the first row: names, units, and which bodies have which quantity
    for (const BodyQuantity& q : body_quantities) per_body.push_back({q.name, q.units, std::vector<double>(n_bodies)});
    present.assign(n_bodies * n_body_quantities, 1);
    for (std::size_t b = 0; b < n_bodies; ++b) {
      const bool turns = sim.bodies()[b].kind != BodyKind::mass_spring;
      const bool coefficients = sim.scene().bodies[b].reference_speed > 0.0;
      for (std::size_t q = 0; q < n_body_quantities; ++q) {
        const std::string name = body_quantities[q].name;
        if ((name == "angle" || name == "angular_velocity") && !turns) present[b * n_body_quantities + q] = 0;
        if (name.find("coefficient") != std::string::npos && !coefficients) present[b * n_body_quantities + q] = 0;
      }
    }
  }
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t b = 0; b < n_bodies; ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    const auto c = centroid(body);
    const Vec2 velocity = body_velocity(sim, b);  // centre-of-mass velocity (rigid motion: V)
    const bool turns = body.kind != BodyKind::mass_spring;
    // What the fluid does to the body in the step just taken (BodyCoupling::hydrodynamic_force), and
    // the same force from the fluid alone: the control-volume balance of the step
    // (sim/checks/control_volume_monitor.hpp).
    const BodyCoupling& coupling = sim.markers()[b];
    const BodyControlVolume& cv = control_volumes.body(b);
    const BodySpec& spec = sim.scene().bodies[b];
    // C = F / (rho_f U_ref^2 L_ref / 2); drag along +x, lift along +y.
    const double length = spec.reference_length > 0.0 ? spec.reference_length : spec.diameter;
    const double scale = spec.reference_speed > 0.0
                             ? 0.5 * sim.fluid_density() * spec.reference_speed * spec.reference_speed * length
                             : none;
    double max_target = 0.0;
    for (const auto& u : coupling.target_velocity) max_target = std::max(max_target, std::hypot(u[0], u[1]));
    // The no-slip error left at the end of the step, max and RMS over the markers of
    // |J u^{n+1} - U_target| / U_ref (BodyCoupling::slip_max, slip_rms), and the same of the face
    // velocities, what "no_slip" holds under ibm.constrained_velocity = "faces".
    const double values[n_body_quantities] = {
        c[0], c[1], velocity[0], velocity[1],
        turns ? sim.rigid()[b].state.angle : none, turns ? sim.rigid()[b].state.angular_velocity : none,
        coupling.hydrodynamic_force[0], coupling.hydrodynamic_force[1], coupling.hydrodynamic_torque,
        cv.force[0], cv.force[1], cv.clearance,
        coupling.hydrodynamic_force[0] / scale, coupling.hydrodynamic_force[1] / scale, cv.force[0] / scale,
        cv.force[1] / scale,
        coupling.slip_max, coupling.slip_rms, coupling.face_slip_max, coupling.face_slip_rms,
        body.diameter, polygon_area(body), deformation_parameter(body), spring_energy(body, body.length_scale()),
        static_cast<double>(sim.substep_planner().body_substeps(b)), max_target};
    for (std::size_t q = 0; q < n_body_quantities; ++q) per_body[q].values[b] = values[q];
  }
  {  // separation: from the walls always, between bodies when there are several
    const Grid& g = sim.grid();
    const BodySeparation sep = body_separation(sim.bodies(), {g.origin_x, g.origin_y},
                                               {g.origin_x + g.length_x, g.origin_y + g.length_y},
                                               {g.periodic_x, g.periodic_y});
    if (!(g.periodic_x && g.periodic_y)) row.trailing.push_back({"bodies/min_wall_distance", "length", sep.min_wall_distance});
    if (sim.scene().has_kind(BodySpec::Kind::mass_spring))
      row.trailing.push_back({"bodies/n_self_crossings", "-", static_cast<double>(sep.n_self_crossings)});
    if (n_bodies > 1) {
      row.trailing.push_back({"bodies/min_rim_distance", "length", sep.min_rim_distance});
      row.trailing.push_back({"bodies/n_points_inside_others", "-", static_cast<double>(sep.n_points_inside_others)});
      row.trailing.push_back({"bodies/n_edge_crossings", "-", static_cast<double>(sep.n_edge_crossings)});
    }
  }
  if (sim.has_contacts()) {  // merged over the sub-steps of the step
    const ContactStats& cs = sim.stats().last_contact_stats;
    row.trailing.push_back({"contact/n_active_pairs", "-", static_cast<double>(cs.n_active_pairs)});
    row.trailing.push_back({"contact/n_wall_contacts", "-", static_cast<double>(cs.n_wall_contacts)});
    row.trailing.push_back({"contact/max_overlap", "length", cs.max_overlap});
    if (sim.contact_model().law == ContactLawKind::collision_time)
      row.trailing.push_back({"contact/collision_time", "time", sim.contact_model().collision_time});
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
  // Surface (rim) points of all bodies, body after body: bodies/x, y, u, v.
  std::vector<std::size_t> body_points;
  std::size_t n_points = 0;
  for (const MassSpringBody& body : sim.bodies()) {
    body_points.push_back(static_cast<std::size_t>(body.n_surface));
    n_points += static_cast<std::size_t>(body.n_surface);
  }
  std::vector<std::vector<double>> rims(4);
  if (n_points > 0) {
    for (std::vector<double>& values : rims) values.reserve(n_points);
    for (const MassSpringBody& body : sim.bodies())
      for (int l = 0; l < body.n_surface; ++l)
        for (int q = 0; q < 4; ++q) rims[q].push_back(q < 2 ? body.position[l][q] : body.velocity[l][q - 2]);
    static const char* names[4] = {"bodies/x", "bodies/y", "bodies/u", "bodies/v"};
    for (int q = 0; q < 4; ++q) arrays.push_back({names[q], q < 2 ? "length" : "length/time", {n_points}, rims[q].data()});
  }
  out.write_snapshot(f.step, f.time, arrays, n_points > 0 ? body_points : std::vector<std::size_t>{});
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
  sim.coupling().measure_slip_at_end(sim.fluid_solver(), sim.fluid(), sim.markers());
  write_series(file_, sim, control_volumes, dt, cfl, steady_residual, body_table_, per_body_, present_);
  series_step_ = sim.fluid().step;
}

void RunOutput::checkpoint(Simulation& sim, double next_snapshot) {
  auto t = sim.timers().time(Stage::output);
  write_simulation_checkpoint(file_, sim, next_snapshot);
}

void RunOutput::finish(Simulation& sim, const ControlVolumeMonitor& control_volumes, double next_snapshot) {
  auto t = sim.timers().time(Stage::output);
  if (last_dt_ > 0.0 && series_step_ != sim.fluid().step) {
    sim.coupling().measure_slip_at_end(sim.fluid_solver(), sim.fluid(), sim.markers());
    write_series(file_, sim, control_volumes, last_dt_, last_cfl_, last_residual_, body_table_, per_body_, present_);
  }
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
