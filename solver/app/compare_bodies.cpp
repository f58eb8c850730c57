// `ibms compare` for the body-cavity cases (compare_bodies.hpp). Metrics and thresholds:
// validation/cavity_swelling_particles/check.cpp (checks 3 and 4: mean centroid path length over
// [10, 20] larger without swelling; over [15, 20] larger with swelling) and
// validation/cavity_deformable_objects/check.cpp (check 5: mean deformation parameter k = 10 at
// least twice k = 100; check 4: rim area within [0.5, 1.5] A0).
#include "app/compare_bodies.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "app/compare_report.hpp"
#include "core/errors.hpp"

namespace ibms {
namespace {

// One quantity of a body series: its column name(s) in the long format and its per-body column
// suffix in ibms's wide <stem>_bodies.csv (body_NNN/<suffix>; empty: not in that format).
struct Quantity {
  std::vector<std::string> long_names;
  std::string wide_suffix;
  bool required;
};

// Per-body time series on common output times.
struct BodySeries {
  std::string path;
  bool wide = false;
  std::vector<double> t;                            // strictly increasing
  std::vector<int> first_line, last_line;           // file line of the first/last row of each time
  std::vector<bool> have;                           // per quantity
  std::vector<std::vector<std::vector<double>>> q;  // q[quantity][body][time]
  std::size_t bodies() const { return q.empty() ? 0 : q[0].size(); }
};

std::string where(const std::string& path, int line) { return path + ":" + std::to_string(line) + ": "; }

std::string g(double v) { return fmt::format("{:.10g}", v); }

// Long format: one row per (time, particle); every particle has a row at every time, and each
// particle's times increase strictly in file order.
BodySeries read_long(const CsvTable& t, const std::vector<Quantity>& quantities, const std::string& columns_text) {
  const int ct = t.find({"time", "t"}), cp = t.find({"particle", "body"});
  std::vector<int> cq;
  for (const Quantity& q : quantities) {
    cq.push_back(t.find(q.long_names));
    if ((ct < 0 || cp < 0 || cq.back() < 0) && q.required)
      throw InputError(where(t.path, t.header_line) + "header needs the columns " + columns_text +
                       " (long format, one row per time and particle) or ibms's body_NNN/... columns");
  }
  std::map<double, std::size_t> index;  // particle id -> order of first appearance
  std::vector<double> ids;
  std::vector<std::vector<std::size_t>> rows;  // per particle, its rows in file order
  const std::vector<double>& time = t.columns[ct];
  for (std::size_t r = 0; r < t.lines.size(); ++r) {
    const double id = t.columns[cp][r];
    auto [it, inserted] = index.emplace(id, rows.size());
    if (inserted) { rows.emplace_back(); ids.push_back(id); }
    std::vector<std::size_t>& mine = rows[it->second];
    if (!mine.empty() && !(time[r] > time[mine.back()]))
      throw InputError(where(t.path, t.lines[r]) + "particle " + g(id) + ": time " + g(time[r]) + " after " +
                       g(time[mine.back()]) + " (each particle's times must increase strictly)");
    mine.push_back(r);
  }
  // Same times for every particle (compared with the first particle's).
  const std::vector<std::size_t>& first = rows[0];
  for (std::size_t p = 1; p < rows.size(); ++p) {
    const std::size_t n = std::min(first.size(), rows[p].size());
    for (std::size_t k = 0; k <= n; ++k) {
      if (k == n && first.size() == rows[p].size()) break;
      const double t0 = k < first.size() ? time[first[k]] : HUGE_VAL;
      const double tp = k < rows[p].size() ? time[rows[p][k]] : HUGE_VAL;
      if (std::abs(tp - t0) <= 1e-9 * std::max(1.0, std::abs(t0))) continue;
      if (tp < t0)  // particle ids[0] lacks time tp
        throw InputError(where(t.path, t.lines[rows[p][k]]) + "particle " + g(ids[0]) + " has no row at time " + g(tp) +
                         " (every particle needs one row at each time)");
      throw InputError(where(t.path, t.lines[first[k]]) + "particle " + g(ids[p]) + " has no row at time " + g(t0) +
                       " (every particle needs one row at each time)");
    }
  }
  if (first.size() < 2)
    throw InputError(where(t.path, t.header_line) + "needs at least 2 output times, got " + std::to_string(first.size()));
  BodySeries s;
  s.path = t.path;
  for (std::size_t k = 0; k < first.size(); ++k) {
    s.t.push_back(time[first[k]]);
    int lo = t.lines[first[k]], hi = lo;
    for (const auto& mine : rows) { lo = std::min(lo, t.lines[mine[k]]); hi = std::max(hi, t.lines[mine[k]]); }
    s.first_line.push_back(lo);
    s.last_line.push_back(hi);
  }
  for (std::size_t i = 0; i < quantities.size(); ++i) {
    s.have.push_back(cq[i] >= 0);
    s.q.emplace_back(cq[i] >= 0 ? rows.size() : 0);
    if (cq[i] < 0) continue;
    for (std::size_t p = 0; p < rows.size(); ++p)
      for (const std::size_t r : rows[p]) s.q[i][p].push_back(t.columns[cq[i]][r]);
  }
  return s;
}

std::string body_column(int b, const std::string& suffix) { return fmt::format("body_{:03d}/{}", b, suffix); }

// ibms's <stem>_bodies.csv: `time` and body_NNN/<suffix> per body, one row per written step.
BodySeries read_wide(const CsvTable& t, const std::vector<Quantity>& quantities) {
  const int ct = t.find({"time", "t"});
  if (ct < 0) throw InputError(where(t.path, t.header_line) + "ibms body series without a 'time' column");
  if (t.lines.size() < 2)
    throw InputError(where(t.path, t.header_line) + "needs at least 2 output times, got " + std::to_string(t.lines.size()));
  require_increasing(t, ct);
  BodySeries s;
  s.path = t.path;
  s.wide = true;
  s.t = t.columns[ct];
  s.first_line = s.last_line = t.lines;
  int n_bodies = 0;
  while (t.find({body_column(n_bodies, quantities[0].wide_suffix)}) >= 0) ++n_bodies;
  for (const Quantity& q : quantities) {
    const bool present = !q.wide_suffix.empty() && t.find({body_column(0, q.wide_suffix)}) >= 0;
    if (!present && q.required)
      throw InputError(where(t.path, t.header_line) + "ibms body series without the column " + body_column(0, q.wide_suffix));
    s.have.push_back(present);
    s.q.emplace_back();
    if (!present) continue;
    for (int b = 0; b < n_bodies; ++b) {
      const int c = t.find({body_column(b, q.wide_suffix)});
      if (c < 0) throw InputError(where(t.path, t.header_line) + "column " + body_column(b, q.wide_suffix) + " missing");
      s.q.back().push_back(t.columns[c]);
    }
  }
  return s;
}

// Reads the long format, or ibms's wide _bodies.csv when the header has no particle column but
// body_000/<first quantity's suffix>.
BodySeries read_body_series(const std::string& path, const std::vector<Quantity>& quantities,
                            const std::string& columns_text) {
  const CsvTable t = read_csv(path);
  if (t.find({"particle", "body"}) < 0 && t.find({body_column(0, quantities[0].wide_suffix)}) >= 0)
    return read_wide(t, quantities);
  return read_long(t, quantities, columns_text);
}

// The series must cover [t0, t1] to within `slack`.
void require_window(const BodySeries& s, double t0, double t1, double slack, const std::string& case_name) {
  if (s.t.front() > t0 + slack || s.t.back() < t1 - slack)
    throw InputError(where(s.path, s.t.front() > t0 + slack ? s.first_line.front() : s.last_line.back()) + "times cover [" +
                     g(s.t.front()) + ", " + g(s.t.back()) + "]; " + case_name + " needs " + g(t0) + " <= t <= " +
                     g(t1) + " (to within " + g(slack) + ")");
}

// ---- cavity_swelling_particles ------------------------------------------------------------------

const std::string swelling_case = "cavity_swelling_particles";
constexpr double t_stop = criteria::particles_t_stop, t_late = criteria::particles_t_late,
                 t_end = criteria::particles_t_end;

const std::vector<Quantity>& trajectory_quantities() {
  static const std::vector<Quantity> q{{{"x", "centroid_x"}, "centroid_x", true}, {{"y", "centroid_y"}, "centroid_y", true}};
  return q;
}

// Whether the chord between output times k-1 and k lies in [t0, t1], compared exactly as check.cpp
// does: a time printed as 15 counts as inside, ibms's unrounded 14.99999999999997 does not
// (docs/compare.md gives the size of that edge effect).
bool chord_in_window(const BodySeries& s, std::size_t k, double t0, double t1) {
  return s.t[k - 1] >= t0 && s.t[k] <= t1;
}

// Mean over particles of the centroid path length over [t0, t1] (metrics/body_series.hpp: the one
// definition, which the case check uses too).
double mean_path_length(const BodySeries& s, double t0, double t1) {
  double total = 0;
  for (std::size_t b = 0; b < s.bodies(); ++b) total += path_length(s.t, s.q[0][b], s.q[1][b], t0, t1);
  return total / static_cast<double>(s.bodies());
}

// Largest interval between consecutive output times inside [t0, t1].
double max_interval(const BodySeries& s, double t0, double t1) {
  double m = 0;
  for (std::size_t k = 1; k < s.t.size(); ++k)
    if (chord_in_window(s, k, t0, t1)) m = std::max(m, s.t[k] - s.t[k - 1]);
  return m;
}

BodySeries read_trajectories(const std::string& path) {
  BodySeries s = read_body_series(path, trajectory_quantities(), "time, particle, x, y");
  require_window(s, t_stop, t_end, 0.01 * (t_end - t_stop), swelling_case);
  return s;
}

// ---- cavity_deformable_objects ------------------------------------------------------------------

const std::string deformable_case = "cavity_deformable_objects";
constexpr double deformable_end = criteria::deformable_t_end;
constexpr double deformation_ratio_min = criteria::deformation_ratio_min;  // README.md, check 5
constexpr double area_min = criteria::area_ratio_min, area_max = criteria::area_ratio_max;  // check 4 (of A0)

struct DeformationFigures {
  std::size_t bodies = 0, times = 0;
  double mean = 0, max = 0;
  bool have_area = false;
  double area_lo = INFINITY, area_hi = -INFINITY;
};

DeformationFigures deformation_figures(const std::string& path) {
  static const std::vector<Quantity> q{
      {{"deformation"}, "deformation", true}, {{"area_ratio"}, "", false}, {{"area"}, "area", false}};
  const BodySeries s = read_body_series(path, q, "time, particle, deformation");
  require_window(s, 0.0, deformable_end, 0.01 * deformable_end, deformable_case);
  DeformationFigures f;
  f.bodies = s.bodies();
  double sum = 0;
  for (std::size_t b = 0; b < s.bodies(); ++b)
    for (std::size_t k = 0; k < s.t.size() && s.t[k] <= deformable_end * (1 + 1e-9); ++k) {
      sum += s.q[0][b][k];
      f.max = std::max(f.max, s.q[0][b][k]);
      ++f.times;
      // Area relative to A0: given (area_ratio), or the area over the body's first value (as the check).
      if (s.have[1] || s.have[2]) {
        const double ratio = s.have[1] ? s.q[1][b][k] : s.q[2][b][k] / s.q[2][b][0];
        f.area_lo = std::min(f.area_lo, ratio);
        f.area_hi = std::max(f.area_hi, ratio);
        f.have_area = true;
      }
    }
  f.mean = sum / static_cast<double>(f.times);
  f.times /= f.bodies;
  return f;
}

void require_two_files(const std::vector<std::string>& files, const std::string& case_name, const std::string& what) {
  if (files.size() != 2) throw InputError(case_name + ": give exactly two CSV files: " + what);
}

}  // namespace

int compare_swelling_particles(const std::vector<std::string>& files, const std::string& validation_dir) {
  require_two_files(files, swelling_case, "NONSWELLING.csv SWELLING.csv (columns time,particle,x,y)");
  const BodySeries plain = read_trajectories(files[0]), swell = read_trajectories(files[1]);
  const std::string dir = validation_dir + "/" + swelling_case + "/reference/";
  const BodySeries ref_plain = read_trajectories(dir + "ibms_trajectories_nonswelling.csv");
  const BodySeries ref_swell = read_trajectories(dir + "ibms_trajectories_swelling.csv");
  const BodySeries papers_plain = read_trajectories(dir + "ibms_papers_coupling_trajectories_nonswelling.csv");
  const BodySeries papers_swell = read_trajectories(dir + "ibms_papers_coupling_trajectories_swelling.csv");

  std::printf("ibms compare %s: non-swelling %s, swelling %s\n", swelling_case.c_str(), files[0].c_str(), files[1].c_str());
  Verdict::header();
  Verdict verdict;
  const double path_plain = mean_path_length(plain, t_stop, t_end), path_swell = mean_path_length(swell, t_stop, t_end);
  const double late_plain = mean_path_length(plain, t_late, t_end), late_swell = mean_path_length(swell, t_late, t_end);
  verdict.gate(fmt::format("mean path {:g}<=t<={:g}: non-swelling - swelling (check 3)", t_stop, t_end), "> 0",
               path_plain - path_swell, path_plain > path_swell);
  verdict.gate(fmt::format("mean path {:g}<=t<={:g}: swelling - non-swelling (check 4)", t_late, t_end), "> 0",
               late_swell - late_plain, late_swell > late_plain);
  // Each figure of the submitted pair beside ibms's under both couplings.
  const auto info_pair = [&](const std::string& what, const auto& figure) {
    Verdict::info("non-swelling: " + what, figure(plain), figure(ref_plain), figure(papers_plain));
    Verdict::info("swelling: " + what, figure(swell), figure(ref_swell), figure(papers_swell));
  };
  for (const double from : {t_stop, t_late})
    info_pair(fmt::format("mean centroid path length {:g}<=t<={:g}", from, t_end),
              [&](const BodySeries& s) { return mean_path_length(s, from, t_end); });
  info_pair("particles", [](const BodySeries& s) { return static_cast<double>(s.bodies()); });
  info_pair(fmt::format("largest output interval in [{:g}, {:g}]", t_stop, t_end),
            [&](const BodySeries& s) { return max_interval(s, t_stop, t_end); });
  std::printf("  not checked from trajectories: active contacts in the swelling run for %g<=t<=%g (check 4),\n"
              "  containment and interpenetration (check 2); the case's check.cpp tests those on ibms's run\n",
              t_late, t_end);
  std::printf("%s: %s\n", swelling_case.c_str(), verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

int compare_deformable_objects(const std::vector<std::string>& files, const std::string& validation_dir) {
  require_two_files(files, deformable_case, "K10.csv K100.csv (columns time,particle,deformation[,area_ratio])");
  const DeformationFigures k10 = deformation_figures(files[0]), k100 = deformation_figures(files[1]);
  const std::string dir = validation_dir + "/" + deformable_case + "/reference/";
  const DeformationFigures ref10 = deformation_figures(dir + "ibms_deformation_k10.csv");
  const DeformationFigures ref100 = deformation_figures(dir + "ibms_deformation_k100.csv");
  const DeformationFigures papers10 = deformation_figures(dir + "ibms_papers_coupling_deformation_k10.csv");
  const DeformationFigures papers100 = deformation_figures(dir + "ibms_papers_coupling_deformation_k100.csv");

  std::printf("ibms compare %s: k = 10 %s, k = 100 %s\n", deformable_case.c_str(), files[0].c_str(), files[1].c_str());
  Verdict::header();
  Verdict verdict;
  const double ratio = k10.mean / k100.mean;
  verdict.gate("mean deformation parameter k = 10 / k = 100 (check 5)", fmt::format(">= {:g}", deformation_ratio_min),
               ratio, ratio >= deformation_ratio_min);
  for (const auto& [label, f] : {std::pair{"k = 10", &k10}, std::pair{"k = 100", &k100}}) {
    if (!f->have_area) continue;
    verdict.gate(fmt::format("{}: min area / A0 (check 4)", label), fmt::format(">= {:g}", area_min), f->area_lo,
                 f->area_lo >= area_min);
    verdict.gate(fmt::format("{}: max area / A0 (check 4)", label), fmt::format("<= {:g}", area_max), f->area_hi,
                 f->area_hi <= area_max);
  }
  // Each figure beside ibms's under both couplings.
  Verdict::info("mean deformation ratio k = 10 / k = 100", ratio, ref10.mean / ref100.mean, papers10.mean / papers100.mean);
  for (const auto& [label, f, r, p] : {std::tuple{"k = 10", &k10, &ref10, &papers10},
                                       std::tuple{"k = 100", &k100, &ref100, &papers100}}) {
    Verdict::info(fmt::format("{}: mean deformation parameter", label), f->mean, r->mean, p->mean);
    Verdict::info(fmt::format("{}: max deformation parameter", label), f->max, r->max, p->max);
    if (f->have_area) {
      Verdict::info(fmt::format("{}: min area / A0", label), f->area_lo, r->area_lo, p->area_lo);
      Verdict::info(fmt::format("{}: max area / A0", label), f->area_hi, r->area_hi, p->area_hi);
    }
    Verdict::info(fmt::format("{}: bodies", label), f->bodies, r->bodies, p->bodies);
    Verdict::info(fmt::format("{}: output times in [0, {:g}]", label, deformable_end), f->times, r->times, p->times);
  }
  if (!k10.have_area || !k100.have_area)
    std::printf("  area bounds (check 4) not checked for a file without area_ratio or area\n");
  std::printf("%s: %s\n", deformable_case.c_str(), verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

}  // namespace ibms
