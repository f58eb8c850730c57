// Check of the two-sided cavity with 16 particles (README.md; issue 4 §3): reads the body series
// of the non-swelling and the swelling run, writes the centre trajectories for
// t_stop <= t <= t_end as CSV (long format: time, particle, x, y, diameter), and verifies
//   1. both runs reach t_end (stable: no blow-up);
//   2. no particle leaves the box and no two interpenetrate, in both runs;
//   3. after the lids stop, the non-swelling particles travel further on average: the mean over
//      particles of the centroid path length over [t_stop, t_end] is larger without swelling;
//   4. swelling particles keep moving as they push each other: over the late window
//      [t_late, t_end] the swelling run has active particle-particle contacts and its particles'
//      mean path length exceeds that of the non-swelling particles over the same window.
// usage: cavity_particles_check <t_stop> <t_late> <t_end> <base_nonswelling> <base_swelling> <out_dir>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"
#include "../settling_disk/body_series.hpp"

using namespace ibms::validation;

namespace {

std::string body(int b, const char* what) {
  char name[48];
  std::snprintf(name, sizeof name, "body_%03d/%s", b, what);
  return name;
}

int count_bodies(const SeriesTable& s) {
  int n = 0;
  while (s.count(body(n, "centroid_x"))) ++n;
  return n;
}

// Mean over particles of the centroid path length over [t0, t1].
double mean_path_length(const SeriesTable& s, double t0, double t1) {
  const auto& t = s.at("time");
  const int n = count_bodies(s);
  double total = 0;
  for (int b = 0; b < n; ++b) {
    const auto& x = s.at(body(b, "centroid_x"));
    const auto& y = s.at(body(b, "centroid_y"));
    for (std::size_t k = 1; k < t.size(); ++k)
      if (t[k - 1] >= t0 && t[k] <= t1) total += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1]);
  }
  return total / n;
}

double max_in_window(const SeriesTable& s, const std::string& column, double t0, double t1) {
  const auto& t = s.at("time");
  const auto& v = s.at(column);
  double m = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) m = std::max(m, v[k]);
  return m;
}

void write_trajectories(const SeriesTable& s, double t0, double t1, const std::string& path, const std::string& run) {
  std::ofstream out(path);
  out << "# ibms two-sided cavity with 16 particles, " << run << " run: particle centroids (rim-polygon area\n"
         "# centroid) and diameters D(t) for " << t0 << " <= t <= " << t1 << ", every output step\n"
         "time [-],particle [-],x [-],y [-],diameter [-]\n";
  out.precision(10);
  const auto& t = s.at("time");
  const int n = count_bodies(s);
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < t0 || t[k] > t1) continue;
    for (int b = 0; b < n; ++b)
      out << t[k] << "," << b << "," << s.at(body(b, "centroid_x"))[k] << "," << s.at(body(b, "centroid_y"))[k] << ","
          << s.at(body(b, "diameter"))[k] << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s <t_stop> <t_late> <t_end> <base_nonswelling> <base_swelling> <out_dir>\n", argv[0]);
    return 2;
  }
  try {
    const double t_stop = std::atof(argv[1]), t_late = std::atof(argv[2]), t_end = std::atof(argv[3]);
    const SeriesTable plain = read_series_csv(std::string(argv[4]) + "_bodies.csv");
    const SeriesTable swell = read_series_csv(std::string(argv[5]) + "_bodies.csv");
    const std::string out_dir = argv[6];
    write_trajectories(plain, t_stop, t_end, out_dir + "/trajectories_nonswelling.csv", "non-swelling");
    write_trajectories(swell, t_stop, t_end, out_dir + "/trajectories_swelling.csv", "swelling");
    // Case name in results.csv: the output folder's name (cavity_swelling_particles, or
    // cavity_swelling_particles_dem1e7 for the slow set), as the report finds its figures there.
    std::string name = out_dir;
    while (!name.empty() && name.back() == '/') name.pop_back();
    name = name.substr(name.find_last_of('/') + 1);
    bool all = true;
    for (const auto& [label, s] : {std::pair{"non-swelling", &plain}, std::pair{"swelling", &swell}}) {
      const double reached = s->at("time").back();
      double min_wall = INFINITY, min_rim = INFINITY, inside = 0;
      for (double v : s->at("bodies/min_wall_distance")) min_wall = std::min(min_wall, v);
      for (double v : s->at("bodies/min_rim_distance")) min_rim = std::min(min_rim, v);
      for (double v : s->at("bodies/n_points_inside_others")) inside = std::max(inside, v);
      const bool stable = reached >= t_end * (1 - 1e-9);
      const bool contained = min_wall > 0 && min_rim > 0 && inside == 0;
      std::printf("%s %s: 1. reached t = %.4g (end %.4g)\n", stable ? "PASS" : "FAIL", label, reached, t_end);
      std::printf("%s %s: 2. min rim distance to a wall %.4g, between particles %.4g, points inside others %g\n",
                  contained ? "PASS" : "FAIL", label, min_wall, min_rim, inside);
      const std::string l = label;
      record(name, l + ": reached t_end (stable; measured: t)", t_end, reached, stable);
      record(name, l + ": min rim distance to walls (> 0)", 0.0, min_wall, min_wall > 0);
      record(name, l + ": min rim distance between particles (> 0, none inside another)", 0.0, min_rim,
             min_rim > 0 && inside == 0);
      all = all && stable && contained;
    }
    const double path_plain = mean_path_length(plain, t_stop, t_end);
    const double path_swell = mean_path_length(swell, t_stop, t_end);
    const bool further = path_plain > path_swell;
    std::printf("%s 3. mean path length %g <= t <= %g: non-swelling %.5f > swelling %.5f\n", further ? "PASS" : "FAIL",
                t_stop, t_end, path_plain, path_swell);
    record(name, "mean path length after the lids stop: non-swelling - swelling (> 0)", 0.0, path_plain - path_swell,
           further);
    record_info(name, "mean path length after the lids stop, non-swelling", path_plain);
    record_info(name, "mean path length after the lids stop, swelling", path_swell);
    const double late_plain = mean_path_length(plain, t_late, t_end);
    const double late_swell = mean_path_length(swell, t_late, t_end);
    const double late_pairs = max_in_window(swell, "contact/n_active_pairs", t_late, t_end);
    const bool pushing = late_pairs > 0 && late_swell > late_plain;
    std::printf("%s 4. %g <= t <= %g: swelling run has up to %g active contact pairs; mean path length swelling "
                "%.5f > non-swelling %.5f\n",
                pushing ? "PASS" : "FAIL", t_late, t_end, late_pairs, late_swell, late_plain);
    record(name, "late window: swelling - non-swelling mean path length (> 0, with contacts)", 0.0,
           late_swell - late_plain, pushing);
    return all && further && pushing ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cavity_particles_check: %s\n", e.what());
    return 2;
  }
}
