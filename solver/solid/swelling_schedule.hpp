// Swelling law of docs/method.md §1.8 (default reading, linear in D):
//   D(t) = clamp(D0 + rate (t - onset), D0, max_diameter),
// applied to a body by scaling all natural lengths by s = D/D0 (§1.2) and the masses at
// constant density, M_i = rho_s (pi D^2/4) mass_fraction_i, so M is proportional to s^2.
#pragma once

#include "solid/mass_spring_body.hpp"

namespace ibms {

// The law's parameters (sim/ fills them from the scene's swelling table).
struct SwellingLaw {
  bool enabled = false;
  double onset_time = 0.0;    // swelling starts [time]
  double rate = 0.0;          // dD/dt [length/time]
  double max_diameter = 0.0;  // swelling stops at this diameter [length]
};

struct SwellingSchedule {
  bool enabled = false;
  double initial_diameter = 0.0;  // D0 [length]
  double onset_time = 0.0;        // [time]
  double rate = 0.0;              // dD/dt while swelling [length/time]
  double max_diameter = 0.0;      // [length]

  SwellingSchedule() = default;
  SwellingSchedule(const SwellingLaw& law, double diameter0);  // std::invalid_argument if bad

  double diameter(double time) const;        // D(t) [length]
  double growth_rate(double time) const;     // dD/dt [length/time]; 0 outside the swelling window
  double length_scale(double time) const;    // s = D/D0 [-]
  // s'/s = (dD/dt)/D [1/time]: the swelling part of the marker velocity is (s'/s)(X_l - X_c), §1.8.
  double relative_growth_rate(double time) const;
};

// Sets body.diameter = D (natural lengths follow through body.length_scale()) and the masses at
// constant density.
void apply_swelling(MassSpringBody& body, double diameter);

}  // namespace ibms
