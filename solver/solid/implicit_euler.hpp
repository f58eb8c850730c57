// Linearly implicit (backward) Euler step of a mass-spring body (stiff springs
// without thousands of sub-steps). One Newton iteration of backward Euler on the springs and
// dashpots, with the external force frozen over the step:
//   (M + dt D + dt^2 S) dU = dt [ F(x, U) + F_ext + dt sum_e S_e (U_j - U_i) ],
//   U' = U + dU,  x' = x + dt U',
// F the spring-dashpot forces at the start of the step (spring_forces.hpp), D the dashpot matrix
// (c e e^T per element) and S the tangent stiffness of each spring, k e e^T + max(T/L, 0)(I - e e^T),
// T = k (L - s L0). The geometric term is kept only in tension, so that M + dt D + dt^2 S is
// symmetric positive definite for every state and step: the step exists for any dt.
// Energy: for a linear spring moving along its axis the step is exact backward Euler, which
// multiplies the oscillator energy (k x^2 + m_r U^2)/2 by exactly 1 / (1 + (omega dt)^2) per step;
// it never increases the energy of an undamped linear system (test_implicit_springs). Modes with
// omega dt >> 1 are damped out within a few steps: the body behaves as stiffly as its springs
// say, without resolving their vibration. Symplectic Euler (symplectic_euler.hpp) instead keeps
// the energy bounded with no drift, but only for dt below its stability limit (stable_substep.hpp).
//
// The linear system is solved by a sparse LDL^T factorisation in the natural order (rim points,
// then the centre: a cyclic band plus one dense border row, little fill), written here so that
// the symbolic analysis and all storage are made once per body and topology and every later
// step allocates nothing (docs/design.md: no allocation inside the step).
#pragma once
#include <array>
#include <utility>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

// Storage of one body's implicit step, reused while the body keeps its points and springs.
class ImplicitSpringSystem {
 public:
  // One backward-Euler step of length dt; external_force [force/length] per point, overwritten
  // (it holds the right-hand side afterwards). Throws BlowUpError on a zero pivot or a spring of
  // zero length.
  void advance(MassSpringBody& body, double dt, std::vector<std::array<double, 2>>& external_force);
  // The same step's velocity change dU without moving the body: external_force in, dU out
  // (overwritten). The factorised matrix stays for response().
  void velocity_change(const MassSpringBody& body, double dt, std::vector<std::array<double, 2>>& external_force);
  // x := (M + dt D + dt^2 S)^{-1} x (two entries per point), the matrix of the latest advance or
  // velocity_change: the velocity change of the points per unit of impulse dt F.
  void response(std::vector<double>& x) const { solve(x); }
  // The matrix of the latest advance or velocity_change with `extra` added to its diagonal (two
  // entries per point), factorised into `into`, whose storage is reused: into.response then
  // solves with M + diag(extra) + dt D + dt^2 S.
  void factorise_with_added_diagonal(const std::vector<double>& extra, ImplicitSpringSystem& into) const;

 private:
  void analyse(const MassSpringBody& body);  // pattern, elimination tree, storage of L
  bool matches(const MassSpringBody& body) const;

  int n_ = 0;                       // unknowns: 2 per point
  std::vector<std::pair<int, int>> topology_;  // (i, j) of every spring when analysed
  // Upper triangle of A in compressed columns (rows <= column within each column).
  std::vector<int> column_start_, row_;
  std::vector<double> value_;
  std::vector<int> diagonal_;                  // position of A(r, r)
  std::vector<int> point_xy_;                  // position of A(2p, 2p + 1)
  std::vector<std::array<int, 4>> spring_slot_;  // per spring: the 2x2 block (min(i,j), max(i,j)) entries
  // L (unit lower triangle, by columns) and D.
  std::vector<int> parent_, l_start_, l_count_, l_row_, flag_, pattern_;
  std::vector<double> l_value_, d_, work_;
  std::vector<double> solution_;

  void factorise();  // numeric LDL^T of the current values; BlowUpError on a zero pivot
  void solve(std::vector<double>& x) const;
};

}  // namespace ibms
