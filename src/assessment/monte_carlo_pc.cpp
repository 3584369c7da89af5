// Monte Carlo Pc from full 6x6 covariances (include/evade/assessment/monte_carlo_pc.hpp gives
// the source, the closest-approach search, the seeding and the stopping rule).
#include "evade/assessment/monte_carlo_pc.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

#include <Eigen/Eigenvalues>

#include "evade/core/elements.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::assessment {
namespace {

constexpr int kNewtonIterations = 12;

Mat6 square_root(const Mat6& c) {
  Eigen::SelfAdjointEigenSolver<Mat6> es(0.5 * (c + c.transpose()));
  Vec6 s = es.eigenvalues();
  for (int i = 0; i < 6; ++i) s(i) = std::sqrt(std::max(0.0, s(i)));
  return es.eigenvectors() * s.asDiagonal();
}

struct Pair {
  StateEci a, b;
};

// Both sampled objects' motion: two-body (analytic) or two-body + J2 (numerical, from the
// nearest grid state).
class PairMotion {
 public:
  PairMotion(const StateEci& s1, const StateEci& s2, const EarthModel& earth, bool j2)
      : s1_(s1), s2_(s2), k1_(s1, earth.mu_m3ps2), k2_(s2, earth.mu_m3ps2), earth_(earth),
        j2_(j2) {}
  void grid(const std::vector<double>& t, std::vector<Pair>* out) const {
    out->resize(t.size());
    if (!j2_) {
      for (std::size_t i = 0; i < t.size(); ++i) (*out)[i] = {k1_.state_at(t[i]), k2_.state_at(t[i])};
      return;
    }
    const auto m = GravityModel::kTwoBodyJ2;
    const std::vector<StateEci> a = propagate_orbit_samples(s1_, t, m, earth_);
    const std::vector<StateEci> b = propagate_orbit_samples(s2_, t, m, earth_);
    for (std::size_t i = 0; i < t.size(); ++i) (*out)[i] = {a[i], b[i]};
  }
  Pair at(double t, double t_ref, const Pair& ref) const {
    if (!j2_) return {k1_.state_at(t), k2_.state_at(t)};
    const auto m = GravityModel::kTwoBodyJ2;
    return {propagate_orbit(ref.a, t - t_ref, m, earth_), propagate_orbit(ref.b, t - t_ref, m, earth_)};
  }
  double mu() const { return earth_.mu_m3ps2; }

 private:
  StateEci s1_, s2_;
  KeplerOrbit k1_, k2_;
  EarthModel earth_;
  bool j2_;
};

double distance(const Pair& p) { return (p.b.r_eci_m - p.a.r_eci_m).norm(); }

// Newton on the range rate inside [lo, hi] from the grid point (t0, p0); the smallest
// distance evaluated.
double refine_minimum(const PairMotion& m, double t0, const Pair& p0, double lo, double hi) {
  double best = distance(p0), t = t0;
  Pair p = p0;
  for (int it = 0; it < kNewtonIterations; ++it) {
    const Vec3 r = p.b.r_eci_m - p.a.r_eci_m, v = p.b.v_eci_mps - p.a.v_eci_mps;
    const Vec3 acc = accel_two_body_eci_mps2(p.b.r_eci_m, m.mu()) -
                     accel_two_body_eci_mps2(p.a.r_eci_m, m.mu());
    double den = v.squaredNorm() + r.dot(acc);
    if (!(den > 0.0)) den = v.squaredNorm();
    if (!(den > 0.0)) break;
    const double tn = std::clamp(t - r.dot(v) / den, lo, hi);
    if (std::abs(tn - t) < 1e-7) break;
    p = m.at(tn, t0, p0);
    t = tn;
    best = std::min(best, distance(p));
  }
  return best;
}

// Whether the pair enters the hard-body sphere during [-w, w] (see the header: an ingress).
bool is_hit(const PairMotion& m, double w, double period_s, double hbr_m,
            std::vector<double>* t, std::vector<Pair>* g) {
  const int n = std::max(2, static_cast<int>(std::ceil(2.0 * w / std::min(period_s / 64.0, w / 16.0))));
  const double h = 2.0 * w / n;
  t->resize(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) (*t)[static_cast<std::size_t>(i)] = -w + i * h;
  m.grid(*t, g);
  std::vector<double> d(g->size());
  for (std::size_t i = 0; i < g->size(); ++i) d[i] = distance((*g)[i]);
  bool outside = false;  // seen outside the sphere at or after the window's start
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d[i] >= hbr_m) outside = true;
    else if (outside) return true;  // entered between the previous grid point and this one
    const bool left = i == 0 || d[i] <= d[i - 1], right = i + 1 == d.size() || d[i] <= d[i + 1];
    if (!outside || !left || !right) continue;
    const Pair& p = (*g)[i];
    const double rmin = std::min(p.a.r_eci_m.norm(), p.b.r_eci_m.norm());
    const double amax = 2.0 * m.mu() / (rmin * rmin);
    if (d[i] - h * ((p.b.v_eci_mps - p.a.v_eci_mps).norm() + amax * h) >= hbr_m) continue;
    const double lo = (*t)[i == 0 ? 0 : i - 1], hi = (*t)[i + 1 == d.size() ? i : i + 1];
    if (refine_minimum(m, (*t)[i], p, lo, hi) < hbr_m) return true;
  }
  return false;
}

void check(const McEncounter& e, const MonteCarloOptions& opt) {
  auto bad = [](const std::string& what) {
    throw std::invalid_argument("Monte Carlo Pc: " + what);
  };
  if (opt.samples < 1) bad("samples must be >= 1");
  if (!(opt.window_s > 0.0) || !std::isfinite(opt.window_s)) bad("window_s must be > 0 s");
  if (!(e.hbr_m > 0.0) || !std::isfinite(e.hbr_m)) bad("hbr_m must be > 0 m");
  if (opt.threads < 1) bad("threads must be >= 1");
  if (!(opt.target_rel_accuracy >= 0.0)) bad("target_rel_accuracy must be >= 0");
  if (opt.wave_blocks < 0) bad("wave_blocks must be >= 0");
  if (!e.obj1.stacked().allFinite() || !e.obj2.stacked().allFinite() ||
      !e.cov1_eci.allFinite() || !e.cov2_eci.allFinite()) {
    bad("states and covariances must be finite");
  }
}

long block_size(const MonteCarloOptions& opt, long b) {
  return std::min(kMcBlockSamples, opt.samples - b * kMcBlockSamples);
}

}  // namespace

long pc_monte_carlo_block(const McEncounter& e, const MonteCarloOptions& opt, long block) {
  const Mat6 l1 = square_root(e.cov1_eci), l2 = square_root(e.cov2_eci);
  const Vec6 m1 = e.obj1.stacked(), m2 = e.obj2.stacked();
  // The block number as 64 bits whatever the width of long (32 bits on armhf): the same seeds,
  // hence the same samples, on every target.
  const auto block_u64 = static_cast<std::uint64_t>(block);
  std::seed_seq seq{static_cast<std::uint32_t>(opt.seed), static_cast<std::uint32_t>(opt.seed >> 32),
                    static_cast<std::uint32_t>(block_u64), static_cast<std::uint32_t>(block_u64 >> 32)};
  std::mt19937_64 rng(seq);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double period = std::min(orbital_period_s(e.obj1, e.earth.mu_m3ps2),
                                 orbital_period_s(e.obj2, e.earth.mu_m3ps2));  // inf: unbound
  std::vector<double> t;
  std::vector<Pair> g;
  long hits = 0;
  for (long s = 0, n = block_size(opt, block); s < n; ++s) {
    Vec6 z1, z2;
    for (int i = 0; i < 6; ++i) z1(i) = normal(rng);
    for (int i = 0; i < 6; ++i) z2(i) = normal(rng);
    const PairMotion m(StateEci::from_stacked(m1 + l1 * z1), StateEci::from_stacked(m2 + l2 * z2),
                       e.earth, opt.j2);
    if (is_hit(m, opt.window_s, period, e.hbr_m, &t, &g)) ++hits;
  }
  return hits;
}

void run_mc_blocks_threaded(const McEncounter& e, const MonteCarloOptions& opt, long first,
                            long count, long* hits) {
  std::atomic<long> next{0};
  auto work = [&]() {
    for (long k = next++; k < count; k = next++) hits[k] = pc_monte_carlo_block(e, opt, first + k);
  };
  const int n = static_cast<int>(std::min<long>(opt.threads, count));
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(work);
  work();
  for (std::thread& th : pool) th.join();
}

void wilson_interval(long k, long n, double z, double* low, double* high) {
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double z2 = z * z;
  const double den = 1.0 + z2 / nn;
  const double centre = (p + z2 / (2.0 * nn)) / den;
  const double half = z * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn)) / den;
  *low = std::max(0.0, centre - half);
  *high = std::min(1.0, centre + half);
}

MonteCarloResult pc_monte_carlo(const McEncounter& e, const MonteCarloOptions& opt,
                                const McBlockRunner& runner) {
  check(e, opt);
  const McBlockRunner run = runner ? runner : McBlockRunner(&run_mc_blocks_threaded);
  const long blocks = (opt.samples + kMcBlockSamples - 1) / kMcBlockSamples;
  const long wave = opt.wave_blocks > 0 ? opt.wave_blocks : std::max<long>(1, opt.threads);
  MonteCarloResult out;
  out.window_s = opt.window_s;
  out.z = opt.z;
  out.j2 = opt.j2;
  std::vector<long> hits(static_cast<std::size_t>(wave));
  for (long first = 0; first < blocks && !out.stopped_at_target; first += wave) {
    const long count = std::min(wave, blocks - first);
    run(e, opt, first, count, hits.data());
    for (long k = 0; k < count && !out.stopped_at_target; ++k) {  // block order: reproducible
      out.hits += hits[static_cast<std::size_t>(k)];
      out.samples += block_size(opt, first + k);
      wilson_interval(out.hits, out.samples, opt.z, &out.pc_low, &out.pc_high);
      const double pc = static_cast<double>(out.hits) / static_cast<double>(out.samples);
      out.stopped_at_target = opt.target_rel_accuracy > 0.0 && out.hits > 0 &&
                              0.5 * (out.pc_high - out.pc_low) <= opt.target_rel_accuracy * pc;
    }
  }
  out.pc = static_cast<double>(out.hits) / static_cast<double>(out.samples);
  return out;
}

}  // namespace evade::assessment
