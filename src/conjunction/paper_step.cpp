// Paper 002's adaptive step (section 2, eq. 3-5, procedure `Step`), corrected reading; see
// paper_step.hpp for the rule and the two defects of the printed pseudo-code.
#include "evade/conjunction/paper_step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace evade::conjunction {

namespace {

const Param<PaperStepParams> kPaperStepRows[] = {
    EVADE_PARAM_REAL(PaperStepParams, h_sim_s, "s", 1e-6, 1e6, false,
                     "h_sim: nominal (initial) simulation step"),
    EVADE_PARAM_REAL(PaperStepParams, n_warning, "-", 1.0, 1e6, true,
                     "N: warning radius R_CA = N R_c"),
    EVADE_PARAM_REAL(PaperStepParams, m_warning_period, "-", 1.0, 1e6, true,
                     "M: warning period T_CA = M h_now"),
    EVADE_PARAM_REAL(PaperStepParams, l_enlarge, "-", 1.0, 1e6, true,
                     "L_E: step growth factor when not approaching"),
    EVADE_PARAM_REAL(PaperStepParams, l_reduce, "-", 1.0, 1e6, true,
                     "L_D: step reduction factor inside the warning period"),
};

}  // namespace

ParamTable<PaperStepParams> paper_step_params() noexcept {
  return make_param_table(kPaperStepRows);
}

void PaperStepParams::validate() const {
  const std::string bad = validate_params(paper_step_params(), *this, "paper_step.");
  if (!bad.empty()) throw std::invalid_argument(bad);
  auto check = [](const char* key, double v, double lo, bool lo_open, const char* range) {
    if (!std::isfinite(v) || (lo_open ? !(v > lo) : !(v >= lo))) {
      std::ostringstream os;
      os << "paper_step." << key << " = " << v << " outside " << range;
      throw std::invalid_argument(os.str());
    }
  };
  check("h_min_s", h_min_s, 0.0, true, "(0, h_sim_s]");
  if (h_min_s > h_sim_s) check("h_min_s", -1.0, 0.0, true, "(0, h_sim_s]");
}

PairSample sample_pair(const StateEci& si, const StateEci& sj, double rc_m, double n_warning) {
  const Vec3 dr = sj.r_eci_m - si.r_eci_m;  // eq. 3 convention: j relative to i
  const Vec3 dv = sj.v_eci_mps - si.v_eci_mps;
  PairSample p;
  p.distance_m = dr.norm();
  p.radial_speed_mps = p.distance_m > 0.0 ? dr.dot(dv) / p.distance_m : 0.0;  // eq. 4
  p.rel_speed_mps = dv.norm();
  p.collision = p.distance_m <= rc_m;               // eq. 2
  p.warning = p.distance_m <= n_warning * rc_m;     // R_CA = N R_c
  return p;
}

double paper_next_step_s(const PairSample& p, double h_now_s, const PaperStepParams& prm) {
  double h;
  const bool approaching =
      prm.literal_sign ? p.radial_speed_mps > 0.0 : p.radial_speed_mps < 0.0;
  if (prm.literal_reset) h_now_s = prm.h_sim_s;
  if (!approaching) {
    // Receding or not closing (dR.dV >= 0; corrected sign): back towards h_sim.
    h = std::min(prm.h_sim_s, prm.l_enlarge * h_now_s);
  } else if (!p.collision) {
    const double t_encounter_s = p.distance_m / std::abs(p.radial_speed_mps);  // eq. 5
    const double t_ca_s = prm.m_warning_period * h_now_s;               // T_CA = M h_now
    h = (t_encounter_s > t_ca_s) ? h_now_s : h_now_s / prm.l_reduce;
  } else {
    h = prm.h_sim_s;
  }
  return std::max(h, prm.h_min_s);
}

namespace {

// Per pair: the best warning sample of the current encounter not yet reported.
struct Pending {
  bool active = false;        // approach phase with a warning sample
  bool collided = false;      // a collision was flagged in this approach phase
  bool in_collision = false;  // the previous sample was a collision sample
  Conjunction best;
};

void check_paper_inputs(const std::vector<SpaceObject>& objects, double span_s,
                        const PaperStepParams& prm, const Ephemeris& eph) {
  prm.validate();
  if (!(span_s >= 0.0) || !std::isfinite(span_s)) {
    throw std::invalid_argument("span_s = " + std::to_string(span_s) + " outside [0, inf)");
  }
  if (eph.size() != objects.size()) throw std::invalid_argument("screen_paper: ephemeris size");
}

// One event per run of consecutive collision samples (the paper's flag), and one per
// approach phase that entered the warning radius without a collision sample.
void record_pair_sample(const PairSample& p, const Conjunction& c, Pending& pd,
                        std::vector<Conjunction>& events) {
  if (p.collision && !pd.in_collision) {
    events.push_back(c);
    pd.collided = true;
  }
  pd.in_collision = p.collision;
  const bool approaching = p.radial_speed_mps < 0.0;
  if (p.warning && !p.collision && (approaching || pd.active)) {
    if (!pd.active || p.distance_m < pd.best.miss_m) pd.best = c;
    pd.active = true;
  }
  if (!approaching) {  // the approach phase (if any) is over
    if (pd.active && !pd.collided) events.push_back(pd.best);
    const bool in_collision = pd.in_collision;
    pd = Pending{};
    pd.in_collision = in_collision;
  }
}

// Every pair at the sample t (states s, reached by step h_now): events into `events`, the
// trace row (the pair setting the next step; ties: the closest) into `row`. Returns the
// next step, the smallest over the pairs.
double sample_all_pairs(const std::vector<SpaceObject>& objects, const PaperStepParams& prm,
                        const std::vector<StateEci>& s, double t, double h_now,
                        std::vector<Pending>& pending, std::vector<Conjunction>& events,
                        TraceRow& row) {
  const std::size_t n = objects.size();
  double h_next = prm.h_sim_s;
  bool first = true;
  std::size_t k = 0;  // pair index of (i, j), lexicographic
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j, ++k) {
      const double rc = collision_radius_m(objects[i], objects[j]);
      const PairSample p = sample_pair(s[i], s[j], rc, prm.n_warning);
      const double h_pair = paper_next_step_s(p, h_now, prm);
      record_pair_sample(p, Conjunction{i, j, t, p.distance_m, p.rel_speed_mps, p.collision, p.warning},
                         pending[k], events);
      if (first || h_pair < h_next || (h_pair == h_next && p.distance_m < row.distance_m)) {
        h_next = std::min(h_next, h_pair);
        row.i = i;
        row.j = j;
        row.distance_m = p.distance_m;
        row.radial_speed_mps = p.radial_speed_mps;
        row.collision = p.collision;
        row.warning = p.warning;
        first = false;
      }
    }
  }
  return h_next;
}

void report_progress(const std::function<void(double)>& progress, double t, double t_next,
                     double span_s) {
  if (progress && span_s > 0.0 && std::floor(100.0 * t_next / span_s) > std::floor(100.0 * t / span_s)) {
    progress(t_next / span_s);
  }
}

}  // namespace

PaperResult screen_paper(const std::vector<SpaceObject>& objects, double span_s,
                         const PaperStepParams& prm, Ephemeris& eph, bool record_trace,
                         const std::function<void(double)>& progress) {
  check_paper_inputs(objects, span_s, prm, eph);
  const std::size_t n = objects.size();
  PaperResult res;
  if (n < 2) return res;
  std::vector<Pending> pending(n * (n - 1) / 2);
  std::vector<StateEci> s;
  double t = 0.0;
  double h_now = prm.h_sim_s;
  for (;;) {
    eph.states_at(t, s);
    TraceRow row;
    row.t_s = t;
    row.step_s = h_now;
    const double h_next = sample_all_pairs(objects, prm, s, t, h_now, pending, res.events, row);
    if (record_trace) res.trace.push_back(row);
    const double t_next = t + h_next;
    if (t_next > span_s) break;
    report_progress(progress, t, t_next, span_s);
    t = t_next;
    h_now = h_next;
    ++res.steps;
  }
  for (const Pending& pd : pending) {  // encounters still open at the end of the span
    if (pd.active && !pd.collided) res.events.push_back(pd.best);
  }
  std::sort(res.events.begin(), res.events.end(), [](const Conjunction& a, const Conjunction& b) {
    return a.tca_s < b.tca_s || (a.tca_s == b.tca_s && (a.i < b.i || (a.i == b.i && a.j < b.j)));
  });
  return res;
}

}  // namespace evade::conjunction
