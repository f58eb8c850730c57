// Output lines of `ibms compare` (docs/compare.md): one line per gated metric (metric, tolerance,
// measured, pass|FAIL) and `info` lines (submitted and reference side by side, not gated).
#pragma once
#include <cstdio>
#include <string>

namespace ibms {

struct Verdict {
  bool pass = true;
  // Gated: passes if measured <= tolerance.
  void line(const std::string& metric, double tolerance, double measured) {
    char tol[32];
    std::snprintf(tol, sizeof tol, "%.4g", tolerance);
    gate(metric, tol, measured, measured <= tolerance);
  }
  // Gated, with the criterion given as text (e.g. "> 0", ">= 2") and its outcome `ok`.
  void gate(const std::string& metric, const std::string& criterion, double measured, bool ok) {
    pass = pass && ok;
    std::printf("  %-62s %10s %12.5g   %s\n", metric.c_str(), criterion.c_str(), measured, ok ? "pass" : "FAIL");
  }
  static void info(const std::string& metric, double submitted, double reference) {
    std::printf("  %-62s submitted %.6g, reference %.6g   info\n", metric.c_str(), submitted, reference);
  }
  // Against ibms's runs of a case under each coupling (the scene's end-of-step constraint and the
  // papers' coupling, reference/ibms_*.csv and reference/ibms_papers_coupling_*.csv).
  static void info(const std::string& metric, double submitted, double end_of_step, double papers) {
    std::printf("  %-62s submitted %.6g, ibms end-of-step %.6g, ibms papers' coupling %.6g   info\n", metric.c_str(),
                submitted, end_of_step, papers);
  }
  static void header() { std::printf("  %-62s %10s %12s   %s\n", "metric", "tolerance", "measured", "result"); }
};

}  // namespace ibms
