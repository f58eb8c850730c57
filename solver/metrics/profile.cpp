// Spline profiles (profile.hpp).
#include "metrics/profile.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_spline.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "metrics/csv_reader.hpp"

namespace ibms {

struct ProfileSpline::Gsl {
  gsl_spline* spline = nullptr;
  gsl_interp_accel* accel = nullptr;
  ~Gsl() {
    gsl_spline_free(spline);
    gsl_interp_accel_free(accel);
  }
};

namespace {

// GSL's default error handler aborts; ibms reports errors by exceptions and checks return codes.
void quiet_gsl() {
  static const bool off = [] { gsl_set_error_handler_off(); return true; }();
  (void)off;
}

}  // namespace

ProfileSpline::ProfileSpline(std::vector<double> s, std::vector<double> f)
    : s_(std::move(s)), f_(std::move(f)), gsl_(std::make_unique<Gsl>()) {
  quiet_gsl();
  if (s_.size() != f_.size() || s_.size() < 3)
    throw std::invalid_argument("profile: need at least 3 points and as many values as coordinates");
  for (std::size_t k = 1; k < s_.size(); ++k)
    if (!(s_[k] > s_[k - 1])) throw std::invalid_argument("profile: coordinates must increase strictly");
  gsl_->spline = gsl_spline_alloc(gsl_interp_cspline, s_.size());
  gsl_->accel = gsl_interp_accel_alloc();
  if (gsl_->spline == nullptr || gsl_->accel == nullptr ||
      gsl_spline_init(gsl_->spline, s_.data(), f_.data(), s_.size()) != GSL_SUCCESS)
    throw std::runtime_error("profile: GSL spline set-up failed");
}

ProfileSpline::~ProfileSpline() = default;
ProfileSpline::ProfileSpline(ProfileSpline&&) noexcept = default;
ProfileSpline& ProfileSpline::operator=(ProfileSpline&&) noexcept = default;

double ProfileSpline::operator()(double s) const {
  return gsl_spline_eval(gsl_->spline, std::clamp(s, s_.front(), s_.back()), gsl_->accel);
}

double ProfileSpline::extremum(bool maximum, double* where) const {
  const auto it = maximum ? std::max_element(f_.begin(), f_.end()) : std::min_element(f_.begin(), f_.end());
  const std::size_t k = static_cast<std::size_t>(it - f_.begin());
  if (k == 0 || k + 1 == f_.size()) {  // at an end (e.g. a lid value): the sample itself
    if (where != nullptr) *where = s_[k];
    return f_[k];
  }
  const double sign = maximum ? -1.0 : 1.0;  // Brent minimises
  struct Data { const ProfileSpline* p; double sign; } data{this, sign};
  gsl_function objective;
  objective.function = [](double s, void* d) {
    const Data* x = static_cast<const Data*>(d);
    return x->sign * (*x->p)(s);
  };
  objective.params = &data;
  double a = s_[k - 1], b = s_[k + 1], m = s_[k];
  // Brent needs f(m) below both ends; on a flat triple (equal samples) the discrete value stands.
  if (!(sign * (*this)(m) < sign * (*this)(a) && sign * (*this)(m) < sign * (*this)(b))) {
    if (where != nullptr) *where = m;
    return f_[k];
  }
  gsl_min_fminimizer* minimizer = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  if (minimizer == nullptr) throw std::runtime_error("profile: GSL minimiser allocation failed");
  if (gsl_min_fminimizer_set(minimizer, &objective, m, a, b) != GSL_SUCCESS) {
    gsl_min_fminimizer_free(minimizer);
    throw std::runtime_error("profile: GSL Brent set-up failed");
  }
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (gsl_min_fminimizer_iterate(minimizer) != GSL_SUCCESS) break;
    m = gsl_min_fminimizer_x_minimum(minimizer);
    a = gsl_min_fminimizer_x_lower(minimizer);
    b = gsl_min_fminimizer_x_upper(minimizer);
    if (gsl_min_test_interval(a, b, 0.0, 1e-12) == GSL_SUCCESS) break;
  }
  gsl_min_fminimizer_free(minimizer);
  if (where != nullptr) *where = m;
  return (*this)(m);
}

ProfileTable read_profile_table(const std::string& path) {
  const CsvTable t = read_csv(path, {{"flag"}});
  const int flag = t.find({"flag"});
  return {t.column(0), t.column(1),
          flag >= 0 ? t.text[static_cast<std::size_t>(flag)] : std::vector<std::string>(t.rows())};
}

double interpolate_profile(const std::vector<double>& s, const std::vector<double>& f, double at) {
  return ProfileSpline(s, f)(at);
}

double profile_extremum(const std::vector<double>& s, const std::vector<double>& f, bool maximum) {
  return ProfileSpline(s, f).extremum(maximum);
}

std::array<double, 3> centreline_extrema(const std::vector<double>& y, const std::vector<double>& u,
                                         const std::vector<double>& x, const std::vector<double>& v) {
  const ProfileSpline pu(y, u), pv(x, v);
  return {pu.extremum(false), pv.extremum(true), pv.extremum(false)};
}

std::array<double, 3> published_extrema(const std::string& path) {
  return {reference_value(path, "u_min"), reference_value(path, "v_max"), reference_value(path, "v_min")};
}

double largest_extremum_error(const std::array<double, 3>& measured, const std::array<double, 3>& published) {
  double worst = 0.0;
  for (int q = 0; q < 3; ++q) worst = std::max(worst, std::abs(measured[q] - published[q]));
  return worst;
}

}  // namespace ibms
