// The options of ibms that a scene names (docs/design.md §4): each option's enum is written once,
// here, with its table of scene names beside it (OptionNames<Enum>::table, in the order messages
// list them), and used as it is by the scene (scene/scene.hpp, whose fields have these types), by
// the modules that act on it, and by the scene schema (scene/scene_schema.hpp, which adds the
// tables of the options only the simulation reads). No module keeps a twin with a translation, and
// no other list of the names exists.
#pragma once
#include <string_view>

namespace ibms {

// One scene name of an enum value; OptionNames<Enum>::table lists every value with its name.
template <class Enum>
struct OptionName {
  Enum value;
  std::string_view name;
};
template <class Enum>
struct OptionNames;

#define IBMS_OPTION_NAMES(Enum, ...)                       \
  template <>                                              \
  struct OptionNames<Enum> {                               \
    static constexpr OptionName<Enum> table[] = {__VA_ARGS__}; \
  }

// The scene name of a value (every enumerator is in its table).
template <class Enum>
constexpr std::string_view option_name(Enum value) {
  for (const OptionName<Enum>& entry : OptionNames<Enum>::table)
    if (entry.value == value) return entry.name;
  return "?";
}

// Convected face values (fluid/fluid_solver.hpp, docs/method.md §2.2): the central mean, or
// upwind-biased of van Leer's kappa family: QUICK (1/2), Fromm (0), third-order (1/3).
enum class ConvectionScheme { central, quick, fromm, upwind3 };

// One side of the box (fluid/boundary_conditions.hpp), an inflow's profile across it, and the
// inflow's factor in time: 1; min(t / ramp_time, 1); or offset + amplitude sin(2 pi t / period).
enum class SideKind { wall, inflow, outflow, periodic };
enum class InflowShape { uniform, parabolic };
enum class TimeFactorKind { constant, ramp, sinusoidal };

// The regularised delta kernel (ibm/delta_kernel.hpp, docs/method.md §4).
enum class KernelKind { roma3, peskin4, cosine4, bkp6 };

// What moves a body's points (docs/design.md §11): springs (the papers' model), one rigid motion from
// Newton-Euler, or a motion given by the scene (solid/rigid_motion.hpp). Rigid and prescribed
// bodies carry no springs; a prescribed body is infinitely heavy for contacts.
enum class BodyKind { mass_spring, rigid, prescribed };
// How a mass_spring body's springs are integrated (sim/bodies/body_update.hpp).
enum class SpringIntegrator { automatic, explicit_euler, implicit_euler };
// How the body's mass is shared among its points (docs/method.md §1.3): equal, M = rho_s V / (N_l + 1),
// or uniform_disk, half at the centre and the rest shared by the rim.
enum class MassLumping { equal, uniform_disk };

// The contact law (contact/contact_model.hpp):
//  linear:         k = k_Dn of the scene for every contact (docs/method.md §1.9, the papers' law);
//  collision_time: k = m_eff (pi^2 + ln^2 e_D) / T_c^2 per contact, T_c = collision_steps fluid steps,
//                  so that a single-pair contact lasts T_c whatever m_eff (docs/method.md §5.5; Kempe &
//                  Froehlich 2012, Biegert, Vowinckel & Meiburg 2017). c follows from e_D as for linear.
enum class ContactLawKind { linear, collision_time };
// Step of the contacts' inner loop (contact/contact_subcycle.hpp). listed_pairs: steps_per_contact
// steps per contact duration of the fastest contact mode the listed CDS pairs can form, bounded from
// above by Collatz-Wielandt (a single pair: A8's t_c / steps_per_contact exactly); lightest_point:
// the group's bound of contact_substep (the lightest CDS point in active_pairs_safety pairs at once).
enum class InnerStepBound { listed_pairs, lightest_point };
// The default outer step of a group in the inner loop (contact_subcycle.hpp), as a fraction of its
// springs' stable sub-step (safety 0.5 already in it, so omega_max dt <= 0.0625): an impact excites
// the fastest spring modes of the rim, which the held slow force must resolve, and the springs'
// dashpots act on a rebounding point only from the next outer step. Measured on soft wheels
// (k_s = 100, k_Dn = 1e4 and 1e7, test_contact_inner_loop's set-up), inner loop against the shared
// sub-step: with elastic contacts (e_D = 1, the papers') the mechanical energy after an impact differs
// by 5.4-7.7 % of the kinetic energy at the full stable sub-step, 1.4-3.3 % at a half, 0.1-0.6 % at a
// quarter, <= 0.23 % at an eighth, <= 0.11 % at a sixteenth, and the centre-of-mass rebound from the
// wall at k_Dn = 1e7 is wrong up to a quarter (0.273 against 0.128) and within 1.6 % at an eighth,
// 0.9 % at a sixteenth (the rebounds of the elastic pair at k_Dn = 1e4 are chaotic: not compared).
// With the fluid (test_multirate_substeps: damped wheels, e_D = 0.8) the largest overlap lies 0.9 %
// below the shared sub-step's at a sixteenth and 2.9 % above it at a half.
inline constexpr double inner_loop_outer_fraction = 0.0625;
// A scene may take a larger fraction (ContactModel::outer_step_fraction, contact.outer_step_fraction):
// where the contacts are damped and slow, as in a settling bed, the sixteenth costs without changing
// the result (docs/method.md §5.4 gives the measured errors against the fraction; bench/README.md the bed).

// How a SpectralSolver plans its transforms (fluid/spectral_solver.hpp). `measure` (FFTW_MEASURE)
// times candidate algorithms and keeps the fastest: two processes may pick different ones, which
// differ at round-off, unless they share wisdom (the checkpoint's, or the cache of
// fluid/fft_wisdom_cache.hpp). `estimate` (FFTW_ESTIMATE) picks them from the sizes alone, the same
// at every run of one binary on one machine, provided the process holds no measured wisdom for
// those sizes (FFTW uses wisdom of a stronger rigour for a weaker request): `ibms run` loads no
// cache for such a scene.
enum class FftPlanning { measure, estimate };

IBMS_OPTION_NAMES(ConvectionScheme, {ConvectionScheme::central, "central"}, {ConvectionScheme::quick, "quick"},
                  {ConvectionScheme::fromm, "fromm"}, {ConvectionScheme::upwind3, "upwind3"});
IBMS_OPTION_NAMES(SideKind, {SideKind::wall, "wall"}, {SideKind::inflow, "inflow"}, {SideKind::outflow, "outflow"},
                  {SideKind::periodic, "periodic"});
IBMS_OPTION_NAMES(InflowShape, {InflowShape::uniform, "uniform"}, {InflowShape::parabolic, "parabolic"});
IBMS_OPTION_NAMES(TimeFactorKind, {TimeFactorKind::constant, "constant"}, {TimeFactorKind::ramp, "ramp"},
                  {TimeFactorKind::sinusoidal, "sinusoidal"});
IBMS_OPTION_NAMES(KernelKind, {KernelKind::roma3, "roma3"}, {KernelKind::peskin4, "peskin4"},
                  {KernelKind::cosine4, "cosine4"}, {KernelKind::bkp6, "bkp6"});
IBMS_OPTION_NAMES(BodyKind, {BodyKind::mass_spring, "mass_spring"}, {BodyKind::rigid, "rigid"},
                  {BodyKind::prescribed, "prescribed"});
IBMS_OPTION_NAMES(SpringIntegrator, {SpringIntegrator::automatic, "auto"},
                  {SpringIntegrator::explicit_euler, "explicit"}, {SpringIntegrator::implicit_euler, "implicit"});
IBMS_OPTION_NAMES(MassLumping, {MassLumping::equal, "equal"}, {MassLumping::uniform_disk, "uniform_disk"});
IBMS_OPTION_NAMES(ContactLawKind, {ContactLawKind::linear, "linear"}, {ContactLawKind::collision_time, "collision_time"});
IBMS_OPTION_NAMES(InnerStepBound, {InnerStepBound::listed_pairs, "listed_pairs"},
                  {InnerStepBound::lightest_point, "lightest_point"});
IBMS_OPTION_NAMES(FftPlanning, {FftPlanning::measure, "measure"}, {FftPlanning::estimate, "estimate"});

}  // namespace ibms
