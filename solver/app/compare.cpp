// `ibms compare` (compare.hpp). The metrics and criteria are those of the case checks, from the one
// definition in the metrics module (metrics/case_criteria.hpp, metrics/profile.hpp,
// metrics/body_series.hpp): validation/common/cavity_check.cpp (max |centre-line velocity - Ghia|
// over the unflagged Ghia points) and validation/settling_disk/check.cpp (maximum settling speed
// within 3 % of 5.5 cm/s); the same metric is also taken against ibms's own finest run
// (validation/<case>/reference/ibms_*.csv, see each reference/README_ibms.md). The two body
// cavities are in compare_bodies.cpp, the DFG cylinders in compare_dfg.cpp.
#include "app/compare.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/compare_bodies.hpp"
#include "app/compare_dfg.hpp"
#include "app/compare_report.hpp"
#include "core/errors.hpp"
#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "metrics/profile.hpp"

#ifndef IBMS_VALIDATION_DIR
#define IBMS_VALIDATION_DIR ""
#endif

namespace ibms {
namespace {

using criteria::CavityCase;

const std::string settling_case = "settling_disk";

struct Profile { std::vector<double> s, value; };  // s: coordinate along the line [length]

void require_rows(const CsvTable& t, std::size_t n, const std::string& what) {
  if (t.lines.size() < n)
    throw InputError(t.path + ":" + std::to_string(t.header_line) + ": " + what + " needs at least " +
                     std::to_string(n) + " rows, got " + std::to_string(t.lines.size()));
}

// A (coordinate, value) profile from the columns named in `coordinate` and `value` aliases.
bool take_profile(const CsvTable& t, const std::vector<std::string>& coordinate,
                  const std::vector<std::string>& value, Profile& out) {
  const int c = t.find(coordinate), v = t.find(value);
  if (c < 0 || v < 0) return false;
  require_rows(t, 4, "a centre-line profile");
  require_increasing(t, c);
  for (std::size_t k = 0; k < t.lines.size(); ++k)
    if (t.columns[c][k] < -1e-9 || t.columns[c][k] > 1 + 1e-9)
      throw InputError(t.path + ":" + std::to_string(t.lines[k]) + ": coordinate " + std::to_string(t.columns[c][k]) +
                       " outside the cavity [0, 1]");
  out = {t.columns[c], t.columns[v]};
  return true;
}

// max |submitted - reference| at the unflagged reference points inside the submitted range;
// n_used counts them.
double max_deviation(const Profile& submitted, const ProfileTable& ref, int& n_used) {
  const ProfileSpline spline(submitted.s, submitted.value);
  double worst = 0.0;
  n_used = 0;
  for (std::size_t k = 0; k < ref.s.size(); ++k) {
    if (!ref.flags[k].empty()) continue;
    if (ref.s[k] < submitted.s.front() - 1e-12 || ref.s[k] > submitted.s.back() + 1e-12) continue;
    worst = std::max(worst, std::abs(spline(ref.s[k]) - ref.f[k]));
    ++n_used;
  }
  return worst;
}

void require_coverage(const Profile& p, const std::string& files, const std::string& what) {
  if (p.s.front() > 0.05 || p.s.back() < 0.95)
    throw InputError(files + ": the " + what + " profile covers [" + std::to_string(p.s.front()) + ", " +
                     std::to_string(p.s.back()) + "]; it must span at least [0.05, 0.95] of the line");
}

int compare_cavity(const CavityCase& c, const std::vector<std::string>& files, const std::string& ref_dir) {
  Profile u, v;
  bool have_u = false, have_v = false;
  for (const std::string& f : files) {
    const CsvTable t = read_csv(f);
    bool used = false;
    if (take_profile(t, {"y"}, {"u"}, u)) { have_u = used = true; }
    if (take_profile(t, {"x"}, {"v"}, v)) { have_v = used = true; }
    if (!used)
      throw InputError(f + ":" + std::to_string(t.header_line) +
                       ": header names neither the columns y,u (u along x = 0.5) nor x,v (v along y = 0.5)");
  }
  std::string all_files;
  for (const std::string& f : files) all_files += (all_files.empty() ? "" : ", ") + f;
  if (!have_u) throw InputError(all_files + ": no u profile (columns y,u) for " + std::string(c.name));
  if (!have_v) throw InputError(all_files + ": no v profile (columns x,v) for " + std::string(c.name));
  require_coverage(u, all_files, "u(0.5, y)");
  require_coverage(v, all_files, "v(x, 0.5)");

  const std::string dir = ref_dir + "/" + std::string(c.name) + "/reference/";
  const ProfileTable ref_u = read_profile_table(dir + "ibms_centreline_u.csv");
  const ProfileTable ref_v = read_profile_table(dir + "ibms_centreline_v.csv");
  std::printf("ibms compare %s: %s\n", std::string(c.name).c_str(), all_files.c_str());
  Verdict::header();
  Verdict verdict;
  int n_u = 0, n_v = 0;
  if (!c.ghia_u.empty()) {
    const double du = max_deviation(u, read_profile_table(dir + std::string(c.ghia_u)), n_u);
    const double dv = max_deviation(v, read_profile_table(dir + std::string(c.ghia_v)), n_v);
    verdict.line(fmt::format("max |centre-line velocity - Ghia| (lid speed 1; {}+{} points)", n_u, n_v),
                 c.tolerance, std::max(du, dv));
  }
  const double du = max_deviation(u, ref_u, n_u);
  const double dv = max_deviation(v, ref_v, n_v);
  verdict.line(fmt::format("max |centre-line velocity - ibms reference| ({}+{} points)", n_u, n_v), c.tolerance,
               std::max(du, dv));
  // The extrema the checks' grid-convergence study uses, and the symmetry defect of the two-sided
  // case (exact in a symmetric scheme; reported, not gated, for another code).
  const ProfileSpline su(u.s, u.value), sv(v.s, v.value), rsu(ref_u.s, ref_u.f), rsv(ref_v.s, ref_v.f);
  Verdict::info("min u on x = 0.5", su.extremum(false), rsu.extremum(false));
  Verdict::info("max v on y = 0.5", sv.extremum(true), rsv.extremum(true));
  Verdict::info("min v on y = 0.5", sv.extremum(false), rsv.extremum(false));
  if (c.ghia_u.empty()) {
    double defect = 0.0;
    for (const double s : {0.125, 0.25, 0.375, 0.5})
      defect = std::max({defect, std::abs(su(s) + su(1 - s)), std::abs(sv(s) + sv(1 - s))});
    Verdict::info("point-symmetry defect |f(s) + f(1-s)|, s = 1/8..1/2", defect, 0.0);
  }
  std::printf("%s: %s\n", std::string(c.name).c_str(), verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

// Settling history: t [s], v [cm/s] (vertical centre-of-mass velocity, negative downwards),
// optional y [cm] (centre height). Accepts ibms's own <stem>_bodies.csv by its column names.
struct History { std::vector<double> t, v, y; };

History take_history(const CsvTable& t) {
  const int ct = t.find({"t", "time"});
  const int cv = t.find({"v", "velocity_y", "body_000/velocity_y"});
  const int cy = t.find({"y", "centroid_y", "body_000/centroid_y"});
  if (ct < 0 || cv < 0)
    throw InputError(t.path + ":" + std::to_string(t.header_line) + ": header needs the columns t and v (settling history)");
  require_rows(t, 2, "a settling history");
  require_increasing(t, ct);
  return {t.columns[ct], t.columns[cv], cy >= 0 ? t.columns[cy] : std::vector<double>{}};
}

double max_speed(const History& h, double& at) {
  std::size_t k_max = 0;
  const double speed = max_settling_speed(h.v, &k_max);
  at = h.t[k_max];
  return speed;
}

double linear(const std::vector<double>& x, const std::vector<double>& f, double xq) {
  const std::size_t k = std::clamp<std::size_t>(std::upper_bound(x.begin(), x.end(), xq) - x.begin(), 1, x.size() - 1);
  const double w = (xq - x[k - 1]) / (x[k] - x[k - 1]);
  return (1 - w) * f[k - 1] + w * f[k];
}

double touchdown(const History& h, double level) { return first_crossing_below(h.t, h.y, level); }

int compare_settling(const std::vector<std::string>& files, const std::string& ref_dir) {
  if (files.size() != 1) throw InputError("settling_disk: give exactly one CSV file (columns t,v[,y])");
  const History h = take_history(read_csv(files[0]));
  const std::string dir = ref_dir + "/" + settling_case + "/reference/";
  const History ref = take_history(read_csv(dir + "ibms_settling_history.csv"));
  // Published values (reference/settling_disk_rho1.25.csv): max settling speed 5.5 cm/s, touchdown 0.80 s.
  const double published = reference_value(dir + "settling_disk_rho1.25.csv", "max_settling_speed");
  const double touchdown_level = criteria::settling_touchdown_height;
  const double settling_tolerance = criteria::settling_speed_tolerance;
  std::printf("ibms compare %s: %s\n", settling_case.c_str(), files[0].c_str());
  Verdict::header();
  double t_max = 0, t_max_ref = 0;
  const double speed = max_speed(h, t_max), speed_ref = max_speed(ref, t_max_ref);
  Verdict verdict;
  verdict.line(fmt::format("|max settling speed / {:.4g} cm/s (published) - 1|", published), settling_tolerance,
               std::abs(speed / published - 1));
  verdict.line(fmt::format("|max settling speed / {:.4g} cm/s (ibms reference) - 1|", speed_ref), settling_tolerance,
               std::abs(speed / speed_ref - 1));
  Verdict::info("max settling speed [cm/s]", speed, speed_ref);
  Verdict::info("time of the max settling speed [s]", t_max, t_max_ref);
  // v(t) against the reference over the common time range before the reference touches down.
  const double t_end = std::min({h.t.back(), ref.t.back(), ref.y.empty() ? HUGE_VAL : touchdown(ref, touchdown_level)});
  double worst = 0.0;
  for (std::size_t k = 0; k < h.t.size() && h.t[k] <= t_end; ++k)
    worst = std::max(worst, std::abs(h.v[k] - linear(ref.t, ref.v, h.t[k])));
  Verdict::info(fmt::format("max |v(t) - v_ref(t)| / v_ref,max for t <= {:.3g} s", t_end), worst / speed_ref, 0.0);
  if (!h.y.empty()) Verdict::info("touchdown time (centre at y = 0.14 cm) [s]", touchdown(h, touchdown_level),
                                  touchdown(ref, touchdown_level));
  std::printf("%s: %s\n", settling_case.c_str(), verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

// DKT of two disks (validation/dkt_two_disks): t [s], y and v of the trailing (upper) and leading
// disk [cm, cm/s]; ibms's own <stem>_bodies.csv is accepted by its column names (body 0 trailing).
// Gated as dkt_check: the trailing disk's max settling speed within 4 % of 1.70 cm/s and its time
// within 0.1 s of 1.12 s (the drafting phase), and the pair tumbles (trailing below leading at the
// end); the leading disk's max speed and the time the pair is horizontal are shown as information.
const std::string dkt_case = "dkt_two_disks";

int compare_dkt(const std::vector<std::string>& files, const std::string& ref_dir) {
  if (files.size() != 1) throw InputError("dkt_two_disks: give exactly one CSV file (t,y_trailing,y_leading,v_trailing[,v_leading])");
  const CsvTable t = read_csv(files[0]);
  const int ct = t.find({"t", "time"});
  const int cy0 = t.find({"y_trailing", "body_000/centroid_y"});
  const int cy1 = t.find({"y_leading", "body_001/centroid_y"});
  const int cv0 = t.find({"v_trailing", "body_000/velocity_y"});
  const int cv1 = t.find({"v_leading", "body_001/velocity_y"});
  if (ct < 0 || cy0 < 0 || cy1 < 0 || cv0 < 0)
    throw InputError(t.path + ":" + std::to_string(t.header_line) +
                     ": header needs the columns t, y_trailing, y_leading and v_trailing (DKT history)");
  require_rows(t, 2, "a DKT history");
  require_increasing(t, ct);
  const std::string ref = ref_dir + "/" + dkt_case + "/reference/wan_turek_dkt_digitized.csv";
  const double speed_ref = reference_value(ref, "max_settling_speed_trailing");
  const double time_ref = reference_value(ref, "time_of_max_speed_trailing");
  const std::vector<double>& time = t.columns[ct];
  std::size_t k_max = 0, k_max_leading = 0;
  double t_level = NAN;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (-t.columns[cv0][k] > -t.columns[cv0][k_max]) k_max = k;
    if (cv1 >= 0 && -t.columns[cv1][k] > -t.columns[cv1][k_max_leading]) k_max_leading = k;
    if (std::isnan(t_level) && t.columns[cy0][k] <= t.columns[cy1][k]) t_level = time[k];
  }
  const double speed = -t.columns[cv0][k_max];
  std::printf("ibms compare %s: %s\n", dkt_case.c_str(), files[0].c_str());
  Verdict::header();
  Verdict verdict;
  verdict.line(fmt::format("|trailing max settling speed / {:.4g} cm/s - 1|", speed_ref), criteria::dkt_speed_tolerance,
               std::abs(speed / speed_ref - 1));
  verdict.line(fmt::format("|time of that maximum - {:.4g} s| [s]", time_ref), criteria::dkt_time_tolerance,
               std::abs(time[k_max] - time_ref));
  verdict.gate("trailing disk ends below the leading one (1 = yes)", "= 1",
               t.columns[cy0].back() < t.columns[cy1].back() ? 1.0 : 0.0, t.columns[cy0].back() < t.columns[cy1].back());
  if (cv1 >= 0)
    Verdict::info("leading max settling speed [cm/s]", -t.columns[cv1][k_max_leading],
                  reference_value(ref, "max_settling_speed_leading"));
  Verdict::info("time the pair is horizontal [s] (set by the initial perturbation)", t_level,
                reference_value(ref, "time_pair_horizontal"));
  std::printf("%s: %s\n", dkt_case.c_str(), verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

}  // namespace

std::vector<std::string> compare_case_names() {
  std::vector<std::string> names;
  for (const CavityCase& c : criteria::cavity_cases) names.emplace_back(c.name);
  names.push_back(settling_case);
  names.push_back(dkt_case);
  names.push_back("cavity_swelling_particles");
  names.push_back("cavity_deformable_objects");
  names.push_back("dfg_cylinder_2d1");
  names.push_back("dfg_cylinder_2d2");
  return names;
}

std::string default_validation_dir() {
  if (const char* env = std::getenv("IBMS_VALIDATION_DIR"); env != nullptr && *env != '\0') return env;
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(IBMS_VALIDATION_DIR, ec)) return IBMS_VALIDATION_DIR;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return (exe.parent_path().parent_path() / "share/ibms/validation").string();
}

int compare_case(const std::string& case_name, const std::vector<std::string>& files, const std::string& validation_dir) {
  if (files.empty()) throw InputError("ibms compare: no input file");
  const std::vector<std::string> names = compare_case_names();
  if (std::find(names.begin(), names.end(), case_name) != names.end() &&
      !std::filesystem::is_directory(validation_dir + "/" + case_name + "/reference"))
    throw InputError(validation_dir + "/" + case_name + "/reference: not found (set --validation-dir)");
  for (const CavityCase& c : criteria::cavity_cases)
    if (c.name == case_name) return compare_cavity(c, files, validation_dir);
  if (case_name == settling_case) return compare_settling(files, validation_dir);
  if (case_name == dkt_case) return compare_dkt(files, validation_dir);
  if (case_name == "cavity_swelling_particles") return compare_swelling_particles(files, validation_dir);
  if (case_name == "cavity_deformable_objects") return compare_deformable_objects(files, validation_dir);
  if (case_name == "dfg_cylinder_2d1") return compare_dfg_steady(files, validation_dir);
  if (case_name == "dfg_cylinder_2d2") return compare_dfg_periodic(files, validation_dir);
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw InputError("ibms compare: unknown case '" + case_name + "' (known: " + known + ")");
}

}  // namespace ibms
