// The full restart state of a Simulation in /checkpoint (docs/design.md §5): what
// advance_one_step reads from one step to the next, so that a run restarted from a checkpoint
// ends bit-identical to one that never stopped.
//   scalars: time, step, time_step_prev (dt^{n-1} of variable-step AB2 and of the swelling part
//            of U_target), has_convection_prev, next_snapshot_time (run loop), grid size, bodies
//   arrays:  fluid_* u, v, p (kinematic), the AB2 history N^{n-1} (x, y), with ghost layers;
//            face velocities U_f, V_f;
//            body_NNN_* position, velocity (x, y interleaved), mass, diameter (the swelling phase:
//            natural lengths are L0_ij D/D0), triangle_momentum (variant K's I_T of the last step),
//            inner_angular_momentum (L, X_ref x, y), rigid_state (rigid and prescribed bodies:
//            X_c x, y, theta, V x, y, Omega);
//            fftw_wisdom (optional: FFTW's planner state as character codes; imported before the
//            restarted run makes its plans, so that it uses the same transforms)
// Everything else is recomputed each step from these (markers, weights, forcing targets,
// sub-step counts, the adaptive dt, the DEM contacts, which keep no history) or is a constant
// of the scene. The reader checks the format version, the scene and every size.
#pragma once
#include <string>

#include "io/checkpoint.hpp"
#include "io/output_file.hpp"
#include "sim/simulation.hpp"

namespace ibms {

// Bumped whenever the meaning or the set of stored names changes; a reader refuses others.
inline constexpr int checkpoint_format_version = 4;  // 4: the no-slip preconditioner blocks' inputs (bodies_block_*)

// Replaces /checkpoint of `out` with the state of `sim`; next_snapshot_time is the run loop's.
void write_simulation_checkpoint(OutputFile& out, const Simulation& sim, double next_snapshot_time);

// Puts the checkpoint's state into `sim` (built from the same scene) and returns the run loop's
// next_snapshot_time. Throws InputError "<path>: <what>: <reason>" on a different format version,
// a scene that differs outside [run] and [output], or any size that does not fit.
double restore_simulation(const Checkpoint& checkpoint, const std::string& path, Simulation& sim);

// Imports the checkpoint's FFTW wisdom (if any); call before building the Simulation to restart.
void import_checkpoint_planner_wisdom(const Checkpoint& checkpoint);

// The resolved scene text without its [run] and [output] sections: what a restart must keep.
std::string restart_relevant_scene(const std::string& resolved_scene);

}  // namespace ibms
