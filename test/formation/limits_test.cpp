// Paper 003 Table 1: closed-form limits of limits.hpp on a hand-built constellation, and
// the validation of FormationSpec (bad inputs rejected with the field named).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "evade/formation/limits.hpp"

namespace evade::formation {
namespace {

constexpr double kA = 7472540.0;
constexpr double kI = 63.4 * kDegToRad;
constexpr double kL = 100e3;
constexpr double kDelta = 5e3;

// A triplet at the nominal geometry plus deviations dev_h (out-of-plane) and dev_s (in-plane).
Group make_group(const std::string& name, double raan, double u, double dh1, double ds1,
                 double dh2, double ds2) {
  Group g;
  g.name = name;
  g.sats[0] = {kA, 0.0, kI, raan, u};
  const double h0 = kL * std::sqrt(3.0) / 2.0;
  auto dep = [&](double dh, double ds, double sign) {
    const double d_raan = (h0 + dh) / (kA * std::sin(kI));
    const double du = sign * (kL / 2.0 + ds) / kA - d_raan * std::cos(kI);
    return MeanElements{kA, 0.0, kI, raan + d_raan, u + du};
  };
  g.sats[1] = dep(dh1, ds1, 1.0);
  g.sats[2] = dep(dh2, ds2, -1.0);
  return g;
}

FormationSpec make_spec() {
  FormationSpec s;
  s.side_length_m = kL;
  s.box_delta_m = kDelta;
  s.raan_tolerance_rad = 0.01 * kDegToRad;
  s.phase_tolerance_rad = 0.1 * kDegToRad;
  s.horizon_days = 3.0;
  s.groups.push_back(make_group("Fbase", 0.7, 0.2, 0, 0, 0, 0));
  Group f1 = make_group("F1", 0.7 + 1.0 + 0.004 * kDegToRad, 0.2 + 0.5 + 0.01 * kDegToRad,
                        14990.0, -1000.0, -3000.0, 1000.0);
  f1.nominal_raan_offset_rad = 1.0;
  f1.nominal_phase_offset_rad = 0.5;
  s.groups.push_back(f1);
  s.reference_group = 0;
  return s;
}

const ConstraintLimit& row(const LimitsResult& r, const std::string& prefix) {
  for (const ConstraintLimit& c : r.rows) {
    if (c.def.name.rfind(prefix, 0) == 0) return c;
  }
  throw std::runtime_error("no row " + prefix);
}

TEST(FormationLimits, CurrentDeviationsAreReadBackFromTheElements) {
  const LimitsResult r = compute_limits(make_spec(), {1, Role::kChief});
  ASSERT_EQ(r.rows.size(), 6u);
  // Round trip of make_group's construction (first order in the small angles: the model's
  // definitions are exact functions of the elements, so agreement is to rounding).
  EXPECT_NEAR(row(r, "inter_group_raan").deviation, 0.004 * kDegToRad, 1e-12);
  EXPECT_NEAR(row(r, "inter_group_phase").deviation, 0.01 * kDegToRad, 1e-12);
  EXPECT_NEAR(row(r, "out_of_plane_deputy1").deviation, 14990.0, 1e-6);
  EXPECT_NEAR(row(r, "out_of_plane_deputy2").deviation, -3000.0, 1e-6);
  EXPECT_NEAR(row(r, "in_plane_deputy1").deviation, -1000.0, 1e-6);
  EXPECT_NEAR(row(r, "in_plane_deputy2").deviation, 1000.0, 1e-6);
}

TEST(FormationLimits, ClosedFormsOfTable1) {
  const FormationSpec s = make_spec();
  const LimitsResult r = compute_limits(s, {1, Role::kChief});
  const double t = s.horizon_days;
  const double ko = r.k.k_omega_rad_per_m_day;
  const double kp = std::abs(r.k.k_phi_rad_per_m_day);
  const double kam = std::abs(r.k.k_am_m_per_m_day);
  // Tolerances: the deviations are read back from angles of ~1.7 rad, whose rounding
  // (~4e-16 rad, i.e. ~3e-9 m at a = 7.5e6 m) sets 1e-10 relative on the RAAN rows (7e-5 rad)
  // and 1e-8 m on metre quantities.
  auto rel = [](double v) { return 1e-10 * std::abs(v); };
  // Paper eq. 3: ΔΩ / (K_Ω T), ΔΩ = distance to the edge the drift moves toward. Raising
  // increases the chief's RAAN (K_Ω > 0): toward +Ω_max.
  EXPECT_NEAR(row(r, "inter_group_raan").raise_max_m, (0.01 - 0.004) * kDegToRad / (ko * t), rel(1666));
  EXPECT_NEAR(row(r, "inter_group_raan").lower_max_m, (0.01 + 0.004) * kDegToRad / (ko * t), rel(3887));
  // Paper eq. 5: raising makes the chief fall behind (K_φ < 0): toward −Δφ_max.
  EXPECT_NEAR(row(r, "inter_group_phase").raise_max_m, (0.1 + 0.01) * kDegToRad / (kp * t), 1e-9);
  EXPECT_NEAR(row(r, "inter_group_phase").lower_max_m, (0.1 - 0.01) * kDegToRad / (kp * t), 1e-9);
  // In-plane: ΔS / (K_am T). Deputy 2 trails: a raised chief falls back toward it (inward).
  EXPECT_NEAR(row(r, "in_plane_deputy2").raise_max_m, (1000.0 + kDelta) / (kam * t), 1e-9);
  EXPECT_NEAR(row(r, "in_plane_deputy2").lower_max_m, (4 * kDelta - 1000.0) / (kam * t), 1e-9);
  EXPECT_NEAR(row(r, "in_plane_deputy1").raise_max_m, (4 * kDelta + 1000.0) / (kam * t), 1e-9);
  EXPECT_NEAR(row(r, "in_plane_deputy1").lower_max_m, (kDelta - 1000.0) / (kam * t), 1e-9);
  // Out-of-plane: Δa K_Ω T (a − Δa) sin i = Δh for a lowering of the chief (deputy planes
  // have larger RAAN, so a lowered chief's plane regresses away: h grows to +3Δ).
  const double x = row(r, "out_of_plane_deputy1").lower_max_m;
  EXPECT_NEAR(x * ko * t * (kA - x) * std::sin(kI), 3 * kDelta - 14990.0, 1e-8);
  // Overall = minimum over rows; asymmetric raise/lower.
  EXPECT_DOUBLE_EQ(r.raise_max_m, row(r, "in_plane_deputy2").raise_max_m);
  EXPECT_DOUBLE_EQ(r.lower_max_m, row(r, "in_plane_deputy1").lower_max_m);
  EXPECT_EQ(r.raise_binding, "in_plane_deputy2(F1)");
  EXPECT_GT(r.raise_max_m / r.lower_max_m, 1.4);
}

TEST(FormationLimits, PredictedDeviationReachesTheEdgeExactlyAtTheLimit) {
  const FormationSpec s = make_spec();
  const LimitsResult r = compute_limits(s, {1, Role::kChief});
  for (const ConstraintLimit& c : r.rows) {
    for (double d : {1.0, -1.0}) {
      const double x = d > 0 ? c.raise_max_m : c.lower_max_m;
      const double q = predicted_deviation(c, d * x, s.horizon_days);
      const double scale = c.def.upper - c.def.lower;
      EXPECT_NEAR(std::min(q - c.def.lower, c.def.upper - q), 0.0, 1e-9 * scale) << c.def.name;
    }
  }
}

TEST(FormationLimits, DeputyManeuverLeavesInterGroupRowsUnbounded) {
  const LimitsResult r = compute_limits(make_spec(), {1, Role::kDeputy1});
  EXPECT_FALSE(row(r, "inter_group_raan").involves_threatened);
  EXPECT_EQ(row(r, "inter_group_raan").raise_max_m, kNoLimit);
  EXPECT_EQ(row(r, "out_of_plane_deputy2").lower_max_m, kNoLimit);
  EXPECT_TRUE(std::isfinite(row(r, "in_plane_deputy1").raise_max_m));
}

TEST(FormationLimits, AlreadyViolatedRowGivesZeroAndIsFlagged) {
  FormationSpec s = make_spec();
  s.groups[1].sats[0].raan_rad += 0.02 * kDegToRad;  // now +0.024 deg > Ω_max = 0.01 deg
  const LimitsResult r = compute_limits(s, {1, Role::kChief});
  EXPECT_TRUE(row(r, "inter_group_raan").already_violated);
  EXPECT_EQ(r.raise_max_m, 0.0);
  EXPECT_EQ(r.lower_max_m, 0.0);
}

TEST(FormationLimits, ThreatenedReferenceChiefIsBoundByEveryOtherGroup) {
  const LimitsResult r = compute_limits(make_spec(), {0, Role::kChief});
  // Rows: inter-group of F1 vs Fbase (the reference chief enters with the opposite sign).
  EXPECT_NEAR(row(r, "inter_group_raan").raise_max_m,
              (0.01 + 0.004) * kDegToRad / (r.k.k_omega_rad_per_m_day * 3.0), 1e-10 * 3887.0);  // rounding, see ClosedFormsOfTable1
}

void expect_rejected(FormationSpec s, const std::string& field) {
  try {
    (void)compute_limits(s, {1, Role::kChief});
    ADD_FAILURE() << "accepted bad " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(FormationLimits, RejectsBadInput) {
  FormationSpec s = make_spec();
  s.box_delta_m = -5.0;
  expect_rejected(s, "box_delta_m");
  s = make_spec();
  s.horizon_days = 0.0;
  expect_rejected(s, "horizon_days");
  s = make_spec();
  s.horizon_days = -1.0;
  expect_rejected(s, "horizon_days");
  s = make_spec();
  s.groups[1].sats[2].a_m = std::nan("");
  expect_rejected(s, "deputy2.a_m");
  s = make_spec();
  s.raan_tolerance_rad = INFINITY;
  expect_rejected(s, "raan_tolerance_rad");
  s = make_spec();
  s.reference_group = 5;
  expect_rejected(s, "reference_group");
  s = make_spec();
  s.groups.pop_back();
  expect_rejected(s, "groups.size");
  EXPECT_THROW((void)compute_limits(make_spec(), {7, Role::kChief}), std::invalid_argument);
}

}  // namespace
}  // namespace evade::formation
