// Collocated-grid SMAC fluid solver (docs/method.md §2.3): AB2 convection with the face velocities,
// Crank-Nicolson diffusion by a direct DST Helmholtz solve, momentum interpolation to faces,
// DCT/FFT Poisson solve for the pressure correction, face velocities divergence-free to round-off.
// Pressure update: the standard incremental form p^{n+1} = p^n + phi. docs/method.md's rotational
// form p^n + phi - (nu dt/2) L_c phi is unstable on this collocated grid once nu dt/h^2 > 1/4:
// the checkerboard pressure mode is invisible to the cell-centre gradient, so the predictor never
// damps it while L_c amplifies it by 4 nu dt/h^2 per step (von Neumann analysis in
// docs/method.md §2.3). The standard form is unconditionally stable and
// measured second order for p in space and time on the manufactured solution.
// Pressure is kinematic (p / rho_f) [length^2/time^2]; forcing terms are accelerations.
// The step is split so the immersed boundary can act between the stages:
//   predict_explicit (u^n -> u~_e), [IB forcing of u~_e], complete_prediction (-> u~ with the
//   force in the Crank-Nicolson solve), project_smac (u* -> u^{n+1}); or, with the forcing after
//   the implicit solve, predict_momentum (u^n -> u~), [IB forcing of u~], project_smac.
#pragma once
#include <memory>
#include <vector>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "core/options.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/spectral_solver.hpp"

namespace ibms {

// The fluid's full state at time level n (everything a restart needs).
struct FluidState {
  double time = 0.0;
  long step = 0;
  CellField velocity_x, velocity_y;      // u^n, v^n at cell centres [length/time]
  CellField pressure;                    // p^n / rho_f [length^2/time^2]
  FaceField velocity_face_x;             // U^n on x-faces, divergence-free transport velocity
  FaceField velocity_face_y;             // V^n on y-faces
  CellField convection_x_prev, convection_y_prev;  // N^{n-1} for AB2 [length/time^2]
  bool has_convection_prev = false;      // false before the first step (Euler start)
  double time_step_prev = 0.0;           // dt^{n-1}, for variable-step AB2

  // The clock: t^{n+1} = t^n + dt, step n + 1, and dt becomes dt^{n-1} of the next step.
  void tick(double dt) {
    time_step_prev = dt;
    time += dt;
    step += 1;
  }
};

struct ProjectionStats {
  double max_divergence_before = 0.0;    // max |D U*| [1/time]
  double max_divergence_after = 0.0;     // max |D U^{n+1}| [1/time]
  double removed_mean = 0.0;             // mean of the Poisson rhs projected out [1/time^2]
  double max_velocity_change = 0.0;      // max |u^{n+1} - u^n| over both components [length/time]
  double max_velocity = 0.0;             // max |u^{n+1}| over both components [length/time]
};

// Spatial options (scene keys fluid.convection and fluid.wall_closure; the defaults are central
// convection and the linear ghost):
//  convection: face values of the convected velocity by the central mean, or upwind-biased
//    (convection_upwind_biased): QUICK (Leonard 1979, kappa = 1/2: (6 q_up + 3 q_down - q_upup) / 8,
//    a fourth-derivative dissipation of order |U| h^3 in place of the central scheme's dispersion)
//    or Fromm (kappa = 0: q_up + (q_down - q_upup) / 4, the steady face value of the unlimited
//    Bell-Colella-Glaz scheme at small Courant numbers; its h^2 dispersion has the sign opposite to
//    the central mean's, and AB2 keeps it stable only up to a CFL number of 0.49,
//    docs/fluid-stability.md §1);
//    or the third-order upwind-biased face value (kappa = 1/3: q_up + (q_down - q_up) / 3 +
//    (q_up - q_upup) / 6, of van Leer's kappa family), whose flux difference is third-order accurate:
//    no h^2 dispersion of either sign, a fourth-derivative dissipation of order |U| h^3; AB2 limit
//    CFL 0.58 (inviscid) like QUICK's. Chosen for the DFG 2D-2 cylinder (its README).
//  quadratic_wall: the viscous term's ghost of the tangential velocity at every side where it is
//    given (walls and inflows, not outflows) from the quadratic through the side value and the two
//    first cells, u_g = (8 u_w - 6 u_1 + u_2) / 3, instead of the
//    linear 2 u_w - u_1 (the normal component keeps it: see add_wall_closure), whose
//    wall-cell Laplacian has an O(1) truncation error (-u''/4). Crank-Nicolson on the quadratic
//    closure: the explicit half directly; the implicit half by defect correction around the linear
//    operator the DST diagonalises: one Helmholtz solve per component from the explicit estimate
//    up to nu dt / h^2 = single_sweep_viscous_number (0.25), FluidSolver::closure_sweeps from u^n
//    above it (each sweep shrinks the defect by < 4/9 at any viscous number; an explicit AB2 treatment of the
//    difference is unstable above nu dt / h^2 ~ 0.5 on the manufactured solution).
// Measured on the Re 1000 cavity against Botella & Peyret (docs/fluid-accuracy.md).

// kappa of an upwind-biased scheme (convection_upwind_biased); central: 1 (the central mean).
double upwind_kappa(ConvectionScheme scheme);
// "central", "QUICK" or "Fromm", for the run's and ibms info's texts.
const char* convection_name(ConvectionScheme scheme);

struct FluidSchemes {
  ConvectionScheme convection = ConvectionScheme::central;
  bool quadratic_wall = false;
  // Up to this viscous number nu dt / h^2 the quadratic closure takes one sweep from the explicit
  // estimate (complete_prediction); 0: always FluidSolver::closure_sweeps sweeps from u^n.
  double single_sweep_viscous_number = 0.25;
  FftPlanning fft_planning = FftPlanning::measure;  // the three spectral solvers' plans
  // tau of the momentum interpolation's face term; 0: the step (FluidSolver::set_interpolation_time).
  double interpolation_time = 0.0;
};

// A force of the step as it enters the face velocities of the momentum interpolation (balanced
// form): u* holds the cell increment dt S F (cell_x, cell_y); the faces take dt S_f F spread onto
// the faces (face_x, face_y) in place of the mean of the cell increment. Where the force is balanced
// by a pressure jump (G_c p = f at the cells, G_f p = f at the faces), the faces then carry no
// dt (mean(G_c) - G_f) p term of the jump, which would be a flux through an immersed boundary of
// order dt that changes its forces with the time step.
struct FaceForcing {
  const CellField* cell_x = nullptr;
  const CellField* cell_y = nullptr;
  const FaceField* face_x = nullptr;
  const FaceField* face_y = nullptr;
};

class FluidSolver {
 public:
  FluidSolver(const Grid& grid, double kinematic_viscosity, const FluidBoundaries& boundaries,
              FluidSchemes schemes = {});
  const FluidSchemes& schemes() const { return schemes_; }
  static constexpr int wall_closure_sweeps = 3;  // Helmholtz solves per component with quadratic_wall, at most
  // The sweeps from u^n at viscous number nu dt / h^2 = d: the fewest whose contraction rho(d)^k
  // reaches (4/9)^wall_closure_sweeps, what wall_closure_sweeps sweeps guarantee at any viscous
  // number (complete_prediction): 2 for d up to 4/3 (where rho = (4/9)^(3/2)), 3 above.
  static int closure_sweeps(double viscous_number);

  const Grid& grid() const { return grid_; }
  const FluidBoundaries& boundaries() const { return boundaries_; }
  double kinematic_viscosity() const { return nu_; }

  FluidState make_state() const;  // fluid at rest, t = 0

  // Face velocities from the cell velocities (averaged, wall faces 0) and one projection so that
  // they are divergence-free; the cell velocities get the same correction. Pressure untouched.
  void initialise_faces(FluidState& state);

  // docs/method.md §2.3 step 1: (u~ - u^n)/dt = -AB2(N) + nu L (u~ + u^n)/2 - G_c p^n + f^{n+1/2}.
  // force_x/force_y (accelerations at t^{n+1/2}) may be null. Result in velocity_star_x/y.
  // Only the ghost layers of `state` are written (they are scratch).
  void predict_momentum(FluidState& state, double dt, const CellField* force_x,
                        const CellField* force_y);

  // The same prediction in two halves, so that the immersed boundary can force the explicit
  // estimate and its force enter the implicit solve (Uhlmann 2005 steps 1-5, docs/method.md §3.1):
  //   predict_explicit: velocity_star = u~_e = u^n + dt (-N_ext + nu L u^n - G_c p^n);
  //   [the caller adds dt f to velocity_star];
  //   complete_prediction: velocity_star = (I - nu dt L/2)^-1 (velocity_star - nu dt L u^n / 2 + walls),
  // i.e. u~ of predict_momentum with f. predict_momentum(f) is exactly these two calls.
  void predict_explicit(FluidState& state, double dt);
  void complete_prediction(FluidState& state, double dt);

  // The predicted velocity, to be forced by the immersed boundary before projection.
  CellField& velocity_star_x() { return star_x_; }
  CellField& velocity_star_y() { return star_y_; }

  // docs/method.md §2.3 steps 3-5: momentum interpolation, L phi = D U*/dt, corrections of U_f, u, p.
  // Writes the fields of level n+1 into `state`; its clock stays at t^n until end_step.
  // forcing: a force in u* that the faces take in the balanced form (FaceForcing), or null.
  ProjectionStats project(FluidState& state, double dt, const FaceForcing* forcing = nullptr);
  // The face increment of the last homogeneous_projection (divergence-free; zero on the faces with a given flux).
  const FaceField& projected_face_increment_x() const { return star_face_x_; }
  const FaceField& projected_face_increment_y() const { return star_face_y_; }
  // P_0 g in place: the homogeneous projection of a cell increment g (no flux through the faces
  // with a given flux): g -= dt G_c phi with L phi = D mean(g) / dt. The face increment
  // mean(g) - dt G_f phi and phi stay in the solver's work fields until the next call.
  // With face_increment_x/y given, the faces take them instead of mean(g) (the balanced form).
  void homogeneous_projection(double dt, CellField& increment_x, CellField& increment_y,
                              const FaceField* face_increment_x = nullptr, const FaceField* face_increment_y = nullptr);
  // The face part of the balanced form alone: the face increment U_g - dt G_f phi with
  // L phi = D U_g / dt, the same bits as homogeneous_projection's with these face increments (the
  // marker system's products under the face constraint read nothing else).
  void homogeneous_face_projection(double dt, const FaceField& face_increment_x, const FaceField& face_increment_y);
  // The same in the caller's fields: U_g becomes U_g - dt G_f phi (0 on the faces with a given flux),
  // the same bits as homogeneous_face_projection's projected_face_increment, without its copies.
  void project_faces_in_place(double dt, FaceField& face_x, FaceField& face_y);
  // After project: adds the projection of a cell increment g (dt S dF of a forcing correction) to
  // the fields of level n+1: u += P_0 g, U_f += mean(g) - dt G_f phi, p += phi (g is overwritten
  // by P_0 g). Returns max |P_0 g| over the cells and both components.
  double project_increment(FluidState& state, double dt, CellField& increment_x, CellField& increment_y,
                           const FaceField* face_increment_x = nullptr, const FaceField* face_increment_y = nullptr);
  // The potential phi of the last homogeneous (face) projection, ghosts filled: L phi = D U_g / dt.
  const CellField& correction_potential() const { return phi_; }
  // Whether fluid.interpolation_time sets the face term's time scale (project_faces_in_place and
  // add_projected_increment then do not apply: they assume the step's).
  bool fixed_interpolation_time() const { return interpolation_time_ > 0.0; }
  // project_increment in the balanced form with the potential of these face increments given
  // (phi: L phi = D U_g / dt, e.g. a combination of earlier projections' potentials, the
  // projection being linear), so that no Poisson solve is needed: u += g - dt G_c phi,
  // U_f += U_g - dt G_f phi, p += phi. Returns max |g - dt G_c phi| as project_increment.
  double add_projected_increment(FluidState& state, double dt, CellField& increment_x, CellField& increment_y,
                                 const FaceField& face_increment_x, const FaceField& face_increment_y,
                                 const CellField& phi);
  // Closes the step's convection: N^n becomes N^{n-1} (AB2 history). The clock is FluidState::tick.
  void end_step(FluidState& state);
  // project, end_step and tick: the step of a scene without immersed boundary.
  ProjectionStats project_smac(FluidState& state, double dt);

  // The time scale tau of the momentum interpolation's face term (0: the step dt, the classic form).
  // With tau > 0 the face velocities differ from the mean of the cell velocities by
  // tau (I - M A)(S_f F - G_f p) whatever the step, and the projection solves the operator
  // D (dt M A + tau (I - M A)) G_f (the wide and compact Laplacians mixed), which the transforms
  // diagonalise; the cells are corrected by dt A G_f phi as before.
  void set_interpolation_time(double tau) { interpolation_time_ = tau; }
  double interpolation_time() const { return interpolation_time_; }

  // Kinetic energy per unit density and depth, 0.5 sum |u|^2 dx dy [length^4/time^2].
  double kinetic_energy(const FluidState& state) const;

  // Faces the projection corrects, inclusive ranges of x-face index i and y-face index j.
  struct FaceRange { int x_first, x_last, y_first, y_last; };
  FaceRange corrected_faces() const;

 private:
  // (I - nu dt/2 L) q = r for both velocity components, in place (wall data already in r).
  void solve_helmholtz_pair(double dt, CellField& x, CellField& y);
  // Normal velocity of the Dirichlet sides (walls: 0, inflows: the profile) at `time` on their faces.
  void set_given_faces(double time, FaceField& face_x, FaceField& face_y) const;

  Grid grid_;
  double nu_;
  FluidBoundaries boundaries_;
  FluidSchemes schemes_;
  // Adds scale (u_g,quadratic - u_g,linear) / h^2 of (u, v) with the wall velocities at t to the
  // wall cells of out_x, out_y (FluidSchemes::quadratic_wall).
  void add_wall_closure(const CellField& u, const CellField& v, double t, double scale, CellField& out_x,
                        CellField& out_y) const;
  // star_face_ -= dt G_f phi with L phi = D star_face_ / dt (phi in phi_).
  void project_star_faces(double dt);
  // star_face_ = the face increments on the corrected faces, 0 on the faces with a given flux.
  void set_star_faces(const FaceField& face_increment_x, const FaceField& face_increment_y);
  // face -= dt G_f phi with L phi = D face / dt (phi in phi_).
  void project_faces(double dt, FaceField& face_x, FaceField& face_y);
  // face -= dt G_f phi_ on the corrected faces (periodic faces synchronised).
  void subtract_face_gradient(double dt, FaceField& face_x, FaceField& face_y);
  // increment -= dt G_c phi_ (the cells' part of the homogeneous projection).
  void subtract_centre_gradient(double dt, CellField& increment_x, CellField& increment_y);
  // u += increment, U_f += star_face_, p += phi_; returns max |increment|.
  double add_increment(FluidState& state, const CellField& increment_x, const CellField& increment_y);
  double interpolation_time_ = 0.0;
  // tau / dt (1 when interpolation_time_ is 0: the classic code path, bit for bit).
  double interpolation_ratio(double dt) const { return interpolation_time_ > 0.0 ? interpolation_time_ / dt : 1.0; }
  // The Poisson problem's eigenvalues for the ratio r: r lambda + (1 - r) lambda (1 + lambda h^2/4).
  void mixed_eigenvalues(double ratio);
  // Poisson solve of buffer_ in place (compact operator, or the mixed one for ratio != 1).
  SpectralSolveStats solve_poisson(double ratio);
  // face -= dt (ratio G_f phi + (1 - ratio) M G_c phi) on the corrected faces; grad_ must hold G_c phi.
  void correct_faces(double dt, double ratio, FaceField& face_x, FaceField& face_y) const;
  std::vector<double> mixed_x_, mixed_y_;
  double mixed_ratio_ = 1.0;
  std::unique_ptr<SpectralSolver> poisson_;    // Neumann/periodic
  // Dirichlet/periodic, one per velocity component: the same transforms (FFTW reuses the first
  // plan's wisdom), so that with two threads the two solves run side by side.
  std::unique_ptr<SpectralSolver> helmholtz_, helmholtz_y_;
  // Work fields, allocated once.
  CellField star_x_, star_y_, conv_x_, conv_y_, lap_x_, lap_y_, grad_x_, grad_y_, phi_, work_;
  FaceField star_face_x_, star_face_y_;
  std::vector<double> buffer_, buffer_y_;
};

}  // namespace ibms
