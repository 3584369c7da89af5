// The perturbation envelope of each element set (sgp4_motion.hpp): its sample times, the
// sampled |r'' - a(r)| and its error, over threads and over processes (sum_over_parts).
// SGP4 motion of a catalog for the screeners (issue 12; see sgp4_motion.hpp). SGP4/SDP4:
// Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753 (evade/sgp4). Central and second
// differences: e.g. Atkinson, An Introduction to Numerical Analysis, 2nd ed., sec. 5.7.
// The perturbation envelope and what it assumes: docs/VALIDATION.md, "Robust mode with SGP4
// motion".
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "evade/conjunction/internal/sgp4_motion_support.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::conjunction {
namespace {

using internal::Envelope;
using internal::fmt;
using internal::n_max_radps;

// The positions at offset_s + t_s[k] (k < n), four at a time (sgp4::propagate_near_x4 or
// propagate_deep_x4: within kSgp4X4PositionErrorRel |r| of propagate_s's); ok[k] 0 where that
// flagged the instant (propagate_s then decides).
void envelope_positions(const sgp4::Sgp4Propagator& p, double offset_s, const double* t_s,
                        std::size_t n, Vec3* r, char* ok) {
  const sgp4::Sgp4Propagator* lanes[4] = {&p, &p, &p, &p};
  const sgp4::Sgp4X4Lanes prepared(lanes);  // the constants gathered once
  for (std::size_t b = 0; b < n; b += 4) {
    double tsince_min[4], rk[4][3], vk[4][3];
    bool okk[4];
    for (std::size_t k = 0; k < 4; ++k) tsince_min[k] = (offset_s + t_s[std::min(b + k, n - 1)]) / 60.0;
    sgp4::propagate_x4(prepared, lanes, tsince_min, rk, vk, okk);
    for (std::size_t k = 0; k < 4 && b + k < n; ++k) {
      r[b + k] = Vec3(rk[k][0], rk[k][1], rk[k][2]);
      ok[b + k] = okk[k] ? 1 : 0;
    }
  }
}

Envelope sample_envelope(const sgp4::Sgp4Propagator& p, double offset_s,
                         const sgp4::MeanElements& m, const Sgp4MotionOptions& opt,
                         const EarthModel& earth) {
  const std::vector<double> times =
      envelope_sample_times(86400.0 / m.mean_motion_revpday, m.eccentricity, opt);
  const double h = opt.envelope_step_s;
  const double n_max = n_max_radps(m), n2 = n_max * n_max;
  // Every instant of the stencils (t - h, t, t + h per sample), four at a time where the
  // processor allows.
  const bool x4 = sgp4::sgp4_x4_vectorized();
  std::vector<double> ts(3 * times.size());
  for (std::size_t s = 0; s < times.size(); ++s)
    for (std::size_t k = 0; k < 3; ++k) ts[3 * s + k] = times[s] + (static_cast<double>(k) - 1.0) * h;
  std::vector<Vec3> pos(ts.size());
  std::vector<char> ok(ts.size(), 0);
  if (x4) envelope_positions(p, offset_s, ts.data(), ts.size(), pos.data(), ok.data());
  // Each position within the jumps 4e-12 |r| (sgp4_motion.hpp) and, four at a time, within a
  // further kSgp4X4PositionErrorRel |r| (deep space: kSgp4X4DeepPositionErrorRel) of
  // propagate_s's.
  const double x4_rel = p.deep_space() ? sgp4::kSgp4X4DeepPositionErrorRel : sgp4::kSgp4X4PositionErrorRel;
  const double jump_rel = 4e-12 + (x4 ? x4_rel : 0.0);
  Envelope env;
  for (std::size_t s = 0; s < times.size(); ++s) {
    Vec3 q[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = 3 * s + k;
      if (ok[i] != 0) {
        q[k] = pos[i];
        continue;
      }
      const sgp4::Sgp4State st = p.propagate_s(offset_s + ts[i]);
      if (st.error != sgp4::Sgp4Error::kNone) {  // the first error met, in time order
        env.failure = st.error;
        env.failed_at_s = ts[i];
        return env;
      }
      q[k] = st.r_teme_m;
    }
    // Three-point second difference: truncation h^2 |r''''| / 12, |r''''| taken as
    // 4 n_max^4 |r|; each of its positions within the jumps, 4 of them.
    const Vec3 acc = (q[0] - 2.0 * q[1] + q[2]) / (h * h);
    const Vec3 pert = acc - accel_eci_mps2(q[1], GravityModel::kTwoBodyJ2, earth);
    const double r = q[1].norm();
    env.p_max_mps2 = std::max(env.p_max_mps2, pert.norm());
    env.error_mps2 = std::max(env.error_mps2, 4.0 * n2 * n2 * r * h * h / 12.0 + 4.0 * jump_rel * r / (h * h));
  }
  return env;
}

// Samples every dt over [t0, t1] (both ends included), appended to out.
void append_samples(double t0, double t1, double dt, std::vector<double>& out) {
  const long n = static_cast<long>(std::ceil((t1 - t0) / dt));
  for (long k = 0; k <= n; ++k) out.push_back(std::min(t0 + static_cast<double>(k) * dt, t1));
}

}  // namespace

std::vector<double> envelope_sample_times(double period_s, double eccentricity,
                                          const Sgp4MotionOptions& opt) {
  const double e = std::clamp(eccentricity, 0.0, 0.99);
  const double span = opt.span_s, gap = opt.envelope_block_gap_s;
  double dt = period_s * std::pow(1.0 - e, 1.5) / opt.samples_per_orbit;
  std::vector<double> t;
  if (gap > period_s && span > period_s) {  // one orbit every gap, and the last orbit
    const long blocks = static_cast<long>(std::ceil((span - period_s) / gap));  // t0 < span - P
    for (long b = 0; b < blocks; ++b) {
      const double t0 = static_cast<double>(b) * gap;
      append_samples(t0, t0 + period_s, dt, t);
    }
    append_samples(span - period_s, span, dt, t);
  } else {
    append_samples(0.0, span, dt, t);
  }
  if (static_cast<long>(t.size()) > opt.max_samples) {  // the cap, spread over the span
    t.clear();
    dt = span / static_cast<double>(opt.max_samples - 1);
    append_samples(0.0, span, dt, t);
  }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

namespace internal {

// The envelopes as Sgp4MotionOptions::sum_over_parts exchanges them (kEnvelopeRecord
// doubles each; the error code is a small integer, exact in a double).
std::vector<double> envelope_records(const std::vector<Envelope>& env) {
  std::vector<double> v(env.size() * kEnvelopeRecord, 0.0);
  for (std::size_t k = 0; k < env.size(); ++k) {
    double* r = &v[k * kEnvelopeRecord];
    r[0] = env[k].p_max_mps2;
    r[1] = env[k].error_mps2;
    r[2] = static_cast<double>(static_cast<int>(env[k].failure));
    r[3] = env[k].failed_at_s;
  }
  return v;
}

std::vector<Envelope> envelopes_from_records(const std::vector<double>& v, std::size_t n) {
  if (v.size() != n * kEnvelopeRecord)
    throw std::logic_error("sgp4 motion: sum_over_parts changed the envelope vector's size");
  std::vector<Envelope> env(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double* r = &v[k * kEnvelopeRecord];
    if (!(r[2] == std::floor(r[2]) && r[2] >= 0.0 && r[2] <= static_cast<double>(sgp4::Sgp4Error::kDecayed)))
      throw std::logic_error("sgp4 motion: sum_over_parts gave element set " + std::to_string(k) +
                             " the SGP4 error code " + fmt(r[2]) + " (was it sampled by two parts?)");
    env[k].p_max_mps2 = r[0];
    env[k].error_mps2 = r[1];
    env[k].failure = static_cast<sgp4::Sgp4Error>(static_cast<int>(r[2]));
    env[k].failed_at_s = r[3];
  }
  return env;
}

// Each element set's perturbation envelope (the setup's cost, independent per object): this
// process's share (k mod parts == part) on opt.threads threads (its j-th element set on
// thread j mod threads), then the other processes' through sum_over_parts; an element set
// that does not initialise keeps an empty envelope (accept names its error).
std::vector<Envelope> envelopes(const std::vector<sgp4::MeanElements>& elements, double start_s,
                                const Sgp4MotionOptions& opt, long* sampled) {
  std::vector<Envelope> env(elements.size());
  const EarthModel earth = wgs72_earth();
  *sampled = 0;
  if (!opt.envelopes) return env;
  const std::size_t parts = static_cast<std::size_t>(opt.parts);
  std::vector<std::size_t> mine;
  for (std::size_t k = static_cast<std::size_t>(opt.part); k < elements.size(); k += parts) mine.push_back(k);
  const auto work = [&](std::size_t first, std::size_t stride) {
    for (std::size_t j = first; j < mine.size(); j += stride) {
      const sgp4::MeanElements& m = elements[mine[j]];
      const sgp4::Sgp4Propagator prop(m, opt.mode);
      if (prop.init_error() != sgp4::Sgp4Error::kNone || !(m.mean_motion_revpday > 0.0)) continue;
      env[mine[j]] = sample_envelope(prop, start_s - sgp4::epoch_seconds_since_j2000(m), m, opt, earth);
    }
  };
  const std::size_t threads = static_cast<std::size_t>(std::max(1, opt.threads));
  std::vector<std::thread> pool;
  for (std::size_t j = 1; j < threads; ++j) pool.emplace_back(work, j, threads);
  work(0, threads);
  for (std::thread& t : pool) t.join();
  *sampled = static_cast<long>(mine.size());
  if (parts == 1) return env;
  std::vector<double> records = envelope_records(env);
  opt.sum_over_parts(records);
  return envelopes_from_records(records, elements.size());
}

}  // namespace internal
}  // namespace evade::conjunction
