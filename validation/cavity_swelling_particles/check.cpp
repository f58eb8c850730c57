// Check of the two-sided cavity with 16 particles (README.md): reads the body series
// of the non-swelling and the swelling run, writes the centre trajectories for
// t_stop <= t <= t_end as CSV (long format: time, particle, x, y, diameter), and verifies
//   1. both runs reach t_end (stable: no blow-up);
//   2. the contacts keep the particles apart and inside the box, in both runs: the smallest
//      rim-point distance between particles stays >= min_gap and to a wall >= min_gap / 2
//      (thresholds from the CDS radius, README.md), no rim point inside another particle and no
//      crossing rim edges (sampled at every output step);
//   3. after the lids stop, the non-swelling particles travel further on average: the mean over
//      particles of the centroid path length over [t_stop, t_end] (metrics::path_length, the sum of
//      chords between output times: the one definition `ibms compare` uses too; it differs from the
//      integral of the centre-of-mass speed by < 1.1 % on these runs) is larger without swelling;
//   4. swelling particles keep moving as they push each other: over [t_late, t_end] the swelling
//      run has more touching CDS pairs on average than the non-swelling run, and its particles'
//      mean path length is larger.
// usage: cavity_particles_check <min_gap> <case_name> <base_nonswelling> <base_swelling> <out_dir>
//        [exact <swelling_rate> <swelling_scene>]
// t_stop, t_late and t_end are solver/metrics/case_criteria.hpp's (one definition with `ibms compare`).
// With `exact` (the 256-particle cavity, README.md) it checks 1 and 2 only, what holds exactly
// whatever the chaotic paths do, and adds in both runs:
//   5. each diameter D(t) follows its schedule, D0 constant without swelling and
//      min(D0 + rate t, D_max) with it, to 1e-9 of D0 (D0 from the first row; D_max the body's
//      max_diameter in the swelling scene, 1.5 D0 to the scene's 6 decimals);
//   and records, not gated, the range of the rim-polygon areas over the regular rim polygon of D(t)
//   and the largest count of folded rims' crossing edge pairs (bodies/n_self_crossings): the papers'
//   soft 21-point wheels fold in the 16-particle runs too (README.md), so neither holds exactly.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "verification/common/results_csv.hpp"
#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "scene/scene_reader.hpp"

using namespace ibms;
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

// Mean over particles of the centroid path length over [t0, t1] (metrics/body_series.hpp).
double mean_path_length(const SeriesTable& s, double t0, double t1) {
  const auto& t = s.at("time");
  const int n = count_bodies(s);
  double total = 0;
  for (int b = 0; b < n; ++b) total += path_length(t, s.at(body(b, "centroid_x")), s.at(body(b, "centroid_y")), t0, t1);
  return total / n;
}

double mean_in_window(const SeriesTable& s, const std::string& column, double t0, double t1) {
  const auto& t = s.at("time");
  const auto& v = s.at(column);
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) {
      sum += v[k];
      ++count;
    }
  return count ? sum / count : 0.0;
}

void write_trajectories(const SeriesTable& s, double t0, double t1, const std::string& path, const std::string& run) {
  std::ofstream out(path);
  out << "# ibms two-sided cavity with particles, " << run << " run: particle centroids (rim-polygon area\n"
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

// The max_diameter of each body's swelling law, in the order of its bodies, read by the solver's
// own scene reader (the scenes of make_scenes.py give every body one).
std::vector<double> max_diameters(const std::string& scene_path) {
  std::vector<double> values;
  for (const BodySpec& body : read_scene_file(scene_path).bodies) values.push_back(body.swelling.max_diameter);
  return values;
}

}  // namespace

// Check 5 of one run (header): the diameters against their schedule; the rims' areas against the
// regular polygon of D(t) with n_rim points and the folded rims, recorded. Returns pass.
bool check_schedule(const std::string& name, const std::string& label, const SeriesTable& s,
                              double rate, const std::vector<double>& max_diameter, int n_rim) {
  const auto& t = s.at("time");
  const int n = count_bodies(s);
  double worst_diameter = 0.0, area_low = INFINITY, area_high = 0.0, self_crossings = 0.0;
  for (double v : s.at("bodies/n_self_crossings")) self_crossings = std::max(self_crossings, v);
  const double polygon = 0.5 * n_rim * std::sin(2.0 * std::acos(-1.0) / n_rim);  // area / R^2 of the regular polygon
  if (rate != 0.0 && static_cast<int>(max_diameter.size()) != n)
    throw std::runtime_error("the swelling scene gives " + std::to_string(max_diameter.size()) +
                             " max_diameter values for " + std::to_string(n) + " bodies");
  for (int b = 0; b < n; ++b) {
    const auto& d = s.at(body(b, "diameter"));
    const auto& a = s.at(body(b, "area"));
    const double d0 = d[0] - rate * t[0];
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double scheduled = rate == 0.0 ? d0 : std::min(d0 + rate * t[k], max_diameter[b]);
      worst_diameter = std::max(worst_diameter, std::abs(d[k] - scheduled) / d0);
      const double ratio = a[k] / (polygon * 0.25 * d[k] * d[k]);
      area_low = std::min(area_low, ratio);
      area_high = std::max(area_high, ratio);
    }
  }
  const bool schedule = worst_diameter <= 1e-9;
  std::printf("%s %s: 5. diameters follow the schedule (rate %g): largest |D - D_schedule| / D0 %.3g (<= 1e-9)\n",
              schedule ? "PASS" : "FAIL", label.c_str(), rate, worst_diameter);
  std::printf("INFO %s: rim area / regular polygon of D(t) in [%.4f, %.4f]; folded rims: up to %g crossing edge "
              "pairs\n", label.c_str(), area_low, area_high, self_crossings);
  record(name, label + ": diameters follow the swelling schedule (largest |D - D_schedule| / D0)", 1e-9,
         worst_diameter, schedule);
  record_info(name, label + ": smallest rim area / regular polygon of D(t)", area_low);
  record_info(name, label + ": largest rim area / regular polygon of D(t)", area_high);
  record_info(name, label + ": largest count of crossing edge pairs of folded rims", self_crossings);
  return schedule;
}

int main(int argc, char** argv) {
  const bool exact = argc == 9 && std::string(argv[6]) == "exact";
  if (argc != 6 && !exact) {
    std::fprintf(stderr, "usage: %s <min_gap> <case_name> <base_nonswelling> <base_swelling> <out_dir> "
                 "[exact <swelling_rate> <swelling_scene>]\n", argv[0]);
    return 2;
  }
  try {
    const double t_stop = criteria::particles_t_stop, t_late = criteria::particles_t_late,
                 t_end = criteria::particles_t_end;
    const double min_gap = std::atof(argv[1]);
    const std::string name = argv[2];  // the case folder's name
    const SeriesTable plain = read_series_csv(std::string(argv[3]) + "_bodies.csv");
    const SeriesTable swell = read_series_csv(std::string(argv[4]) + "_bodies.csv");
    const std::string out_dir = argv[5];
    write_trajectories(plain, t_stop, t_end, out_dir + "/trajectories_nonswelling.csv", "non-swelling");
    write_trajectories(swell, t_stop, t_end, out_dir + "/trajectories_swelling.csv", "swelling");
    // The collision-time set and the papers'-coupling set record their metrics under a prefix.
    const std::string prefix = out_dir.find("collision_time") != std::string::npos    ? "collision_time: "
                               : out_dir.find("papers_coupling") != std::string::npos ? "papers' coupling: "
                               : exact                                                 ? "256 particles: "
                                                                                     : "";
    bool all = true;
    for (const auto& [label, s] : {std::pair{"non-swelling", &plain}, std::pair{"swelling", &swell}}) {
      const double reached = s->at("time").back();
      double min_wall = INFINITY, min_rim = INFINITY, inside = 0, crossings = 0;
      for (double v : s->at("bodies/min_wall_distance")) min_wall = std::min(min_wall, v);
      for (double v : s->at("bodies/min_rim_distance")) min_rim = std::min(min_rim, v);
      for (double v : s->at("bodies/n_points_inside_others")) inside = std::max(inside, v);
      for (double v : s->at("bodies/n_edge_crossings")) crossings = std::max(crossings, v);
      const bool stable = reached >= t_end * (1 - 1e-9);
      const bool walls_ok = min_wall >= 0.5 * min_gap;
      const bool apart = min_rim >= min_gap && inside == 0 && crossings == 0;
      std::printf("%s %s: 1. reached t = %.4g (end %.4g)\n", stable ? "PASS" : "FAIL", label, reached, t_end);
      std::printf("%s %s: 2a. min rim distance to a wall %.4g (>= %.4g)\n", walls_ok ? "PASS" : "FAIL", label,
                  min_wall, 0.5 * min_gap);
      std::printf("%s %s: 2b. min rim distance between particles %.4g (>= %.4g), points inside others %g, "
                  "crossing edges %g\n",
                  apart ? "PASS" : "FAIL", label, min_rim, min_gap, inside, crossings);
      const std::string l = prefix + label;
      record(name, l + ": reached t_end (stable; measured: t)", t_end, reached, stable);
      record(name, l + ": min rim distance to walls", 0.5 * min_gap, min_wall, walls_ok);
      record(name, l + ": min rim distance between particles (none inside another, no crossing edges)", min_gap,
             min_rim, apart);
      all = all && stable && walls_ok && apart;
      if (exact) {
        const bool swelling = std::string(label) == "swelling";
        const double rate = swelling ? std::atof(argv[7]) : 0.0;
        all = check_schedule(name, l, *s, rate, swelling ? max_diameters(argv[8]) : std::vector<double>{}, 21) && all;
      }
    }
    if (exact) return all ? 0 : 1;
    const double path_plain = mean_path_length(plain, t_stop, t_end);
    const double path_swell = mean_path_length(swell, t_stop, t_end);
    const bool further = path_plain > path_swell;
    std::printf("%s 3. mean centre-of-mass path %g <= t <= %g: non-swelling %.5f > swelling %.5f\n",
                further ? "PASS" : "FAIL", t_stop, t_end, path_plain, path_swell);
    record(name, prefix + "mean path length after the lids stop: non-swelling - swelling (> 0)", 0.0,
           path_plain - path_swell, further);
    record_info(name, prefix + "mean path length after the lids stop, non-swelling", path_plain);
    record_info(name, prefix + "mean path length after the lids stop, swelling", path_swell);
    const double late_plain = mean_path_length(plain, t_late, t_end);
    const double late_swell = mean_path_length(swell, t_late, t_end);
    const double pairs_plain = mean_in_window(plain, "contact/n_active_pairs", t_late, t_end);
    const double pairs_swell = mean_in_window(swell, "contact/n_active_pairs", t_late, t_end);
    const bool pushing = pairs_swell > pairs_plain && late_swell > late_plain;
    std::printf("%s 4. %g <= t <= %g: mean touching CDS pairs swelling %.3g > non-swelling %.3g; mean path "
                "swelling %.5f > non-swelling %.5f\n",
                pushing ? "PASS" : "FAIL", t_late, t_end, pairs_swell, pairs_plain, late_swell, late_plain);
    record(name, prefix + "late window: swelling - non-swelling mean path length (> 0, with more contacts)", 0.0,
           late_swell - late_plain, pushing);
    record_info(name, prefix + "late window: mean touching CDS pairs, swelling", pairs_swell);
    record_info(name, prefix + "late window: mean touching CDS pairs, non-swelling", pairs_plain);
    return all && further && pushing ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cavity_particles_check: %s\n", e.what());
    return 2;
  }
}
