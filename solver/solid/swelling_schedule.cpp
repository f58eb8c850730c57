// Linear swelling schedule and its application to a body, docs/method.md §1.2, §1.8.
#include "solid/swelling_schedule.hpp"

#include <algorithm>
#include <stdexcept>

namespace ibms {

SwellingSchedule::SwellingSchedule(const SwellingLaw& law, double diameter0)
    : enabled(law.enabled), initial_diameter(diameter0), onset_time(law.onset_time),
      rate(law.rate), max_diameter(law.max_diameter) {
  if (!(diameter0 > 0.0)) throw std::invalid_argument("swelling: initial diameter must be > 0");
  if (enabled && !(max_diameter >= diameter0))
    throw std::invalid_argument("swelling: max_diameter must be >= the initial diameter");
  if (enabled && !(rate >= 0.0)) throw std::invalid_argument("swelling: rate must be >= 0");
}

double SwellingSchedule::diameter(double time) const {
  if (!enabled) return initial_diameter;
  return std::clamp(initial_diameter + rate*(time - onset_time), initial_diameter, max_diameter);
}

double SwellingSchedule::growth_rate(double time) const {
  if (!enabled || time < onset_time) return 0.0;
  return diameter(time) < max_diameter ? rate : 0.0;
}

double SwellingSchedule::length_scale(double time) const {
  return diameter(time) / initial_diameter;
}

double SwellingSchedule::relative_growth_rate(double time) const {
  return growth_rate(time) / diameter(time);
}

void apply_swelling(MassSpringBody& body, double diameter) {
  if (!(diameter > 0.0)) throw std::invalid_argument("apply_swelling: diameter must be > 0");
  body.diameter = diameter;
  const double total_mass = body.density * body.solid_area();
  for (int p = 0; p < body.n_points(); ++p) body.mass[p] = total_mass * body.mass_fraction[p];
}

}  // namespace ibms
