// Check of the settling-disk case (README.md): for each grid, reads <base>_bodies.csv, prints the
// maximum settling speed (max of -v of the centre of mass), its deviation from the reference
// 5.5 cm/s (reference/settling_disk_rho1.25.csv), the touchdown time (centre at y = 0.14) and the
// differences between successive grids; exits non-zero unless the finest grid with D/h >= 25 is
// within the tolerance.
//
// usage: settling_disk_check <reference.csv> <diameter> <n_x:base>...   (coarse to fine;
//        n_x = cells across the 2 cm width)
// The tolerance (3 %) and the touchdown height are solver/metrics/case_criteria.hpp's, the figures
// metrics/body_series.hpp's: one definition with `ibms compare`.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "verification/common/results_csv.hpp"

using namespace ibms;
using namespace ibms::validation;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s <reference.csv> <diameter> <n_x:base>...\n", argv[0]);
    return 2;
  }
  try {
    const double reference = reference_value(argv[1], "max_settling_speed");
    const double reference_touchdown = reference_value(argv[1], "time_of_touchdown_centre_at_y_0.14");
    const double tolerance = criteria::settling_speed_tolerance;
    const double diameter = std::atof(argv[2]);
    const double width = 2.0;  // cm, the channel of the reference
    std::printf("settling disk: max settling speed vs %.4g cm/s (tolerance %.1f %%), touchdown vs %.3g s\n",
                reference, 100 * tolerance, reference_touchdown);
    std::printf("  n_x   D/h     max speed [cm/s]  deviation   t(max) [s]  touchdown [s]  change vs previous grid\n");
    double previous = NAN, finest_deviation = NAN, finest_resolution = 0;
    for (int a = 3; a < argc; ++a) {
      const std::string arg = argv[a];
      const int n_x = std::atoi(arg.substr(0, arg.find(':')).c_str());
      const std::string base = arg.substr(arg.find(':') + 1);
      const SeriesTable s = read_series_csv(base + "_bodies.csv");
      const std::string file = base + "_bodies.csv";
      const std::vector<double>& t = series_column(s, "time", file);
      std::size_t k_max = 0;
      const double speed = max_settling_speed(series_column(s, "body_000/velocity_y", file), &k_max);
      const double touchdown = first_crossing_below(t, series_column(s, "body_000/centroid_y", file),
                                                    criteria::settling_touchdown_height);
      const double resolution = diameter / (width / n_x);
      const double deviation = speed / reference - 1.0;
      std::printf("  %4d  %6.2f  %10.4f        %+7.2f %%   %8.4f    %s      %s\n", n_x, resolution, speed,
                  100 * deviation, t[k_max], touchdown > 0 ? std::to_string(touchdown).c_str() : "not reached",
                  std::isnan(previous) ? "" : (std::to_string(speed - previous) + " cm/s").c_str());
      previous = speed;
      char label[96];
      std::snprintf(label, sizeof label, "max settling speed [cm/s], D/h = %.2f", resolution);
      record_info("settling_disk", label, speed);
      std::snprintf(label, sizeof label, "touchdown time (centre at y = 0.14) [s], D/h = %.2f", resolution);
      if (touchdown > 0) record_info("settling_disk", label, touchdown);
      if (resolution >= 25.0 - 1e-9) { finest_deviation = deviation; finest_resolution = resolution; }
    }
    if (std::isnan(finest_deviation)) {
      std::printf("FAIL: no grid with D/h >= 25\n");
      return 1;
    }
    const bool pass = std::abs(finest_deviation) <= tolerance;
    char label[96];
    std::snprintf(label, sizeof label, "|max settling speed / 5.5 cm/s - 1| at D/h = %.2f", finest_resolution);
    record("settling_disk", label, tolerance, std::abs(finest_deviation), pass);
    std::printf("%s: D/h = %.2f deviates by %+.2f %% (tolerance %.1f %%)\n", pass ? "PASS" : "FAIL", finest_resolution,
                100 * finest_deviation, 100 * tolerance);
    return pass ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "settling_disk_check: %s\n", e.what());
    return 2;
  }
}
