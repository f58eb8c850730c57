// Choosing the coupling when the Simulation is built, and the stages the couplings share (coupling.hpp).
#include "sim/coupling/coupling.hpp"

#include "sim/coupling/direct_forcing_coupling.hpp"
#include "sim/coupling/end_of_step_constraint.hpp"

namespace ibms {

std::unique_ptr<Coupling> make_coupling(const Scene& scene, const Grid& grid, KernelKind kernel,
                                        const std::vector<MassSpringBody>& bodies, std::vector<BodyCoupling>& markers,
                                        std::vector<RigidBody>& rigid) {
  if (!scene.has_bodies()) return std::make_unique<FluidOnly>();
  switch (scene.ibm.coupling) {
    case IbmSpec::Coupling::uhlmann: return std::make_unique<DirectForcing>(scene.ibm, kernel);
    case IbmSpec::Coupling::no_slip:
      return std::make_unique<EndOfStepConstraint>(scene, grid, kernel, bodies, markers, rigid);
  }
  return std::make_unique<DirectForcing>(scene.ibm, kernel);
}

void force_markers(const CouplingStep& step, KernelKind kernel, int passes) {
  auto t = step.timers.time(Stage::ib_forcing);
  apply_direct_forcing(step.solver.grid(), kernel, wall_velocities_at(step.solver.boundaries(), step.time_n), step.dt,
                       passes, step.markers, step.solver.velocity_star_x(), step.solver.velocity_star_y());
}

}  // namespace ibms
