// The immersed-boundary coupling of the mass-spring bodies with the fluid (docs/method.md §1.6, §1.8,
// §3.5, §3.6, §7 steps 1, 2 and 6): the markers X^n (rim points), their volume weights dV_l = h s_l,
// the forcing target U_target_l = U_l - (s'/s)(X_l - X_c) (swelling part removed, §1.8), the
// multi-direct forcing passes on the predicted velocity, and the fluid reaction
// F_f,l = -rho_f (sum_m F_l^(m)) dV_l on the rim points (the centre point gets none).
// Work arrays live in BodyCoupling, one per body, sized when the Simulation is built.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "fluid/boundary_conditions.hpp"
#include "ibm/delta_kernel.hpp"
#include "ibm/ib_operators.hpp"
#include "ibm/triangle_cell_overlap.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/swelling_schedule.hpp"

namespace ibms {

using Vec2 = std::array<double, 2>;

// The response of body b's rim to marker impulses: velocity_change_l = the change of U_l over the step
// when the fluid reaction of the impulses impulse_l = dt F_l acts on the body [length/time].
using BodyResponse = std::function<void(std::size_t body, const std::vector<Vec2>& impulse,
                                        std::vector<Vec2>& velocity_change)>;

struct BodyCoupling {
  // IB markers, per marker l: the rim points and, with ibm.sub_markers, the sub-markers that split
  // each rim edge (docs/method.md §3.6, an extension, off by default). Marker l sits on rim edge
  // marker_edge[l] (points e -> e+1) at fraction marker_fraction[l] in [0, 1): its target velocity
  // is the linear interpolation of the two end points' targets, and its force reaction goes back
  // to the end points with the same weights (1 - w, w), which keeps total force and torque.
  // Without sub-markers marker l is rim point l (edge l, fraction 0).
  std::vector<Vec2> marker;                // X_l^n [length]
  std::vector<int> marker_edge;            // rim edge (and first end point) of marker l [-]
  std::vector<double> marker_fraction;     // position along that edge [-]
  std::vector<double> marker_fraction_work; // radial factor of each marker (ibm.marker_retraction) [-]
  std::vector<double> marker_volume;       // dV_l = h s_l [length^2 per unit depth]
  std::vector<Vec2> target_velocity;       // U_target_l [length/time]
  std::vector<FaceStencils> face_stencils; // the markers' face stencils over one marker solve (work)
  std::vector<Vec2> rigid_arm;             // a responding rigid body's arms over one step (rigid_arms)
  std::vector<Vec2> interpolated_velocity; // U~_l = J u~ [length/time]
  std::vector<Vec2> pass_force;            // F_l^(m) of one pass [length/time^2]
  std::vector<Vec2> pass_increment;        // dt F_l^(m), what one pass spreads [length/time]
  std::vector<Vec2> forcing_sum;           // sum_m F_l^(m) [length/time^2]
  // Per body point (rim + centre): forces frozen over the fluid step [force/length].
  std::vector<Vec2> fluid_force;           // F_f,l (§1.6)
  std::vector<Vec2> inner_fluid_force;     // F_int distributed to the points (§1.7)
  std::vector<Vec2> external_force;        // work: F_f + F_int + F_e + F_c per sub-step
  // Variant K (§1.7): fan triangles T_l = (c, l, l+1), their cells at X^n, and
  // I_T = sum alpha_T u h^2 from the previous step (region X^{n-1}, velocity u^n).
  std::vector<std::vector<CellOverlap>> triangle_cells;
  std::vector<Vec2> triangle_momentum;     // [length^3/time per unit depth]
  // A rigid or prescribed body takes the rim polygon's cells in one pass (triangle_cells[0]) and its
  // momentum in triangle_momentum[0] (the others 0): its force and torque are sums over the
  // triangles, which the polygon gives at once.
  PolygonOverlapWork polygon_work;
  // Angular momentum of the inner fluid, sum_T sum_ij alpha_T (x_ij - X_ref) x u_ij h^2, about the
  // centre point X_ref at the time it was sampled [length^4/time per unit depth], and the torque
  // rho_f dL/dt about the centre X_c^n that it gives (variant K; 0 for variant A) [force].
  double inner_angular_momentum = 0.0;
  Vec2 inner_reference_centre{0.0, 0.0};   // X_ref [length]
  double inner_fluid_torque = 0.0;
  // What the fluid does to the body this step: the IB reaction plus the inner-fluid
  // term, F = sum_p F_f,p + rho_f dI/dt [force/length], and its torque about the centre point X_c^n,
  // T = sum_p (X_p - X_c) x F_f,p + rho_f dL/dt [force] (docs/method.md §1.7 eq. 1.7a). Buoyancy is not
  // in it: gravity acts on the bodies only (§2.6), as the buoyancy-corrected weight.
  Vec2 hydrodynamic_force{0.0, 0.0};
  double hydrodynamic_torque = 0.0;
  // The slip left at the end of the step, |J u^{n+1} - U_target_l| / U_ref over the markers: the
  // largest and the root mean square [-]. U_ref is the body's reference_speed, else the scene's
  // driving speed (slip_reference_speed).
  double slip_max = 0.0;
  double slip_rms = 0.0;
  // The same of the face velocities, |J_f U_f^{n+1} - U_target_l| / U_ref: the divergence-free
  // velocity that carries mass and momentum, the one "no_slip" holds under
  // ibm.constrained_velocity = "faces" (§3.7).
  double face_slip_max = 0.0;
  double face_slip_rms = 0.0;
  double slip_reference_speed = 1.0;       // [length/time]
  // ibm.coupling = "no_slip": the forces F_l of the latest step, the predictor of the next one while
  // the marker count stays the same (previous_force.size() == marker.size(); empty before the first step).
  std::vector<Vec2> previous_force;        // [length/time^2]
  // ibm.coupling = "no_slip" on a mass-spring body: the change of the marker velocities over the step
  // that the fluid reaction of forcing_sum gives through the body's linearised response,
  // -(M + dt D + dt^2 S)^{-1} rho_f dV dt F (docs/method.md §3.7), each sub-marker's share taken to and
  // from its edge's end points with the weights (1 - w, w) (§3.6). The target of
  // the constraint is the rim velocity at the end of the step, target_velocity (U^n + the step
  // without the fluid) + this. Empty for other bodies [length/time].
  std::vector<Vec2> body_velocity_change;
  std::vector<double> response_work;       // two entries per body point: scratch of the response
  // ibm.coupling = "no_slip": a prescribed body, whose motion does not answer its force; the
  // marker system's preconditioner holds its exact fluid operator (marker_preconditioner.hpp).
  bool given_motion = false;
  // ibm.coupling = "no_slip" on a rigid body that responds in the marker system: the mass and moment
  // of inertia that answer the immersed-boundary reaction over the step, the body's less the inner
  // fluid's when its inertia is counted (docs/method.md §3.7, "Rigid bodies"); 0: no response.
  double response_mass = 0.0;     // [mass/length]
  double response_inertia = 0.0;  // [mass length]

  // max_markers: capacity reserved once for the marker arrays, so that sub-markers added as the
  // body swells (up to 1.5x the nominal swollen edge) do not reallocate them within the step loop.
  BodyCoupling(const MassSpringBody& body, std::size_t max_markers);
};

// Markers per rim edge needed for spacing <= h on a body of diameter d with n_surface rim points
// (ceil(|e|/h) pieces per edge, docs/method.md §3.6), for reserving capacity.
std::size_t max_sub_marker_count(double diameter, int n_surface, double h);

// Tangential wall speeds at `time` seen by interpolation (ghost rule of the fluid walls).
WallVelocities wall_velocities_at(const FluidBoundaries& boundaries, double time);

// X^n, dV_l and U_target_l of every body (docs/method.md §1.8, §3.6) at `time` = t^n; previous_dt is
// dt^{n-1} (0 on the first step), over which the swelling part of U^n is measured. With
// sub_markers, each rim edge e is split into ceil(|e|/h) pieces at X^n (docs/method.md §3.6).
// retraction: markers moved towards the centre of mass X_c by this length (ibm.marker_retraction
// times h), each marker's velocity relative to X_c's scaled by the same radial factor (exact for a
// rigid motion and a uniform dilation), volumes dV_l from the moved markers.
void prepare_markers(const std::vector<MassSpringBody>& bodies,
                     const std::vector<SwellingSchedule>& swelling, double time, double previous_dt,
                     const Grid& grid, bool sub_markers, std::vector<BodyCoupling>& coupling,
                     double retraction = 0.0);

// Marker l of a rim sits on edge e0 -> e0 + 1 at fraction w (docs/method.md §3.6): a rim field's
// value there is (1 - w) of e0's plus w of e1's, exactly e0's own at w = 0 (markers = rim points).
// `at(p)` is the field's component at rim point p.
template <class At>
inline double on_marker_edge(const BodyCoupling& c, std::size_t l, int n_rim, At at) {
  const int e0 = c.marker_edge[l];
  const double w = c.marker_fraction[l];
  if (w == 0.0) return at(e0);
  return (1.0 - w) * at(e0) + w * at((e0 + 1) % n_rim);
}

inline double rim_to_marker(const BodyCoupling& c, std::size_t l, int n_rim, const std::vector<Vec2>& point, int d) {
  return on_marker_edge(c, l, n_rim, [&](int p) { return point[p][d]; });
}

// point: two entries per body point, as the response systems take them.
inline double rim_to_marker(const BodyCoupling& c, std::size_t l, int n_rim, const std::vector<double>& point, int d) {
  return on_marker_edge(c, l, n_rim, [&](int p) { return point[2 * p + d]; });
}

// The transpose: marker l's value shared to its edge's end points with the same weights, all of it
// to e0 at w = 0. `add(p, share)` adds a share to rim point p's component.
template <class Add>
inline void to_marker_edge_ends(const BodyCoupling& c, std::size_t l, int n_rim, double value, Add add) {
  const int e0 = c.marker_edge[l];
  const double w = c.marker_fraction[l];
  if (w == 0.0) {
    add(e0, value);
    return;
  }
  add(e0, (1.0 - w) * value);
  add((e0 + 1) % n_rim, w * value);
}

inline void marker_to_rim(const BodyCoupling& c, std::size_t l, int n_rim, double value, int d, std::vector<Vec2>& point) {
  to_marker_edge_ends(c, l, n_rim, value, [&](int p, double share) { point[p][d] += share; });
}

// point: two entries per body point, as the response systems take them.
inline void marker_to_rim(const BodyCoupling& c, std::size_t l, int n_rim, double value, int d, std::vector<double>& point) {
  to_marker_edge_ends(c, l, n_rim, value, [&](int p, double share) { point[2 * p + d] += share; });
}

// Adds to each marker's target U_target_l the change `change` of its body's point velocities (one
// entry per body point), interpolated along the marker's rim edge and scaled by its radial factor
// as the target itself is (prepare_markers): the target becomes that of the changed velocities.
// The change over the step of a rigid body's marker velocities when the fluid reaction of the
// marker impulses dt F_l acts on it with c.response_mass and c.response_inertia: the reaction
// -rho_f dV_l dt F_l goes to the rim points as compute_fluid_reaction sends it, its force and torque
// about the centre point change U and omega, and marker l takes the change as its target does
// (edge weights and radial factor) [length/time].
// The response depends on the body through its markers' arms only (rigid_arms), which the marker
// preconditioner keeps with the block it builds from them.
void rigid_response(double fluid_density, const BodyCoupling& c, const std::vector<Vec2>& arm,
                    const std::vector<double>& marker_volume, const std::vector<double>& radial_factor,
                    const std::vector<Vec2>& impulse, std::vector<Vec2>& change);
// arm_l: the rim point of marker l (its edge's end points with the marker's weights) less the
// centre point, where the marker's reaction acts on the body [length].
void rigid_arms(const MassSpringBody& body, const BodyCoupling& c, std::vector<Vec2>& arm);

void add_point_velocity_change(const MassSpringBody& body, const std::vector<Vec2>& change, BodyCoupling& c);

// n_passes direct-forcing passes on (velocity_star_x, velocity_star_y): interpolate u~ at X^n,
// F = (U_target - U~)/dt, spread dt F with dV_l, u~ += dt f; accumulates F in forcing_sum.
void apply_direct_forcing(const Grid& grid, KernelKind kernel, const WallVelocities& walls, double dt,
                          int n_passes, std::vector<BodyCoupling>& coupling, CellField& velocity_star_x,
                          CellField& velocity_star_y);

// The forces of the previous step as the predictor of ibm.coupling = "no_slip": if every body has
// them for its present markers, forcing_sum = previous_force and u~ += dt S F (returns true);
// otherwise nothing is changed (returns false) and the caller forces by apply_direct_forcing.
// Each body's face_stencils must be mapped at its markers (map_face_stencils).
bool spread_previous_forces(const Grid& grid, double dt, std::vector<BodyCoupling>& coupling,
                            CellField& velocity_star_x, CellField& velocity_star_y);

// Slip of the velocity (velocity_x, velocity_y) at the markers: r_l = U_target_l (+ body_velocity_change_l
// where the body responds) - J u (kept in
// pass_increment), slip_max and slip_rms of every body; returns the largest slip_max.
double measure_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const CellField& velocity_x,
                    const CellField& velocity_y, std::vector<BodyCoupling>& coupling);
// The same with J_f on the face velocities (ibm/ib_operators.hpp interpolate_faces): face_slip_max,
// face_slip_rms; returns the largest face_slip_max.
double measure_face_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, const FaceField& face_x,
                         const FaceField& face_y, std::vector<BodyCoupling>& coupling);
// The same with each body's markers' face stencils as mapped in face_stencils (map_face_stencils;
// the form above maps them at the current markers first).
double measure_face_slip(const Grid& grid, const WallVelocities& walls, const FaceField& face_x, const FaceField& face_y,
                         std::vector<BodyCoupling>& coupling);

// One correction of the no-slip iteration after measure_slip: dF_l = r_l / dt is added to
// forcing_sum, and dt S dF = S r is added to (increment_x, increment_y).
void spread_slip_correction(const Grid& grid, KernelKind kernel, double dt, std::vector<BodyCoupling>& coupling,
                            CellField& increment_x, CellField& increment_y);

// (cell_x, cell_y) = the mean of each cell's two faces of (face_x, face_y), as G_c p is the mean of
// the two face gradients G_f p (overwrites the interior).
void average_faces_to_cells(const Grid& grid, const FaceField& face_x, const FaceField& face_y, CellField& cell_x,
                            CellField& cell_y);

// The cells take the step's force as the mean of its face values, A S_f F, in place of the kernel
// spread S F already in u~ and force_cell: u~ += A(force_face) - force_cell; force_cell = A(force_face).
void cell_forces_from_faces(const Grid& grid, const FaceField& force_face_x, const FaceField& force_face_y,
                            CellField& force_cell_x, CellField& force_cell_y, CellField& velocity_star_x,
                            CellField& velocity_star_y);

// force_cell = dt S F and force_face = dt S_f F of forcing_sum F of every body (overwritten), with
// each body's face_stencils mapped at its markers.
void spread_step_forces(const Grid& grid, double dt, std::vector<BodyCoupling>& coupling,
                        CellField& force_cell_x, CellField& force_cell_y, FaceField& force_face_x, FaceField& force_face_y);

// previous_force = forcing_sum of every body (the predictor of the next step).
void keep_forces(std::vector<BodyCoupling>& coupling);

// F_f = -rho_f forcing_sum_l dV_l of every marker, returned to the rim points of its edge with
// weights (1 - w, w); 0 on the centre (docs/method.md §1.6, §3.6).
void compute_fluid_reaction(double fluid_density, std::vector<BodyCoupling>& coupling);

// hydrodynamic_force and hydrodynamic_torque of every body from its fluid reaction and inner-fluid
// terms (call after compute_fluid_reaction and the inner-fluid inertia), at the positions X^n.
void compute_hydrodynamic_loads(const std::vector<MassSpringBody>& bodies, std::vector<BodyCoupling>& coupling);

}  // namespace ibms
