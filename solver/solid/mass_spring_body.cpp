// Wheel construction, mass lumping and rim geometry, docs/method.md §1.2, §1.3, §1.5.
#include "solid/mass_spring_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "solid/spring_dashpot.hpp"

namespace ibms {

double MassSpringBody::solid_area() const { return 0.25 * pi * diameter * diameter; }

double MassSpringBody::total_mass() const {
  double sum = 0.0;
  for (double m : mass) sum += m;
  return sum;
}

namespace {

void check_wheel_spec(const BodyParameters& spec) {
  if (spec.n_surface_points < 3) throw std::invalid_argument("build_wheel: n_surface_points < 3");
  if (!(spec.diameter > 0.0)) throw std::invalid_argument("build_wheel: diameter must be > 0");
  if (!(spec.density > 0.0)) throw std::invalid_argument("build_wheel: density must be > 0");
  if (!(spec.spring_stiffness >= 0.0))
    throw std::invalid_argument("build_wheel: spring_stiffness must be >= 0");
  if (spec.spring_damping < 0.0 &&
      !(spec.restitution_coefficient > 0.0 && spec.restitution_coefficient <= 1.0))
    throw std::invalid_argument("build_wheel: restitution_coefficient must be in (0, 1]");
}

std::vector<double> lumped_mass_fractions(MassLumping lumping, int n_surface) {
  std::vector<double> fraction(n_surface + 1);
  switch (lumping) {
    case MassLumping::equal:
      // Guinea et al.: M = rho_s V_s / N with N = N_l + 1 (docs/method.md §1.3).
      for (double& f : fraction) f = 1.0 / (n_surface + 1);
      break;
    case MassLumping::uniform_disk:
      // Mass and moment of inertia of a uniform disk: M_tot/2 at the centre (docs/method.md §1.3).
      for (int l = 0; l < n_surface; ++l) fraction[l] = 0.5 / n_surface;
      fraction[n_surface] = 0.5;
      break;
  }
  return fraction;
}


}  // namespace

MassSpringBody build_wheel(const BodyParameters& spec) {
  check_wheel_spec(spec);
  MassSpringBody body;
  const int n_l = spec.n_surface_points;
  body.n_surface = n_l;
  body.density = spec.density;
  body.diameter0 = spec.diameter;
  body.diameter = spec.diameter;
  const double radius = 0.5 * spec.diameter;
  for (int l = 0; l < n_l; ++l) {
    const double angle = 2.0 * pi * l / n_l;
    body.position.push_back({spec.centre[0] + radius*std::cos(angle),
                             spec.centre[1] + radius*std::sin(angle)});
  }
  body.position.push_back(spec.centre);
  body.velocity.assign(n_l + 1, spec.velocity);
  body.mass_fraction = lumped_mass_fractions(spec.mass_lumping, n_l);
  body.mass.resize(n_l + 1);
  for (int p = 0; p <= n_l; ++p) body.mass[p] = spec.density * body.solid_area() * body.mass_fraction[p];

  const auto add_spring = [&](int i, int j) {
    const double length = std::hypot(body.position[j][0] - body.position[i][0],
                                     body.position[j][1] - body.position[i][1]);
    double damping = spec.spring_damping;
    if (damping < 0.0) {
      const double m_eff = body.mass[i] * body.mass[j] / (body.mass[i] + body.mass[j]);
      damping = damping_from_restitution(spec.restitution_coefficient, m_eff, spec.spring_stiffness);
    }
    body.springs.push_back({i, j, spec.spring_stiffness, damping, length});
  };
  for (int l = 0; l < n_l; ++l) add_spring(l, (l + 1) % n_l);  // ring
  for (int l = 0; l < n_l; ++l) add_spring(l, n_l);             // spokes
  if (spec.cross_springs)
    for (int l = 0; l < n_l; ++l) add_spring(l, (l + 2) % n_l);  // cross (l, l+2)
  return body;
}

MassSpringBody build_body(const BodyParameters& spec, double fluid_density) {
  const BodyKind kind = spec.kind;
  BodyParameters point_set = spec;
  if (kind == BodyKind::prescribed) point_set.density = fluid_density;
  if (kind != BodyKind::mass_spring) point_set.spring_stiffness = 0.0;
  MassSpringBody body = build_wheel(point_set);
  body.kind = kind;
  body.integrator = spec.spring_integrator;
  if (kind != BodyKind::mass_spring) body.springs.clear();
  // Initial rotation about the centre: U_i = V + Omega e_z x (x_i - X_c).
  const auto& centre = body.position[body.centre_index()];
  for (int p = 0; p < body.n_points(); ++p) {
    body.velocity[p][0] -= spec.angular_velocity * (body.position[p][1] - centre[1]);
    body.velocity[p][1] += spec.angular_velocity * (body.position[p][0] - centre[0]);
  }
  return body;
}

double polygon_area(const MassSpringBody& body) {
  // Shoelace formula over the rim, A = (1/2) sum (x_l y_{l+1} - x_{l+1} y_l).
  double twice_area = 0.0;
  for (int l = 0; l < body.n_surface; ++l) {
    const auto& a = body.position[l];
    const auto& b = body.position[(l + 1) % body.n_surface];
    twice_area += a[0]*b[1] - b[0]*a[1];
  }
  return 0.5 * twice_area;
}

std::array<double, 2> centroid(const MassSpringBody& body) {
  // Polygon centroid, c = (1/(6A)) sum (x_l + x_{l+1}) (x_l y_{l+1} - x_{l+1} y_l); taken
  // relative to the first rim point to limit round-off far from the origin.
  const auto& o = body.position[0];
  double twice_area = 0.0, cx = 0.0, cy = 0.0;
  for (int l = 0; l < body.n_surface; ++l) {
    const auto& pa = body.position[l];
    const auto& pb = body.position[(l + 1) % body.n_surface];
    const double ax = pa[0] - o[0], ay = pa[1] - o[1], bx = pb[0] - o[0], by = pb[1] - o[1];
    const double cross = ax*by - bx*ay;
    twice_area += cross;
    cx += (ax + bx) * cross;
    cy += (ay + by) * cross;
  }
  return {o[0] + cx / (3.0*twice_area), o[1] + cy / (3.0*twice_area)};
}

std::array<double, 2> centre_of_mass(const MassSpringBody& body) {
  double m_sum = 0.0, mx = 0.0, my = 0.0;
  for (int p = 0; p < body.n_points(); ++p) {
    m_sum += body.mass[p];
    mx += body.mass[p] * body.position[p][0];
    my += body.mass[p] * body.position[p][1];
  }
  return {mx / m_sum, my / m_sum};
}

double max_point_speed(const std::vector<MassSpringBody>& bodies) {
  double speed = 0.0;
  for (const MassSpringBody& body : bodies)
    for (const auto& u : body.velocity) speed = std::max(speed, std::hypot(u[0], u[1]));
  return speed;
}

double kinetic_energy(const MassSpringBody& body) {
  double energy = 0.0;
  for (int p = 0; p < body.n_points(); ++p) {
    const auto& u = body.velocity[p];
    energy += 0.5 * body.mass[p] * (u[0]*u[0] + u[1]*u[1]);
  }
  return energy;
}

}  // namespace ibms
