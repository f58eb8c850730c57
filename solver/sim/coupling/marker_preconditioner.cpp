// The marker system's preconditioner (marker_preconditioner.hpp, docs/method.md §3.7).
#include "sim/coupling/marker_preconditioner.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

void MarkerPreconditioner::reserve(const std::vector<BodyCoupling>& coupling) {
  blocks_.resize(coupling.size());
  std::size_t largest = 0;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    const Eigen::Index n = static_cast<Eigen::Index>(coupling[b].marker.capacity());
    largest = std::max(largest, coupling[b].marker.capacity());
    for (int d = 0; d < 2; ++d) {
      blocks_[b].overlap[d].resize(n, n);
      blocks_[b].factor[d] = Eigen::LLT<Eigen::MatrixXd>(n);
    }
    blocks_[b].rhs.resize(n);
    blocks_[b].normal.reserve(coupling[b].marker.capacity());
    blocks_[b].factorised_at.reserve(coupling[b].marker.capacity());
  }
  weights_.resize(largest);
  for (auto& w : weights_) w.reserve(36);
}

namespace {

// The sum over the nodes both lists touch of the product of their weights (lists sorted by node).
double overlap(const std::vector<NodeWeight>& a, const std::vector<NodeWeight>& b) {
  double sum = 0.0;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i].node < b[j].node)
      ++i;
    else if (b[j].node < a[i].node)
      ++j;
    else
      sum += a[i++].weight * b[j++].weight;
  }
  return sum;
}

// <v . n> over a body's markers.
double mean_normal(const std::vector<Vec2>& normal, const double* v) {
  double sum = 0.0;
  for (std::size_t k = 0; k < normal.size(); ++k) sum += v[2 * k] * normal[k][0] + v[2 * k + 1] * normal[k][1];
  return normal.empty() ? 0.0 : sum / static_cast<double>(normal.size());
}

}  // namespace

bool MarkerPreconditioner::factorise(const Grid& grid, KernelKind kernel, bool on_faces,
                                     const std::vector<BodyCoupling>& coupling) {
  cell_area_ = grid.dx() * grid.dy();
  // Markers farther apart than the kernel's support in x or y share no node, unless a periodic
  // image brings them together (the node lists hold the wrapped nodes).
  const double reach_x = kernel_support(kernel) * grid.dx(), reach_y = kernel_support(kernel) * grid.dy();
  const bool wraps = grid.periodic_x || grid.periodic_y;
  bool moved = false;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    const BodyCoupling& c = coupling[b];
    const Eigen::Index n = static_cast<Eigen::Index>(c.marker.size());
    Block& block = blocks_[b];
    // A body whose rim responds in the marker system (mass-spring) keeps the identity: its rim's
    // inertia and springs, not the kernel, set that part of the system.
    block.identity = !c.body_velocity_change.empty();
    if (block.identity) {
      block.leak = 0.0;
      continue;
    }
    if (block.factorised_at == c.marker) continue;
    moved = true;
    block.factorised_at.assign(c.marker.begin(), c.marker.end());
    for (int d = 0; d < 2; ++d) {
      for (Eigen::Index k = 0; k < n; ++k) marker_node_weights(grid, kernel, c.marker[k], on_faces, d, weights_[k]);
      Eigen::MatrixXd& C = block.overlap[d];
      C.resize(n, n);
      double largest = 0.0;
      for (Eigen::Index k = 0; k < n; ++k) {
        C(k, k) = overlap(weights_[k], weights_[k]);
        largest = std::max(largest, C(k, k));
        for (Eigen::Index l = k + 1; l < n; ++l) {
          const bool near = std::abs(c.marker[k][0] - c.marker[l][0]) < reach_x &&
                            std::abs(c.marker[k][1] - c.marker[l][1]) < reach_y;
          C(k, l) = C(l, k) = near || wraps ? overlap(weights_[k], weights_[l]) : 0.0;
        }
      }
      // Markers closer than the kernel resolves make C nearly singular; the shift bounds the
      // preconditioner's gain on such a pattern (the kernel cannot carry it either).
      C.diagonal().array() += 1e-8 * largest;
      block.factor[d].compute(C);
    }
    // The markers run along the rim in order: the normal at marker l is that of the chord from
    // l - 1 to l + 1, turned outward by the sign of the polygon's area.
    double twice_area = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const Vec2& a = c.marker[k];
      const Vec2& z = c.marker[(k + 1) % n];
      twice_area += a[0] * z[1] - z[0] * a[1];
    }
    const double orientation = twice_area >= 0.0 ? 1.0 : -1.0;
    block.normal.resize(c.marker.size());
    for (Eigen::Index k = 0; k < n; ++k) {
      const Vec2& before = c.marker[(k + n - 1) % n];
      const Vec2& after = c.marker[(k + 1) % n];
      const double tx = after[0] - before[0], ty = after[1] - before[1], length = std::hypot(tx, ty);
      block.normal[k] = length > 0.0 ? Vec2{orientation * ty / length, -orientation * tx / length} : Vec2{0.0, 0.0};
    }
    block.leak = 0.0;
  }
  return moved;
}

void MarkerPreconditioner::normal_pattern(const std::vector<BodyCoupling>& coupling, double* z) const {
  std::size_t first = 0;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    for (std::size_t k = 0; k < coupling[b].marker.size(); ++k)
      for (int d = 0; d < 2; ++d) z[first + 2 * k + d] = blocks_[b].identity ? 0.0 : blocks_[b].normal[k][d];
    first += 2 * coupling[b].marker.size();
  }
}

void MarkerPreconditioner::set_leaks(const std::vector<BodyCoupling>& coupling, const double* y) {
  std::size_t first = 0;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    const double leak = blocks_[b].identity ? 0.0 : mean_normal(blocks_[b].normal, y + first);
    // A body too small to hold a pressure (fewer than three markers) or a leak of the wrong sign
    // (the pattern is not a pressure there) gets no leak part.
    blocks_[b].leak = coupling[b].marker.size() >= 3 && leak > 0.0 ? leak : 0.0;
    first += 2 * coupling[b].marker.size();
  }
}

void MarkerPreconditioner::apply(const std::vector<BodyCoupling>& coupling, const double* v, double* x) {
  std::size_t first = 0;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    const BodyCoupling& c = coupling[b];
    const Eigen::Index n = static_cast<Eigen::Index>(c.marker.size());
    Block& block = blocks_[b];
    if (block.identity) {
      std::copy(v + first, v + first + 2 * n, x + first);
      first += 2 * static_cast<std::size_t>(n);
      continue;
    }
    for (int d = 0; d < 2; ++d) {
      block.rhs.resize(n);
      for (Eigen::Index k = 0; k < n; ++k) block.rhs[k] = v[first + 2 * k + d];
      block.factor[d].solveInPlace(block.rhs);
      for (Eigen::Index k = 0; k < n; ++k) x[first + 2 * k + d] = block.rhs[k] * cell_area_ / c.marker_volume[k];
    }
    if (block.leak > 0.0) {
      const double amount = mean_normal(block.normal, v + first) / block.leak;
      for (Eigen::Index k = 0; k < n; ++k)
        for (int d = 0; d < 2; ++d) x[first + 2 * k + d] += amount * block.normal[k][d];
    }
    first += 2 * static_cast<std::size_t>(n);
  }
}

}  // namespace ibms
