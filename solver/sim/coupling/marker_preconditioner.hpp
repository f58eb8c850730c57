// The preconditioner of the marker system (no_slip_system.hpp, docs/method.md §3.7, "The marker
// system's preconditioner"), applied on the right of GMRES, body by body (other bodies' markers
// within reach are left out: a preconditioner; the iteration stops on the true residual).
//  - A prescribed body under the face constraint (ibm.constrained_velocity = "faces"): the body's
//    own marker operator
//    J_f P_0 S_f, built without a Poisson solve. P_0 = I - G_f L^{-1} D on the corrected faces and
//    L^{-1} is taken on the unbounded grid, its lattice Green's function
//    (fluid/lattice_green_function.hpp): with R_k the cells' weights of J_f G_f at marker k,
//        A_kl = (C_kl + sum_ab R_k(a) R_l(b) G(a - b)) dV_l / (dx dy),
//    C_kl the kernels' overlap on the corrected faces (below). What it leaves out: the walls' and periodic
//    images' part of L^{-1}, smooth over the rim, and other bodies. Factorised by LU per body.
//  - Other bodies, and every body under the cell constraint ("cells"): the system without its
//    projection, J S, and the leak. A rigid body answers its force one step late (its virtual mass,
//    docs/method.md §3.7): with its exact fluid operator the marker system takes every mode at
//    once, and a rigid disk settling onto a wall then rocks with a growing force from a gap of
//    0.7 h (validation/settling_disk at 100 x 300 cells), which the slower iteration damps.
//    * J S: per body and velocity component, C_kl = sum over the constrained nodes (the faces of
//      that component, or the cell centres) of phi_k phi_l, so that (J S v)_k = sum_l C_kl dV_l / (dx dy) v_l; factorised by
//      Cholesky, dense per body. It holds the small eigenvalues of the force patterns that vary
//      from marker to marker and that the kernel smooths.
//    * the leak: a uniform normal force on a closed rim spreads into a field that is nearly a
//      gradient, so the projection takes nearly all of it into the pressure and leaves a mean
//      normal velocity at the markers mu_b times the force, mu_b ~ 3e-4 at D/h = 20, which J S does
//      not see. The preconditioner adds z_b <v . n>_b / mu_b, z_b the body's normal pattern and
//      mu_b measured by one product per step for all bodies together.
// The J S block and the leak are kept while a body's markers stay where they were (a fixed body:
// once per run). A moving body's own operator is kept while its markers stay within
// ibm.preconditioner_drift cells of where it was built (0: built again at every move); it is built
// from what it was built with (the markers, their volumes and radial factors, a rigid body's arms),
// which the checkpoint keeps, so that a restarted run builds the same block (docs/method.md §3.7).
// A body whose rim responds in the marker system (mass-spring, docs/method.md §3.7): its rim's
// inertia and springs dominate that part of the system (J S alone there doubled the products: 16
// swelling wheels in the two-sided cavity, 5.2 a step without it, 10.4 with it). With
// ibm.rim_preconditioner = "response" (attach_rim_systems), under the face constraint and with the
// markers on its rim points, it takes (D + R)^-1, D the diagonal of J_f S_f and
// R = B K^-1 B^T rho_f dV its response (K = M + dt D_s + dt^2 S its implicit system, B the rim
// points), by Woodbury:  x = D^-1 (v - B y),  (K + B^T rho_f dV D^-1 B) y = B^T rho_f dV D^-1 v,
// the rim's implicit system with rho_f dV_l / D_l added to each rim point's mass, factorised once a
// step in O(N). Otherwise (the default) it keeps the identity: at a loose slip tolerance, where a
// rim needs a correction at a few steps only, the block's nearly complete corrections leave the
// tolerance's sawtooth in the body's motion (docs/method.md §3.7, the settling wheel).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>

#include "core/grid.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/lattice_green_function.hpp"
#include "ibm/delta_kernel.hpp"
#include "ibm/ib_operators.hpp"
#include "sim/coupling/body_coupling.hpp"
#include "solid/implicit_euler.hpp"

namespace ibms {

// Whether a body may take its own operator (faces): prescribed, or rigid and responding in the
// marker system (response_mass set).
inline bool may_take_own_operator(const BodyCoupling& c) { return c.given_motion || c.response_mass > 0.0; }

// ibm.preconditioner_drift = "auto": a moving body's block costs about (2 n_b)^2 times a kernel
// stencil's work to build, a product about a Poisson solve on the grid; a block kept within a tenth
// of a cell adds one or two products a step. So the blocks are kept within 0.1 cell when the sum over
// the moving bodies of (2 n_b)^2 exceeds the grid's cells, and built at every move otherwise
// (docs/method.md §3.7: an oscillating cylinder, 0.6 of the cells, 1.0 products a step at 0 and 2.7
// at 0.1; 16-1024 rigid disks, 15 times the cells, coupling 2.5-4.5 → 1.0-1.5 the fluid stages).
inline double automatic_preconditioner_drift(double block_unknowns_squared, long cells) {
  return block_unknowns_squared > static_cast<double>(cells) ? 0.1 : 0.0;
}

// What a body's own operator was built from: its markers, their volumes and radial factors, and a
// responding rigid body's arms (empty otherwise). Empty before the first build.
struct ExactBlockInputs {
  std::vector<Vec2> marker;
  std::vector<double> volume, radial;
  std::vector<Vec2> arm;
};

class MarkerPreconditioner {
 public:
  // Storage for bodies with up to marker capacity markers each (the own-operator blocks for the
  // prescribed and the responding rigid bodies only); fluid_density for the rigid bodies' response,
  // drift: ibm.preconditioner_drift [cells].
  void reserve(const std::vector<BodyCoupling>& coupling, double fluid_density, double drift);
  // The mass-spring rims' implicit systems of the step (factorised before factorise is called):
  // their rims take (D + R)^-1 (ibm.rim_preconditioner = "response"); without them the identity.
  void attach_rim_systems(const std::vector<ImplicitSpringSystem>* systems) { rim_systems_ = systems; }
  // The blocks of every body whose markers moved since they were last factorised (faces: the local
  // operator; cells: C and the outward normals), free_faces the faces the projection corrects;
  // returns whether leaks must be measured again (a body with a J S block moved).
  // A responding rigid body (response_mass > 0, its rigid_arm filled for the step) takes A_b less
  // its response (the impulses and changes are built in pass_increment and pass_force). The
  // markers' face_stencils must be mapped at the current markers (map_face_stencils; hold_no_slip
  // maps them).
  bool factorise(const Grid& grid, KernelKind kernel, bool on_faces, const FluidSolver::FaceRange& free_faces,
                 std::vector<BodyCoupling>& coupling);
  // The inputs of body b's own operator (empty: none built), for the checkpoint; restore_inputs
  // gives them back to a restarted run, whose next factorise builds the block from them.
  const ExactBlockInputs& exact_inputs(std::size_t body) const { return blocks_[body].inputs; }
  void restore_inputs(std::size_t body, const ExactBlockInputs& inputs);
  // z: every body's markers pushed along their outward normals n_l (unknowns 2l + d of each body in
  // turn), the pattern whose image under the marker system gives the leaks.
  void normal_pattern(const std::vector<BodyCoupling>& coupling, double* z) const;
  // From y = A z, the marker system applied to normal_pattern: mu_b = <y . n> over body b's markers.
  void set_leaks(const std::vector<BodyCoupling>& coupling, const double* y);
  // x = A_b^-1 v or (J S)^-1 v + z_b <v . n>_b / mu_b, body by body, for the marker
  // vector v (scaled by each body's reference speed, which a body's block leaves unchanged).
  void apply(const std::vector<BodyCoupling>& coupling, const double* v, double* x);

 private:
  // One cell's weight in R_k (J_f G_f at a marker), the cell unwrapped around the body.
  struct CellWeight {
    int i = 0, j = 0;
    double weight = 0.0;
  };
  struct Block {
    Eigen::MatrixXd local;               // A_b, 2n x 2n, unknowns 2k + d
    Eigen::PartialPivLU<Eigen::MatrixXd> local_factor;
    bool exact = false;                  // local_factor holds A_b (a prescribed body, faces)
    Eigen::MatrixXd overlap[2];          // C of each component
    Eigen::LLT<Eigen::MatrixXd> factor[2];
    Eigen::VectorXd rhs;
    std::vector<Vec2> normal;            // outward unit normal at each marker [-]
    double leak = 0.0;                   // mu_b [-]; 0: no leak part
    std::vector<Vec2> factorised_at;     // the markers of the factorisation and the leak
    bool identity = false;               // a responding (mass-spring) rim: no block, no leak
    ExactBlockInputs inputs;             // what local was built from (exact blocks)
    bool restored = false;               // inputs given back by a restart, block not yet built
    // A responding mass-spring rim (markers = rim points, faces): (D + R)^-1 by Woodbury, D the
    // diagonal of J_f S_f, R the rim's response; rim_system the rim's implicit system with
    // rho_f dV / D added to its rim points' masses.
    bool rim = false;
    ImplicitSpringSystem rim_system;
    std::vector<double> rim_diagonal;    // D per unknown 2k + d
    std::vector<double> rim_work;        // two entries per body point
  };
  const std::vector<ImplicitSpringSystem>* rim_systems_ = nullptr;
  std::vector<Block> blocks_;
  // A_b (less a rigid body's response) from block.inputs.
  void build_local(const Grid& grid, KernelKind kernel, const FluidSolver::FaceRange& free_faces, BodyCoupling& c,
                   Block& block);
  double fluid_density_ = 0.0;
  double drift_ = 0.0;  // ibm.preconditioner_drift [cells]
  std::vector<FaceStencils> stencils_;            // the face stencils of block.inputs.marker (work)
  std::vector<std::vector<NodeWeight>> weights_;  // the nodes of each marker of the largest body
  std::vector<std::vector<CellWeight>> cells_;    // R of each marker and component (2k + d) of the largest body
  LatticeGreensFunction green_;
  // The band of cells the R of one body touch, (j, i) sorted; each R entry's place in it; G among
  // the band's cells and the potential G R_q of one column.
  std::vector<std::array<int, 2>> band_;
  std::vector<std::vector<int>> band_index_;
  std::vector<double> band_green_, band_potential_;
  double cell_area_ = 1.0;
};

}  // namespace ibms
