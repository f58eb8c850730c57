// A deformable body as a mass-spring network (docs/method.md §1.1-1.3): N_l rim points (the IB
// markers) plus one centre point joined by spring-dashpot elements listed as data
// (i, j, k_ij, c_ij, L0_ij). build_wheel makes the ring + spokes (+ optional (l, l+2) cross)
// topology of §1.2 from a BodyParameters. 2D, per unit depth: masses [mass/length], stiffness
// [force/length^2], energies [energy/length]. Knows nothing about the grid.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/options.hpp"

namespace ibms {

// One spring-dashpot element between points i and j (docs/method.md §1.2).
struct Spring {
  int i = 0, j = 0;
  double stiffness = 0.0;        // k_ij [force/length^2 per unit depth]
  double damping = 0.0;          // c_ij [force time/length^2 per unit depth]
  double natural_length0 = 0.0;  // L0_ij at the initial diameter D0 [length]
};

// BodyKind, SpringIntegrator, MassLumping: core/options.hpp.

// What build_wheel and build_body take of a body (sim/ fills it from the scene's BodySpec).
struct BodyParameters {
  BodyKind kind = BodyKind::mass_spring;
  std::array<double, 2> centre{0.0, 0.0};    // [length]
  std::array<double, 2> velocity{0.0, 0.0};  // initial velocity of every point [length/time]
  double angular_velocity = 0.0;             // initial rotation rate, counter-clockwise [1/time]
  double diameter = 0.0;                     // D0 [length]
  int n_surface_points = 0;                  // N_l [-]
  double density = 0.0;                      // rho_s [mass/length^3]
  double spring_stiffness = 0.0;             // k_s [force/length^2 per unit depth]
  double spring_damping = -1.0;              // c_s [force time/length^2]; < 0: from restitution
  double restitution_coefficient = 1.0;      // e_s in (0, 1] [-], used when spring_damping < 0
  bool cross_springs = false;                // extra (l, l+2) rim springs
  MassLumping mass_lumping = MassLumping::equal;
  SpringIntegrator spring_integrator = SpringIntegrator::automatic;
};

struct MassSpringBody {
  BodyKind kind = BodyKind::mass_spring;
  SpringIntegrator integrator = SpringIntegrator::automatic;
  std::vector<std::array<double, 2>> position;  // x_i [length]; rim 0..n_surface-1, centre n_surface
  std::vector<std::array<double, 2>> velocity;  // U_i [length/time]
  std::vector<double> mass;                     // M_i [mass/length] = density * solid_area() * mass_fraction_i
  std::vector<double> mass_fraction;            // share of the total mass per point [-], sums to 1
  std::vector<Spring> springs;
  int n_surface = 0;                            // N_l [-]
  double density = 0.0;                         // rho_s [mass/length^3]
  double diameter0 = 0.0;                       // D0 [length]
  double diameter = 0.0;                        // current D [length] (swelling)

  int n_points() const { return static_cast<int>(position.size()); }
  int centre_index() const { return n_surface; }
  // Swelling factor s = D / D0 [-]; natural lengths are s * L0 (docs/method.md §1.2).
  double length_scale() const { return diameter / diameter0; }
  // V_s: the area of the disk of diameter D [length^2 per unit depth]. This (not the area of the
  // inscribed rim polygon, 1.6 % smaller for N_l = 20) is the V_s of M = rho_s V_s / N.
  double solid_area() const;
  double total_mass() const;
  // M (1 - rho_f / rho_s) g: the weight of mass M of this body less the buoyancy of the fluid it
  // displaces (no gravity in the fluid, docs/method.md §2.6).
  std::array<double, 2> buoyant_weight(double point_mass, double fluid_density,
                                       const std::array<double, 2>& gravity) const {
    const double factor = 1.0 - fluid_density / density;
    return {point_mass * factor * gravity[0], point_mass * factor * gravity[1]};
  }
};

// Wheel of docs/method.md §1.2 from a body's parameters: rim points at angles 2 pi l / N_l (counter-clockwise),
// ring springs (l, l+1), spokes (l, c), cross springs (l, l+2) if asked, natural lengths from
// this regular polygon; all points start with spec.velocity. Masses (§1.3): "equal" gives
// 1/(N_l+1) of rho_s V_s to every point; "uniform_disk" half to the centre, the rest shared by
// the rim. Dashpots: spec.spring_damping if >= 0, else from the restitution coefficient with
// the pair effective mass m_i m_j / (m_i + m_j) (= M/2 for equal masses; §1.5, A8).
MassSpringBody build_wheel(const BodyParameters& spec);

// The point set of a body of any kind: build_wheel for mass_spring (with the initial rotation
// angular_velocity added to the point velocities); for rigid and prescribed bodies the same rim and
// centre without springs. A prescribed body has no density of its own: its point masses are those
// of the displaced fluid (fluid_density), used only as weights (centre of mass).
MassSpringBody build_body(const BodyParameters& spec, double fluid_density);

// Geometry and energies. polygon_area: signed (counter-clockwise > 0) shoelace area of the rim
// [length^2]; centroid: area centroid of that polygon [length]; centre_of_mass of all points.
double polygon_area(const MassSpringBody& body);
std::array<double, 2> centroid(const MassSpringBody& body);
std::array<double, 2> centre_of_mass(const MassSpringBody& body);
double kinetic_energy(const MassSpringBody& body);  // sum M_i |U_i|^2 / 2 [energy/length]
// Largest speed |U_i| of any point of these bodies [length/time] (0 without bodies).
double max_point_speed(const std::vector<MassSpringBody>& bodies);

}  // namespace ibms
