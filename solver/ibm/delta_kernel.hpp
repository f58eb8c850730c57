// One-dimensional regularised delta functions phi(r) of docs/method.md §4 and appendix A9
// (r = distance / grid spacing [-]); the 2D kernel is delta_h = phi(x/dx) phi(y/dy) / (dx dy).
// Roma, Peskin & Berger (1999) 3-point, Peskin (2002) 4-point, cosine 4-point, and the
// Bao, Kaye & Peskin (2016) 6-point C^3 kernel in the IBAMR form (ib_6_delta_fcn).
#pragma once
#include <array>
#include <string>

#include "core/options.hpp"

namespace ibms {

inline constexpr std::array<KernelKind, 4> all_kernel_kinds = {
    KernelKind::roma3, KernelKind::peskin4, KernelKind::cosine4, KernelKind::bkp6};

std::string kernel_name(KernelKind kind);  // its scene name (core/options.hpp)

// Number of grid nodes a kernel touches in one direction [-]: 3, 4, 4, 6.
int kernel_support(KernelKind kind);

// phi(r), r in grid units; zero outside |r| < support/2.
double kernel_phi(KernelKind kind, double r);

// The weights of all nodes one marker touches in one direction, computed once per marker.
// The marker sits at xi in node-index units (node m at xi = m); the nodes are
// first, first+1, ..., first+support-1 and weight[k] = phi(xi - (first + k)).
struct KernelStencil {
  int first = 0;                       // index of the first node [-]
  int n_nodes = 0;                     // kernel_support(kind) [-]
  std::array<double, 6> weight{};      // phi of each node [-]; entries past n_nodes are 0
};
KernelStencil kernel_stencil(KernelKind kind, double xi);

// Bao, Kaye & Peskin (2016) second-moment constant K = 59/60 - sqrt(29)/20 [-].
double bkp6_second_moment();

}  // namespace ibms
