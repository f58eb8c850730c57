// The lattice Green's function of the projection's Poisson operator on the unbounded grid
// (docs/method.md §3.7, "The marker system's preconditioner"): G solves
//     (G(m+1,n) - 2 G(m,n) + G(m-1,n)) / dx^2 + (G(m,n+1) - 2 G(m,n) + G(m,n-1)) / dy^2 = delta_{m0} delta_{n0},
// the five-point Laplacian L = D G_f of the face projection (fluid/fluid_solver.hpp). G grows like
// ln r, so the table holds G(m,n) - G(0,0); the constant drops out of every gradient G_f L^{-1}.
// Fourier in n and exact in m (the 1-D difference equation decays as lambda^|m|,
// lambda + 1/lambda = 2 + (dx/dy)^2 (2 - 2 cos eta)):
//     G(m,n) - G(0,0) = (dx^2 / pi) int_0^pi (lambda^|m| cos(n eta) - 1) / (lambda - 1/lambda) d eta,
// whose integrand is bounded (its limit at eta = 0 is dx^2 |m| / (2 pi)) with a kink there: the midpoint rule
// on 8192 points gives about 1e-8 of the table's largest entry (test_lattice_green_function). Used
// by the marker preconditioner to build the local marker operator J_f P_0 S_f without Poisson solves
// (Liska & Colonius 2016 solve the immersed-boundary system with the lattice Green's function).
#pragma once
#include <vector>

namespace ibms {

class LatticeGreensFunction {
 public:
  // The table for offsets |m|, |n| <= radius on cells dx x dy; kept when it already covers them,
  // else grown to at least twice its reach.
  void ensure(double dx, double dy, int radius);
  // G(m,n) - G(0,0) for |m|, |n| <= radius() [time^0 length^2: L G = delta].
  double operator()(int m, int n) const {
    const int a = m < 0 ? -m : m, b = n < 0 ? -n : n;
    return table_[static_cast<std::size_t>(b) * static_cast<std::size_t>(radius_ + 1) + static_cast<std::size_t>(a)];
  }
  int radius() const { return radius_; }

 private:
  double dx_ = 0.0, dy_ = 0.0;
  int radius_ = -1;
  std::vector<double> table_;  // (radius + 1)^2, n-major
};

}  // namespace ibms
