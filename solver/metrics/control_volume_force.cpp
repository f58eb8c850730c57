// Control-volume momentum balance (control_volume_force.hpp).
#include "metrics/control_volume_force.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ibms {
namespace {

constexpr int domain_clearance = 2;  // cells between the rectangle and the sides of the box
constexpr double margin_cells = 6.0;
constexpr double margin_diameters = 0.5;

void require_inside(const Grid& g, const CellRectangle& r) {
  if (r.i_begin >= r.i_end || r.j_begin >= r.j_end)
    throw std::invalid_argument("control volume: empty rectangle");
  if (r.i_begin < 1 || r.j_begin < 1 || r.i_end > g.nx - 1 || r.j_end > g.ny - 1)
    throw std::invalid_argument("control volume: cells [" + std::to_string(r.i_begin) + ", " +
                                std::to_string(r.i_end) + ") x [" + std::to_string(r.j_begin) + ", " +
                                std::to_string(r.j_end) + ") must lie one cell or more inside the " +
                                std::to_string(g.nx) + " x " + std::to_string(g.ny) + " box");
}

// One side at x = x_face(i) between the cells i - 1 and i, outward normal sign * e_x.
void add_x_side(const Grid& g, const FlowFields& f, double nu, int i, int j_begin, int j_end, double sign,
                ControlVolumeTerms& t) {
  const double dx = g.dx(), dy = g.dy();
  const CellField &u = f.velocity_x, &v = f.velocity_y, &p = f.pressure;
  for (int j = j_begin; j < j_end; ++j) {
    const double flux = sign * f.velocity_face_x(i, j) * dy;  // (U.n) ds
    t.momentum_flux[0] += 0.5 * (u(i - 1, j) + u(i, j)) * flux;
    t.momentum_flux[1] += 0.5 * (v(i - 1, j) + v(i, j)) * flux;
    t.pressure[0] -= sign * 0.5 * (p(i - 1, j) + p(i, j)) * dy;
    const double du_dx = (u(i, j) - u(i - 1, j)) / dx;
    const double dv_dx = (v(i, j) - v(i - 1, j)) / dx;
    const double du_dy = (u(i - 1, j + 1) - u(i - 1, j - 1) + u(i, j + 1) - u(i, j - 1)) / (4.0 * dy);
    t.viscous[0] += sign * nu * du_dx * dy;  // nu (grad u).n
    t.viscous[1] += sign * nu * dv_dx * dy;
    t.viscous_transpose[0] += sign * nu * du_dx * dy;  // nu (grad u^T).n
    t.viscous_transpose[1] += sign * nu * du_dy * dy;
  }
}

// One side at y = y_face(j) between the cells j - 1 and j, outward normal sign * e_y.
void add_y_side(const Grid& g, const FlowFields& f, double nu, int j, int i_begin, int i_end, double sign,
                ControlVolumeTerms& t) {
  const double dx = g.dx(), dy = g.dy();
  const CellField &u = f.velocity_x, &v = f.velocity_y, &p = f.pressure;
  for (int i = i_begin; i < i_end; ++i) {
    const double flux = sign * f.velocity_face_y(i, j) * dx;
    t.momentum_flux[0] += 0.5 * (u(i, j - 1) + u(i, j)) * flux;
    t.momentum_flux[1] += 0.5 * (v(i, j - 1) + v(i, j)) * flux;
    t.pressure[1] -= sign * 0.5 * (p(i, j - 1) + p(i, j)) * dx;
    const double du_dy = (u(i, j) - u(i, j - 1)) / dy;
    const double dv_dy = (v(i, j) - v(i, j - 1)) / dy;
    const double dv_dx = (v(i + 1, j - 1) - v(i - 1, j - 1) + v(i + 1, j) - v(i - 1, j)) / (4.0 * dx);
    t.viscous[0] += sign * nu * du_dy * dx;
    t.viscous[1] += sign * nu * dv_dy * dx;
    t.viscous_transpose[0] += sign * nu * dv_dx * dx;
    t.viscous_transpose[1] += sign * nu * dv_dy * dx;
  }
}

}  // namespace

CellRectangle control_volume_around(const Grid& g, const ForceVector& lower, const ForceVector& upper,
                                    double diameter) {
  if (g.nx < 2 * domain_clearance + 1 || g.ny < 2 * domain_clearance + 1)
    throw std::invalid_argument("control volume: the grid needs at least 5 cells in each direction");
  const double margin_x = std::max(margin_diameters * diameter, margin_cells * g.dx());
  const double margin_y = std::max(margin_diameters * diameter, margin_cells * g.dy());
  const auto clip = [](double cell, int low, int high) {  // a non-finite position gives `low`
    if (!(cell >= low)) return low;
    return cell > high ? high : static_cast<int>(cell);
  };
  CellRectangle r;
  r.i_begin = clip(std::floor((lower[0] - margin_x - g.origin_x) / g.dx()), domain_clearance, g.nx - domain_clearance - 1);
  r.i_end = clip(std::ceil((upper[0] + margin_x - g.origin_x) / g.dx()), r.i_begin + 1, g.nx - domain_clearance);
  r.j_begin = clip(std::floor((lower[1] - margin_y - g.origin_y) / g.dy()), domain_clearance, g.ny - domain_clearance - 1);
  r.j_end = clip(std::ceil((upper[1] + margin_y - g.origin_y) / g.dy()), r.j_begin + 1, g.ny - domain_clearance);
  return r;
}

double control_volume_clearance(const Grid& g, const CellRectangle& r, const ForceVector& lower,
                                const ForceVector& upper) {
  return std::min({lower[0] - g.x_face(r.i_begin), g.x_face(r.i_end) - upper[0], lower[1] - g.y_face(r.j_begin),
                   g.y_face(r.j_end) - upper[1]});
}

ControlVolumeTerms control_volume_terms(const Grid& g, const CellRectangle& r, const FlowFields& f,
                                       double kinematic_viscosity) {
  require_inside(g, r);
  ControlVolumeTerms t;
  const double area = g.cell_area();
  for (int j = r.j_begin; j < r.j_end; ++j)
    for (int i = r.i_begin; i < r.i_end; ++i) {
      t.momentum[0] += f.velocity_x(i, j) * area;
      t.momentum[1] += f.velocity_y(i, j) * area;
    }
  add_x_side(g, f, kinematic_viscosity, r.i_begin, r.j_begin, r.j_end, -1.0, t);
  add_x_side(g, f, kinematic_viscosity, r.i_end, r.j_begin, r.j_end, +1.0, t);
  add_y_side(g, f, kinematic_viscosity, r.j_begin, r.i_begin, r.i_end, -1.0, t);
  add_y_side(g, f, kinematic_viscosity, r.j_end, r.i_begin, r.i_end, +1.0, t);
  return t;
}

ForceVector control_volume_force(const ControlVolumeTerms& before, const ControlVolumeTerms& after, double dt,
                                 double density) {
  if (!(dt > 0.0)) throw std::invalid_argument("control volume: the time step must be > 0");
  ForceVector force{};
  for (int d = 0; d < 2; ++d)
    force[d] = density * (-(after.momentum[d] - before.momentum[d]) / dt -
                          0.5 * (before.momentum_flux[d] + after.momentum_flux[d]) + after.pressure[d] +
                          0.5 * (before.viscous[d] + after.viscous[d] + before.viscous_transpose[d] +
                                 after.viscous_transpose[d]));
  return force;
}

ForceVector control_volume_force(const Grid& grid, const CellRectangle& rectangle, const FlowFields& before,
                                 const FlowFields& after, double kinematic_viscosity, double density, double dt) {
  return control_volume_force(control_volume_terms(grid, rectangle, before, kinematic_viscosity),
                              control_volume_terms(grid, rectangle, after, kinematic_viscosity), dt, density);
}

DragAgreement final_drag_agreement(const std::vector<double>& ib, const std::vector<double>& cv) {
  if (ib.empty() || ib.size() != cv.size())
    throw std::invalid_argument("drag agreement: two histories of one non-zero length expected");
  return {ib.back(), cv.back(), cv.back() / ib.back() - 1.0};
}

DragAgreement mean_drag_agreement(const std::vector<double>& time, const std::vector<double>& ib,
                                  const std::vector<double>& cv, double t_from) {
  if (time.size() != ib.size() || time.size() != cv.size())
    throw std::invalid_argument("drag agreement: time and the two histories differ in length");
  double weight = 0.0, sum_ib = 0.0, sum_cv = 0.0;
  int rows = 0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    if (time[k] < t_from) continue;
    const double w = time[k] - time[k - 1];
    weight += w;
    sum_ib += w * ib[k];
    sum_cv += w * cv[k];
    ++rows;
  }
  if (rows < 2 || !(weight > 0.0))
    throw std::invalid_argument("drag agreement: fewer than two rows after t = " + std::to_string(t_from));
  const double mean_ib = sum_ib / weight, mean_cv = sum_cv / weight;
  return {mean_ib, mean_cv, mean_cv / mean_ib - 1.0};
}

}  // namespace ibms
