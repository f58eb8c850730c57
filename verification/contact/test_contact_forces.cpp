// Properties of the DEM contact forces during wheel collisions with no fluid
// (docs/method.md §1.9, §A8): pair forces are equal and opposite, so total momentum is conserved to
// round-off; the largest CDS overlap stays below the undamped estimate
// delta_max = v0 sqrt(m_eff / (n_c k_Dn)) (A8) with n_c parallel pairs sharing the load (m_eff of
// the whole bodies: the wheels are stiff).
#define BOOST_TEST_MODULE contact_forces
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "solid/spring_dashpot.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

constexpr double stiff_ratio = 1000.0;  // k_s / k_Dn, as in test_wheel_restitution
const WallBox open_box{{-10.0, -10.0}, {20.0, 20.0}, {false, false}};

}  // namespace

BOOST_AUTO_TEST_CASE(total_momentum_is_conserved_during_contact) {
  // Damped (e = 0.5), slightly off-centre (0.004 D) collision of unequal speeds with overlapping
  // CDS (0.167 D, right wheel turned by pi/N_l): two pairs at unequal overlaps, the wheels spin.
  std::vector<MassSpringBody> bodies = {make_wheel({-0.7, 0.0}, {0.8, 0.05}, stiff_ratio),
                                        make_wheel({0.7, 0.004}, {-0.3, 0.0}, stiff_ratio, M_PI / 20.0)};
  const double momentum_scale = bodies[0].total_mass() * impact_speed;
  const CollisionRecord r = collide(make_contact_model(0.5, 0.167), open_box, bodies);
  const double drift = r.max_momentum_drift / momentum_scale;
  BOOST_TEST_MESSAGE("max_active_pairs  contact_steps  max |P - P0| / (M v0)");
  BOOST_TEST_MESSAGE(r.max_active << "  " << r.contact_time / r.substep << "  " << drift);
  BOOST_TEST(r.max_active >= 2);  // the claim is about several simultaneous pairs
  // Round-off: ~1e4 sub-steps of sums with relative error 1e-16 each.
  BOOST_TEST(drift <= 1e-12);
}

BOOST_AUTO_TEST_CASE(largest_overlap_stays_below_stiffness_estimate) {
  // Undamped contacts (e = 1) give the largest overlap; one pair tip to tip (CDS 0.05 D), then two
  // parallel pairs (right wheel turned by pi/N_l, CDS 0.167 D).
  BOOST_TEST_MESSAGE("n_c  delta_max measured  v0 sqrt(m_eff/(n_c k))  ratio");
  const double cds_fraction[2] = {0.05, 0.167};
  const double turn[2] = {0.0, M_PI / 20.0};
  for (int c = 0; c < 2; ++c) {
    const double half_gap = 0.5 + cds_fraction[c] + 0.05;
    const std::vector<MassSpringBody> bodies = {
        make_wheel({-half_gap, 0.0}, {0.5*impact_speed, 0.0}, stiff_ratio),
        make_wheel({half_gap, 0.0}, {-0.5*impact_speed, 0.0}, stiff_ratio, turn[c])};
    const CollisionRecord r = collide(make_contact_model(1.0, cds_fraction[c]), open_box, bodies);
    const double m_eff = 0.5 * bodies[0].total_mass();  // two equal wheels
    const double estimate = max_overlap_estimate(impact_speed, m_eff, r.max_active * contact_stiffness);
    BOOST_TEST_MESSAGE(r.max_active << "  " << r.max_overlap << "  " << estimate << "  "
                                    << r.max_overlap / estimate);
    BOOST_TEST(r.max_active == c + 1);  // the configuration engages the pairs it was built for
    BOOST_TEST(r.max_overlap <= estimate);  // A8: the undamped rigid-body value bounds it
  }
}
