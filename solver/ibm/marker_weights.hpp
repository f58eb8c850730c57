// Volume weights of the IB markers of a closed deformable rim, docs/method.md §3.6:
// dV_l = h s_l, s_l = (|X_{l+1} - X_l| + |X_l - X_{l-1}|) / 2 (indices modulo N),
// the 2D analogue of Uhlmann's (2005) shell of thickness h; recompute every step.
#pragma once
#include <array>
#include <vector>

namespace ibms {

// closed_ring: the rim markers in order, the last joined to the first [length];
// h: grid spacing [length]. Returns dV_l [length^2 per unit depth].
std::vector<double> marker_weights(const std::vector<std::array<double, 2>>& closed_ring,
                                   double h);
// The same into `volume` (resized to the ring; no allocation within its capacity).
void marker_weights(const std::vector<std::array<double, 2>>& closed_ring, double h, std::vector<double>& volume);

}  // namespace ibms
