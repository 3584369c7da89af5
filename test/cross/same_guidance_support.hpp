// Shared by the cross-target comparison (same_guidance_test.cpp, docs/VALIDATION.md "The same
// guidance on every target") and its inputs check (same_guidance_inputs_test.cpp): the plan
// runs' inputs and a writer of doubles as C++ hexadecimal literals, which carry every bit.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "evade/core/burn_plan.hpp"
#include "evade/sim/plan_run.hpp"

namespace evade::test {

/// One plan run: the simulator's objects and models, the plan and where its t = 0 is.
struct PlanCase {
  const char* name = "";
  sim::PlanRunConfig cfg;
  BurnPlan plan;
  std::int64_t epoch_utime_us = 0;  ///< the plan's t = 0 [us]
};

/// A plan case as one list of doubles (same_guidance_cases.hpp): both objects' r and v at
/// t = 0 (12), gravity (0 two-body, 1 J2), mu, J2, Re, rate [Hz], duration [s], the plan's
/// t = 0 after the run's start [us], the sample count and times [s], the impulse count and
/// per impulse t [s] and the RSW dv (3) [m/s]. Every other setting is the default.
inline std::vector<double> encode_case(const PlanCase& c) {
  std::vector<double> v;
  for (const StateEci* s : {&c.cfg.satellite0, &c.cfg.other0}) {
    for (int i = 0; i < 3; ++i) v.push_back(s->r_eci_m[i]);
    for (int i = 0; i < 3; ++i) v.push_back(s->v_eci_mps[i]);
  }
  v.push_back(c.cfg.gravity == GravityModel::kTwoBodyJ2 ? 1.0 : 0.0);
  v.push_back(c.cfg.earth.mu_m3ps2);
  v.push_back(c.cfg.earth.j2);
  v.push_back(c.cfg.earth.re_m);
  v.push_back(c.cfg.rate_hz);
  v.push_back(c.cfg.duration_s);
  v.push_back(static_cast<double>(c.epoch_utime_us - sim::kPlanRunUtime0));
  v.push_back(static_cast<double>(c.cfg.sample_t_s.size()));
  for (double t : c.cfg.sample_t_s) v.push_back(t);
  v.push_back(static_cast<double>(c.plan.n_impulses));
  for (int k = 0; k < c.plan.n_impulses; ++k) {
    const ImpulsiveBurn& b = c.plan.impulses[static_cast<std::size_t>(k)];
    v.push_back(b.t_s);
    for (int i = 0; i < 3; ++i) v.push_back(b.dv_rsw_mps[i]);
  }
  return v;
}

/// The inverse of encode_case (the list's length is checked by the caller's test).
inline PlanCase decode_case(const char* name, const std::vector<double>& v) {
  PlanCase c;
  c.name = name;
  std::size_t k = 0;
  for (StateEci* s : {&c.cfg.satellite0, &c.cfg.other0}) {
    for (int i = 0; i < 3; ++i) s->r_eci_m[i] = v.at(k++);
    for (int i = 0; i < 3; ++i) s->v_eci_mps[i] = v.at(k++);
  }
  c.cfg.gravity = v.at(k++) == 1.0 ? GravityModel::kTwoBodyJ2 : GravityModel::kTwoBody;
  c.cfg.earth.mu_m3ps2 = v.at(k++);
  c.cfg.earth.j2 = v.at(k++);
  c.cfg.earth.re_m = v.at(k++);
  c.cfg.rate_hz = v.at(k++);
  c.cfg.duration_s = v.at(k++);
  c.epoch_utime_us = sim::kPlanRunUtime0 + static_cast<std::int64_t>(v.at(k++));
  const auto n_samples = static_cast<std::size_t>(v.at(k++));
  for (std::size_t i = 0; i < n_samples; ++i) c.cfg.sample_t_s.push_back(v.at(k++));
  c.plan.n_impulses = static_cast<int>(v.at(k++));
  for (int j = 0; j < c.plan.n_impulses; ++j) {
    ImpulsiveBurn& b = c.plan.impulses.at(static_cast<std::size_t>(j));
    b.t_s = v.at(k++);
    for (int i = 0; i < 3; ++i) b.dv_rsw_mps[i] = v.at(k++);
  }
  return c;
}

inline std::uint64_t bits_of(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

/// "%a" keeps every bit of a finite double and is a valid C++17 literal.
inline std::string hex_literal(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

inline std::string hex_list(const std::vector<double>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) {
    s += (i % 3 == 0) ? "\n    " : " ";
    s += hex_literal(v[i]) + ",";
  }
  return s;
}

}  // namespace evade::test
