// Discrete moment conditions of the four delta kernels, docs/method.md §4 and §A9 (its moment table):
// sums over the integer nodes j of phi(x - j) for a sweep of 1201 marker offsets x in [0, 1].
// Each moment's row (kernel, moment, expected, max error, range of the sum, tolerance) also goes
// to $IBMS_RESULTS_DIR/kernel_moments.csv for the report's kernel-moment table.
#define BOOST_TEST_MODULE delta_kernel
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <string>

#include "core/constants.hpp"
#include "ibm/delta_kernel.hpp"
#include "../common/results_csv.hpp"

using namespace ibms;

namespace {

constexpr int n_offsets = 1201;  // >= 1000 offsets, including x = 0, 1/2 and 1 exactly
// Every identity below is a sum of <= 6 terms of size <= 3^3 * 0.45: round-off is a few 1e-16.
constexpr double round_off = 1e-14;

// sum_j g(x - j) phi(x - j) over all nodes j with phi != 0 (kernel_stencil's nodes).
double node_sum(KernelKind kernel, double x, const std::function<double(double, double)>& g) {
  const KernelStencil stencil = kernel_stencil(kernel, x);
  double sum = 0.0;
  for (int k = 0; k < stencil.n_nodes; ++k) {
    const double r = x - (stencil.first + k);
    sum += g(r, stencil.weight[k]);
  }
  return sum;
}

// max over the sweep of |sum - expected(x)|, and the range of the sum.
struct Sweep { double max_error = 0, min_sum = 1e300, max_sum = -1e300; };
Sweep sweep(KernelKind kernel, const std::function<double(double, double)>& g,
            const std::function<double(double)>& expected) {
  Sweep s;
  for (int n = 0; n < n_offsets; ++n) {
    const double x = static_cast<double>(n) / (n_offsets - 1);
    const double sum = node_sum(kernel, x, g);
    s.max_error = std::max(s.max_error, std::abs(sum - expected(x)));
    s.min_sum = std::min(s.min_sum, sum);
    s.max_sum = std::max(s.max_sum, sum);
  }
  return s;
}

const auto zero = [](double) { return 0.0; };

// One row of kernel_moments.csv: kernel,moment,expected,max_error,min_sum,max_sum,tolerance.
void record_moment(KernelKind kernel, const std::string& moment, const std::string& expected, const Sweep& s,
                   double tolerance) {
  using verification::csv_number;
  verification::append_results_csv(
      "kernel_moments.csv", "kernel,moment,expected,max_error,min_sum,max_sum,tolerance",
      {kernel_name(kernel) + ",\"" + moment + "\",\"" + expected + "\"," + csv_number(s.max_error) + "," +
       csv_number(s.min_sum) + "," + csv_number(s.max_sum) + "," + csv_number(tolerance)});
}

}  // namespace

BOOST_AUTO_TEST_CASE(stencil_weights_equal_kernel_phi_and_cover_the_support) {
  double worst = 0.0;
  for (KernelKind kernel : all_kernel_kinds)
    for (int n = 0; n < n_offsets; ++n) {
      const double x = -3.7 + 7.4 * n / (n_offsets - 1);
      const KernelStencil s = kernel_stencil(kernel, x);
      for (int k = 0; k < s.n_nodes; ++k)
        worst = std::max(worst, std::abs(s.weight[k] - kernel_phi(kernel, x - (s.first + k))));
      // Nodes just outside the stencil carry no weight.
      worst = std::max(worst, std::abs(kernel_phi(kernel, x - (s.first - 1))));
      worst = std::max(worst, std::abs(kernel_phi(kernel, x - (s.first + s.n_nodes))));
    }
  BOOST_TEST_MESSAGE("max |stencil weight - phi| = " << worst);
  BOOST_TEST(worst <= round_off);
  // A9 node values of the BKP kernel (15 significant digits quoted, hence 1e-15).
  BOOST_TEST(std::abs(kernel_phi(KernelKind::bkp6, 0.0) - 0.446481226755848) <= 1e-15);
  BOOST_TEST(std::abs(kernel_phi(KernelKind::bkp6, 1.0) - 0.25) <= 1e-15);
  BOOST_TEST(std::abs(kernel_phi(KernelKind::bkp6, -2.0) - 0.026759386622076) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(kernel_weights_sum_to_one) {
  BOOST_TEST_MESSAGE("kernel    max|sum phi - 1|");
  for (KernelKind kernel : all_kernel_kinds) {
    const Sweep s = sweep(kernel, [](double, double p) { return p; }, [](double) { return 1.0; });
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << s.max_error);
    record_moment(kernel, "sum phi", "1", s, round_off);
    BOOST_TEST(s.max_error <= round_off);
  }
}

BOOST_AUTO_TEST_CASE(first_moment_vanishes_except_cosine_which_follows_its_closed_form) {
  // Cosine: sum_j (x-j) phi = x - 1/2 + (cos(pi x/2) - sin(pi x/2))/2 on [0, 1] (nodes -1..2),
  // up to +-0.021 (A9): the documented non-zero first moment.
  const auto cosine_moment = [](double x) {
    return x - 0.5 + 0.5*(std::cos(0.5*pi*x) - std::sin(0.5*pi*x));
  };
  BOOST_TEST_MESSAGE("kernel    max|error|    range of sum (x-j) phi");
  for (KernelKind kernel : all_kernel_kinds) {
    const bool is_cosine = kernel == KernelKind::cosine4;
    const Sweep s = sweep(kernel, [](double r, double p) { return r*p; },
                          is_cosine ? std::function<double(double)>(cosine_moment) : zero);
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << s.max_error << "    [" << s.min_sum
                                           << ", " << s.max_sum << "]");
    record_moment(kernel, "sum (x-j) phi", is_cosine ? "closed form (A9)" : "0", s, round_off);
    BOOST_TEST(s.max_error <= round_off);
    if (is_cosine) BOOST_TEST(s.max_sum > 0.02);  // A9: "error up to +-0.021"
  }
}

BOOST_AUTO_TEST_CASE(even_and_odd_node_sums_are_one_half_except_roma3) {
  BOOST_TEST_MESSAGE("kernel    max|sum_even - 1/2|   range of sum_even");
  for (KernelKind kernel : all_kernel_kinds) {
    double worst = 0.0, lo = 1.0, hi = 0.0;
    for (int n = 0; n < n_offsets; ++n) {
      const double x = static_cast<double>(n) / (n_offsets - 1);
      const KernelStencil st = kernel_stencil(kernel, x);
      double even = 0.0, odd = 0.0;
      for (int k = 0; k < st.n_nodes; ++k) ((st.first + k) % 2 == 0 ? even : odd) += st.weight[k];
      worst = std::max({worst, std::abs(even - 0.5), std::abs(odd - 0.5)});
      lo = std::min(lo, even);
      hi = std::max(hi, even);
    }
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << worst << "    [" << lo << ", " << hi << "]");
    Sweep even_sums;
    even_sums.max_error = kernel == KernelKind::roma3 ? NAN : worst;
    even_sums.min_sum = lo;
    even_sums.max_sum = hi;
    record_moment(kernel, "sum over even j of phi", kernel == KernelKind::roma3 ? "in [1/3, 2/3]" : "1/2", even_sums,
                  round_off);
    if (kernel == KernelKind::roma3) {
      BOOST_TEST(lo >= 1.0/3.0 - round_off);  // A9: Roma 3-point sums range over [1/3, 2/3]
      BOOST_TEST(hi <= 2.0/3.0 + round_off);
    } else {
      BOOST_TEST(worst <= round_off);
    }
  }
}

BOOST_AUTO_TEST_CASE(sum_of_squares_is_the_documented_constant) {
  // A9: 1/2, 3/8, 3/8 exactly; BKP: a constant C ~ 0.3257776154 (10 digits quoted -> 1e-10).
  const double exact[] = {0.5, 0.375, 0.375, 0.0};
  BOOST_TEST_MESSAGE("kernel    min sum phi^2           max sum phi^2");
  for (KernelKind kernel : all_kernel_kinds) {
    const Sweep s = sweep(kernel, [](double, double p) { return p*p; }, zero);
    BOOST_TEST_MESSAGE(kernel_name(kernel) << "    " << std::setprecision(16) << s.min_sum
                                           << "    " << s.max_sum);
    BOOST_TEST(s.max_sum - s.min_sum <= round_off);
    const double constant = kernel == KernelKind::bkp6 ? 0.3257776154 : exact[static_cast<int>(kernel)];
    Sweep squares = s;
    squares.max_error = std::max(std::abs(s.max_sum - constant), std::abs(s.min_sum - constant));
    record_moment(kernel, "sum phi^2", kernel == KernelKind::bkp6 ? "0.3257776154 (C)" : std::to_string(constant).substr(0, 5),
                  squares, kernel == KernelKind::bkp6 ? 1e-10 : round_off);
    if (kernel == KernelKind::bkp6) BOOST_TEST(std::abs(s.max_sum - 0.3257776154) <= 1e-10);
    else BOOST_TEST(std::abs(s.max_sum - exact[static_cast<int>(kernel)]) <= round_off);
  }
}

BOOST_AUTO_TEST_CASE(bkp6_second_moment_is_K_and_third_moment_vanishes) {
  const double K = 59.0/60.0 - std::sqrt(29.0)/20.0;  // A9
  const Sweep second = sweep(KernelKind::bkp6, [](double r, double p) { return r*r*p; },
                             [K](double) { return K; });
  const Sweep third = sweep(KernelKind::bkp6, [](double r, double p) { return r*r*r*p; }, zero);
  BOOST_TEST_MESSAGE("bkp6: max|sum r^2 phi - K| = " << second.max_error
                     << ", max|sum r^3 phi| = " << third.max_error << ", K = " << K);
  record_moment(KernelKind::bkp6, "sum (x-j)^2 phi", "K = 59/60 - sqrt(29)/20", second, round_off);
  record_moment(KernelKind::bkp6, "sum (x-j)^3 phi", "0", third, round_off);
  BOOST_TEST(std::abs(bkp6_second_moment() - 0.7140750929766) <= 1e-13);  // 13 digits in A9
  BOOST_TEST(second.max_error <= round_off);
  BOOST_TEST(third.max_error <= round_off);
}
