// SMAC projection with momentum interpolation on a collocated grid: docs/method.md §2.3, §2.5, §6.
#include "fluid/fluid_solver.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>

#include "fluid/operators.hpp"
#include "fluid/threads.hpp"

namespace ibms {
namespace {

// Spectral boundary kind of one side for the pressure Poisson problem (phi: Neumann where the
// face flux is given, Dirichlet p = 0 at an outflow) or the velocity Helmholtz problem (Dirichlet
// where the velocity is given, Neumann at an outflow).
SpectralBoundary poisson_kind(SideKind k) {
  if (k == SideKind::periodic) return SpectralBoundary::periodic;
  return k == SideKind::outflow ? SpectralBoundary::dirichlet : SpectralBoundary::neumann;
}
SpectralBoundary helmholtz_kind(SideKind k) {
  if (k == SideKind::periodic) return SpectralBoundary::periodic;
  return k == SideKind::outflow ? SpectralBoundary::neumann : SpectralBoundary::dirichlet;
}

}  // namespace

double upwind_kappa(ConvectionScheme scheme) {
  switch (scheme) {
    case ConvectionScheme::quick: return 0.5;
    case ConvectionScheme::fromm: return 0.0;
    case ConvectionScheme::upwind3: return 1.0 / 3.0;
    case ConvectionScheme::central: break;
  }
  return 1.0;
}

const char* convection_name(ConvectionScheme scheme) {
  switch (scheme) {
    case ConvectionScheme::quick: return "QUICK";
    case ConvectionScheme::fromm: return "Fromm";
    case ConvectionScheme::upwind3: return "third-order upwind-biased (kappa 1/3)";
    case ConvectionScheme::central: break;
  }
  return "central";
}

FluidSolver::FluidSolver(const Grid& grid, double kinematic_viscosity, const FluidBoundaries& boundaries,
                         FluidSchemes schemes)
    : grid_(grid), nu_(kinematic_viscosity), boundaries_(boundaries), schemes_(schemes),
      star_x_(grid), star_y_(grid), conv_x_(grid), conv_y_(grid), lap_x_(grid), lap_y_(grid),
      grad_x_(grid), grad_y_(grid), phi_(grid), work_(grid),
      star_face_x_(FaceField::x_faces(grid)), star_face_y_(FaceField::y_faces(grid)),
      buffer_(grid.n_cells()), buffer_y_(grid.n_cells()) {
  boundaries_.periodic_x = grid.periodic_x;
  boundaries_.periodic_y = grid.periodic_y;
  for (const Side s : all_sides)
    boundaries_.side(s).kind = boundaries_.kind(grid, s);
  const BoundarySide &l = boundaries_.left, &r = boundaries_.right, &b = boundaries_.bottom, &t = boundaries_.top;
  poisson_ = std::make_unique<SpectralSolver>(grid, poisson_kind(l.kind), poisson_kind(r.kind), poisson_kind(b.kind),
                                              poisson_kind(t.kind), schemes.fft_planning);
  helmholtz_ = std::make_unique<SpectralSolver>(grid, helmholtz_kind(l.kind), helmholtz_kind(r.kind),
                                                helmholtz_kind(b.kind), helmholtz_kind(t.kind), schemes.fft_planning);
  helmholtz_y_ = std::make_unique<SpectralSolver>(grid, helmholtz_kind(l.kind), helmholtz_kind(r.kind),
                                                  helmholtz_kind(b.kind), helmholtz_kind(t.kind), schemes.fft_planning);
  interpolation_time_ = schemes.interpolation_time;
}

void FluidSolver::mixed_eigenvalues(double ratio) {
  if (ratio == mixed_ratio_ && !mixed_x_.empty()) return;
  const auto mix = [ratio](const std::vector<double>& lambda, double h, std::vector<double>& out) {
    out.resize(lambda.size());
    for (std::size_t k = 0; k < lambda.size(); ++k)
      out[k] = ratio * lambda[k] + (1.0 - ratio) * lambda[k] * (1.0 + 0.25 * lambda[k] * h * h);
  };
  mix(poisson_->eigenvalues_x(), grid_.dx(), mixed_x_);
  mix(poisson_->eigenvalues_y(), grid_.dy(), mixed_y_);
  mixed_ratio_ = ratio;
}

SpectralSolveStats FluidSolver::solve_poisson(double ratio) {
  if (ratio == 1.0) return poisson_->solve(/*a=*/0.0, /*b=*/1.0, buffer_.data(), buffer_.data());
  mixed_eigenvalues(ratio);
  return poisson_->solve(/*a=*/0.0, /*b=*/1.0, buffer_.data(), buffer_.data(), mixed_x_, mixed_y_);
}

void FluidSolver::correct_faces(double dt, double ratio, FaceField& face_x, FaceField& face_y) const {
  // grad_ holds G_c phi with even ghosts: M G_c phi at an outflow face is the last cell's G_c phi,
  // the mean under the transform's extension (phi odd about the face, G_c phi even).
  const FaceRange faces = corrected_faces();
  const double inv_dx = 1.0 / grid_.dx(), inv_dy = 1.0 / grid_.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i)
      face_x(i, j) -= dt * (ratio * (phi_(i, j) - phi_(i - 1, j)) * inv_dx +
                            (1.0 - ratio) * 0.5 * (grad_x_(i - 1, j) + grad_x_(i, j)));
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i)
      face_y(i, j) -= dt * (ratio * (phi_(i, j) - phi_(i, j - 1)) * inv_dy +
                            (1.0 - ratio) * 0.5 * (grad_y_(i, j - 1) + grad_y_(i, j)));
}

void FluidSolver::set_given_faces(double time, FaceField& face_x, FaceField& face_y) const {
  for (const Side s : all_sides) {
    if (!boundaries_.side(s).is_dirichlet()) continue;
    const SideCells c = side_cells(grid_, s);
    FaceField& faces = c.normal_to_x ? face_x : face_y;
    const int normal = c.normal_to_x ? 0 : 1;  // the velocity component through the side
    for (int n = 0; n < c.count; ++n) {
      const std::array<double, 2> at = side_point(grid_, s, n);
      faces(c.face_i(n), c.face_j(n)) = boundaries_.velocity_at(grid_, s, at[0], at[1], time)[normal];
    }
  }
}

FluidSolver::FaceRange FluidSolver::corrected_faces() const {
  // Faces whose flux the projection corrects: interior faces, a periodic direction's first face
  // (its last is synced from it) and outflow faces; faces with a given flux (walls, inflows) keep it.
  const auto given = [&](Side s) { return boundaries_.side(s).is_dirichlet(); };
  const auto outflow = [&](Side s) { return boundaries_.side(s).kind == SideKind::outflow; };
  return {given(Side::left) ? 1 : 0, outflow(Side::right) ? grid_.nx : grid_.nx - 1,
          given(Side::bottom) ? 1 : 0, outflow(Side::top) ? grid_.ny : grid_.ny - 1};
}

FluidState FluidSolver::make_state() const {
  FluidState s;
  s.velocity_x = CellField(grid_);
  s.velocity_y = CellField(grid_);
  s.pressure = CellField(grid_);
  s.velocity_face_x = FaceField::x_faces(grid_);
  s.velocity_face_y = FaceField::y_faces(grid_);
  s.convection_x_prev = CellField(grid_);
  s.convection_y_prev = CellField(grid_);
  return s;
}

void FluidSolver::initialise_faces(FluidState& state) {
  fill_velocity_ghosts(grid_, boundaries_, state.time, state.velocity_x, state.velocity_y);
  // Interior (and periodic) faces: mean of the two neighbouring cells; wall faces: no flow.
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i <= grid_.nx; ++i)
      state.velocity_face_x(i, j) = 0.5 * (state.velocity_x(i - 1, j) + state.velocity_x(i, j));
  for (int j = 0; j <= grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i)
      state.velocity_face_y(i, j) = 0.5 * (state.velocity_y(i, j - 1) + state.velocity_y(i, j));
  set_given_faces(state.time, state.velocity_face_x, state.velocity_face_y);  // walls, inflows
  // One projection with unit time step: L phi = D U, U -= G_f phi, u -= G_c phi.
  divergence(grid_, state.velocity_face_x, state.velocity_face_y, 1.0, buffer_.data());
  poisson_->solve(/*a=*/0.0, /*b=*/1.0, buffer_.data(), buffer_.data());
  phi_.copy_interior_from(buffer_.data());
  fill_correction_ghosts(grid_, boundaries_, phi_);
  const double inv_dx = 1.0 / grid_.dx(), inv_dy = 1.0 / grid_.dy();
  const FaceRange faces = corrected_faces();
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i)
      state.velocity_face_x(i, j) -= (phi_(i, j) - phi_(i - 1, j)) * inv_dx;
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i) state.velocity_face_y(i, j) -= (phi_(i, j) - phi_(i, j - 1)) * inv_dy;
  sync_periodic_faces(grid_, state.velocity_face_x, state.velocity_face_y);
  centre_gradient(grid_, phi_, grad_x_, grad_y_);
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      state.velocity_x(i, j) -= grad_x_(i, j);
      state.velocity_y(i, j) -= grad_y_(i, j);
    }
}

void FluidSolver::solve_helmholtz_pair(double dt, CellField& x, CellField& y) {
  // (I - nu dt/2 L) q = r with homogeneous Dirichlet/periodic rules. With two or more loop threads
  // the components are solved side by side, each on one thread (the loops and FFT jobs inside a
  // section run on its thread alone: threads.hpp allows one active parallel level): one fork per
  // pair instead of one per loop of each solve, and the same arithmetic as one after the other.
  const double b = -0.5 * nu_ * dt;
  x.copy_interior_to(buffer_.data());
  y.copy_interior_to(buffer_y_.data());
  const auto solve_x = [&] { helmholtz_->solve(/*a=*/1.0, b, buffer_.data(), buffer_.data()); };
  const auto solve_y = [&] { helmholtz_y_->solve(/*a=*/1.0, b, buffer_y_.data(), buffer_y_.data()); };
  if (loop_threads() >= 2) {
    IBMS_PARALLEL_PAIR(solve_x, solve_y);
  } else {
    solve_x();
    solve_y();
  }
  x.copy_interior_from(buffer_.data());
  y.copy_interior_from(buffer_y_.data());
}

void FluidSolver::add_wall_closure(const CellField& u, const CellField& v, double t, double scale, CellField& out_x,
                                   CellField& out_y) const {
  // scale (u_g,quadratic - u_g,linear) / h^2 = scale (2 u_w - 3 u_1 + u_2) / (3 h^2) in each wall cell,
  // for the velocity component tangential to the wall only: applied to the normal one as well, it
  // costs the pressure its order on the manufactured solution (max norm 1.21, L2 1.60; tangential
  // only: 1.91, 1.98, with half the default's velocity and pressure errors).
  const auto closure = [](double wall, double first, double second) { return (2.0 * wall - 3.0 * first + second) / 3.0; };
  // Tangential component on every side where it is given (walls, inflows); an outflow has none.
  // The closure needs two cells across the side.
  for (const Side s : all_sides) {
    const SideCells c = side_cells(grid_, s);
    if (!boundaries_.side(s).is_dirichlet() || (c.normal_to_x ? grid_.nx : grid_.ny) < 2) continue;
    const int tangential = c.normal_to_x ? 1 : 0;
    const CellField& q = c.normal_to_x ? v : u;
    CellField& out = c.normal_to_x ? out_y : out_x;
    const double coefficient = scale / (c.normal_spacing * c.normal_spacing);
    for (int n = 0; n < c.count; ++n) {
      const std::array<double, 2> at = side_point(grid_, s, n);
      const double wall = boundaries_.velocity_at(grid_, s, at[0], at[1], t)[tangential];
      out(c.i(n, 0), c.j(n, 0)) += coefficient * closure(wall, q(c.i(n, 0), c.j(n, 0)), q(c.i(n, 1), c.j(n, 1)));
    }
  }
}

void FluidSolver::predict_explicit(FluidState& state, double dt) {
  // Ghosts of u^n with the wall velocities at t^n, of p^n with zero normal gradient.
  CellField& u = state.velocity_x;
  CellField& v = state.velocity_y;
  CellField& p = state.pressure;
  fill_velocity_ghosts(grid_, boundaries_, state.time, u, v);
  fill_pressure_ghosts(grid_, boundaries_, p);

  if (schemes_.convection == ConvectionScheme::central) {
    convection(grid_, state.velocity_face_x, state.velocity_face_y, u, conv_x_);  // N^n
    convection(grid_, state.velocity_face_x, state.velocity_face_y, v, conv_y_);
  } else {
    const double kappa = upwind_kappa(schemes_.convection);
    convection_upwind_biased(grid_, state.velocity_face_x, state.velocity_face_y, u, conv_x_, kappa);
    convection_upwind_biased(grid_, state.velocity_face_x, state.velocity_face_y, v, conv_y_, kappa);
  }

  laplacian(grid_, u, lap_x_);
  laplacian(grid_, v, lap_y_);
  // Quadratic wall closure: L u^n with the quadratic ghost (the explicit half keeps it after
  // complete_prediction takes back half of lap_).
  if (schemes_.quadratic_wall) add_wall_closure(u, v, state.time, 1.0, lap_x_, lap_y_);
  centre_gradient(grid_, p, grad_x_, grad_y_);

  // Variable-step AB2: N_ext = (1 + r/2) N^n - (r/2) N^{n-1}, r = dt^n/dt^{n-1}; Euler first step.
  // The explicit estimate u~_e = u^n + dt (-N_ext + nu L u^n - G_c p^n) (Uhlmann 2005, step 1).
  const double r = state.has_convection_prev ? dt / state.time_step_prev : 0.0;
  const double c_new = 1.0 + 0.5 * r, c_old = -0.5 * r;
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      const double nx_ext = c_new * conv_x_(i, j) + c_old * state.convection_x_prev(i, j);
      const double ny_ext = c_new * conv_y_(i, j) + c_old * state.convection_y_prev(i, j);
      star_x_(i, j) = u(i, j) + dt * (-nx_ext + nu_ * lap_x_(i, j) - grad_x_(i, j));
      star_y_(i, j) = v(i, j) + dt * (-ny_ext + nu_ * lap_y_(i, j) - grad_y_(i, j));
    }
}

void FluidSolver::complete_prediction(FluidState& state, double dt) {
  // The quadratic closure's first guess of u~ (below): the explicit estimate u~_e + dt f while the
  // viscous number is small, kept before velocity_star becomes the right-hand side.
  const double h = std::min(grid_.dx(), grid_.dy());
  const bool one_sweep = schemes_.quadratic_wall && nu_ * dt / (h * h) <= schemes_.single_sweep_viscous_number;
  if (one_sweep) {
    phi_ = star_x_;
    work_ = star_y_;
  }
  // velocity_star now holds u~_e + dt f: take back the implicit half of the viscous term, so that
  // it is the Crank-Nicolson right-hand side u^n + dt (-N_ext + nu L u^n / 2 - G_c p^n + f).
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      star_x_(i, j) -= 0.5 * dt * nu_ * lap_x_(i, j);
      star_y_(i, j) -= 0.5 * dt * nu_ * lap_y_(i, j);
    }
  // Boundary velocities at t^{n+1} in the implicit half: the row of L next to a Dirichlet side
  // (wall, inflow) is the homogeneous row plus 2 u_b / h^2 (docs/method.md §6, inhomogeneous
  // Dirichlet), moved to the rhs; an outflow's zero-gradient row is homogeneous.
  const double t_new = state.time + dt;
  // Bottom and top before left and right: a corner cell takes its two terms in that order.
  for (const Side s : {Side::bottom, Side::top, Side::left, Side::right}) {
    if (!boundaries_.side(s).is_dirichlet()) continue;
    const SideCells c = side_cells(grid_, s);
    const double coefficient = 0.5 * nu_ * dt * 2.0 / (c.normal_spacing * c.normal_spacing);
    for (int n = 0; n < c.count; ++n) {
      const std::array<double, 2> at = side_point(grid_, s, n);
      const std::array<double, 2> b = boundaries_.velocity_at(grid_, s, at[0], at[1], t_new);
      star_x_(c.i(n, 0), c.j(n, 0)) += coefficient * b[0];
      star_y_(c.i(n, 0), c.j(n, 0)) += coefficient * b[1];
    }
  }
  if (!schemes_.quadratic_wall) {
    solve_helmholtz_pair(dt, star_x_, star_y_);
    return;
  }
  // Quadratic wall closure in the implicit half: (I - nu dt/2 L_lin) u~ = r + (nu dt/2) C(u~), C the
  // wall-cell difference of the closures, by defect correction. C touches only the wall cells and
  // is at most 4/3 of L_lin's wall diagonal (3/h^2): each sweep multiplies the defect by at most
  // rho = (2/3) D / (1 + (3/2) D), D = nu dt / h^2 (< 4/9 for every dt).
  //  - D <= single_sweep_viscous_number (rho <= 0.12): one sweep from the explicit estimate
  //    u~_e + dt f, which differs from u~ by O(dt^2): the defect left, rho O(dt^2) = O(dt^3) per
  //    step, keeps the scheme second order in time, and a steady state is the same as the
  //    converged iteration's (u~ = u~_e = u^n there);
  //  - above it: closure_sweeps(D) sweeps from u^n (the explicit estimate's viscous half grows
  //    with D), which leave at most (4/9)^wall_closure_sweeps of the first guess's defect, whatever
  //    the viscous number; a steady state is again the converged iteration's (u^n = u~ there).
  const double half = 0.5 * nu_ * dt;
  const int sweeps = one_sweep ? 1 : closure_sweeps(nu_ * dt / (h * h));
  if (one_sweep) {
    add_wall_closure(phi_, work_, t_new, half, star_x_, star_y_);  // first guess u~_e + dt f
  } else {
    phi_ = star_x_;  // r (phi_, work_ and lap_ are free until project_smac)
    work_ = star_y_;
    add_wall_closure(state.velocity_x, state.velocity_y, t_new, half, star_x_, star_y_);  // first guess u^n
  }
  for (int sweep = 0;; ++sweep) {
    solve_helmholtz_pair(dt, star_x_, star_y_);
    if (sweep + 1 == sweeps) break;
    lap_x_ = phi_;
    lap_y_ = work_;
    add_wall_closure(star_x_, star_y_, t_new, half, lap_x_, lap_y_);  // r + (nu dt/2) C(u~ of this sweep)
    std::swap(star_x_, lap_x_);
    std::swap(star_y_, lap_y_);
  }
}

int FluidSolver::closure_sweeps(double viscous_number) {
  const double rho = (2.0 / 3.0) * viscous_number / (1.0 + 1.5 * viscous_number);
  const double bound = std::pow(4.0 / 9.0, wall_closure_sweeps);
  int sweeps = 1;
  for (double left = rho; left > bound && sweeps < wall_closure_sweeps; left *= rho) ++sweeps;
  return sweeps;
}

void FluidSolver::predict_momentum(FluidState& state, double dt, const CellField* force_x,
                                   const CellField* force_y) {
  predict_explicit(state, dt);
  if (force_x != nullptr || force_y != nullptr)
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        if (force_x != nullptr) star_x_(i, j) += dt * (*force_x)(i, j);
        if (force_y != nullptr) star_y_(i, j) += dt * (*force_y)(i, j);
      }
  complete_prediction(state, dt);
}

ProjectionStats FluidSolver::project_smac(FluidState& state, double dt) {
  const ProjectionStats stats = project(state, dt, nullptr);
  end_step(state);
  state.tick(dt);
  return stats;
}

ProjectionStats FluidSolver::project(FluidState& state, double dt, const FaceForcing* forcing) {
  ProjectionStats stats;
  const double inv_dx = 1.0 / grid_.dx(), inv_dy = 1.0 / grid_.dy();
  // Momentum interpolation (docs/method.md §2.3 step 3): remove the wide gradient of p^n from the
  // cell velocity, average to the face, add the compact face gradient back.
  //   U*_{i-1/2} = mean(u* + dt G_c p^n) - dt (p_i - p_{i-1})/dx
  // With a FaceForcing, the force's cell increment is taken out of u* before the mean and its face
  // increment added after it (the balanced form, see FaceForcing).
  // grad_x_/grad_y_ still hold G_c p^n from the predictor; p^n ghosts are filled.
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      phi_(i, j) = star_x_(i, j) + dt * grad_x_(i, j);  // phi_ and work_ as scratch for u-hat
      work_(i, j) = star_y_(i, j) + dt * grad_y_(i, j);
    }
  if (forcing != nullptr) {
    IBMS_PARALLEL_ROWS
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        phi_(i, j) -= (*forcing->cell_x)(i, j);
        work_(i, j) -= (*forcing->cell_y)(i, j);
      }
  }
  // Ghosts: periodic wraps, and zero gradient at an outflow (u-hat like the velocity; p^n's ghosts
  // are those of the predictor, p = 0 at an outflow); faces with a given flux are set below.
  fill_neumann_ghosts(grid_, phi_);
  fill_neumann_ghosts(grid_, work_);
  const CellField& p = state.pressure;
  const FaceRange faces = corrected_faces();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i)
      star_face_x_(i, j) = 0.5 * (phi_(i - 1, j) + phi_(i, j)) - dt * (p(i, j) - p(i - 1, j)) * inv_dx;
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i)
      star_face_y_(i, j) = 0.5 * (work_(i, j - 1) + work_(i, j)) - dt * (p(i, j) - p(i, j - 1)) * inv_dy;
  if (forcing != nullptr) {
    IBMS_PARALLEL_ROWS
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = faces.x_first; i <= faces.x_last; ++i) star_face_x_(i, j) += (*forcing->face_x)(i, j);
    IBMS_PARALLEL_ROWS
    for (int j = faces.y_first; j <= faces.y_last; ++j)
      for (int i = 0; i < grid_.nx; ++i) star_face_y_(i, j) += (*forcing->face_y)(i, j);
  }
  const double ratio = interpolation_ratio(dt);
  if (ratio != 1.0) {
    // U*_f = M u~ + (tau/dt) (U*_f - M u~): the face term tau (I - M A)(S_f F - G_f p^n).
    lap_x_ = star_x_;
    lap_y_ = star_y_;
    fill_neumann_ghosts(grid_, lap_x_);
    fill_neumann_ghosts(grid_, lap_y_);
    IBMS_PARALLEL_ROWS
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = faces.x_first; i <= faces.x_last; ++i) {
        const double mean = 0.5 * (lap_x_(i - 1, j) + lap_x_(i, j));
        star_face_x_(i, j) = mean + ratio * (star_face_x_(i, j) - mean);
      }
    IBMS_PARALLEL_ROWS
    for (int j = faces.y_first; j <= faces.y_last; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        const double mean = 0.5 * (lap_y_(i, j - 1) + lap_y_(i, j));
        star_face_y_(i, j) = mean + ratio * (star_face_y_(i, j) - mean);
      }
  }
  set_given_faces(state.time + dt, star_face_x_, star_face_y_);  // walls, inflows at t^{n+1}
  sync_periodic_faces(grid_, star_face_x_, star_face_y_);
  stats.max_divergence_before = max_abs_divergence(grid_, star_face_x_, star_face_y_);

  // docs/method.md §2.3 step 4: L_c phi = D U* / dt, pure Neumann (mean removed) or periodic.
  divergence(grid_, star_face_x_, star_face_y_, 1.0 / dt, buffer_.data());
  stats.removed_mean = solve_poisson(ratio).removed_mean;
  phi_.copy_interior_from(buffer_.data());
  fill_correction_ghosts(grid_, boundaries_, phi_);
  if (ratio != 1.0) {
    centre_gradient(grid_, phi_, grad_x_, grad_y_);
    fill_neumann_ghosts(grid_, grad_x_);
    fill_neumann_ghosts(grid_, grad_y_);
  }

  // Step 5: U^{n+1} = U* - dt G_f phi; faces with a given flux take it (walls, inflows at t^{n+1}).
  set_given_faces(state.time + dt, state.velocity_face_x, state.velocity_face_y);
  if (ratio != 1.0) {
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = faces.x_first; i <= faces.x_last; ++i) state.velocity_face_x(i, j) = star_face_x_(i, j);
    for (int j = faces.y_first; j <= faces.y_last; ++j)
      for (int i = 0; i < grid_.nx; ++i) state.velocity_face_y(i, j) = star_face_y_(i, j);
    correct_faces(dt, ratio, state.velocity_face_x, state.velocity_face_y);
  } else {
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i)
      state.velocity_face_x(i, j) = star_face_x_(i, j) - dt * (phi_(i, j) - phi_(i - 1, j)) * inv_dx;
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i)
      state.velocity_face_y(i, j) = star_face_y_(i, j) - dt * (phi_(i, j) - phi_(i, j - 1)) * inv_dy;
  }
  sync_periodic_faces(grid_, state.velocity_face_x, state.velocity_face_y);
  stats.max_divergence_after = max_abs_divergence(grid_, state.velocity_face_x, state.velocity_face_y);

  // u^{n+1} = u* - dt G_c phi;  p^{n+1} = p^n + phi (standard incremental form, see header).
  centre_gradient(grid_, phi_, grad_x_, grad_y_);
  double max_change = 0.0, max_velocity = 0.0;  // maxima: exact in any order, so thread-independent
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(max : max_change, max_velocity)
#endif
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      const double u_new = star_x_(i, j) - dt * grad_x_(i, j);
      const double v_new = star_y_(i, j) - dt * grad_y_(i, j);
      max_change = std::max({max_change, std::abs(u_new - state.velocity_x(i, j)), std::abs(v_new - state.velocity_y(i, j))});
      max_velocity = std::max({max_velocity, std::abs(u_new), std::abs(v_new)});
      state.velocity_x(i, j) = u_new;
      state.velocity_y(i, j) = v_new;
      state.pressure(i, j) += phi_(i, j);
    }

  stats.max_velocity_change = max_change;
  stats.max_velocity = max_velocity;
  return stats;
}

// star_face_ = the given face increments on the corrected faces (0 on faces with a given flux),
// then projected (project_star_faces).
void FluidSolver::homogeneous_face_projection(double dt, const FaceField& face_increment_x,
                                              const FaceField& face_increment_y) {
  set_star_faces(face_increment_x, face_increment_y);
  const double ratio = interpolation_ratio(dt);
  if (ratio != 1.0) {
    // The faces take (M A + (tau/dt)(I - M A)) g: A g is the cells' increment (their face mean).
    const FaceRange faces = corrected_faces();
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        lap_x_(i, j) = 0.5 * (face_increment_x(i, j) + face_increment_x(i + 1, j));
        lap_y_(i, j) = 0.5 * (face_increment_y(i, j) + face_increment_y(i, j + 1));
      }
    fill_neumann_ghosts(grid_, lap_x_);
    fill_neumann_ghosts(grid_, lap_y_);
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = faces.x_first; i <= faces.x_last; ++i)
        star_face_x_(i, j) = ratio * star_face_x_(i, j) + (1.0 - ratio) * 0.5 * (lap_x_(i - 1, j) + lap_x_(i, j));
    for (int j = faces.y_first; j <= faces.y_last; ++j)
      for (int i = 0; i < grid_.nx; ++i)
        star_face_y_(i, j) = ratio * star_face_y_(i, j) + (1.0 - ratio) * 0.5 * (lap_y_(i, j - 1) + lap_y_(i, j));
  }
  project_star_faces(dt);
}

void FluidSolver::set_star_faces(const FaceField& face_increment_x, const FaceField& face_increment_y) {
  const FaceRange faces = corrected_faces();
  star_face_x_.fill(0.0);  // faces with a given flux: no increment
  star_face_y_.fill(0.0);
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i) star_face_x_(i, j) = face_increment_x(i, j);
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i) star_face_y_(i, j) = face_increment_y(i, j);
}

// star_face_ -= dt G_f phi with L phi = D star_face_ / dt on the corrected faces; phi_ keeps phi.
void FluidSolver::project_star_faces(double dt) { project_faces(dt, star_face_x_, star_face_y_); }

void FluidSolver::project_faces_in_place(double dt, FaceField& face_x, FaceField& face_y) {
  if (interpolation_ratio(dt) != 1.0)
    throw std::logic_error("project_faces_in_place: the face increments of fluid.interpolation_time > 0 need "
                           "homogeneous_face_projection");
  const FaceRange faces = corrected_faces();
  for (int j = 0; j < grid_.ny; ++j) {  // faces with a given flux: no increment
    for (int i = 0; i < faces.x_first; ++i) face_x(i, j) = 0.0;
    for (int i = faces.x_last + 1; i <= grid_.nx; ++i) face_x(i, j) = 0.0;
  }
  for (int j = 0; j <= grid_.ny; ++j)
    if (j < faces.y_first || j > faces.y_last)
      for (int i = 0; i < grid_.nx; ++i) face_y(i, j) = 0.0;
  project_faces(dt, face_x, face_y);
}

void FluidSolver::project_faces(double dt, FaceField& face_x, FaceField& face_y) {
  sync_periodic_faces(grid_, face_x, face_y);
  divergence(grid_, face_x, face_y, 1.0 / dt, buffer_.data());
  const double ratio = interpolation_ratio(dt);
  solve_poisson(ratio);
  phi_.copy_interior_from(buffer_.data());
  fill_correction_ghosts(grid_, boundaries_, phi_);
  if (ratio != 1.0) {
    centre_gradient(grid_, phi_, grad_x_, grad_y_);
    fill_neumann_ghosts(grid_, grad_x_);
    fill_neumann_ghosts(grid_, grad_y_);
    correct_faces(dt, ratio, face_x, face_y);
    sync_periodic_faces(grid_, face_x, face_y);
    return;
  }
  subtract_face_gradient(dt, face_x, face_y);
}

// The face increment, divergence-free: U_g - dt G_f phi on the corrected faces.
void FluidSolver::subtract_face_gradient(double dt, FaceField& face_x, FaceField& face_y) {
  const FaceRange faces = corrected_faces();
  const double inv_dx = 1.0 / grid_.dx(), inv_dy = 1.0 / grid_.dy();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i) face_x(i, j) -= dt * (phi_(i, j) - phi_(i - 1, j)) * inv_dx;
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i) face_y(i, j) -= dt * (phi_(i, j) - phi_(i, j - 1)) * inv_dy;
  sync_periodic_faces(grid_, face_x, face_y);
}

void FluidSolver::subtract_centre_gradient(double dt, CellField& increment_x, CellField& increment_y) {
  centre_gradient(grid_, phi_, grad_x_, grad_y_);
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      increment_x(i, j) -= dt * grad_x_(i, j);
      increment_y(i, j) -= dt * grad_y_(i, j);
    }
}

void FluidSolver::homogeneous_projection(double dt, CellField& increment_x, CellField& increment_y,
                                         const FaceField* face_increment_x, const FaceField* face_increment_y) {
  // The projection is affine in u*: of u* + g it gives P(u*) + P_0(g), P_0 the projection with
  // homogeneous data (no flux through the faces with a given flux; p^n's gradient is in P(u*)).
  const bool balanced = face_increment_x != nullptr && face_increment_y != nullptr;
  if (balanced) {
    homogeneous_face_projection(dt, *face_increment_x, *face_increment_y);
  } else {
    phi_ = increment_x;
    work_ = increment_y;
    fill_neumann_ghosts(grid_, phi_);
    fill_neumann_ghosts(grid_, work_);
    const FaceRange faces = corrected_faces();
    star_face_x_.fill(0.0);  // faces with a given flux: no increment
    star_face_y_.fill(0.0);
    IBMS_PARALLEL_ROWS
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = faces.x_first; i <= faces.x_last; ++i) star_face_x_(i, j) = 0.5 * (phi_(i - 1, j) + phi_(i, j));
    IBMS_PARALLEL_ROWS
    for (int j = faces.y_first; j <= faces.y_last; ++j)
      for (int i = 0; i < grid_.nx; ++i) star_face_y_(i, j) = 0.5 * (work_(i, j - 1) + work_(i, j));
    project_star_faces(dt);
  }
  subtract_centre_gradient(dt, increment_x, increment_y);
}

double FluidSolver::project_increment(FluidState& state, double dt, CellField& increment_x, CellField& increment_y,
                                      const FaceField* face_increment_x, const FaceField* face_increment_y) {
  homogeneous_projection(dt, increment_x, increment_y, face_increment_x, face_increment_y);
  return add_increment(state, increment_x, increment_y);
}

double FluidSolver::add_projected_increment(FluidState& state, double dt, CellField& increment_x,
                                            CellField& increment_y, const FaceField& face_increment_x,
                                            const FaceField& face_increment_y, const CellField& phi) {
  if (interpolation_time_ > 0.0)
    throw std::logic_error("add_projected_increment: fluid.interpolation_time > 0 projects with project_increment");
  phi_ = phi;
  set_star_faces(face_increment_x, face_increment_y);
  sync_periodic_faces(grid_, star_face_x_, star_face_y_);
  subtract_face_gradient(dt, star_face_x_, star_face_y_);
  subtract_centre_gradient(dt, increment_x, increment_y);
  return add_increment(state, increment_x, increment_y);
}

double FluidSolver::add_increment(FluidState& state, const CellField& increment_x, const CellField& increment_y) {
  const FaceRange faces = corrected_faces();
  IBMS_PARALLEL_ROWS
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = faces.x_first; i <= faces.x_last; ++i) state.velocity_face_x(i, j) += star_face_x_(i, j);
  IBMS_PARALLEL_ROWS
  for (int j = faces.y_first; j <= faces.y_last; ++j)
    for (int i = 0; i < grid_.nx; ++i) state.velocity_face_y(i, j) += star_face_y_(i, j);
  sync_periodic_faces(grid_, state.velocity_face_x, state.velocity_face_y);
  double max_change = 0.0;
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(max : max_change)
#endif
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      max_change = std::max({max_change, std::abs(increment_x(i, j)), std::abs(increment_y(i, j))});
      state.velocity_x(i, j) += increment_x(i, j);
      state.velocity_y(i, j) += increment_y(i, j);
      state.pressure(i, j) += phi_(i, j);
    }
  return max_change;
}

void FluidSolver::end_step(FluidState& state) {
  // N^n becomes N^{n-1} of the next step.
  std::swap(state.convection_x_prev, conv_x_);
  std::swap(state.convection_y_prev, conv_y_);
  state.has_convection_prev = true;
}

double FluidSolver::kinetic_energy(const FluidState& state) const {
  double sum = 0.0;
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i)
      sum += state.velocity_x(i, j) * state.velocity_x(i, j) + state.velocity_y(i, j) * state.velocity_y(i, j);
  return 0.5 * sum * grid_.cell_area();
}

}  // namespace ibms
