// A validated, typed scene: everything a run needs, with defaults filled in (docs/design.md §4).
// scene/scene_reader.cpp builds it from TOML and checks every value once; the rest of the code
// trusts it. Units: the solver is unit-agnostic, each scene states its system in a comment.
// Every option with a fixed set of values is an enum here; its scene names are in one table per
// enum (scene_schema.hpp: Choices, name_of), which the reader, the resolved text and messages use.
#pragma once
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/options.hpp"
#include "solid/swelling_schedule.hpp"

namespace ibms {

struct RunSpec {
  enum class SolidSubsteps { per_group, global };
  enum class OnInstability { stop, warn };
  using FftPlans = FftPlanning;  // core/options.hpp
  double end_time = 1.0;             // stop time [time]
  double time_step = 0.0;            // fixed dt [time]; 0 selects the adaptive step
  double cfl = 0.5;                  // adaptive dt = cfl / max(|u|/dx + |v|/dy) [-]
  double max_time_step = std::numeric_limits<double>::infinity();  // cap on adaptive dt [time]
  double steady_tolerance = 0.0;     // stop when max|u^{n+1}-u^n| / (dt max|u|) < this [1/time]; 0 = off
  long max_steps = 0;                // 0 = unlimited [-]
  double max_cfl = 1.0;              // blow-up guard: stop if the CFL number exceeds this [-]
  // Adaptive dt <= max_viscous_number h^2 / nu; 0 = no such bound [-]. Why a body scene may need it:
  // the direct forcing's slip at the markers grows like (nu dt / h^2) h, so with dt ~ h alone
  // it stops converging (settling disk: validation/settling_disk/README.md).
  double max_viscous_number = 0.0;
  // Solid sub-steps (sim/bodies/body_update.hpp): "per_group" (each group of bodies that may touch within
  // the step takes its own sub-step; contact sub-steps only for a group that may touch something)
  // or "global" (every body takes the smallest sub-step of all).
  SolidSubsteps solid_substeps = SolidSubsteps::per_group;
  // A body whose kinetic energy exceeds what the scene can give it (Simulation::body_energy_scale:
  // an unstable spring or contact) stops the run with the blow-up message ("stop") or is reported
  // once on stderr ("warn").
  OnInstability on_body_instability = OnInstability::stop;
  // A fluid whose kinetic energy exceeds its budget (what the walls, open sides and bodies can feed
  // it) or whose largest speed exceeds FluidGuard::speed_factor times the scene's speed scale
  // (sim/checks/fluid_guard.hpp, docs/method.md §7) stops the run ("stop") or is reported once ("warn").
  OnInstability on_fluid_instability = OnInstability::stop;
  // How the fluid's FFTs are planned (fluid/spectral_solver.hpp, docs/design.md §9): "measure"
  // times candidate algorithms (the fastest; kept between runs in the wisdom cache, so which one
  // wins, and so the last bits of the result, can differ between machines or a cleared cache),
  // "estimate" picks them from the sizes alone (the same plans, and so the same bits, at every run
  // on one machine: the validation scenes whose references are regenerated bit for bit).
  FftPlans fft_plans = FftPlans::measure;
};

struct DomainSpec {
  double length_x = 1.0, length_y = 1.0;  // [length]
  int cells_x = 64, cells_y = 64;         // [-]
  bool periodic_x = false, periodic_y = false;
};

struct FluidSpec {
  using Convection = ConvectionScheme;  // core/options.hpp
  enum class WallClosure { linear, quadratic };
  double density = 1.0;              // rho_f [mass/length^3]
  double kinematic_viscosity = 0.01; // nu [length^2/time]
  std::array<double, 2> gravity{0.0, 0.0};  // g [length/time^2]; acts on bodies only (docs/method.md §2.6)
  // Spatial options (fluid/fluid_solver.hpp, FluidSchemes; docs/fluid-accuracy.md): convected face
  // values central | quick | fromm | upwind3, and the viscous wall closure linear | quadratic.
  Convection convection = Convection::central;
  WallClosure wall_closure = WallClosure::linear;
  // The time scale of the momentum interpolation's face term, tau (FluidSolver::set_interpolation_time):
  // 0, the default, takes the step dt (the classic form, whose solution depends on dt where the
  // pressure or an immersed-boundary force is sharp); > 0 a fixed tau, so that the solution does
  // not depend on the step (give tau no smaller than the largest step).
  double interpolation_time = 0.0;   // [time]
};

// One side of the box ([walls.<side>], fluid/boundary_conditions.hpp): a wall (tangential speed,
// stopping at stop_time), an inflow (normal velocity profile times a time factor), an outflow
// (zero normal gradient, p = 0) or periodic (both sides of a direction; domain.periodic_x/y).
struct WallSpec {
  using Kind = SideKind;  // core/options.hpp, as the three below
  using Profile = InflowShape;
  using TimeFactor = TimeFactorKind;
  Kind kind = Kind::wall;
  double speed = 0.0;                // wall: tangential speed [length/time]; +x on bottom/top, +y on left/right
  double stop_time = std::numeric_limits<double>::infinity();  // wall stops (speed 0) from here [time]
  Profile profile = Profile::uniform;  // inflow: uniform | parabolic (velocity is then the peak)
  double velocity = 0.0;             // inflow: normal speed into the box [length/time]
  TimeFactor time_factor = TimeFactor::constant;  // inflow: constant | ramp | sinusoidal
  double ramp_time = 0.0;            // ramp: factor min(t / ramp_time, 1) [time]
  double factor_offset = 0.0;        // sinusoidal: factor offset + amplitude sin(2 pi t / period) [-]
  double factor_amplitude = 1.0;     // [-]
  double factor_period = 0.0;        // [time]
};

struct WallsSpec {
  WallSpec left, right, bottom, top;
};

struct IbmSpec {
  using Kernel = KernelKind;  // core/options.hpp
  enum class ForcingStage { explicit_estimate, implicit_prediction };
  enum class InnerFluidInertia { kempe, none, kempe_by_mass };
  enum class Coupling { uhlmann, no_slip };
  enum class ConstrainedVelocity { cells, faces };
  enum class RigidResponse { implicit, virtual_mass };
  enum class RimPreconditioner { identity, response };
  Kernel kernel = Kernel::roma3;     // roma3 | peskin4 | cosine4 | bkp6
  int forcing_passes = 1;            // multi-direct forcing passes [-]
  // Which velocity the markers force: "explicit_estimate" (Uhlmann 2005: the explicit estimate
  // u^n + dt(-N + nu L u^n - G p^n), the force then enters the Crank-Nicolson solve) or
  // "implicit_prediction" (the Crank-Nicolson prediction, force added after it).
  ForcingStage forcing_stage = ForcingStage::explicit_estimate;
  // kempe_by_mass (variant K, the body's inner-fluid force and torque laid on its points as the
  // load of a rigid motion of their masses) | kempe (variant K, each fan triangle's force a third to
  // each of its vertices) | none (variant A, the papers' literal form); docs/method.md §1.7. For a
  // rigid or prescribed body the two kempe variants are one computation.
  InnerFluidInertia inner_fluid_inertia = InnerFluidInertia::kempe_by_mass;
  bool sub_markers = false;          // extra IB markers when marker spacing exceeds the cell size
  // Markers moved towards the body's centre by this fraction of h (Breugem 2012 "retraction"): the
  // regularised kernel makes the forced body look larger than its rim by a fraction of a cell
  // (validation/dfg_cylinder_2d1/README.md measures it); 0 = markers on the rim [-].
  double marker_retraction = 0.0;
  // How the forces hold the no-slip condition (docs/method.md §3.5, §3.7):
  //  "uhlmann"  Uhlmann (2005): the forcing passes on the explicit estimate, the force then enters
  //             the implicit solve; the implicit solve and the projection leave a slip at the end
  //             of the step that scales with nu dt / h^2 (the papers' scheme);
  //  "no_slip"  the forces are the Lagrange multipliers of the no-slip constraint at t^{n+1}: the
  //             previous step's forces enter the implicit solve as a predictor, and corrections are
  //             projected with the pressure until the slip |J u^{n+1} - U_target| is below
  //             slip_tolerance U_ref at every marker (Taira & Colonius 2007, in incremental form).
  Coupling coupling = Coupling::uhlmann;
  double slip_tolerance = 1.0e-3;    // no_slip: largest slip left at the end of the step / U_ref [-]
  int max_coupling_iterations = 100; // no_slip: GMRES products (one Poisson solve each) per step at most [-]
  // no_slip on "faces": how far a moving (prescribed or rigid) body's markers go, in cells, before
  // its own preconditioner block is built again. 0 builds it at every move (fewest products); with
  // many moving bodies the builds outweigh the few products a kept block adds, and 0.1 costs less.
  // "auto" (the default): 0.1 when the blocks' unknowns, sum over those bodies of (2 n_b)^2,
  // outnumber the grid's cells, else 0 (docs/method.md §3.7, the figures) [cells].
  static constexpr double preconditioner_drift_auto = -1.0;
  double preconditioner_drift = preconditioner_drift_auto;
  // no_slip: the velocity the constraint holds (docs/method.md §3.7):
  //  "cells"  J u^{n+1}, the cell-centred velocity of the momentum equation;
  //  "faces"  J_f U_f^{n+1}, the divergence-free face velocity that carries mass and momentum
  //           (interpolated from the faces, as on a staggered grid), the cells taking the force as
  //           the mean of its face values like the pressure gradient. It removes the flux through
  //           the body that the momentum interpolation leaves under "cells", whose size is
  //           proportional to dt (validation/dfg_cylinder_2d2/README.md).
  ConstrainedVelocity constrained_velocity = ConstrainedVelocity::cells;
  // no_slip: a rigid body moves with a virtual mass C_V rho_f V on both sides of Newton-Euler, the
  // right-hand one times the previous step's acceleration (Schwarz, Kempe & Froehlich 2015), so that
  // the fluid's added mass, which the constraint force carries one step late, does not set off the
  // explicit coupling's step-to-step oscillation; 0 leaves Newton-Euler as it is [-].
  double virtual_mass_coefficient = 1.0;
  // no_slip: how a rigid body answers its force (docs/method.md §3.7, "Rigid bodies"):
  //  "implicit"      in the marker system, with its mass less the inner fluid's: the constraint
  //                  holds the rim at the velocity the body reaches at the end of the step;
  //  "virtual_mass"  one step late, with virtual_mass_coefficient (Schwarz, Kempe & Froehlich 2015).
  // A body no heavier than the fluid (with an inner_fluid_inertia other than "none") takes the virtual mass.
  RigidResponse rigid_response = RigidResponse::implicit;
  // no_slip on "faces": the marker system's preconditioner block of a mass-spring rim whose markers
  // are its rim points (docs/method.md §3.7, "Mass-spring rims"):
  //  "identity"  none (the default);
  //  "response"  (D + R)^-1, D the diagonal of J_f S_f and R the rim's response, by Woodbury through
  //              the rim's implicit system: fewer products where the rims need a correction at
  //              most steps (the papers' swelling cavity 6.2 -> 4.0 a step), but where corrections
  //              come at a few steps only, their larger jumps leave the loose slip tolerance's
  //              sawtooth in the body's motion (a settling wheel at 1e-3: its velocity's step-to-step
  //              second difference 40 times the identity's).
  RimPreconditioner rim_preconditioner = RimPreconditioner::identity;
};

// A body's [bodies.swelling] table: the swelling law's parameters (solid/swelling_schedule.hpp).
using SwellingSpec = SwellingLaw;

// A body of one of three kinds (docs/design.md §11), chosen by `kind`:
//  mass_spring  the papers' deformable wheel (springs, swelling, sub-steps);
//  rigid        Newton-Euler translation and rotation of a rigid ring of Lagrangian points;
//  prescribed   centre X(t) = X0 + V t + A sin(2 pi t / T + phase), angle
//               theta(t) = Omega t + Theta sin(2 pi t / T + phase); the fluid is forced to it.
// scene/scene_reader.cpp rejects keys that do not belong to the kind (scene_schema.hpp).
struct BodySpec {
  using Kind = BodyKind;  // core/options.hpp, as the two below
  using MassLumping = ibms::MassLumping;
  using SpringIntegrator = ibms::SpringIntegrator;  // auto | explicit | implicit
  Kind kind = Kind::mass_spring;     // mass_spring | rigid | prescribed
  std::array<double, 2> centre{0.0, 0.0};          // [length]
  std::array<double, 2> velocity{0.0, 0.0};        // initial (prescribed: constant) velocity [length/time]
  double angular_velocity = 0.0;     // initial (prescribed: constant) rotation rate, counter-clockwise [1/time]
  double diameter = 0.0;             // D0 [length]
  int n_surface_points = 0;          // N_l [-]
  double density = 0.0;              // rho_s [mass/length^3] (prescribed: not used, 0)
  // Prescribed oscillation (kind = prescribed only): amplitudes of position and angle, period, phase.
  std::array<double, 2> oscillation_amplitude{0.0, 0.0};  // A [length]
  double angle_amplitude = 0.0;      // Theta [rad]
  double oscillation_period = 0.0;   // T [time]; 0 = no oscillation
  double oscillation_phase = 0.0;    // phase [rad]
  // Drag and lift coefficients C = F / (rho_f U_ref^2 L_ref / 2) in the output when U_ref > 0.
  double reference_speed = 0.0;      // U_ref [length/time]; 0 = no coefficients
  double reference_length = 0.0;     // L_ref [length]; 0 = the diameter
  double spring_stiffness = 0.0;     // k_s [force/length^2 per unit depth]
  double spring_damping = -1.0;      // c_s [force time/length^2]; < 0: from restitution
  double restitution_coefficient = 1.0;  // e_s in (0, 1] [-], used when spring_damping < 0
  bool cross_springs = false;        // extra (l, l+2) rim springs
  MassLumping mass_lumping = MassLumping::equal;  // equal (M = rho_s V / (N_l + 1)) | uniform_disk
  // explicit: symplectic-Euler sub-steps below the springs' stability limit; implicit: one
  // linearly implicit Euler step per solid sub-step, no spring limit (solid/implicit_euler.hpp);
  // auto: implicit when the springs would need more than 50 explicit sub-steps per fluid step.
  SpringIntegrator spring_integrator = SpringIntegrator::automatic;
  SwellingSpec swelling;
};

struct ContactSpec {
  enum class TimeStepping { inner_loop, shared };
  using Model = ContactLawKind;  // core/options.hpp, as the one below
  using InnerStep = InnerStepBound;
  double stiffness = 0.0;            // k_Dn [force/length^2 per unit depth]; 0 = contacts off
  double restitution_coefficient = 1.0;  // e_D in (0, 1] [-]
  double cds_radius = 0.0;           // absolute CDS radius [length]; 0: use cds_radius_fraction
  double cds_radius_fraction = 0.0;  // CDS radius as a fraction of the body diameter [-]
  bool walls = true;                 // body-wall contacts
  // A CDS on each mass-spring body's centre point too (walls and other bodies), not only on its
  // surface points (docs/method.md §1.9): keeps a crushed wheel's centre point in the box.
  bool centre_point = false;
  // "inner_loop": a group of mass-spring bodies that may touch something takes its springs'
  // sub-step, the contact sub-step only in an inner loop over the points near a contact
  // (contact/contact_subcycle.hpp); "shared": every point of the group at the contact sub-step.
  TimeStepping time_stepping = TimeStepping::inner_loop;
  // The inner loop's step: "listed_pairs", steps_per_contact (20) steps per contact duration of the
  // fastest mode its listed CDS pairs can form (a Collatz-Wielandt bound; docs/method.md §5.4);
  // "lightest_point", the group's bound (the lightest CDS point in four pairs at once).
  InnerStep inner_step = InnerStep::listed_pairs;
  // The inner loop's outer step (springs and fluid held over it) as a fraction of the group's
  // springs' stable sub-step, in (0, 1]: 1/16 resolves the papers' elastic impacts of soft wheels;
  // damped, slow contacts (a settling bed) keep their result at larger fractions for less work
  // (docs/method.md §5.4, measured).
  double outer_step_fraction = inner_loop_outer_fraction;  // [-]
  // "linear": the papers' law at k_Dn = stiffness. "collision_time": the same law with k and c
  // chosen per contact from m_eff and e_D so that a single-pair contact lasts
  // T_c = collision_steps fluid steps (docs/method.md §5.5); stiffness is then not given.
  Model model = Model::linear;
  double collision_steps = 10.0;     // T_c / dt [-], collision_time only
  // Contacts act: a linear law with k_Dn > 0, or the collision-time law.
  bool enabled() const { return stiffness > 0.0 || model == Model::collision_time; }
};

struct OutputSpec {
  std::string file = "ibms_out.h5";  // HDF5 output path; XDMF and CSV files go beside it
  int series_every = 1;              // write /series every k steps [-]
  double snapshot_interval = 0.0;    // time between snapshots [time]; 0 = only the final state
  bool centreline_profiles = true;   // write <file stem>_centreline_u.csv / _v.csv at the end
  bool progress = true;              // progress line on stderr
  long checkpoint_every = 0;         // write /checkpoint every k steps [-]; 0 = only at the end
                                     // (and on SIGINT/SIGTERM); `ibms run --restart` reads it
  // Points where the series records the pressure and velocity (bilinear in the cell centres),
  // e.g. the DFG cylinder's front and back points [length].
  std::vector<std::array<double, 2>> probes;
};

struct Scene {
  std::string source_file;           // path the scene came from (for messages)
  std::string resolved_text;         // TOML text of the fully resolved scene (defaults filled)
  RunSpec run;
  DomainSpec domain;
  FluidSpec fluid;
  WallsSpec walls;
  IbmSpec ibm;
  std::vector<BodySpec> bodies;
  ContactSpec contact;
  OutputSpec output;

  bool has_bodies() const { return !bodies.empty(); }
  bool has_kind(BodySpec::Kind kind) const {
    for (const BodySpec& b : bodies)
      if (b.kind == kind) return true;
    return false;
  }
};

// Largest speed the sides give the fluid: wall speeds and inflow peaks (times the largest time
// factor) [length/time]; the velocity scale of a fluid that starts at rest.
double boundary_speed_scale(const WallsSpec& walls);

}  // namespace ibms
