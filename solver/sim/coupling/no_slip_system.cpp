// GMRES on the marker constraint of the no_slip coupling (see no_slip_coupling.hpp).
#include "sim/coupling/no_slip_system.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

void NoSlipWorkspace::reserve(std::size_t n) {
  basis.assign((restart + 1) * n, 0.0);
  images.assign(restart * n, 0.0);
  hessenberg.assign((restart + 1) * restart, 0.0);
  cosine.assign(restart, 0.0);
  sine.assign(restart, 0.0);
  rotated.assign(restart + 1, 0.0);
  coefficients.assign(restart, 0.0);
  rhs.reserve(n);
  solution.reserve(n);
  residual.reserve(n);
  preconditioned.reserve(n);
}

namespace {

std::size_t unknowns(const std::vector<BodyCoupling>& coupling) {
  std::size_t n = 0;
  for (const BodyCoupling& c : coupling) n += 2 * c.marker.size();
  return n;
}

// Marker vector (scaled by each body's reference speed) <-> pass_increment [length/time].
void scatter(const double* x, std::vector<BodyCoupling>& coupling) {
  std::size_t k = 0;
  for (BodyCoupling& c : coupling)
    for (auto& u : c.pass_increment)
      for (int d = 0; d < 2; ++d) u[d] = c.slip_reference_speed * x[k++];
}

// Largest |r_l| over the markers, r_l the 2-vector of marker l.
double max_marker_norm(const double* r, std::size_t n) {
  double largest = 0.0;
  for (std::size_t k = 0; k + 1 < n; k += 2) largest = std::max(largest, std::hypot(r[k], r[k + 1]));
  return largest;
}

double dot(const double* a, const double* b, std::size_t n) {
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) s += a[k] * b[k];
  return s;
}

}  // namespace

NoSlipResult hold_no_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, double dt,
                          double tolerance, bool on_faces, bool cells_from_faces, int max_products, FluidSolver& solver, FluidState& state,
                          std::vector<BodyCoupling>& coupling, CellField& increment_x, CellField& increment_y,
                          FaceField& face_increment_x, FaceField& face_increment_y, NoSlipWorkspace& work,
                          const BodyResponse& response, MarkerPreconditioner* preconditioner) {
  NoSlipResult result;
  const std::size_t n = unknowns(coupling);
  work.preconditioned.resize(n);
  // x = M^-1 v (marker_preconditioner.hpp), or v without a preconditioner.
  const auto precondition = [&](const double* v) -> const double* {
    if (preconditioner == nullptr) return v;
    preconditioner->apply(coupling, v, work.preconditioned.data());
    return work.preconditioned.data();
  };
  const int m_max = NoSlipWorkspace::restart;
  const WallVelocities at_rest{};  // the increments have homogeneous wall data
  // dt S_f dF onto the faces, dt dF in pass_increment.
  const auto spread_face_increment = [&]() {
    face_increment_x.fill(0.0);
    face_increment_y.fill(0.0);
    for (BodyCoupling& c : coupling)
      spread_to_faces(grid, c.face_stencils, c.pass_increment, c.marker_volume, face_increment_x, face_increment_y);
  };
  // ... and onto the cells: by the kernel, or the faces' mean (cells_from_faces).
  const auto spread_increment = [&]() {
    increment_x.fill(0.0);
    increment_y.fill(0.0);
    spread_face_increment();
    if (cells_from_faces)
      average_faces_to_cells(grid, face_increment_x, face_increment_y, increment_x, increment_y);
    else
      for (BodyCoupling& c : coupling)
        spread(grid, c.face_stencils, c.pass_increment, c.marker_volume, increment_x, increment_y);
  };
  // body_velocity_change of the responding bodies from the forces so far (pass_force: scratch).
  const auto update_body_change = [&]() {
    if (!response) return;
    for (std::size_t b = 0; b < coupling.size(); ++b) {
      BodyCoupling& c = coupling[b];
      if (c.body_velocity_change.empty()) continue;
      for (std::size_t l = 0; l < c.marker.size(); ++l)
        for (int d = 0; d < 2; ++d) c.pass_force[l][d] = dt * c.forcing_sum[l][d];
      response(b, c.pass_force, c.body_velocity_change);
    }
  };
  // y = J P_0 S (U_ref x) / U_ref: the cell or face part of the projected increment at the markers,
  // less the rim's response to it where the body responds.
  // Under the face constraint with the cells from the faces the product reads the projected faces
  // only: the cells' increment is left to the correction at the end.
  const bool faces_only = on_faces && cells_from_faces;
  // The faces' own projection in place and the corrections from the products' potentials assume
  // the face term's time scale is the step's (fluid.interpolation_time = 0).
  const bool in_place = faces_only && !solver.fixed_interpolation_time();
  const auto product = [&](const double* x, double* y) {
    scatter(x, coupling);
    if (in_place) {
      spread_face_increment();
      solver.project_faces_in_place(dt, face_increment_x, face_increment_y);
    } else if (faces_only) {
      spread_face_increment();
      solver.homogeneous_face_projection(dt, face_increment_x, face_increment_y);
    } else {
      spread_increment();
      solver.homogeneous_projection(dt, increment_x, increment_y, &face_increment_x, &face_increment_y);
    }
    std::size_t k = 0;
    for (std::size_t b = 0; b < coupling.size(); ++b) {
      BodyCoupling& c = coupling[b];
      const std::size_t first = k;
      if (in_place)
        interpolate_faces(grid, c.face_stencils, at_rest, face_increment_x, face_increment_y, c.interpolated_velocity);
      else if (on_faces)
        interpolate_faces(grid, c.face_stencils, at_rest, solver.projected_face_increment_x(),
                          solver.projected_face_increment_y(), c.interpolated_velocity);
      else
        interpolate(grid, kernel, at_rest, increment_x, increment_y, c.marker, c.interpolated_velocity);
      for (const auto& u : c.interpolated_velocity)
        for (int d = 0; d < 2; ++d) y[k++] = u[d] / c.slip_reference_speed;
      if (response && !c.body_velocity_change.empty()) {
        response(b, c.pass_increment, c.pass_force);  // pass_increment = dt dF of this product
        for (std::size_t l = 0; l < c.marker.size(); ++l)
          for (int d = 0; d < 2; ++d) y[first + 2 * l + d] -= c.pass_force[l][d] / c.slip_reference_speed;
      }
    }
    ++result.products;
  };
  // The right-preconditioned system: y = A M^-1 v.
  const auto apply = [&](const double* v, double* y) { product(precondition(v), y); };

  double previous_slip = HUGE_VAL;
  bool prepared = false;
  for (;;) {
    update_body_change();
    // The slip of the constrained velocity, r = (U_target - J u) / U_ref of u^{n+1} or J_f U_f^{n+1}
    // (measure_slip / measure_face_slip leave U_target - J u in pass_increment).
    const double slip = on_faces ? measure_face_slip(grid, walls, state.velocity_face_x, state.velocity_face_y, coupling)
                                 : measure_slip(grid, kernel, walls, state.velocity_x, state.velocity_y, coupling);
    if (slip <= tolerance || result.products >= max_products) break;
    // A cycle that did not halve the slip has met the floor of the marker system (a part of the
    // target that the constrained velocity cannot take, §3.7): further products would not lower it.
    if (slip > 0.5 * previous_slip) break;
    previous_slip = slip;
    work.rhs.resize(n);
    work.solution.resize(n);
    work.residual.resize(n);
    {
      std::size_t k = 0;
      for (const BodyCoupling& c : coupling)
        for (const auto& r : c.pass_increment)
          for (int d = 0; d < 2; ++d) work.rhs[k++] = r[d] / c.slip_reference_speed;
    }
    // The preconditioner at the step's markers, once the slip asks for a correction: the blocks, and
    // each body's leak from one product for all bodies (the leak of one body at another's markers
    // is left out; the product overwrites pass_increment, read above), both kept while no body moves.
    if (preconditioner != nullptr && !prepared) {
      if (preconditioner->factorise(grid, kernel, on_faces, solver.corrected_faces(), coupling)) {
        preconditioner->normal_pattern(coupling, work.solution.data());
        product(work.solution.data(), work.residual.data());
        preconditioner->set_leaks(coupling, work.residual.data());
      }
      prepared = true;
    }
    std::fill(work.solution.begin(), work.solution.end(), 0.0);
    // One GMRES cycle from x = 0, stopped when the true residual's largest marker slip is half the
    // tolerance (the margin absorbs the round-off of applying the correction on the grid).
    const double beta = std::sqrt(dot(work.rhs.data(), work.rhs.data(), n));
    double* V = work.basis.data();
    double* W = work.images.data();
    double* H = work.hessenberg.data();
    const auto h = [&](int i, int j) -> double& { return H[i + (m_max + 1) * j]; };
    for (std::size_t k = 0; k < n; ++k) V[k] = work.rhs[k] / beta;
    std::fill(work.rotated.begin(), work.rotated.end(), 0.0);
    work.rotated[0] = beta;
    int m = 0;
    // potentials phi_j kept (-1: none, the corrections projected with a solve of their own)
    const int kept = solver.fixed_interpolation_time() ? -1 : static_cast<int>(work.potentials.size()) - 1;
    while (m < m_max && result.products < max_products) {
      const int j = m;
      double* w = V + (j + 1) * n;
      apply(V + j * n, W + j * n);
      if (j < kept) work.potentials[j] = solver.correction_potential();
      std::copy(W + j * n, W + (j + 1) * n, w);
      for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        h(i, j) = dot(w, V + i * n, n);
        for (std::size_t k = 0; k < n; ++k) w[k] -= h(i, j) * V[i * n + k];
      }
      h(j + 1, j) = std::sqrt(dot(w, w, n));
      const bool breakdown = !(h(j + 1, j) > 0.0);  // the Krylov space holds the solution
      if (!breakdown)
        for (std::size_t k = 0; k < n; ++k) w[k] /= h(j + 1, j);
      for (int i = 0; i < j; ++i) {  // the previous rotations on the new column
        const double a = h(i, j), b = h(i + 1, j);
        h(i, j) = work.cosine[i] * a + work.sine[i] * b;
        h(i + 1, j) = -work.sine[i] * a + work.cosine[i] * b;
      }
      const double a = h(j, j), b = h(j + 1, j), r = std::hypot(a, b);
      work.cosine[j] = r > 0.0 ? a / r : 1.0;
      work.sine[j] = r > 0.0 ? b / r : 0.0;
      h(j, j) = r;
      h(j + 1, j) = 0.0;
      work.rotated[j + 1] = -work.sine[j] * work.rotated[j];
      work.rotated[j] *= work.cosine[j];
      m = j + 1;
      // Coefficients y of x = V y (back substitution), and the true residual b - A V y.
      for (int i = m - 1; i >= 0; --i) {
        double s = work.rotated[i];
        for (int l = i + 1; l < m; ++l) s -= h(i, l) * work.coefficients[l];
        work.coefficients[i] = h(i, i) != 0.0 ? s / h(i, i) : 0.0;
      }
      std::copy(work.rhs.begin(), work.rhs.end(), work.residual.begin());
      for (int i = 0; i < m; ++i)
        for (std::size_t k = 0; k < n; ++k) work.residual[k] -= work.coefficients[i] * W[i * n + k];
      if (max_marker_norm(work.residual.data(), n) <= 0.5 * tolerance || breakdown) break;
    }
    for (int i = 0; i < m; ++i)
      for (std::size_t k = 0; k < n; ++k) work.solution[k] += work.coefficients[i] * V[i * n + k];
    // The correction x = M^-1 V y: forcing_sum += U_ref x / dt; u^{n+1}, U_f^{n+1}, p^{n+1} += the
    // projection of S (U_ref x).
    scatter(precondition(work.solution.data()), coupling);
    for (BodyCoupling& c : coupling)
      for (std::size_t l = 0; l < c.marker.size(); ++l)
        for (int d = 0; d < 2; ++d) c.forcing_sum[l][d] += c.pass_increment[l][d] / dt;
    spread_increment();
    if (m <= kept) {
      // phi = sum_j y_j phi_j: the correction's potential from the products' own.
      CellField& phi = work.potentials[kept];
      const std::size_t size = static_cast<std::size_t>(phi.stride()) * (phi.ny() + 2);
      double* out = phi.data();
      std::fill(out, out + size, 0.0);
      for (int i = 0; i < m; ++i) {
        const double* in = work.potentials[i].data();
        const double y = work.coefficients[i];
        for (std::size_t k = 0; k < size; ++k) out[k] += y * in[k];
      }
      result.max_change += solver.add_projected_increment(state, dt, increment_x, increment_y, face_increment_x,
                                                          face_increment_y, phi);
    } else {
      result.max_change +=
          solver.project_increment(state, dt, increment_x, increment_y, &face_increment_x, &face_increment_y);
    }
  }
  return result;
}

}  // namespace ibms
