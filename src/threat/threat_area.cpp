// Potential threat area sweep. Paper 001 (Yu, Wang, Sun 2017) sec. 2.2 (direct search over
// one chaser period with a fixed step, Fig. 2) and sec. 3.1 eq. 4–7 (relative states after the
// evasion, N_T × S_step). Model and decision tests: see evade/threat/threat_area.hpp.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

#include "evade/core/constants.hpp"
#include "evade/dynamics/hcw.hpp"
#include "evade/threat/threat_area.hpp"

namespace evade::threat {
namespace {

void require(bool ok, const std::string& field, double value, const std::string& allowed) {
  if (!ok) {
    throw std::invalid_argument("threat area: " + field + " = " + std::to_string(value) +
                                " is invalid; allowed: " + allowed);
  }
}

// Runs body(part) for part = 0..parts-1, parts 1.. on their own threads and part 0 on the
// caller's; rethrows the first exception (in part order) after all have finished.
template <class Body>
void run_parts(int parts, const Body& body) {
  std::vector<std::exception_ptr> errors(parts);
  auto guarded = [&](int part) {
    try {
      body(part);
    } catch (...) {
      errors[part] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int p = 1; p < parts; ++p) pool.emplace_back(guarded, p);
  guarded(0);
  for (auto& th : pool) th.join();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace

DecisionCounts& DecisionCounts::operator+=(const DecisionCounts& o) {
  two_impulse_accept += o.two_impulse_accept;
  bound_reject += o.bound_reject;
  sqp_threat += o.sqp_threat;
  sqp_safe += o.sqp_safe;
  plan_accept += o.plan_accept;
  return *this;
}

ThreatAreaSolver::ThreatAreaSolver(const ThreatGeometry& geom, const ThreatOptions& opt)
    : geom_(geom),
      opt_(opt),
      tr_((require(std::isfinite(geom.n_radps) && geom.n_radps > 0.0, "n_radps", geom.n_radps,
                   "finite, > 0"),
           require(std::isfinite(opt.transfer_s) && opt.transfer_s > 0.0, "dt_transfer_s",
                   opt.transfer_s, "finite, > 0"),
           HcwTransfer(geom.n_radps, opt.transfer_s))) {
  require(std::isfinite(opt.dv_max_mps) && opt.dv_max_mps > 0.0, "dv_max_mps", opt.dv_max_mps,
          "finite, > 0");
  require(opt.impulses >= 2 && opt.impulses <= 4, "impulses", opt.impulses, "2, 3 or 4");
  require(std::isfinite(opt.step_s) && opt.step_s > 0.0, "step_s", opt.step_s, "finite, > 0");
  require(std::isfinite(opt.span_s) && opt.span_s >= 0.0, "span_s", opt.span_s,
          "finite, >= 0 (0 = one chaser period)");
  require(std::isfinite(opt.edge_tol_s) && opt.edge_tol_s >= 0.0, "edge_tol_s", opt.edge_tol_s,
          "finite, >= 0 (0 = no edge refinement)");
  require(opt.threads >= 1 && opt.threads <= 64, "threads", opt.threads, "1..64");
  require(geom.chaser0_rsw.allFinite(), "chaser0_rsw", geom.chaser0_rsw.norm(), "finite");
  require(geom.target0_rsw.allFinite(), "target0_rsw", geom.target0_rsw.norm(), "finite");
  opt_.sqp.impulses = opt_.impulses;
  if (opt_.span_s == 0.0) opt_.span_s = period_s();
  const long k = static_cast<long>(std::ceil(opt_.span_s / opt_.step_s - 1e-9));
  require(k >= 1 && k <= 10'000'000, "span_s/step_s", opt_.span_s / opt_.step_s, "1..1e7");
  const Vec6 rel0 = geom_.target0_rsw - geom_.chaser0_rsw;
  t_grid_.reserve(k);
  w_grid_.reserve(k);
  b_grid_.reserve(k);
  for (long i = 0; i < k; ++i) {
    const double t = static_cast<double>(i) * opt_.step_s;
    t_grid_.push_back(t);
    w_grid_.push_back(hcw_propagate(geom_.n_radps, t + opt_.transfer_s, rel0));
    b_grid_.push_back(hcw_impulse_matrix(geom_.n_radps, t + opt_.transfer_s));
  }
}

double ThreatAreaSolver::period_s() const { return kTwoPi / geom_.n_radps; }

Vec6 ThreatAreaSolver::required_change(double t_s, const Vec3& evasion_dv_rsw_mps) const {
  const double tf = t_s + opt_.transfer_s;
  return hcw_propagate(geom_.n_radps, tf, geom_.target0_rsw - geom_.chaser0_rsw) +
         hcw_impulse_matrix(geom_.n_radps, tf) * evasion_dv_rsw_mps;
}

RendezvousPlan ThreatAreaSolver::min_cost_plan(double t_s, const Vec3& evasion_dv_rsw_mps) const {
  SqpOptions s = opt_.sqp;
  s.stop_at_cost_mps = -1.0;
  return optimize_rendezvous(tr_, required_change(t_s, evasion_dv_rsw_mps), s);
}

bool ThreatAreaSolver::threatening(const Vec6& d, DecisionCounts& counts) const {
  const double vmax = opt_.dv_max_mps;
  const double j2 = tr_.two_impulse_cost(d);
  if (j2 <= vmax) {
    ++counts.two_impulse_accept;
    return true;
  }
  if (opt_.impulses == 2) {  // the 2-impulse plan is the whole search space: exact verdict
    ++counts.bound_reject;
    return false;
  }
  const PrimerBound pb = tr_.primer_bound(d);
  if (pb.lower_bound_mps > vmax) {
    ++counts.bound_reject;
    return false;
  }
  // Tighter certified dual bound before the SQP. A certified bound above ΔV_max can only
  // turn what would be an SQP "safe" verdict into a certified one: the SQP's plans are
  // feasible, so their cost is ≥ any valid lower bound.
  RendezvousPlan quick;
  if (tr_.dual_bound(d, pb, vmax, 40, &quick).lower_bound_mps > vmax) {
    ++counts.bound_reject;
    return false;
  }
  // A feasible 3-impulse plan (exact cost) from the same iteration: within ΔV_max ⇒
  // threatening, exactly as an SQP plan within ΔV_max would be (N ≥ 3; a zero 4th impulse).
  if (!quick.impulses.empty() && quick.cost_mps <= vmax) {
    ++counts.plan_accept;
    return true;
  }
  SqpOptions s = opt_.sqp;
  s.stop_at_cost_mps = vmax;
  const RendezvousPlan plan = optimize_rendezvous(tr_, d, s);
  if (plan.cost_mps <= vmax) {
    ++counts.sqp_threat;
    return true;
  }
  ++counts.sqp_safe;
  return false;
}

std::vector<char> ThreatAreaSolver::sweep_grid(const Vec3& dv_e,
                                               std::vector<DecisionCounts>& counts) const {
  const long k = static_cast<long>(t_grid_.size());
  std::vector<char> threat(k, 0);
  // Dynamic chunks: the costly points (near interval edges) are not evenly spread, so the
  // threads take the next chunk of 32 points when free. Each point's verdict is independent
  // of which thread decides it, so the result does not depend on the schedule.
  constexpr long kChunk = 32;
  std::atomic<long> next{0};
  run_parts(static_cast<int>(counts.size()), [&](int part) {
    for (long lo = next.fetch_add(kChunk); lo < k; lo = next.fetch_add(kChunk)) {
      const long hi = std::min(k, lo + kChunk);
      for (long i = lo; i < hi; ++i) {
        const Vec6 d = w_grid_[i] + b_grid_[i] * dv_e;
        threat[i] = threatening(d, counts[part]) ? 1 : 0;
      }
    }
  });
  return threat;
}

std::vector<ThreatAreaSolver::Edge> ThreatAreaSolver::grid_intervals(
    const std::vector<char>& threat, const Vec3& dv_e, DecisionCounts& counts,
    std::vector<ThreatInterval>& intervals) const {
  // Runs of threatening points → intervals [first point, last point + step) in grid mode;
  // with refinement, each edge is bisected between the safe and the threatening neighbour.
  const long k = static_cast<long>(threat.size());
  std::vector<Edge> edges;
  for (long i = 0; i < k;) {
    if (!threat[i]) {
      ++i;
      continue;
    }
    long j = i;
    while (j + 1 < k && threat[j + 1]) ++j;
    const std::size_t idx = intervals.size();
    intervals.push_back({t_grid_[i], std::min(t_grid_[j] + opt_.step_s, opt_.span_s)});
    if (opt_.edge_tol_s > 0.0) {
      if (i > 0) edges.push_back({t_grid_[i - 1], t_grid_[i], idx, true});
      if (j + 1 < k) {
        edges.push_back({t_grid_[j + 1], t_grid_[j], idx, false});
      } else if (threatening(required_change(opt_.span_s, dv_e), counts)) {
        intervals[idx].end_s = opt_.span_s;  // the window's end itself threatens
      } else {
        edges.push_back({opt_.span_s, t_grid_[j], idx, false});
      }
    }
    i = j + 1;
  }
  return edges;
}

double ThreatAreaSolver::bisect_edge(const Edge& edge, const Vec3& dv_e,
                                     DecisionCounts& counts) const {
  double s = edge.safe_t;
  double th = edge.threat_t;
  while (std::abs(s - th) > opt_.edge_tol_s) {
    const double mid = 0.5 * (s + th);
    if (threatening(required_change(mid, dv_e), counts)) {
      th = mid;
    } else {
      s = mid;
    }
  }
  return 0.5 * (s + th);
}

void ThreatAreaSolver::refine_edges(const std::vector<Edge>& edges, const Vec3& dv_e,
                                    std::vector<DecisionCounts>& counts,
                                    std::vector<ThreatInterval>& intervals) const {
  if (edges.empty()) return;
  const int ethreads = static_cast<int>(std::min<std::size_t>(counts.size(), edges.size()));
  const long ne = static_cast<long>(edges.size());
  run_parts(ethreads, [&](int part) {
    for (long e = ne * part / ethreads; e < ne * (part + 1) / ethreads; ++e) {
      ThreatInterval& iv = intervals[edges[e].interval];
      (edges[e].is_start ? iv.start_s : iv.end_s) = bisect_edge(edges[e], dv_e, counts[part]);
    }
  });
}

ThreatArea ThreatAreaSolver::evaluate(const Vec3& evasion_dv_rsw_mps) const {
  if (!evasion_dv_rsw_mps.allFinite()) {
    throw std::invalid_argument("threat area: evasion dv_rsw_mps is not finite");
  }
  const long k = static_cast<long>(t_grid_.size());
  const int nthreads = static_cast<int>(std::min<long>(opt_.threads, k));
  std::vector<DecisionCounts> counts(nthreads);
  const std::vector<char> threat = sweep_grid(evasion_dv_rsw_mps, counts);

  ThreatArea out;
  out.points = k;
  for (long i = 0; i < k; ++i) out.threatening_points += threat[i];
  out.grid_arc_s = static_cast<double>(out.threatening_points) * opt_.step_s;
  const std::vector<Edge> edges =
      grid_intervals(threat, evasion_dv_rsw_mps, counts[0], out.intervals);
  refine_edges(edges, evasion_dv_rsw_mps, counts, out.intervals);
  for (const auto& iv : out.intervals) out.arc_s += iv.end_s - iv.start_s;
  out.arc_deg = out.arc_s / period_s() * 360.0;
  for (const auto& c : counts) out.counts += c;
  return out;
}

}  // namespace evade::threat
