// Sweep + local refinement + certificate of the evasion burn direction
// (include/evade/threat/direction_search.hpp). Paper 001 (Yu, Wang, Sun 2017) sec. 3.1–3.2,
// eq. 4 (Δv from V_E, α, θ) and eq. 7 (the arc objective); the certificate's bound is in
// include/evade/threat/arc_bound.hpp.
#include "evade/threat/direction_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include <nlopt.hpp>

#include "evade/threat/arc_bound.hpp"

namespace evade::threat {
namespace {

Vec3 unit_dir(double u, double theta) {
  return evasion_dv_vvlh(1.0, std::asin(std::clamp(u, -1.0, 1.0)), theta);
}

// Exact evaluations with the best kept; stops counting at the budget.
struct Tracker {
  const ThreatAreaSolver* solver = nullptr;
  double dv_mps = 0.0;
  long evaluations = 0;
  DecisionCounts counts;
  double best_arc = 1e300;
  double best_u = 0.0, best_theta = 0.0;
  ThreatArea best_area;

  double eval(double u, double theta) {
    const double alpha = std::asin(std::clamp(u, -1.0, 1.0));
    const ThreatArea a = solver->evaluate(evasion_dv_rsw(dv_mps, alpha, theta));
    ++evaluations;
    counts += a.counts;
    if (a.arc_s < best_arc) {
      best_arc = a.arc_s;
      best_u = u;
      best_theta = theta;
      best_area = a;
    }
    return a.arc_s;
  }
};

// A cell [u1, u2] × [t1, t2] with its sample point and bound.
struct Cell {
  double u1, u2, t1, t2, u, t;
  double bound = 0.0;
};

struct Box {
  double u1, u2, t1, t2;
  int nu, nt;
  double du() const { return (u2 - u1) / nu; }
  double dt() const { return (t2 - t1) / nt; }
};

Box make_box(const EvasionOptions& opt) {
  return {std::sin(opt.alpha_min_rad), std::sin(opt.alpha_max_rad), opt.theta_min_rad,
          opt.theta_max_rad, opt.sweep_alpha_cells, opt.sweep_theta_cells};
}

// The sweep's cells with their sample points at the seed's fractional position.
std::vector<Cell> sweep_cells(const Box& b, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> frac(0.1, 0.9);
  const double fu = frac(rng), ft = frac(rng);
  std::vector<Cell> cells;
  for (int i = 0; i < b.nu; ++i) {
    for (int j = 0; j < b.nt; ++j) {
      const double u1 = b.u1 + i * b.du(), t1 = b.t1 + j * b.dt();
      cells.push_back({u1, u1 + b.du(), t1, t1 + b.dt(), u1 + fu * b.du(), t1 + ft * b.dt()});
    }
  }
  return cells;
}

// True if sweep cells a and b (row-major indices) touch, θ wrapping around a full circle.
bool neighbours(const Box& b, int a, int c) {
  const int ia = a / b.nt, ja = a % b.nt, ic = c / b.nt, jc = c % b.nt;
  int dj = std::abs(ja - jc);
  if (b.t2 - b.t1 > 2.0 * M_PI - 1e-9) dj = std::min(dj, b.nt - dj);
  return std::abs(ia - ic) <= 1 && dj <= 1;
}

// BOBYQA from (u, θ) with initial step half a sweep cell; the tracker keeps the best.
double refine(Tracker& tr, const Box& b, const EvasionOptions& opt, double u, double theta,
              long max_eval) {
  nlopt::opt o(nlopt::LN_BOBYQA, 2);
  o.set_lower_bounds({b.u1, b.t1});
  o.set_upper_bounds({b.u2, b.t2});
  o.set_initial_step({0.5 * b.du(), 0.5 * b.dt()});
  o.set_xtol_abs(opt.local_xtol_rad);
  o.set_maxeval(static_cast<int>(std::max<long>(1, max_eval)));
  if (opt.stop_arc_s >= 0.0) o.set_stopval(opt.stop_arc_s);
  auto f = [](unsigned, const double* x, double*, void* data) {
    return static_cast<Tracker*>(data)->eval(x[0], x[1]);
  };
  o.set_min_objective(f, &tr);
  std::vector<double> x = {u, theta};
  double best = 0.0;
  try {
    o.optimize(x, best);
  } catch (const nlopt::roundoff_limited&) {
    // the tracker holds the best point
  } catch (const nlopt::forced_stop&) {
  }
  return best;
}

// Runs f(i) for i in [0, n) on `threads` threads (dynamic, one index at a time).
template <class F>
void parallel_for(long n, int threads, const F& f) {
  std::atomic<long> next{0};
  auto work = [&]() {
    for (long i = next.fetch_add(1); i < n; i = next.fetch_add(1)) f(i);
  };
  std::vector<std::thread> pool;
  for (int p = 1; p < threads; ++p) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
}

// Bounds `cells` (2-impulse edges first, SQP edges only if that is not enough).
void bound_cells(const ArcBound& ab, double dv_mps, double threshold, int threads,
                 std::vector<Cell>& cells) {
  parallel_for(static_cast<long>(cells.size()), threads, [&](long i) {
    Cell& c = cells[i];
    const double alpha = std::asin(std::clamp(c.u, -1.0, 1.0));
    const Vec3 e = evasion_dv_rsw(1.0, alpha, c.t);
    const double r = cell_chord_radius(c.u1, c.u2, c.t1, c.t2, c.u, c.t);
    c.bound = ab.lower_bound_s(e, dv_mps, r, false);
    if (c.bound < threshold) c.bound = std::max(c.bound, ab.lower_bound_s(e, dv_mps, r, true));
  });
}

// Branch and bound over the sweep cells; fills the certificate's bound fields.
void certify(const ThreatAreaSolver& solver, double dv_mps, const EvasionOptions& opt,
             std::vector<Cell> cells, double best, SearchCertificate& cert) {
  const ArcBound ab(solver);
  const double threshold = (1.0 - opt.certify_rel_tol) * best;
  const int threads = std::max(1, solver.options().threads);
  double closed_min = best;
  std::vector<Cell> open;
  while (!cells.empty() && cert.bound_cells + static_cast<long>(cells.size()) <=
                               static_cast<long>(opt.certify_max_cells)) {
    bound_cells(ab, dv_mps, threshold, threads, cells);
    cert.bound_cells += static_cast<long>(cells.size());
    open.clear();
    for (const Cell& c : cells) {
      if (c.bound >= threshold) {
        closed_min = std::min(closed_min, c.bound);
      } else {
        open.push_back(c);
      }
    }
    cells.clear();
    for (const Cell& c : open) {  // four children, sampled at their centres
      const double um = 0.5 * (c.u1 + c.u2), tm = 0.5 * (c.t1 + c.t2);
      for (const auto& q : {std::array<double, 4>{c.u1, um, c.t1, tm}, {um, c.u2, c.t1, tm},
                            {c.u1, um, tm, c.t2}, {um, c.u2, tm, c.t2}}) {
        cells.push_back({q[0], q[1], q[2], q[3], 0.5 * (q[0] + q[1]), 0.5 * (q[2] + q[3])});
      }
    }
  }
  double lb = closed_min;
  for (const Cell& c : open) lb = std::min(lb, c.bound);
  cert.open_cells = static_cast<long>(open.size());
  cert.lower_bound_arc_s = std::min(lb, best);
  cert.certified = open.empty() && cert.lower_bound_arc_s >= threshold;
}

// Indices of the best cells, skipping neighbours of better chosen ones.
std::vector<int> pick_starts(const Box& b, const std::vector<double>& arc, int count) {
  std::vector<int> order(arc.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  // Ascending arc, ties in index order (what a stable sort gives; std::sort with the index as
  // the tie-break avoids libstdc++'s deprecated temporary buffer).
  std::sort(order.begin(), order.end(), [&](int a, int c) { return arc[a] < arc[c] || (!(arc[c] < arc[a]) && a < c); });
  std::vector<int> starts;
  for (int i : order) {
    if (static_cast<int>(starts.size()) >= count) break;
    bool near = false;
    for (int s : starts) near = near || neighbours(b, i, s);
    if (!near) starts.push_back(i);
  }
  return starts;
}

// The solver the sweep ranks cells with: the same one, or a copy with coarser edges.
std::unique_ptr<ThreatAreaSolver> ranking_solver(const ThreatAreaSolver& solver,
                                                 const EvasionOptions& opt) {
  ThreatOptions o = solver.options();
  if (opt.sweep_edge_tol_s <= o.edge_tol_s) return nullptr;
  o.edge_tol_s = opt.sweep_edge_tol_s;
  return std::make_unique<ThreatAreaSolver>(solver.geometry(), o);
}

// Local refinements from the best separated cells (or one exact evaluation of the best).
void refine_best(Tracker& tr, const Box& box, const EvasionOptions& opt,
                 const std::vector<Cell>& cells, const std::vector<double>& arc,
                 SearchCertificate& cert) {
  const std::vector<int> starts = pick_starts(box, arc, std::max(1, opt.local_starts));
  if (opt.local_starts == 0) {
    tr.eval(cells[starts[0]].u, cells[starts[0]].t);
    return;
  }
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const long left = opt.max_evaluations - tr.evaluations;
    if (left <= 0 || tr.best_arc <= opt.stop_arc_s) break;
    const double f = refine(tr, box, opt, cells[starts[k]].u, cells[starts[k]].t,
                            left / static_cast<long>(starts.size() - k));
    lo = std::min(lo, f);
    hi = std::max(hi, f);
    ++cert.local_starts;
  }
  cert.local_spread_s = cert.local_starts > 0 ? hi - lo : 0.0;
}

}  // namespace

double cell_chord_radius(double u1, double u2, double theta1, double theta2, double u,
                         double theta) {
  const Vec3 e = unit_dir(u, theta);
  double r = 0.0;
  for (double cu : {u1, u2}) {
    for (double ct : {theta1, theta2}) r = std::max(r, (unit_dir(cu, ct) - e).norm());
  }
  return r * (1.0 + 1e-12);
}

EvasionResult sweep_direction_search(const ThreatAreaSolver& solver, double dv_mps,
                                     const EvasionOptions& opt) {
  const Box box = make_box(opt);
  const std::vector<Cell> cells = sweep_cells(box, opt.seed);
  const std::unique_ptr<ThreatAreaSolver> coarse = ranking_solver(solver, opt);
  Tracker grid;
  grid.solver = coarse ? coarse.get() : &solver;
  grid.dv_mps = dv_mps;
  std::vector<double> arc;
  for (const Cell& c : cells) {
    if (grid.evaluations >= opt.max_evaluations || grid.best_arc <= opt.stop_arc_s) break;
    arc.push_back(grid.eval(c.u, c.t));
  }
  SearchCertificate cert;
  cert.grid_evaluations = grid.evaluations;
  // The result's tracker: the grid's best only if it was evaluated with the solver's edges
  // or has no edges (a zero arc, as in the elimination search).
  Tracker tr;
  tr.solver = &solver;
  tr.dv_mps = dv_mps;
  tr.evaluations = grid.evaluations;
  tr.counts = grid.counts;
  if (!coarse || grid.best_arc <= opt.stop_arc_s) {
    tr.best_arc = grid.best_arc;
    tr.best_u = grid.best_u;
    tr.best_theta = grid.best_theta;
    tr.best_area = grid.best_area;
  }
  if (grid.best_arc > opt.stop_arc_s && arc.size() == cells.size()) {
    refine_best(tr, box, opt, cells, arc, cert);
  }
  if (tr.best_arc == 1e300) tr.eval(grid.best_u, grid.best_theta);  // budget cut the sweep
  cert.local_evaluations = tr.evaluations - cert.grid_evaluations;
  if (opt.stop_arc_s < 0.0 && opt.certify_max_cells > 0 && arc.size() == cells.size()) {
    const auto t0 = std::chrono::steady_clock::now();
    certify(solver, dv_mps, opt, cells, tr.best_arc, cert);
    cert.certify_runtime_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  EvasionResult r;
  r.dv_mps = dv_mps;
  r.alpha_rad = std::asin(std::clamp(tr.best_u, -1.0, 1.0));
  r.theta_rad = tr.best_theta;
  r.area = tr.best_area;
  r.evaluations = tr.evaluations;
  r.counts = tr.counts;
  r.certificate = cert;
  return r;
}

}  // namespace evade::threat
