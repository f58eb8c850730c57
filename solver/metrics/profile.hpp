// Profiles along a line (centre-line velocities, histories): interpolation and extrema by a cubic
// spline (GSL, natural end conditions) and Brent's minimisation. One definition
// for the cavity checks, `ibms compare`, the work-precision bench and the accuracy tests.
//  - interpolation: O(h^4) away from the ends; within a few points of an end the natural end
//    condition (f'' = 0) adds an O(h^2) error that decays by ~(2 - sqrt 3) per point inward;
//  - extremum: the spline's extremum in the two intervals around the discrete extremum, located by
//    Brent's method to 1e-12 in the coordinate (an extremum at an end point is that sample).
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ibms {

class ProfileSpline {
 public:
  // s strictly increasing, at least 3 points; throws std::invalid_argument otherwise.
  ProfileSpline(std::vector<double> s, std::vector<double> f);
  ~ProfileSpline();
  ProfileSpline(ProfileSpline&&) noexcept;
  ProfileSpline& operator=(ProfileSpline&&) noexcept;

  double operator()(double s) const;  // s clamped to [s_front, s_back]
  double front() const { return s_.front(); }
  double back() const { return s_.back(); }
  // The spline's minimum (or maximum) next to the discrete one; its value, and its position in
  // *where when given. When the discrete extremum is an end point (a lid value), that sample.
  double extremum(bool maximum, double* where = nullptr) const;

 private:
  struct Gsl;
  std::vector<double> s_, f_;
  std::unique_ptr<Gsl> gsl_;
};

// A profile table: the first two columns (coordinate, value) of a CSV through read_csv, and its
// `flag` column if there is one (Ghia et al.'s tables: a non-empty flag excludes the point);
// flags has one (possibly empty) entry per row.
struct ProfileTable {
  std::vector<double> s, f;
  std::vector<std::string> flags;
};
ProfileTable read_profile_table(const std::string& path);

// Shorthands for one use.
double interpolate_profile(const std::vector<double>& s, const std::vector<double>& f, double at);
double profile_extremum(const std::vector<double>& s, const std::vector<double>& f, bool maximum);

// The lid-driven cavity's centre-line extrema as compared with Botella & Peyret (1998):
// {u_min on x = 1/2, v_max and v_min on y = 1/2} of profiles u(y) and v(x).
std::array<double, 3> centreline_extrema(const std::vector<double>& y, const std::vector<double>& u,
                                         const std::vector<double>& x, const std::vector<double>& v);
// The published {u_min, v_max, v_min} of a case: reference/botella_peyret_extrema.csv
// (quantity,value,position).
std::array<double, 3> published_extrema(const std::string& path);
// Largest |measured - published| over the three extrema.
double largest_extremum_error(const std::array<double, 3>& measured, const std::array<double, 3>& published);

}  // namespace ibms
