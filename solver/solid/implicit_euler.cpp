// Linearly implicit Euler step of a mass-spring body with a sparse LDL^T (see implicit_euler.hpp).
// The factorisation is the up-looking sparse LDL^T of T. A. Davis, "Direct Methods for Sparse
// Linear Systems" (SIAM 2006, ch. 4): elimination tree and column counts once (analyse), then per
// step the numeric factorisation row by row from the tree's reach, in storage sized once.
#include "solid/implicit_euler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {

bool ImplicitSpringSystem::matches(const MassSpringBody& body) const {
  if (n_ != 2 * body.n_points() || topology_.size() != body.springs.size()) return false;
  for (std::size_t s = 0; s < topology_.size(); ++s)
    if (topology_[s].first != body.springs[s].i || topology_[s].second != body.springs[s].j) return false;
  return true;
}

void ImplicitSpringSystem::analyse(const MassSpringBody& body) {
  n_ = 2 * body.n_points();
  topology_.clear();
  for (const Spring& spring : body.springs) topology_.emplace_back(spring.i, spring.j);
  // Pattern of the upper triangle: the 2x2 block of every point and of every spring.
  std::vector<std::vector<int>> rows(n_);
  const auto add_block = [&](int a, int b) {  // block (a, b), a <= b (points)
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c)
        if (2*a + r <= 2*b + c) rows[2*b + c].push_back(2*a + r);
  };
  for (int p = 0; p < body.n_points(); ++p) add_block(p, p);
  for (const Spring& spring : body.springs) add_block(std::min(spring.i, spring.j), std::max(spring.i, spring.j));
  column_start_.assign(n_ + 1, 0);
  row_.clear();
  for (int c = 0; c < n_; ++c) {
    std::sort(rows[c].begin(), rows[c].end());
    rows[c].erase(std::unique(rows[c].begin(), rows[c].end()), rows[c].end());
    row_.insert(row_.end(), rows[c].begin(), rows[c].end());
    column_start_[c + 1] = static_cast<int>(row_.size());
  }
  value_.assign(row_.size(), 0.0);
  const auto slot = [&](int r, int c) {  // position of A(r, c), r <= c
    for (int q = column_start_[c]; q < column_start_[c + 1]; ++q)
      if (row_[q] == r) return q;
    throw std::logic_error("ImplicitSpringSystem: entry missing from the pattern");
  };
  diagonal_.resize(n_);
  for (int r = 0; r < n_; ++r) diagonal_[r] = slot(r, r);
  point_xy_.resize(body.n_points());
  for (int p = 0; p < body.n_points(); ++p) point_xy_[p] = slot(2*p, 2*p + 1);
  spring_slot_.clear();
  for (const Spring& spring : body.springs) {
    const int a = std::min(spring.i, spring.j), b = std::max(spring.i, spring.j);
    spring_slot_.push_back({slot(2*a, 2*b), slot(2*a, 2*b + 1), slot(2*a + 1, 2*b), slot(2*a + 1, 2*b + 1)});
  }
  // Elimination tree and the number of entries of each column of L.
  parent_.assign(n_, -1);
  flag_.assign(n_, 0);
  l_count_.assign(n_, 0);
  for (int k = 0; k < n_; ++k) {
    flag_[k] = k;
    for (int q = column_start_[k]; q < column_start_[k + 1]; ++q) {
      for (int i = row_[q]; i < k && flag_[i] != k; i = parent_[i]) {
        if (parent_[i] == -1) parent_[i] = k;
        ++l_count_[i];
        flag_[i] = k;
      }
    }
  }
  l_start_.assign(n_ + 1, 0);
  for (int k = 0; k < n_; ++k) l_start_[k + 1] = l_start_[k] + l_count_[k];
  l_row_.assign(l_start_[n_], 0);
  l_value_.assign(l_start_[n_], 0.0);
  d_.assign(n_, 0.0);
  work_.assign(n_, 0.0);
  pattern_.assign(n_, 0);
  solution_.assign(n_, 0.0);
}

void ImplicitSpringSystem::factorise() {
  for (int k = 0; k < n_; ++k) {
    // Row k of L: the reach of column k's entries in the elimination tree, in topological order.
    work_[k] = 0.0;
    int top = n_;
    flag_[k] = k;
    l_count_[k] = 0;
    for (int q = column_start_[k]; q < column_start_[k + 1]; ++q) {
      int i = row_[q];
      work_[i] += value_[q];
      int length = 0;
      for (; flag_[i] != k; i = parent_[i]) {
        pattern_[length++] = i;
        flag_[i] = k;
      }
      while (length > 0) pattern_[--top] = pattern_[--length];
    }
    d_[k] = work_[k];
    work_[k] = 0.0;
    for (; top < n_; ++top) {
      const int i = pattern_[top];
      const double y_i = work_[i];
      work_[i] = 0.0;
      const int end = l_start_[i] + l_count_[i];
      for (int q = l_start_[i]; q < end; ++q) work_[l_row_[q]] -= l_value_[q] * y_i;
      const double l_ki = y_i / d_[i];
      d_[k] -= l_ki * y_i;
      l_row_[end] = k;
      l_value_[end] = l_ki;
      ++l_count_[i];
    }
    if (!(d_[k] > 0.0))  // A is symmetric positive definite by construction: a pivot <= 0 is garbage
      throw BlowUpError("implicit spring step: non-positive pivot " + std::to_string(d_[k]) + " at unknown " +
                        std::to_string(k) + " (non-finite body state?)");
  }
}

void ImplicitSpringSystem::factorise_with_added_diagonal(const std::vector<double>& extra,
                                                         ImplicitSpringSystem& into) const {
  into = *this;
  for (int r = 0; r < n_; ++r) into.value_[diagonal_[r]] += extra[r];
  into.factorise();
}

void ImplicitSpringSystem::solve(std::vector<double>& x) const {
  for (int j = 0; j < n_; ++j)
    for (int q = l_start_[j]; q < l_start_[j + 1]; ++q) x[l_row_[q]] -= l_value_[q] * x[j];
  for (int j = 0; j < n_; ++j) x[j] /= d_[j];
  for (int j = n_ - 1; j >= 0; --j)
    for (int q = l_start_[j]; q < l_start_[j + 1]; ++q) x[j] -= l_value_[q] * x[l_row_[q]];
}

void ImplicitSpringSystem::advance(MassSpringBody& body, double dt,
                                   std::vector<std::array<double, 2>>& external_force) {
  velocity_change(body, dt, external_force);
  for (int p = 0; p < body.n_points(); ++p)
    for (int d = 0; d < 2; ++d) {
      body.velocity[p][d] += external_force[p][d];
      body.position[p][d] += dt * body.velocity[p][d];
    }
}

void ImplicitSpringSystem::velocity_change(const MassSpringBody& body, double dt,
                                           std::vector<std::array<double, 2>>& external_force) {
  if (static_cast<int>(external_force.size()) != body.n_points())
    throw std::invalid_argument("ImplicitSpringSystem::advance: external force has the wrong size");
  if (!matches(body)) analyse(body);
  const double s = body.length_scale();
  add_spring_forces(body, s, external_force);  // F(x, U) + F_ext
  std::fill(value_.begin(), value_.end(), 0.0);
  for (int p = 0; p < body.n_points(); ++p) {
    value_[diagonal_[2*p]] = body.mass[p];
    value_[diagonal_[2*p + 1]] = body.mass[p];
  }
  for (std::size_t e = 0; e < body.springs.size(); ++e) {
    const Spring& spring = body.springs[e];
    const auto& xi = body.position[spring.i];
    const auto& xj = body.position[spring.j];
    const double dx = xj[0] - xi[0], dy = xj[1] - xi[1];
    const double length = std::sqrt(dx*dx + dy*dy);
    if (!(length > 0.0))
      throw BlowUpError("spring between points " + std::to_string(spring.i) + " and " + std::to_string(spring.j) +
                        " has zero or non-finite length");
    const double ex = dx / length, ey = dy / length;
    const double tension = spring.stiffness * (length - s * spring.natural_length0);
    const double geometric = std::max(tension / length, 0.0);  // tension only: A stays positive definite
    // S_e = k e e^T + g (I - e e^T), D_e = c e e^T; B = dt^2 S_e + dt D_e.
    const double see[3] = {spring.stiffness*ex*ex + geometric*(1.0 - ex*ex), (spring.stiffness - geometric)*ex*ey,
                           spring.stiffness*ey*ey + geometric*(1.0 - ey*ey)};
    const double dee[3] = {spring.damping*ex*ex, spring.damping*ex*ey, spring.damping*ey*ey};
    double block[3];
    for (int c = 0; c < 3; ++c) block[c] = dt*dt*see[c] + dt*dee[c];
    for (int p : {spring.i, spring.j}) {  // +B on the block of each point
      value_[diagonal_[2*p]] += block[0];
      value_[point_xy_[p]] += block[1];
      value_[diagonal_[2*p + 1]] += block[2];
    }
    // Block between the two points (rows of the lower index): -B.
    const std::array<int, 4>& q = spring_slot_[e];
    value_[q[0]] -= block[0];
    value_[q[1]] -= block[1];
    value_[q[2]] -= block[1];
    value_[q[3]] -= block[2];
    // dt S_e (U_j - U_i): the stiffness acting on this step's motion dt U (right-hand side).
    const auto& ui = body.velocity[spring.i];
    const auto& uj = body.velocity[spring.j];
    const double du[2] = {uj[0] - ui[0], uj[1] - ui[1]};
    const double f[2] = {dt * (see[0]*du[0] + see[1]*du[1]), dt * (see[1]*du[0] + see[2]*du[1])};
    external_force[spring.i][0] += f[0];
    external_force[spring.i][1] += f[1];
    external_force[spring.j][0] -= f[0];
    external_force[spring.j][1] -= f[1];
  }
  for (int p = 0; p < body.n_points(); ++p)
    for (int d = 0; d < 2; ++d) solution_[2*p + d] = dt * external_force[p][d];
  factorise();
  solve(solution_);
  for (int p = 0; p < body.n_points(); ++p)
    for (int d = 0; d < 2; ++d) external_force[p][d] = solution_[2*p + d];
}

}  // namespace ibms
