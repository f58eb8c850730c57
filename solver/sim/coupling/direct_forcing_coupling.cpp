// The papers' coupling and the fluid-only prediction (direct_forcing_coupling.hpp).
#include "sim/coupling/direct_forcing_coupling.hpp"

#include "scene/scene_schema.hpp"

namespace ibms {

void FluidOnly::predict(const CouplingStep& step) {
  auto t = step.timers.time(Stage::predictor);
  step.solver.predict_momentum(step.fluid, step.dt, nullptr, nullptr);  // u~
}

DirectForcing::DirectForcing(const IbmSpec& ibm, KernelKind kernel)
    : kernel_(kernel),
      passes_(ibm.forcing_passes),
      on_explicit_estimate_(ibm.forcing_stage == IbmSpec::ForcingStage::explicit_estimate),
      kernel_name_(scene_schema::name_of(ibm.kernel)) {}

void DirectForcing::predict(const CouplingStep& step) {
  if (on_explicit_estimate_) {
    { auto t = step.timers.time(Stage::predictor); step.solver.predict_explicit(step.fluid, step.dt); }  // u~_e
    force_markers(step, kernel_, passes_);                                                                // u~_e + dt f
    { auto t = step.timers.time(Stage::predictor); step.solver.complete_prediction(step.fluid, step.dt); }  // u~ with f
  } else {
    { auto t = step.timers.time(Stage::predictor); step.solver.predict_momentum(step.fluid, step.dt, nullptr, nullptr); }  // u~
    force_markers(step, kernel_, passes_);                                                                // u~ + dt f
  }
}

void DirectForcing::measure_slip_at_end(const FluidSolver& solver, const FluidState& fluid,
                                        std::vector<BodyCoupling>& markers) const {
  const Grid& grid = solver.grid();
  const WallVelocities walls = wall_velocities_at(solver.boundaries(), fluid.time);  // t^{n+1}
  measure_face_slip(grid, kernel_, walls, fluid.velocity_face_x, fluid.velocity_face_y, markers);
  measure_slip(grid, kernel_, walls, fluid.velocity_x, fluid.velocity_y, markers);
}

std::string DirectForcing::forcing_stage() const {
  return "immersed-boundary forcing (" + kernel_name_ + ", " + std::to_string(passes_) + " pass(es) on the " +
         (on_explicit_estimate_ ? "explicit estimate, force inside the Crank-Nicolson solve" : "Crank-Nicolson prediction") +
         "; target = marker velocity minus swelling part)";
}

}  // namespace ibms
