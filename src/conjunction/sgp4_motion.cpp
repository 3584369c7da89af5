// SGP4 motion of a catalog for the screeners (issue 12; see sgp4_motion.hpp). SGP4/SDP4:
// Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753 (evade/sgp4). Central and second
// differences: e.g. Atkinson, An Introduction to Numerical Analysis, 2nd ed., sec. 5.7.
// The perturbation envelope and what it assumes: docs/VALIDATION.md, "Robust mode with SGP4
// motion".
#include "evade/conjunction/sgp4_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "evade/dynamics/gravity.hpp"
#include "evade/sgp4/gravity_constants.hpp"

namespace evade::conjunction {
namespace {

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string label(long norad, const std::string& name) {
  return "NORAD " + std::to_string(norad) + (name.empty() ? "" : " (" + name + ")");
}

// "SGP4 error N (text)".
std::string sgp4_error_label(sgp4::Sgp4Error e) {
  return "SGP4 error " + std::to_string(static_cast<int>(e)) + " (" + sgp4::sgp4_error_text(e) + ")";
}

// Position at t_s seconds from the element epoch, or the SGP4 error text.
struct Position {
  bool ok = false;
  Vec3 r;
  std::string error;
};

Position position(const sgp4::Sgp4Propagator& p, double t_s) {
  const sgp4::Sgp4State s = p.propagate_s(t_s);
  Position out;
  out.ok = s.error == sgp4::Sgp4Error::kNone;
  out.r = s.r_teme_m;
  if (!out.ok) {
    out.error = sgp4_error_label(s.error);
  }
  return out;
}

// Largest angular rate of an orbit, n (1 + e)^2 / (1 - e^2)^1.5 (at perigee) [rad/s].
double n_max_radps(const sgp4::MeanElements& m) {
  const double e = std::min(m.eccentricity, 0.99);
  const double n_radps = m.mean_motion_revpday * 2.0 * kPi / 86400.0;
  return n_radps * (1.0 + e) * (1.0 + e) / std::pow(1.0 - e * e, 1.5);
}

// Largest sampled |r'' - a(r)| of one object over [0, span] (t counted from the start) and
// the largest error of those samples, or the first SGP4 error met and its sample time.
struct Envelope {
  double p_max_mps2 = 0.0;
  double error_mps2 = 0.0;
  sgp4::Sgp4Error failure = sgp4::Sgp4Error::kNone;
  double failed_at_s = 0.0;
  std::string reason() const {
    if (failure == sgp4::Sgp4Error::kNone) return {};
    return sgp4_error_label(failure) + " at t = " + fmt(failed_at_s) + " s from the start";
  }
};

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

// Throws std::invalid_argument naming an Sgp4MotionOptions field, its value and its range.
[[noreturn]] void fail_option(const char* key, double v, const char* range) {
  std::ostringstream os;
  os << "sgp4 motion: " << key << " = " << v << " outside " << range;
  throw std::invalid_argument(os.str());
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

void Sgp4MotionOptions::validate() const {
  if (!(span_s > 0.0) || !std::isfinite(span_s)) fail_option("span_s", span_s, "(0, inf)");
  if (!std::isfinite(start_j2000_s)) fail_option("start_j2000_s", start_j2000_s, "finite");
  if (threads < 1 || threads > 256) fail_option("threads", threads, "[1, 256]");
  if (!(envelope_block_gap_s >= 0.0) || !std::isfinite(envelope_block_gap_s))
    fail_option("envelope_block_gap_s", envelope_block_gap_s, "[0, inf)");
  validate_steps();
  validate_parts();
}

void Sgp4MotionOptions::validate_parts() const {
  if (parts < 1) fail_option("parts", parts, "[1, inf)");
  if (part < 0 || part >= parts) fail_option("part", part, "[0, parts)");
  if (parts > 1 && !sum_over_parts)
    throw std::invalid_argument("sgp4 motion: parts = " + std::to_string(parts) + " needs sum_over_parts");
}

void Sgp4MotionOptions::validate_steps() const {
  if (!(velocity_step_s > 0.0 && velocity_step_s <= 1.0))
    fail_option("velocity_step_s", velocity_step_s, "(0, 1]");
  if (!(accel_step_s > 0.0 && accel_step_s <= 10.0)) fail_option("accel_step_s", accel_step_s, "(0, 10]");
  if (samples_per_orbit < 8 || samples_per_orbit > 100000)
    fail_option("samples_per_orbit", samples_per_orbit, "[8, 100000]");
  if (max_samples < 2) fail_option("max_samples", static_cast<double>(max_samples), "[2, inf)");
  if (!(object_size_m >= 0.0) || !std::isfinite(object_size_m))
    fail_option("object_size_m", object_size_m, "[0, inf)");
  validate_envelope();
}

void Sgp4MotionOptions::validate_envelope() const {
  if (!(envelope_step_s > 0.0 && envelope_step_s <= 10.0))
    fail_option("envelope_step_s", envelope_step_s, "(0, 10]");
  if (!(envelope_factor >= 1.0) || !std::isfinite(envelope_factor))
    fail_option("envelope_factor", envelope_factor, "[1, inf)");
  if (!(envelope_floor_mps2 >= 0.0) || !std::isfinite(envelope_floor_mps2))
    fail_option("envelope_floor_mps2", envelope_floor_mps2, "[0, inf)");
}

std::string RejectedElementSet::message() const { return label(norad_id, name) + ": " + reason; }

EarthModel wgs72_earth() {
  const sgp4::GravityConstants k = sgp4::gravity_constants(sgp4::GravityModel::kWgs72);
  EarthModel e;
  e.mu_m3ps2 = k.mu_km3ps2 * 1e9;
  e.re_m = k.radius_km * 1e3;
  e.j2 = k.j2;
  return e;
}

EarthModel Sgp4Motion::reference_earth() const { return wgs72_earth(); }

StateEci Sgp4Motion::state_at(std::size_t i, double t_s) const {
  const double t = offset_s_[i] + t_s, tau = velocity_step_s_;
  const Position a = position(props_[i], t - tau), b = position(props_[i], t),
                 c = position(props_[i], t + tau);
  if (!a.ok || !b.ok || !c.ok) {
    throw std::runtime_error("SGP4 motion: " + label(norad_[i], names_[i]) + ": " +
                             (!b.ok ? b.error : !a.ok ? a.error : c.error) + " at t = " +
                             fmt(t_s) + " s from the start");
  }
  return StateEci{b.r, (c.r - a.r) / (2.0 * tau)};
}

StateEci Sgp4Motion::grid_state_at(std::size_t i, double t_s) const {
  const sgp4::Sgp4State s = props_[i].propagate_s(offset_s_[i] + t_s);
  if (s.error != sgp4::Sgp4Error::kNone) return state_at(i, t_s);  // throws naming the error
  return StateEci{s.r_teme_m, s.v_teme_mps};
}

void Sgp4Motion::grid_states_at(double t_s, std::size_t begin, std::size_t end,
                                StateEci* out) const {
  const std::size_t windows = window_first_group_.empty() ? 0 : window_first_group_.size() - 1;
  for (std::size_t i = begin; i < end;) {
    const std::size_t w = i / kLaneWindow, w0 = w * kLaneWindow;
    const std::size_t w1 = std::min(size(), w0 + kLaneWindow);
    if (i == w0 && w1 <= end && w < windows) {  // a whole window: its prepared groups
      window_states(w, t_s, out);
      i = w1;
    } else {
      const std::size_t j = std::min(end, w1);
      grouped_states(t_s, i, j, out);
      i = j;
    }
  }
}

void Sgp4Motion::window_states(std::size_t w, double t_s, StateEci* out) const {
  const std::size_t w0 = w * kLaneWindow, w1 = std::min(size(), w0 + kLaneWindow);
  scalar_states(t_s, w0, w1, out);
  for (std::size_t g = window_first_group_[w]; g < window_first_group_[w + 1]; ++g)
    group_states(groups_[g], group_lanes_[g], t_s, out);
}

void Sgp4Motion::grouped_states(double t_s, std::size_t begin, std::size_t end,
                                StateEci* out) const {
  scalar_states(t_s, begin, end, out);
  for (const LaneGroup& lg : lane_groups(begin, end)) group_states(lg, lanes_of(lg), t_s, out);
}

void Sgp4Motion::scalar_states(double t_s, std::size_t begin, std::size_t end, StateEci* out) const {
  for (std::size_t i = begin; i < end; ++i)
    if (!four_lane(i)) out[i] = grid_state_at(i, t_s);
}

void Sgp4Motion::group_states(const LaneGroup& lg, const sgp4::Sgp4X4Lanes& lanes, double t_s,
                              StateEci* out) const {
  const sgp4::Sgp4Propagator* p[4];
  double tsince_min[4], r[4][3], v[4][3];
  bool ok[4];
  for (std::size_t k = 0; k < 4; ++k) {
    p[k] = &props_[lg.obj[k]];
    tsince_min[k] = (offset_s_[lg.obj[k]] + t_s) / 60.0;  // as propagate_s
  }
  sgp4::propagate_x4(lanes, p, tsince_min, r, v, ok);
  for (std::size_t k = 0; k < lg.n; ++k) {
    const std::size_t i = lg.obj[k];
    out[i] = ok[k] ? StateEci{Vec3(r[k][0], r[k][1], r[k][2]), Vec3(v[k][0], v[k][1], v[k][2])}
                   : grid_state_at(i, t_s);  // an error: named by state_at
  }
}

sgp4::Sgp4X4Lanes Sgp4Motion::lanes_of(const LaneGroup& lg) const {
  const sgp4::Sgp4Propagator* p[4];
  for (std::size_t k = 0; k < 4; ++k) p[k] = &props_[lg.obj[k]];
  return sgp4::Sgp4X4Lanes(p);
}

std::vector<Sgp4Motion::LaneGroup> Sgp4Motion::lane_groups(std::size_t begin, std::size_t end) const {
  std::vector<LaneGroup> out;
  for (const char kind : {char{1}, char{2}}) {  // near-Earth, then deep-space groups
    LaneGroup lg{};
    for (std::size_t i = begin; i <= end; ++i) {
      if (i < end && four_lane_[i] != kind) continue;
      if (i < end) lg.obj[lg.n++] = static_cast<std::uint32_t>(i);
      if (lg.n == 4 || (i == end && lg.n > 0)) {
        for (std::size_t k = lg.n; k < 4; ++k) lg.obj[k] = lg.obj[lg.n - 1];  // repeats the last
        out.push_back(lg);
        lg = LaneGroup{};
      }
    }
  }
  return out;
}

void Sgp4Motion::build_lane_groups() {
  groups_.clear();
  group_lanes_.clear();
  window_first_group_.assign(1, 0);
  for (std::size_t w0 = 0; w0 < size(); w0 += kLaneWindow) {
    for (const LaneGroup& lg : lane_groups(w0, std::min(size(), w0 + kLaneWindow))) {
      groups_.push_back(lg);
      group_lanes_.push_back(lanes_of(lg));
    }
    window_first_group_.push_back(groups_.size());
  }
}

double Sgp4Motion::grid_velocity_error_mps(std::size_t i) const {
  static const double kErrorMps = [] {  // the same for every object: computed once
    const EarthModel e = wgs72_earth();
    return velocity_allowance_mps(std::sqrt(2.0 * e.mu_m3ps2 / e.re_m));
  }();
  return kErrorMps + (four_lane(i) ? 1e-6 : 0.0);
}

double Sgp4Motion::grid_position_error_m(std::size_t i) const { return grid_err_m_[i]; }

bool Sgp4Motion::acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const {
  const double h = accel_step_s_, t = offset_s_[i] + t_s;
  Position q[5];
  for (int m = 0; m < 5; ++m) {
    q[m] = position(props_[i], t + (m - 2) * h);
    if (!q[m].ok) return false;  // the caller falls back to the envelope
  }
  a_mps2 = (-q[0].r + 16.0 * q[1].r - 30.0 * q[2].r + 16.0 * q[3].r - q[4].r) / (12.0 * h * h);
  const double r = q[2].r.norm(), n2 = n_max_radps_[i] * n_max_radps_[i];
  const double truncation = 4.0 * n2 * n2 * n2 * r * h * h * h * h / 90.0;
  const double jumps = 34.0 / 12.0 * 4e-12 * r / (h * h);
  error_mps2 = truncation + jumps;
  return true;
}

// Builds Sgp4Motion (a friend, so the motion's vectors stay private).
struct Sgp4CatalogBuilder {
  static Sgp4Screening build(const std::vector<sgp4::MeanElements>& elements,
                             const Sgp4MotionOptions& opt);
  static std::string accept(Sgp4Motion& mo, const sgp4::MeanElements& m, double start_s,
                            const Sgp4MotionOptions& opt, const Envelope& env, SpaceObject& obj);
};

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

// Adds one element set to the motion, or returns why it is rejected.
std::string Sgp4CatalogBuilder::accept(Sgp4Motion& mo, const sgp4::MeanElements& m,
                                       double start_s, const Sgp4MotionOptions& opt,
                                       const Envelope& env, SpaceObject& obj) {
  const sgp4::Sgp4Propagator prop(m, opt.mode);
  if (prop.init_error() != sgp4::Sgp4Error::kNone) {
    return sgp4_error_label(prop.init_error()) + " at the element epoch";
  }
  if (!(m.mean_motion_revpday > 0.0)) return "mean motion " + fmt(m.mean_motion_revpday) + " rev/day <= 0";
  const EarthModel earth = wgs72_earth();
  const double offset_s = start_s - sgp4::epoch_seconds_since_j2000(m);
  if (env.failure != sgp4::Sgp4Error::kNone) return env.reason();
  mo.props_.push_back(prop);
  mo.offset_s_.push_back(offset_s);
  const char lanes = !sgp4::sgp4_x4_vectorized() ? char{0} : prop.deep_space() ? char{2} : char{1};
  mo.four_lane_.push_back(lanes);
  mo.norad_.push_back(m.norad_id);
  mo.names_.push_back(m.name);
  const std::size_t i = mo.props_.size() - 1;
  obj.name = std::to_string(m.norad_id) + (m.name.empty() ? "" : " " + m.name);
  obj.size_m = opt.object_size_m;
  obj.state = mo.state_at(i, 0.0);
  std::string bad;
  try {
    const OrbitShape shape = orbit_shape(obj.state, earth.mu_m3ps2);
    if (shape.perigee_radius_m <= earth.re_m)
      bad = "osculating perigee radius " + fmt(shape.perigee_radius_m) +
            " m at the start is below the Earth radius";
  } catch (const std::invalid_argument& ex) {
    bad = std::string("osculating orbit at the start: ") + ex.what();
  }
  if (!bad.empty()) {
    mo.props_.pop_back();
    mo.offset_s_.pop_back();
    mo.four_lane_.pop_back();
    mo.norad_.pop_back();
    mo.names_.pop_back();
    return bad;
  }
  const double e = std::min(m.eccentricity, 0.99);
  const double n_radps = m.mean_motion_revpday * 2.0 * kPi / 86400.0;
  const double n_max = n_max_radps(m);
  PerturbationBound b;
  b.accel_mps2 = opt.envelope_factor * (env.p_max_mps2 + env.error_mps2) + opt.envelope_floor_mps2;
  b.rate_mps3 = 4.0 * n_max * b.accel_mps2;
  if (!opt.envelopes) b.accel_mps2 = b.rate_mps3 = std::numeric_limits<double>::infinity();
  mo.bounds_.push_back(b);
  mo.sampled_.push_back(env.p_max_mps2);
  mo.n_max_radps_.push_back(n_max);
  // Largest radius: the mean semi-major axis from n (Kepler's third law) times (1 + e), +10 %.
  const double a_m = std::cbrt(earth.mu_m3ps2 / (n_radps * n_radps));
  const double r_max = 1.1 * a_m * (1.0 + e), tau = opt.velocity_step_s;
  mo.v_err_mps_.push_back(tau * tau * n_max * n_max * n_max * r_max / 3.0 + 4e-12 * r_max / tau);
  mo.grid_err_m_.push_back(!mo.four_lane(i) ? 0.0
                           : mo.deep_lane(i) ? std::max(sgp4::kSgp4X4PositionError_m,
                                                        10.0 * sgp4::kSgp4X4DeepPositionErrorRel * r_max)
                                             : sgp4::kSgp4X4PositionError_m);
  return {};
}

Sgp4Screening Sgp4CatalogBuilder::build(const std::vector<sgp4::MeanElements>& elements,
                                        const Sgp4MotionOptions& opt) {
  opt.validate();
  Sgp4Screening out;
  out.start_j2000_s = opt.start_j2000_s;
  if (opt.start_at_latest_epoch) out.start_j2000_s = sgp4::latest_epoch_seconds_since_j2000(elements);
  auto motion = std::make_shared<Sgp4Motion>();
  motion->velocity_step_s_ = opt.velocity_step_s;
  motion->accel_step_s_ = opt.accel_step_s;
  const std::vector<Envelope> env = envelopes(elements, out.start_j2000_s, opt, &out.envelopes_sampled);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const sgp4::MeanElements& m = elements[k];
    SpaceObject obj;
    const std::string why = accept(*motion, m, out.start_j2000_s, opt, env[k], obj);
    if (!why.empty()) {
      out.rejected.push_back(RejectedElementSet{m.norad_id, m.name, why});
      continue;
    }
    out.objects.push_back(obj);
    out.norad_ids.push_back(m.norad_id);
    out.element_index.push_back(k);
  }
  motion->build_lane_groups();
  out.motion = std::move(motion);
  return out;
}

Sgp4Screening sgp4_screening(const std::vector<sgp4::MeanElements>& elements,
                             const Sgp4MotionOptions& opt) {
  return Sgp4CatalogBuilder::build(elements, opt);
}

}  // namespace evade::conjunction
