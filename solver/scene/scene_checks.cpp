// Cross-section scene checks (scene_checks.hpp). Bodies are checked as their initial disks
// (centre, diameter); the box is [0, length_x] x [0, length_y]. Touching is allowed, overlap not.
#include "scene/scene_checks.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "scene/scene_schema.hpp"

namespace ibms {

namespace {

// The adaptive step aims at run.cfl with the velocity of the step before, so the CFL number it
// reaches exceeds run.cfl a little wherever the flow speeds up; run.max_cfl, the blow-up guard,
// must sit above it or it stops a sound run (the Re 1000 cavity at cfl = 1 would stop
// at step 1174 with "CFL number 1 exceeds run.max_cfl = 1"). A fixed run.time_step does not use run.cfl.
void check_run(const RunSpec& run, const SceneDiagnostics& diagnostics) {
  if (run.time_step > 0.0 || run.cfl < run.max_cfl) return;
  const bool blame_cfl = diagnostics.was_given("run.cfl") || !diagnostics.was_given("run.max_cfl");
  diagnostics.fail(blame_cfl ? "run.cfl" : "run.max_cfl",
                   fmt::format("run.cfl = {} must be below run.max_cfl = {} with the adaptive time step "
                               "(run.time_step = 0): the step aims at run.cfl with the previous velocity, so "
                               "the blow-up guard run.max_cfl would stop a sound run; lower run.cfl or raise "
                               "run.max_cfl (docs/fluid-stability.md)",
                               run.cfl, run.max_cfl));
}

// An inflow or outflow side has no ghost rule for the immersed boundary's kernel (its mirror
// images assume a wall), and a body crossing it would leave the box: a body keeps
// open_side_clearance_cells cells (the widest kernel's support, bkp6) from an open side.
constexpr double open_side_clearance_cells = 3.0;

void check_open_sides(const Scene& scene, const SceneDiagnostics& diagnostics) {
  const DomainSpec& d = scene.domain;
  const struct {
    const char* name;
    const WallSpec& side;
    int axis;
    bool high;
  } sides[] = {{"left", scene.walls.left, 0, false},
               {"right", scene.walls.right, 0, true},
               {"bottom", scene.walls.bottom, 1, false},
               {"top", scene.walls.top, 1, true}};
  for (const auto& side : sides) {
    if (side.side.kind != WallSpec::Kind::inflow && side.side.kind != WallSpec::Kind::outflow) continue;
    const double length = side.axis == 0 ? d.length_x : d.length_y;
    const double h = length / (side.axis == 0 ? d.cells_x : d.cells_y);
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      const BodySpec& body = scene.bodies[b];
      const double rim = side.high ? body.centre[side.axis] + 0.5 * body.diameter
                                   : body.centre[side.axis] - 0.5 * body.diameter;
      const double gap = side.high ? length - rim : rim;
      if (gap < open_side_clearance_cells * h)
        diagnostics.fail(fmt::format("bodies.{}.centre", b),
                         fmt::format("the body's rim is {} from the {} side ({}), closer than {} cells ({}): the "
                                     "immersed boundary needs walls or periodic sides within its kernel's reach",
                                     gap, side.name, scene_schema::name_of(side.side.kind), open_side_clearance_cells,
                                     open_side_clearance_cells * h));
    }
  }
}

// Along one direction: the disk [c - r, c + r] must lie in [0, length] for walls; with periodic
// sides the centre must lie in the box and the disk must not reach around to meet itself.
void check_body_in_box(const BodySpec& body, std::size_t b, int axis, double length, bool periodic,
                       const SceneDiagnostics& diagnostics) {
  const double centre = body.centre[axis];
  const double radius = 0.5 * body.diameter;
  const char* const name = axis == 0 ? "x" : "y";
  if (periodic) {
    if (centre < 0.0 || centre > length) {
      diagnostics.fail(fmt::format("bodies.{}.centre", b),
                       fmt::format("{} = {} must lie in the periodic box [0, {}]", name, centre, length));
    }
    if (body.diameter >= length) {
      diagnostics.fail(fmt::format("bodies.{}.diameter", b),
                       fmt::format("must be smaller than the periodic length {} = {}, got {}",
                                   axis == 0 ? "length_x" : "length_y", length, body.diameter));
    }
  } else if (centre - radius < 0.0 || centre + radius > length) {
    diagnostics.fail(fmt::format("bodies.{}.centre", b),
                     fmt::format("body disk spans {} in [{}, {}], outside the box [0, {}] (walls)",
                                 name, centre - radius, centre + radius, length));
  }
}

// Distance along one direction, the nearest periodic image when periodic.
double separation(double a, double b, double length, bool periodic) {
  double d = std::abs(a - b);
  if (periodic) d = std::min(d, length - std::fmod(d, length));
  return d;
}

void check_bodies(const Scene& scene, const SceneDiagnostics& diagnostics) {
  const DomainSpec& domain = scene.domain;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    check_body_in_box(scene.bodies[b], b, 0, domain.length_x, domain.periodic_x, diagnostics);
    check_body_in_box(scene.bodies[b], b, 1, domain.length_y, domain.periodic_y, diagnostics);
  }
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    for (std::size_t other = 0; other < b; ++other) {
      const BodySpec& neighbour = scene.bodies[other];
      const double dx = separation(body.centre[0], neighbour.centre[0], domain.length_x, domain.periodic_x);
      const double dy = separation(body.centre[1], neighbour.centre[1], domain.length_y, domain.periodic_y);
      const double distance = std::hypot(dx, dy);
      const double contact_distance = 0.5 * (body.diameter + neighbour.diameter);
      // Prescribed bodies may overlap each other, and a body may lie wholly inside a prescribed
      // one (a container such as the outer cylinder of circular Couette flow): neither is moved by
      // the other. Any other overlap is an error.
      constexpr BodySpec::Kind prescribed = BodySpec::Kind::prescribed;
      const bool both_prescribed = body.kind == prescribed && neighbour.kind == prescribed;
      const double r_body = 0.5 * body.diameter, r_neighbour = 0.5 * neighbour.diameter;
      const bool nested = (neighbour.kind == prescribed && distance + r_body < r_neighbour) ||
                          (body.kind == prescribed && distance + r_neighbour < r_body);
      if (distance < contact_distance && !both_prescribed && !nested) {
        diagnostics.fail(fmt::format("bodies.{}.centre", b),
                         fmt::format("body {} overlaps body {}: centre distance {} < sum of radii {}",
                                     b, other, distance, contact_distance));
      }
    }
  }
}

void check_contact(const ContactSpec& contact, const SceneDiagnostics& diagnostics) {
  const bool collision_time = contact.model == ContactSpec::Model::collision_time;
  if (contact.enabled() && contact.cds_radius <= 0.0 && contact.cds_radius_fraction <= 0.0) {
    if (collision_time)
      diagnostics.fail("contact.model", "is \"collision_time\" (contacts on) but neither contact.cds_radius nor "
                                        "contact.cds_radius_fraction is > 0");
    diagnostics.fail("contact.stiffness",
                     fmt::format("is {} (contacts on) but neither contact.cds_radius nor "
                                 "contact.cds_radius_fraction is > 0",
                                 contact.stiffness));
  }
  if (!collision_time) return;
  // The collision-time law sets k per contact (docs/method.md §5.5): a stiffness given beside it
  // would be silently unused.
  if (contact.stiffness > 0.0)
    diagnostics.fail("contact.stiffness",
                     fmt::format("is {} but contact.model = \"collision_time\" chooses the stiffness of each contact "
                                 "from T_c = contact.collision_steps fluid steps; remove it, or use "
                                 "contact.model = \"linear\"", contact.stiffness));
  // The fluid reaction is updated once per fluid step: a contact shorter than one step is never
  // seen by the fluid, and T_c below a step defeats the model (it only gets stiffer and slower).
  if (contact.collision_steps < 1.0)
    diagnostics.fail("contact.collision_steps",
                     fmt::format("is {}; a collision must last at least one fluid step (T_c = collision_steps dt; "
                                 "the published choice is 10)", contact.collision_steps));
}

// The run must not fail after hours because it cannot write; nothing is created here.
void check_output(const OutputSpec& output, const SceneDiagnostics& diagnostics) {
  if (output.file.empty()) diagnostics.fail("output.file", "must not be empty");
  if (output.file.find('\0') != std::string::npos) {
    diagnostics.fail("output.file", "must not contain a NUL character");
  }
  const std::filesystem::path file(output.file);
  std::error_code error;
  if (std::filesystem::is_directory(file, error)) {
    diagnostics.fail("output.file", fmt::format("'{}' is a directory, expected a file path", output.file));
  }
  const std::filesystem::path directory = file.has_parent_path() ? file.parent_path() : ".";
  if (!std::filesystem::is_directory(directory, error)) {
    diagnostics.fail("output.file", fmt::format("directory '{}' does not exist", directory.string()));
  }
  if (access(directory.c_str(), W_OK | X_OK) != 0) {
    diagnostics.fail("output.file", fmt::format("directory '{}' is not writable: {}", directory.string(),
                                                std::strerror(errno)));
  }
}

}  // namespace

void check_scene_consistency(const Scene& scene, const SceneDiagnostics& diagnostics) {
  check_run(scene.run, diagnostics);
  check_open_sides(scene, diagnostics);
  check_bodies(scene, diagnostics);
  check_contact(scene.contact, diagnostics);
  check_output(scene.output, diagnostics);
}

double boundary_speed_scale(const WallsSpec& walls) {
  double speed = 0.0;
  for (const WallSpec* w : {&walls.left, &walls.right, &walls.bottom, &walls.top}) {
    if (w->kind == WallSpec::Kind::wall) speed = std::max(speed, std::abs(w->speed));
    if (w->kind == WallSpec::Kind::inflow) {
      const double factor = w->time_factor == WallSpec::TimeFactor::sinusoidal
                                ? std::abs(w->factor_offset) + std::abs(w->factor_amplitude)
                                : 1.0;
      speed = std::max(speed, std::abs(w->velocity) * factor);
    }
  }
  return speed;
}

}  // namespace ibms
