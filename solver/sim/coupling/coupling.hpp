// The immersed-boundary coupling of fluid and bodies (docs/method.md §3), one object per choice of
// ibm.coupling, chosen when the Simulation is built:
//  - no bodies: FluidOnly, the momentum prediction alone;
//  - "uhlmann": DirectForcing, the papers' coupling (Uhlmann 2005): direct-forcing passes on the
//    predicted velocity, the slip left at t^{n+1} measured (sim/coupling/direct_forcing_coupling.hpp);
//  - "no_slip": EndOfStepConstraint, the forces as the Lagrange multipliers of no-slip at t^{n+1}
//    (Taira & Colonius 2007; sim/coupling/end_of_step_constraint.hpp).
// The step (sim/time_step.cpp) calls the same three stages of any coupling, never testing which it
// is: predict (step 2), the force the projection balances (step 3), hold (step 4). Each coupling
// owns its arrays, its section of the checkpoint and the description `ibms info` prints.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/stage_timers.hpp"
#include "fluid/fluid_solver.hpp"
#include "ibm/delta_kernel.hpp"
#include "io/checkpoint.hpp"
#include "scene/scene.hpp"
#include "sim/coupling/body_coupling.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/rigid_motion.hpp"

namespace ibms {

// What one step's coupling works on: the fluid from t^n = time_n over dt, the markers of every
// body and the bodies they sit on, and the timers its stages are counted in.
struct CouplingStep {
  FluidSolver& solver;
  FluidState& fluid;
  std::vector<BodyCoupling>& markers;
  const std::vector<MassSpringBody>& bodies;
  const std::vector<RigidBody>& rigid;  // the motion of the rigid and prescribed bodies
  StageTimers& timers;
  double time_n = 0.0;
  double dt = 0.0;
};

// What the hold stage did to u^{n+1}: marker-system products (one Poisson solve each) and a bound
// on the change of u^{n+1} they made, the sum over corrections of max |P_0 g| [length/time].
struct CouplingWork {
  int products = 0;
  double max_change = 0.0;
};

// Checkpoint arrays by name (sim/run/simulation_checkpoint.cpp writes them to /checkpoint).
using CheckpointArrays = std::map<std::string, std::vector<double>>;

class Coupling {
 public:
  virtual ~Coupling() = default;
  // Step 2: the momentum prediction u~ with the immersed-boundary force (docs/method.md §2.3, §3.1).
  virtual void predict(const CouplingStep& step) = 0;
  // Step 3: the force the projection balances on cells and faces (FaceForcing, §2.3); nullptr: none.
  virtual const FaceForcing* projection_forcing() const { return nullptr; }
  // Step 4: the corrections where the coupling holds no-slip at t^{n+1} (§3.7), with the slip they
  // leave in the markers' slip_max ... face_slip_rms.
  virtual CouplingWork hold(const CouplingStep& step) = 0;
  // The slip at t^{n+1} into the markers' slip_max ... face_slip_rms where hold leaves it unmeasured
  // (the papers' coupling corrects nothing): called when a series row records it, with the step's
  // markers and targets and the fluid at t^{n+1}.
  virtual void measure_slip_at_end(const FluidSolver& /*solver*/, const FluidState& /*fluid*/,
                                   std::vector<BodyCoupling>& /*markers*/) const {}

  // The stages `ibms info` lists (Simulation::stage_names): the forcing, and the corrections
  // after the projection (empty: none).
  virtual std::string forcing_stage() const = 0;
  virtual std::string correction_stage() const { return {}; }
  // Whether the series carry coupling_iterations (the products of hold).
  virtual bool counts_products() const { return false; }

  // The coupling's state between steps in the checkpoint, per-body arrays (append_body_array).
  virtual void write_checkpoint(const std::vector<BodyCoupling>& /*markers*/, CheckpointArrays& /*arrays*/) const {}
  virtual void read_checkpoint(const CheckpointReader& /*read*/, std::vector<BodyCoupling>& /*markers*/) {}
};

// The coupling of `scene` (FluidOnly without bodies). markers: one per body, sized; the
// end-of-step constraint sizes its own arrays and the bodies' response storage, and gives the
// rigid bodies their virtual mass (docs/method.md §3.7).
std::unique_ptr<Coupling> make_coupling(const Scene& scene, const Grid& grid, KernelKind kernel,
                                        const std::vector<MassSpringBody>& bodies, std::vector<BodyCoupling>& markers,
                                        std::vector<RigidBody>& rigid);

// Timed stages the couplings share.
// F = (U_target - J u)/dt in forcing passes, u~ += dt S F (§3.5), on velocity_star (ib_forcing).
void force_markers(const CouplingStep& step, KernelKind kernel, int passes);

}  // namespace ibms
