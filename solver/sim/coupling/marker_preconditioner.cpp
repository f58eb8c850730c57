// The marker system's preconditioner (marker_preconditioner.hpp, docs/method.md §3.7).
#include "sim/coupling/marker_preconditioner.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

void MarkerPreconditioner::reserve(const std::vector<BodyCoupling>& coupling, double fluid_density, double drift) {
  fluid_density_ = fluid_density;
  drift_ = drift;
  blocks_.resize(coupling.size());
  std::size_t largest = 0;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    const Eigen::Index n = static_cast<Eigen::Index>(coupling[b].marker.capacity());
    largest = std::max(largest, coupling[b].marker.capacity());
    for (int d = 0; d < 2; ++d) {
      blocks_[b].overlap[d].resize(n, n);
      // Factorised once here (the identity) so that the factors hold their storage and a defined
      // state; later factorisations of the same size reuse it.
      blocks_[b].factor[d].compute(Eigen::MatrixXd::Identity(n, n));
    }
    blocks_[b].rhs.resize(n);
    if (may_take_own_operator(coupling[b])) {
      blocks_[b].local.resize(2 * n, 2 * n);
      blocks_[b].local_factor.compute(Eigen::MatrixXd::Identity(2 * n, 2 * n));
      ExactBlockInputs& inputs = blocks_[b].inputs;
      for (auto* v : {&inputs.marker, &inputs.arm}) v->reserve(coupling[b].marker.capacity());
      for (auto* v : {&inputs.volume, &inputs.radial}) v->reserve(coupling[b].marker.capacity());
    }
    blocks_[b].normal.reserve(coupling[b].marker.capacity());
    blocks_[b].factorised_at.reserve(coupling[b].marker.capacity());
  }
  stencils_.reserve(largest);
  weights_.resize(2 * largest);
  for (auto& w : weights_) w.reserve(36);
  cells_.resize(2 * largest);
  for (auto& r : cells_) r.reserve(72);
  band_index_.resize(2 * largest);
  for (auto& r : band_index_) r.reserve(72);
  band_.reserve(16 * largest);
  band_potential_.reserve(16 * largest);
  band_green_.reserve(64 * largest * largest);  // the band holds about 5 cells per marker
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
                                     const FluidSolver::FaceRange& free_faces,
                                     std::vector<BodyCoupling>& coupling) {
  cell_area_ = grid.dx() * grid.dy();
  // Markers farther apart than the kernel's support in x or y share no node, unless a periodic
  // image brings them together (the node lists hold the wrapped nodes).
  const double reach_x = kernel_support(kernel) * grid.dx(), reach_y = kernel_support(kernel) * grid.dy();
  const bool wraps = grid.periodic_x || grid.periodic_y;
  bool moved = false;
  for (std::size_t b = 0; b < coupling.size(); ++b) {
    BodyCoupling& c = coupling[b];
    const Eigen::Index n = static_cast<Eigen::Index>(c.marker.size());
    Block& block = blocks_[b];
    // A rigid body that responds in the marker system takes A_b less its response. A mass-spring
    // rim takes, when the rims' systems are attached (ibm.rim_preconditioner = "response"),
    // (D + W R W^T rho dV)^-1 under the face constraint, D the diagonal of J_f S_f, R its response
    // on the rim points and W the markers' weights on their edges' end points (the identity when the
    // markers are the rim points; (1 - w, w) for sub-markers, docs/method.md §3.6), by Woodbury
    // through its implicit system with W^T rho dV D^-1 W added to the rim points' masses: exactly for
    // markers at the rim points, lumped to its row sums with sub-markers. O(N) a step, where its own
    // block (A_b less its response, rebuilt as the rim moves) costs more to build than the products it
    // saves (docs/method.md §3.7). Other responding rims keep the identity.
    const bool responds = !c.body_velocity_change.empty();
    const bool rigid = c.response_mass > 0.0;
    block.identity = responds && !rigid;
    block.rim = false;
    if (block.identity) {
      block.leak = 0.0;
      if (rim_systems_ != nullptr && on_faces) {
        block.rim = true;
        const int n_rim = static_cast<int>(c.triangle_momentum.size());
        block.rim_diagonal.resize(2 * n);
        block.rim_work.assign(c.response_work.size(), 0.0);
        for (Eigen::Index k = 0; k < n; ++k)
          for (int d = 0; d < 2; ++d) {
            marker_node_weights(grid, c.face_stencils[k], on_faces, d, weights_[0]);
            const double diagonal = overlap(weights_[0], weights_[0]) * c.marker_volume[k] / cell_area_;
            block.rim_diagonal[2 * k + d] = diagonal;
            marker_to_rim(c, static_cast<std::size_t>(k), n_rim, fluid_density_ * c.marker_volume[k] / diagonal, d,
                          block.rim_work);
          }
        (*rim_systems_)[b].factorise_with_added_diagonal(block.rim_work, block.rim_system);
      }
      continue;
    }
    block.exact = on_faces && may_take_own_operator(c) && n > 0;
    if (block.exact) {
      block.leak = 0.0;
      ExactBlockInputs& inputs = block.inputs;
      if (block.restored) {  // a restarted run: the block in use when the checkpoint was written
        build_local(grid, kernel, free_faces, c, block);
        block.restored = false;
      }
      if (inputs.marker.size() == c.marker.size()) {
        double drift = 0.0;
        for (Eigen::Index k = 0; k < n; ++k)
          drift = std::max({drift, std::abs(c.marker[k][0] - inputs.marker[k][0]) / grid.dx(),
                            std::abs(c.marker[k][1] - inputs.marker[k][1]) / grid.dy()});
        if (drift <= drift_) continue;
      }
      inputs.marker.assign(c.marker.begin(), c.marker.end());
      inputs.volume.assign(c.marker_volume.begin(), c.marker_volume.end());
      inputs.radial.assign(c.marker_fraction_work.begin(), c.marker_fraction_work.end());
      if (rigid)
        inputs.arm.assign(c.rigid_arm.begin(), c.rigid_arm.end());
      else
        inputs.arm.clear();
      build_local(grid, kernel, free_faces, c, block);
      continue;
    }
    if (block.factorised_at == c.marker) continue;
    block.factorised_at.assign(c.marker.begin(), c.marker.end());
    block.leak = 0.0;
    moved = true;
    for (int d = 0; d < 2; ++d) {
      for (Eigen::Index k = 0; k < n; ++k) marker_node_weights(grid, c.face_stencils[k], on_faces, d, weights_[k]);
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

void MarkerPreconditioner::restore_inputs(std::size_t body, const ExactBlockInputs& inputs) {
  Block& block = blocks_[body];
  block.inputs.marker.assign(inputs.marker.begin(), inputs.marker.end());
  block.inputs.volume.assign(inputs.volume.begin(), inputs.volume.end());
  block.inputs.radial.assign(inputs.radial.begin(), inputs.radial.end());
  block.inputs.arm.assign(inputs.arm.begin(), inputs.arm.end());
  block.restored = !inputs.marker.empty();
}

// A_b = J_f P_0 S_f of one body on the unbounded grid at block.inputs (marker_preconditioner.hpp).
void MarkerPreconditioner::build_local(const Grid& grid, KernelKind kernel, const FluidSolver::FaceRange& free_faces,
                                       BodyCoupling& c, Block& block) {
  const ExactBlockInputs& inputs = block.inputs;
  const int n = static_cast<int>(inputs.marker.size());
  map_face_stencils(grid, kernel, inputs.marker, stencils_);
  const int nx = grid.nx, ny = grid.ny;
  const double dx = grid.dx(), dy = grid.dy();
  // Offsets between two cells of the body, the nearest periodic image.
  const auto offset = [&](int a, int b, int period, bool periodic) {
    int d = a - b;
    if (periodic) d -= period * static_cast<int>(std::lround(static_cast<double>(d) / period));
    return d;
  };
  // The face nodes of every marker and component, and R (the cells of J_f G_f) from them: a face
  // between cells a (below) and b (above) gives b + w / h and a - w / h. Faces the projection does
  // not correct (walls, inflows) carry no increment and are left out of both C and R.
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < 2; ++d) {
      std::vector<NodeWeight>& nodes = weights_[2 * k + d];
      marker_node_weights(grid, stencils_[k], /*on_faces=*/true, d, nodes);
      std::vector<CellWeight>& r = cells_[2 * k + d];
      r.clear();
      std::size_t corrected = 0;  // the nodes kept for C: the corrected faces only
      for (const NodeWeight& w : nodes) {
        if (d == 0) {
          const int i = w.node % (nx + 1), j = w.node / (nx + 1);
          if (i < free_faces.x_first || i > free_faces.x_last) continue;
          const int below = grid.periodic_x && i == 0 ? nx - 1 : i - 1;
          r.push_back({i, j, w.weight / dx});
          r.push_back({below, j, -w.weight / dx});
        } else {
          const int i = w.node % nx, j = w.node / nx;
          if (j < free_faces.y_first || j > free_faces.y_last) continue;
          const int below = grid.periodic_y && j == 0 ? ny - 1 : j - 1;
          r.push_back({i, j, w.weight / dy});
          r.push_back({i, below, -w.weight / dy});
        }
        nodes[corrected++] = w;
      }
      nodes.resize(corrected);
      std::sort(r.begin(), r.end(), [](const CellWeight& a, const CellWeight& b) {
        return a.j != b.j ? a.j < b.j : a.i < b.i;
      });
      std::size_t kept = 0;
      for (std::size_t q = 0; q < r.size(); ++q) {
        if (kept > 0 && r[kept - 1].i == r[q].i && r[kept - 1].j == r[q].j)
          r[kept - 1].weight += r[q].weight;
        else
          r[kept++] = r[q];
      }
      r.resize(kept);
    }
  // The body's cells, unwrapped around the first one in a periodic direction.
  const CellWeight* first = nullptr;
  for (int k = 0; k < 2 * n && first == nullptr; ++k)
    if (!cells_[k].empty()) first = &cells_[k].front();
  if (first == nullptr) {  // no marker touches a corrected face: nothing to hold
    block.local.setIdentity(2 * n, 2 * n);
    block.local_factor.compute(block.local);
    return;
  }
  int low_i = first->i, high_i = first->i, low_j = first->j, high_j = first->j;
  for (int k = 0; k < 2 * n; ++k)
    for (const CellWeight& a : cells_[k]) {
      const int i = first->i + offset(a.i, first->i, nx, grid.periodic_x);
      const int j = first->j + offset(a.j, first->j, ny, grid.periodic_y);
      low_i = std::min(low_i, i);
      high_i = std::max(high_i, i);
      low_j = std::min(low_j, j);
      high_j = std::max(high_j, j);
    }
  const int extent = std::max(high_i - low_i, high_j - low_j);
  // The image of the nearer side in each direction with walls, when the body is within its own
  // extent of it: a wall or an inflow (phi even about the face) adds G(a - b*), an outflow
  // (phi = 0 on the face, odd) subtracts it; b* = -1 - b (low side) or 2 n - 1 - b (high side).
  // Farther sides and further images are smooth over the rim: the iteration takes them.
  struct Image {
    int sign = 0;    // 0: none
    int mirror = 0;  // b* = mirror - b
  };
  const auto image = [&](int low, int high, int cells, bool periodic, bool low_outflow, bool high_outflow) {
    if (periodic) return Image{};
    const int to_low = low, to_high = cells - 1 - high;
    if (to_low <= to_high && to_low <= extent) return Image{low_outflow ? -1 : 1, -1};
    if (to_high < to_low && to_high <= extent) return Image{high_outflow ? -1 : 1, 2 * cells - 1};
    return Image{};
  };
  const Image image_x = image(low_i, high_i, nx, grid.periodic_x, free_faces.x_first == 0, free_faces.x_last == nx);
  const Image image_y = image(low_j, high_j, ny, grid.periodic_y, free_faces.y_first == 0, free_faces.y_last == ny);
  int reach = extent;
  if (image_x.sign != 0) reach = std::max({reach, std::abs(2 * low_i - image_x.mirror), std::abs(2 * high_i - image_x.mirror)});
  if (image_y.sign != 0) reach = std::max({reach, std::abs(2 * low_j - image_y.mirror), std::abs(2 * high_j - image_y.mirror)});
  green_.ensure(dx, dy, reach + 1);
  const auto green = [&](const CellWeight& a, const CellWeight& b) {
    const int di = offset(a.i, b.i, nx, grid.periodic_x), dj = offset(a.j, b.j, ny, grid.periodic_y);
    double g = green_(di, dj);
    if (image_x.sign != 0) g += image_x.sign * green_(a.i + b.i - image_x.mirror, dj);
    if (image_y.sign != 0) g += image_y.sign * green_(di, a.j + b.j - image_y.mirror);
    if (image_x.sign != 0 && image_y.sign != 0)
      g += image_x.sign * image_y.sign * green_(a.i + b.i - image_x.mirror, a.j + b.j - image_y.mirror);
    return g;
  };
  // The cells all the R_k touch (the band along the rim), G among them once, then for each
  // column q the potential T_q = G R_q on the band, and A_pq = C_pq + R_p . T_q.
  band_.clear();
  for (int k = 0; k < 2 * n; ++k)
    for (const CellWeight& a : cells_[k]) band_.push_back({a.j, a.i});
  std::sort(band_.begin(), band_.end());
  band_.erase(std::unique(band_.begin(), band_.end()), band_.end());
  const std::size_t cells = band_.size();
  for (int k = 0; k < 2 * n; ++k) {
    band_index_[k].clear();
    for (const CellWeight& a : cells_[k])
      band_index_[k].push_back(static_cast<int>(
          std::lower_bound(band_.begin(), band_.end(), std::array<int, 2>{a.j, a.i}) - band_.begin()));
  }
  band_green_.resize(cells * cells);
  for (std::size_t r = 0; r < cells; ++r)
    for (std::size_t t = 0; t <= r; ++t) {
      const CellWeight a{band_[r][1], band_[r][0], 0.0}, b{band_[t][1], band_[t][0], 0.0};
      band_green_[r * cells + t] = band_green_[t * cells + r] = green(a, b);
    }
  band_potential_.resize(cells);
  Eigen::MatrixXd& A = block.local;
  A.resize(2 * n, 2 * n);
  const double inv_cell = 1.0 / (dx * dy);
  for (int q = 0; q < 2 * n; ++q) {
    std::fill(band_potential_.begin(), band_potential_.end(), 0.0);
    for (std::size_t e = 0; e < cells_[q].size(); ++e) {
      const double w = cells_[q][e].weight;
      const double* column = band_green_.data() + static_cast<std::size_t>(band_index_[q][e]) * cells;
      for (std::size_t r = 0; r < cells; ++r) band_potential_[r] += w * column[r];
    }
    for (int p = 0; p < 2 * n; ++p) {
      // C: the kernels' overlap on the corrected faces of one component.
      double sum = p % 2 == q % 2 ? overlap(weights_[p], weights_[q]) : 0.0;
      for (std::size_t e = 0; e < cells_[p].size(); ++e) sum += cells_[p][e].weight * band_potential_[band_index_[p][e]];
      A(p, q) = sum * inputs.volume[q / 2] * inv_cell;
    }
  }
  // A rigid body that responds: less its response to each unit impulse (the product's y -= R x).
  if (!inputs.arm.empty()) {
    for (int q = 0; q < 2 * n; ++q) {
      for (Vec2& v : c.pass_increment) v = {0.0, 0.0};
      c.pass_increment[q / 2][q % 2] = 1.0;
      rigid_response(fluid_density_, c, inputs.arm, inputs.volume, inputs.radial, c.pass_increment, c.pass_force);
      for (int p = 0; p < 2 * n; ++p) A(p, q) -= c.pass_force[p / 2][p % 2];
    }
  }
  block.local_factor.compute(A);
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
    if (block.rim) {
      // x = D^-1 (v - W y), (K + W^T rho dV D^-1 W) y = W^T rho dV D^-1 v on the rim points.
      std::vector<double>& t = block.rim_work;
      std::fill(t.begin(), t.end(), 0.0);
      const int n_rim = static_cast<int>(c.triangle_momentum.size());
      for (Eigen::Index q = 0; q < 2 * n; ++q)
        marker_to_rim(c, static_cast<std::size_t>(q / 2), n_rim,
                      fluid_density_ * c.marker_volume[q / 2] * v[first + q] / block.rim_diagonal[q],
                      static_cast<int>(q % 2), t);
      block.rim_system.response(t);
      for (Eigen::Index q = 0; q < 2 * n; ++q)
        x[first + q] = (v[first + q] - rim_to_marker(c, static_cast<std::size_t>(q / 2), n_rim, t, static_cast<int>(q % 2))) /
                       block.rim_diagonal[q];
      first += 2 * static_cast<std::size_t>(n);
      continue;
    }
    if (block.identity) {
      std::copy(v + first, v + first + 2 * n, x + first);
      first += 2 * static_cast<std::size_t>(n);
      continue;
    }
    if (block.exact) {
      Eigen::Map<Eigen::VectorXd>(x + first, 2 * n) = block.local_factor.solve(Eigen::Map<const Eigen::VectorXd>(v + first, 2 * n));
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
