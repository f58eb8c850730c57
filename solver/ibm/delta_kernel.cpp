// Regularised delta functions of docs/method.md §4 / A9; formulas copied term by term from A9.
#include "ibm/delta_kernel.hpp"

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace ibms {
namespace {

// Roma, Peskin & Berger (1999), JCP 153:509, 3-point kernel (docs/method.md A9).
double roma3_phi(double r) {
  const double a = std::abs(r);
  if (a <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0*a*a)) / 3.0;
  if (a <= 1.5) {
    const double b = 1.0 - a;
    return (5.0 - 3.0*a - std::sqrt(std::max(0.0, 1.0 - 3.0*b*b))) / 6.0;
  }
  return 0.0;
}

// Peskin (2002), Acta Numerica 11:479, standard 4-point kernel (docs/method.md A9).
double peskin4_phi(double r) {
  const double a = std::abs(r);
  if (a <= 1.0) return (3.0 - 2.0*a + std::sqrt(1.0 + 4.0*a - 4.0*a*a)) / 8.0;
  if (a <= 2.0) return (5.0 - 2.0*a - std::sqrt(std::max(0.0, -7.0 + 12.0*a - 4.0*a*a))) / 8.0;
  return 0.0;
}

// Cosine 4-point kernel (docs/method.md A9); not first-moment exact.
double cosine4_phi(double r) {
  const double a = std::abs(r);
  if (a <= 2.0) return 0.25 * (1.0 + std::cos(0.5 * pi * a));
  return 0.0;
}

// Bao, Kaye & Peskin (2016) 6-point kernel, IBAMR ib_6_delta_fcn (docs/method.md A9): for
// rl in [0, 1) returns w[0..5], the weights of the nodes at distances rl - 3, ..., rl + 2.
std::array<double, 6> bkp6_weights(double rl) {
  const double K = bkp6_second_moment();
  const double rl2 = rl * rl, rl3 = rl2 * rl;
  const double alpha = 28.0;
  const double beta = 9.0/4.0 - 1.5*(K + rl2) + (22.0/3.0 - 7.0*K)*rl - (7.0/3.0)*rl3;
  const double gamma = 0.25 * ((161.0/36.0 - (59.0/6.0)*K + 5.0*K*K) * 0.5*rl2
                               + (-109.0/24.0 + 5.0*K) * (1.0/3.0)*rl2*rl2
                               + (5.0/18.0) * rl3*rl3);
  const double sign = (1.5 - K) > 0.0 ? 1.0 : -1.0;
  const double discriminant = std::max(0.0, beta*beta - 4.0*alpha*gamma);
  const double w0 = (-beta + sign*std::sqrt(discriminant)) / (2.0*alpha);
  std::array<double, 6> w;
  w[0] = w0;
  w[1] = -3.0*w0 - 1.0/16.0 + (K + rl2)/8.0 + (3.0*K - 1.0)*rl/12.0 + rl3/12.0;
  w[2] = 2.0*w0 + 0.25 + (4.0 - 3.0*K)*rl/6.0 - rl3/6.0;
  w[3] = 2.0*w0 + 5.0/8.0 - (K + rl2)/4.0;
  w[4] = -3.0*w0 + 0.25 - (4.0 - 3.0*K)*rl/6.0 + rl3/6.0;
  w[5] = w0 - 1.0/16.0 + (K + rl2)/8.0 - (3.0*K - 1.0)*rl/12.0 - rl3/12.0;
  return w;
}

double bkp6_phi(double r) {
  if (!(r > -3.0 && r < 3.0)) return 0.0;
  // Node i of the IBAMR set sits at distance i - 3 + rl, so r = floor(r) + rl is node floor(r) + 3.
  const double floor_r = std::floor(r);
  return bkp6_weights(r - floor_r)[static_cast<int>(floor_r) + 3];
}

}  // namespace

double bkp6_second_moment() { return 59.0/60.0 - std::sqrt(29.0)/20.0; }

std::string kernel_name(KernelKind kind) { return std::string(option_name(kind)); }

int kernel_support(KernelKind kind) {
  switch (kind) {
    case KernelKind::roma3: return 3;
    case KernelKind::peskin4: return 4;
    case KernelKind::cosine4: return 4;
    case KernelKind::bkp6: return 6;
  }
  return 0;
}

double kernel_phi(KernelKind kind, double r) {
  switch (kind) {
    case KernelKind::roma3: return roma3_phi(r);
    case KernelKind::peskin4: return peskin4_phi(r);
    case KernelKind::cosine4: return cosine4_phi(r);
    case KernelKind::bkp6: return bkp6_phi(r);
  }
  return 0.0;
}

KernelStencil kernel_stencil(KernelKind kind, double xi) {
  KernelStencil stencil;
  stencil.n_nodes = kernel_support(kind);
  if (kind == KernelKind::bkp6) {
    // One quadratic root serves all six nodes: with rl = xi - floor(xi) the nodes
    // floor(xi) - 2 + k lie at distance (5 - k) - 3 + rl from the marker (phi is even).
    const double floor_xi = std::floor(xi);
    const std::array<double, 6> w = bkp6_weights(xi - floor_xi);
    stencil.first = static_cast<int>(floor_xi) - 2;
    for (int k = 0; k < 6; ++k) stencil.weight[k] = w[5 - k];
    return stencil;
  }
  // Nodes m with |xi - m| < support/2: the first is floor(xi - support/2) + 1.
  stencil.first = static_cast<int>(std::floor(xi - 0.5*stencil.n_nodes)) + 1;
  for (int k = 0; k < stencil.n_nodes; ++k)
    stencil.weight[k] = kernel_phi(kind, xi - (stencil.first + k));
  return stencil;
}

}  // namespace ibms
