// The preconditioner of the marker system (no_slip_system.hpp, docs/method.md §3.7, "The marker
// system's preconditioner"), applied on the right of GMRES, in two parts per body:
//  - the system without its projection, J S: what the kernel does to a force pattern on the rim,
//    local and symmetric up to the marker volumes. It holds the small eigenvalues of the force
//    patterns that vary from marker to marker and that the kernel smooths. Per body and velocity
//    component, C_kl = sum over the constrained nodes (the faces of that component, or the cell
//    centres) of phi_k phi_l, so that (J S v)_k = sum_l C_kl dV_l / (dx dy) v_l; factorised by
//    Cholesky, dense per body: a ring's markers overlap their neighbours only. Other bodies'
//    markers within the kernel's reach are left out (a preconditioner; the iteration stops on the
//    true residual).
//  - the leak: a uniform normal force on a closed rim spreads into a field that is nearly a
//    gradient, so the projection takes nearly all of it into the pressure and leaves a mean normal
//    velocity at the markers mu_b times the force, mu_b ~ 3e-4 at D/h = 20. It is the only pattern
//    that can change the mean normal slip (the discrete flux through the rim that the interpolated
//    divergence-free velocity carries), and J S does not see it: without this part GMRES resolves
//    it last, over tens of products. The preconditioner adds z_b <v . n>_b / mu_b, z_b the body's
//    normal pattern and mu_b measured by one product per step for all bodies together (the leak of
//    one body at another's markers is left out).
// Both are kept while a body's markers stay where they were (a fixed body: once per run). A body
// whose rim responds in the marker system (mass-spring, docs/method.md §3.7) keeps the identity: its
// rim's inertia and springs dominate that part of the system, and J S there doubled the products
// (16 swelling wheels in the two-sided cavity: 5.2 a step without it, 10.4 with it).
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "core/grid.hpp"
#include "ibm/delta_kernel.hpp"
#include "ibm/ib_operators.hpp"
#include "sim/coupling/body_coupling.hpp"

namespace ibms {

class MarkerPreconditioner {
 public:
  // Storage for bodies with up to marker capacity markers each.
  void reserve(const std::vector<BodyCoupling>& coupling);
  // C of every body whose markers moved since they were last factorised, and its outward normals;
  // returns whether any body moved, so that the leaks must be measured again.
  bool factorise(const Grid& grid, KernelKind kernel, bool on_faces, const std::vector<BodyCoupling>& coupling);
  // z: every body's markers pushed along their outward normals n_l (unknowns 2l + d of each body in
  // turn), the pattern whose image under the marker system gives the leaks.
  void normal_pattern(const std::vector<BodyCoupling>& coupling, double* z) const;
  // From y = A z, the marker system applied to normal_pattern: mu_b = <y . n> over body b's markers.
  void set_leaks(const std::vector<BodyCoupling>& coupling, const double* y);
  // x = (J S)^-1 v + z_b <v . n>_b / mu_b, body by body, for the marker vector v (scaled by each
  // body's reference speed, which a body's block leaves unchanged).
  void apply(const std::vector<BodyCoupling>& coupling, const double* v, double* x);

 private:
  struct Block {
    Eigen::MatrixXd overlap[2];          // C of each component
    Eigen::LLT<Eigen::MatrixXd> factor[2];
    Eigen::VectorXd rhs;
    std::vector<Vec2> normal;            // outward unit normal at each marker [-]
    double leak = 0.0;                   // mu_b [-]; 0: no leak part
    std::vector<Vec2> factorised_at;     // the markers of the factorisation and the leak
    bool identity = false;               // a responding (mass-spring) rim: no block, no leak
  };
  std::vector<Block> blocks_;
  std::vector<std::vector<NodeWeight>> weights_;  // the nodes of each marker of the largest body
  double cell_area_ = 1.0;
};

}  // namespace ibms
