// Check of the quiescent swelling disk (README.md): reads <base>_bodies.csv and verifies
//   1. the induced flow stays at the level the §1.8 forcing allows: max over the run of the largest
//      fluid velocity component <= max over the run of the largest forcing target speed
//      |U_l - (s'/s)(X_l - X_c)| (a homothetic swelling has target 0 and leaves the fluid at rest);
//   2. the pressure equation stays compatible: max |Poisson removed mean| <= 1e-10 (1/s^2), round-off
//      of a 4e4-cell sum of terms up to ~1e2 (1/s^2);
//   3. the disk reached D_max.
// usage: swelling_disk_quiescent_check <base> <max_diameter>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "verification/common/results_csv.hpp"
#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"

using namespace ibms;
using namespace ibms::validation;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <base> <max_diameter>\n", argv[0]);
    return 2;
  }
  try {
    const SeriesTable s = read_series_csv(std::string(argv[1]) + "_bodies.csv");
    const double max_diameter = std::atof(argv[2]);
    double max_fluid = 0, max_target = 0, max_mean = 0;
    for (double v : s.at("max_fluid_velocity_component")) max_fluid = std::max(max_fluid, v);
    for (double v : s.at("body_000/max_target_speed")) max_target = std::max(max_target, v);
    for (double v : s.at("poisson_removed_mean_bodies")) max_mean = std::max(max_mean, std::abs(v));
    const double final_diameter = s.at("body_000/diameter").back();
    const double swelling_speed = 0.5 * 0.25;  // D'/2 [cm/s], the rim speed of the dilation
    const bool pass1 = max_fluid <= max_target;
    const bool pass2 = max_mean <= 1e-10;
    const bool pass3 = std::abs(final_diameter - max_diameter) < 1e-9;
    std::printf("%s 1. max fluid velocity component %.4g cm/s (%.3g D'/2) <= max target speed %.4g cm/s (%.3g D'/2)\n",
                pass1 ? "PASS" : "FAIL", max_fluid, max_fluid / swelling_speed, max_target, max_target / swelling_speed);
    std::printf("%s 2. max |Poisson removed mean| = %.3g 1/s^2 (<= 1e-10)\n", pass2 ? "PASS" : "FAIL", max_mean);
    std::printf("%s 3. final diameter %.6g (D_max %.6g)\n", pass3 ? "PASS" : "FAIL", final_diameter, max_diameter);
    record("swelling_disk_quiescent", "max fluid velocity component - max forcing target speed [cm/s]", 0.0,
           max_fluid - max_target, pass1);
    record("swelling_disk_quiescent", "max |Poisson removed mean| [1/s^2]", 1e-10, max_mean, pass2);
    record("swelling_disk_quiescent", "|final diameter - D_max| [cm]", 1e-9, std::abs(final_diameter - max_diameter),
           pass3);
    return pass1 && pass2 && pass3 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swelling_disk_quiescent_check: %s\n", e.what());
    return 2;
  }
}
