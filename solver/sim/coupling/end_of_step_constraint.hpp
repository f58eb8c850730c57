// The end-of-step constraint, ibm.coupling = "no_slip" (docs/method.md §3.7): the immersed-boundary
// forces are the Lagrange multipliers of no-slip at t^{n+1} (Taira & Colonius 2007). The prediction
// spreads the previous step's forces into the Crank-Nicolson solve (direct forcing on the first
// step, or when the markers changed); the projection balances the step's force on cells and faces;
// after it, force corrections solve the marker system (sim/coupling/no_slip_system.hpp) until the
// slip of the constrained velocity is below the tolerance. Mass-spring rims and rigid bodies take
// their target at t^{n+1}, their response in the marker system (a rigid body may instead move with
// a virtual mass, ibm.rigid_response).
#pragma once
#include "sim/coupling/coupling.hpp"
#include "sim/coupling/no_slip_system.hpp"

namespace ibms {

class EndOfStepConstraint final : public Coupling {
 public:
  // Sizes its arrays for the markers' capacities, the response storage of the mass-spring bodies,
  // and gives the rigid bodies their response mass or virtual mass C_V rho_f V (docs/method.md §3.7).
  EndOfStepConstraint(const Scene& scene, const Grid& grid, KernelKind kernel, const std::vector<MassSpringBody>& bodies,
                      std::vector<BodyCoupling>& markers, std::vector<RigidBody>& rigid);

  void predict(const CouplingStep& step) override;
  const FaceForcing* projection_forcing() const override { return &balanced_; }
  CouplingWork hold(const CouplingStep& step) override;
  // The slip of the velocity hold does not constrain (cells under "faces", faces under "cells"):
  // measured only for the series rows that record it.
  void measure_slip_at_end(const FluidSolver& solver, const FluidState& fluid,
                           std::vector<BodyCoupling>& markers) const override;
  std::string forcing_stage() const override;
  std::string correction_stage() const override;
  bool counts_products() const override { return true; }
  // The latest forces, the next step's predictor: "bodies_previous_force", two values per marker
  // (none before the first step); what each body's own preconditioner block was built from
  // ("bodies_block_markers", "_volumes", "_radial_factors", "_arms"; none before it is built).
  void write_checkpoint(const std::vector<BodyCoupling>& markers, CheckpointArrays& arrays) const override;
  void read_checkpoint(const CheckpointReader& read, std::vector<BodyCoupling>& markers) override;

 private:
  // The backward-Euler step of each responding body over dt without the fluid, joined to its
  // target; returns whether any body responds.
  bool prepare_body_responses(const CouplingStep& step);

  KernelKind kernel_;
  std::string kernel_name_;
  int passes_;                 // ibm.forcing_passes (the first step's direct forcing)
  double slip_tolerance_;      // ibm.slip_tolerance [-]
  int max_products_;           // ibm.max_coupling_iterations
  bool on_faces_;              // ibm.constrained_velocity = "faces": J_f U_f^{n+1}, cells from faces
  bool has_mass_spring_;       // a mass-spring body responds in the marker system
  bool has_responding_rigid_ = false;  // a rigid body responds in the marker system
  double preconditioner_drift_ = 0.0;  // ibm.preconditioner_drift, "auto" resolved [cells]
  bool rim_response_ = false;          // ibm.rim_preconditioner = "response"
  double fluid_density_;       // rho_f [mass/length^3]
  Vec2 gravity_;               // g [length/time^2]
  NoSlipArrays arrays_;
  ExactBlockInputs restored_inputs_;  // read_checkpoint's work
  FaceForcing balanced_;
};

}  // namespace ibms
