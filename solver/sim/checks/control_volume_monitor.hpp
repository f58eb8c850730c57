// The control-volume force of every body (metrics/control_volume_force.hpp) over the run's steps:
// begin_step before advance_one_step chooses each body's rectangle from its rim points at t^n and
// takes the balance terms there; end_step after it takes them at t^{n+1} on the same rectangle and
// forms the force of the step. The body's own volume is not fluid: the momentum it carries,
// A V (rim-polygon area times the centre-of-mass velocity; rigid and prescribed bodies: the velocity
// of their centre), is taken out of the rate of change inside, F += rho ((A V)^{n+1} - (A V)^n) / dt,
// so that the force compares with body_NNN/force_x, force_y (IB reaction plus inner-fluid term); zero
// for a fixed body.
// Nothing is carried from one step to the next that the fluid state does not hold: the terms at
// t^{n+1} are reused at the start of the next step only while the rectangle stays the same and the
// fluid has not moved on, otherwise recomputed from the fields, so that a run restarted from a
// checkpoint computes the same bits. Storage is sized once; the steps allocate nothing. On a grid
// with fewer than 5 cells in a direction there is no rectangle: every body reports force 0 and
// clearance 0.
#pragma once
#include <vector>

#include "metrics/control_volume_force.hpp"
#include "sim/simulation.hpp"

namespace ibms {

struct BodyControlVolume {
  CellRectangle rectangle;        // the rectangle of the step under way (begin_step)
  double start_clearance = 0.0;   // control_volume_clearance of that rectangle at t^n [length]
  double clearance = 0.0;         // the same for the step of `force` [length]
  ControlVolumeTerms before, after;
  Vec2 body_momentum_before{0.0, 0.0};  // (A V)^n [length^3/time]
  long after_step = -1;           // fluid step at which `after` was taken (-1: none)
  Vec2 force{0.0, 0.0};           // force of the fluid on the body over the latest step [force/length]
};

class ControlVolumeMonitor {
 public:
  explicit ControlVolumeMonitor(const Simulation& sim);
  void begin_step(const Simulation& sim);
  void end_step(const Simulation& sim, double dt);
  const BodyControlVolume& body(std::size_t b) const;

 private:
  std::vector<BodyControlVolume> bodies_;
};

// A V of body b (see the header) [length^3/time per unit depth].
Vec2 body_volume_momentum(const Simulation& sim, std::size_t b);
// Centre-of-mass velocity of body b: all points mass-weighted (mass_spring), V (rigid, prescribed).
Vec2 body_velocity(const Simulation& sim, std::size_t b);

}  // namespace ibms
