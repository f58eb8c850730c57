// The papers' coupling (Uhlmann 2005; docs/method.md §3.1, §3.5): direct-forcing passes that drive
// the predicted velocity towards the marker targets, the force spread into the momentum
// prediction, and the slip left at t^{n+1} measured after the projection, not corrected.
// ibm.forcing_stage chooses where the passes act: on the explicit estimate u~_e, with the force
// then inside the Crank-Nicolson solve (Uhlmann's steps 1-5), or on the Crank-Nicolson prediction.
#pragma once
#include "sim/coupling/coupling.hpp"

namespace ibms {

// No bodies: the momentum prediction alone, nothing to hold.
class FluidOnly final : public Coupling {
 public:
  void predict(const CouplingStep& step) override;
  CouplingWork hold(const CouplingStep& /*step*/) override { return {}; }
  std::string forcing_stage() const override { return {}; }
};

class DirectForcing final : public Coupling {
 public:
  DirectForcing(const IbmSpec& ibm, KernelKind kernel);
  void predict(const CouplingStep& step) override;
  // Nothing to correct: the slip is measured only when a series row records it.
  CouplingWork hold(const CouplingStep& /*step*/) override { return {}; }
  void measure_slip_at_end(const FluidSolver& solver, const FluidState& fluid,
                           std::vector<BodyCoupling>& markers) const override;
  std::string forcing_stage() const override;

 private:
  KernelKind kernel_;
  int passes_;                   // ibm.forcing_passes
  bool on_explicit_estimate_;    // ibm.forcing_stage = "explicit_estimate"
  std::string kernel_name_;
};

}  // namespace ibms
