// Cross-section scene checks (scene_checks.hpp). Bodies are checked as their initial disks
// (centre, diameter); the box is [0, length_x] x [0, length_y]. Touching is allowed, overlap not.
#include "scene/scene_checks.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace ibms {

namespace {

// The adaptive step aims at run.cfl with the velocity of the step before, so the CFL number it
// reaches exceeds run.cfl a little wherever the flow speeds up; run.max_cfl, the blow-up guard,
// must sit above it or it stops a sound run (issue 15 item 7: the Re 1000 cavity at cfl = 1 stopped
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

void check_walls(const Scene& scene, const SceneDiagnostics& diagnostics) {
  // A periodic direction has no walls at its ends, so a speed there would silently be ignored.
  const struct {
    const char* name;
    const WallSpec& wall;
    bool periodic;
    const char* direction;
  } sides[] = {{"left", scene.walls.left, scene.domain.periodic_x, "x"},
               {"right", scene.walls.right, scene.domain.periodic_x, "x"},
               {"bottom", scene.walls.bottom, scene.domain.periodic_y, "y"},
               {"top", scene.walls.top, scene.domain.periodic_y, "y"}};
  for (const auto& side : sides) {
    if (side.periodic && side.wall.speed != 0.0) {
      diagnostics.fail(fmt::format("walls.{}.speed", side.name),
                       fmt::format("must be 0 because domain.periodic_{} = true (no wall there), got {}",
                                   side.direction, side.wall.speed));
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
      const bool both_prescribed = body.kind == "prescribed" && neighbour.kind == "prescribed";
      const double r_body = 0.5 * body.diameter, r_neighbour = 0.5 * neighbour.diameter;
      const bool nested = (neighbour.kind == "prescribed" && distance + r_body < r_neighbour) ||
                          (body.kind == "prescribed" && distance + r_neighbour < r_body);
      if (distance < contact_distance && !both_prescribed && !nested) {
        diagnostics.fail(fmt::format("bodies.{}.centre", b),
                         fmt::format("body {} overlaps body {}: centre distance {} < sum of radii {}",
                                     b, other, distance, contact_distance));
      }
    }
  }
}

void check_contact(const ContactSpec& contact, const SceneDiagnostics& diagnostics) {
  if (contact.stiffness > 0.0 && contact.cds_radius <= 0.0 && contact.cds_radius_fraction <= 0.0) {
    diagnostics.fail("contact.stiffness",
                     fmt::format("is {} (contacts on) but neither contact.cds_radius nor "
                                 "contact.cds_radius_fraction is > 0",
                                 contact.stiffness));
  }
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
  check_walls(scene, diagnostics);
  check_bodies(scene, diagnostics);
  check_contact(scene.contact, diagnostics);
  check_output(scene.output, diagnostics);
}

}  // namespace ibms
