// Plan execution in the simulator (plan_run.hpp; docs/GUIDANCE_NODE.md PLAN-SIM-1): truth of
// both objects by DOP853 with the actuator's acceleration held over each cycle, burns
// recorded as the actuator delivered them.
#include "evade/sim/plan_run.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "evade/guidance/plan_executor.hpp"
#include "evade/sim/actuator_model.hpp"
#include "evade/sim/internal/thrusted_truth.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {
namespace {

// The two-body state vector: pack, sat_of, deb_of (internal/thrusted_truth.hpp).

void check(const PlanRunConfig& cfg) {
  if (!(cfg.rate_hz > 0.0 && cfg.rate_hz <= 1000.0))
    throw std::invalid_argument("plan run: rate_hz must be in (0, 1000]");
  if (!(cfg.duration_s > 0.0 && cfg.duration_s <= 1e7))
    throw std::invalid_argument("plan run: duration_s must be in (0, 1e7]");
  if (cfg.utime0_us <= 0) throw std::invalid_argument("plan run: utime0_us must be > 0");
  cfg.integrator.validate();
  for (std::size_t i = 0; i < cfg.sample_t_s.size(); ++i) {
    const double t = cfg.sample_t_s[i];
    if (!std::isfinite(t) || t < 0.0 || t > cfg.duration_s || (i > 0 && t < cfg.sample_t_s[i - 1]))
      throw std::invalid_argument("plan run: sample_t_s[" + std::to_string(i) + "] = " +
                                  std::to_string(t) + " must be finite, ascending and in [0, "
                                  "duration_s]");
  }
}

class PlanLoop {
 public:
  PlanLoop(const PlanRunConfig& cfg, GuidanceEndpoint& g)
      : cfg_(cfg),
        g_(g),
        cycle_us_(std::llround(1e6 / cfg.rate_hz)),
        integ_(Dop853<Vec12>::Rhs([this](double, const Vec12& x) { return rhs(x); }),
               cfg.integrator),
        x_(pack(cfg.satellite0, cfg.other0)),
        actuator_(cfg.actuator) {}

  PlanRunResult run(const PlanRunHook& hook) {
    const long n =
        static_cast<long>(std::llround(cfg_.duration_s * 1e6 / static_cast<double>(cycle_us_)));
    for (long k = 0; k < n; ++k) {
      const std::int64_t utime = cfg_.utime0_us + k * cycle_us_;
      if (hook) hook(k, utime);
      record(1e-6 * static_cast<double>(k * cycle_us_));
      exchange(utime);
      integrate(1e-6 * static_cast<double>(k * cycle_us_),
                1e-6 * static_cast<double>((k + 1) * cycle_us_));
      ++res_.cycles;
    }
    close_burn(1e-6 * static_cast<double>(n * cycle_us_));
    record(1e-6 * static_cast<double>(n * cycle_us_), true);
    res_.satellite_end = sat_of(x_);
    res_.other_end = deb_of(x_);
    res_.has_final_status = g_.status(&res_.final_status);
    return res_;
  }

 private:
  Vec12 rhs(const Vec12& x) const {
    Vec12 d;
    d.head<6>() = orbit_derivative(x.head<6>(), cfg_.gravity, cfg_.earth);
    d.segment<3>(3) += a_;
    d.tail<6>() = orbit_derivative(x.tail<6>(), cfg_.gravity, cfg_.earth);
    return d;
  }

  void exchange(std::int64_t utime) {
    guidance::NavState nav;
    nav.utime_us = utime;
    nav.r_eci_m = x_.segment<3>(0);
    nav.v_eci_mps = x_.segment<3>(3);
    nav.valid = true;
    a_ = actuator_.accel_eci_mps2(g_.exchange(utime, nav, nullptr));
    const double t = 1e-6 * static_cast<double>(utime - cfg_.utime0_us);
    if (a_.norm() > 0.0) {
      if (!burning_) {
        burning_ = true;
        burn_ = DeliveredBurn{};
        burn_.t_start_s = t;
        states_.clear();
      }
      states_.push_back(sat_of(x_));
    } else {
      close_burn(t);
    }
  }

  // Records every sample due at cycle start t_s (all that remain at the end).
  void record(double t_s, bool end = false) {
    const std::vector<double>& want = cfg_.sample_t_s;
    while (res_.samples.size() < want.size() &&
           (end || want[res_.samples.size()] <= t_s + 1e-9))
      res_.samples.push_back({t_s, sat_of(x_), deb_of(x_)});
  }

  void close_burn(double t_s) {
    if (!burning_) return;
    burning_ = false;
    burn_.t_end_s = t_s;
    burn_.satellite_at_centre = states_[states_.size() / 2];
    res_.burns.push_back(burn_);
  }

  void integrate(double t0, double t1) {
    if (burning_) burn_.dv_eci_mps += a_ * (t1 - t0);
    integ_.reset(t0, x_);
    while (integ_.t_s() != t1)
      if (!integ_.step(t1)) throw std::runtime_error("plan run: " + integ_.failure_reason());
    x_ = integ_.x();
  }

  const PlanRunConfig& cfg_;
  GuidanceEndpoint& g_;
  const std::int64_t cycle_us_;
  Dop853<Vec12> integ_;
  Vec12 x_;
  Vec3 a_ = Vec3::Zero();
  Actuator actuator_;
  bool burning_ = false;
  DeliveredBurn burn_;
  std::vector<StateEci> states_;
  PlanRunResult res_;
};

class PlanEndpoint final : public GuidanceEndpoint {
 public:
  PlanEndpoint(const guidance::GuidanceConfig& cfg, const BurnPlan& plan, std::int64_t epoch_us,
               guidance::PlanFrame frame)
      : law_(cfg), exec_(guidance::PlanExecutorConfig::from(cfg)) {
    up_.plan = plan;
    up_.epoch_utime_us = epoch_us;
    up_.frame = frame;
  }
  guidance::ThrustCommand exchange(std::int64_t utime_us, const guidance::NavState& nav,
                                   const guidance::AnglesMeasurement* meas) override {
    guidance::GuidanceInput in;
    in.nav = nav;
    in.armed = true;
    in.has_measurement = (meas != nullptr);
    if (meas != nullptr) in.meas = *meas;
    if (!loaded_) {
      loaded_ = true;
      const guidance::PlanReject r = exec_.load(up_, utime_us, true, 0.0);
      if (r != guidance::PlanReject::kNone)
        throw std::invalid_argument(std::string("plan rejected: ") +
                                    guidance::plan_reject_name(r));
    }
    const guidance::ThrustCommand c = law_.step(in, utime_us);
    return guidance::merge_plan_thrust(c, exec_.step(nav, true, c.mode, utime_us));
  }
  bool status(guidance::GuidanceStatus* out) const override {
    *out = law_.status();
    return true;
  }

 private:
  guidance::GuidanceLaw law_;
  guidance::PlanExecutor exec_;
  guidance::UplinkedPlan up_;
  bool loaded_ = false;
};

}  // namespace

PlanRunResult run_plan_simulation(const PlanRunConfig& cfg, GuidanceEndpoint& guidance,
                                  const PlanRunHook& before_exchange) {
  check(cfg);
  PlanLoop loop(cfg, guidance);
  return loop.run(before_exchange);
}

void propagate_unforced(const PlanRunConfig& cfg, double t_s, StateEci* satellite,
                        StateEci* other) {
  const GravityModel model = cfg.gravity;
  const EarthModel earth = cfg.earth;
  Dop853<Vec12> integ(Dop853<Vec12>::Rhs([model, earth](double, const Vec12& x) {
                        Vec12 d;
                        d.head<6>() = orbit_derivative(x.head<6>(), model, earth);
                        d.tail<6>() = orbit_derivative(x.tail<6>(), model, earth);
                        return d;
                      }),
                      cfg.integrator);
  integ.reset(0.0, pack(cfg.satellite0, cfg.other0));
  while (integ.t_s() != t_s)
    if (!integ.step(t_s)) throw std::runtime_error("plan run: " + integ.failure_reason());
  *satellite = sat_of(integ.x());
  *other = deb_of(integ.x());
}

std::unique_ptr<GuidanceEndpoint> make_in_process_plan_endpoint(
    const guidance::GuidanceConfig& cfg, const BurnPlan& plan, std::int64_t epoch_utime_us,
    guidance::PlanFrame frame) {
  return std::make_unique<PlanEndpoint>(cfg, plan, epoch_utime_us, frame);
}

PlanRunConfig plan_run_config(const SimConfig& sim, const BurnPlan& plan, double epoch_s,
                              double after_s) {
  if (plan.n_impulses < 1 || plan.n_impulses > BurnPlan::kMaxImpulses)
    throw std::invalid_argument("plan run: the plan has " + std::to_string(plan.n_impulses) +
                                " impulses, expected 1.." +
                                std::to_string(BurnPlan::kMaxImpulses));
  if (!std::isfinite(epoch_s) || epoch_s < 0.0)
    throw std::invalid_argument("plan run: plan epoch " + std::to_string(epoch_s) +
                                " s after the start must be finite and >= 0");
  if (!std::isfinite(after_s) || after_s < 0.0)
    throw std::invalid_argument("plan run: " + std::to_string(after_s) +
                                " s after the last burn must be finite and >= 0");
  PlanRunConfig cfg;
  cfg.satellite0 = sim.satellite0;
  cfg.other0 = sim.debris0;
  cfg.gravity = sim.gravity;
  cfg.earth = sim.earth;
  cfg.rate_hz = sim.guidance.rate_hz;
  cfg.actuator = sim.actuator;
  cfg.integrator = sim.integrator;
  const ImpulsiveBurn& last = plan.impulses[static_cast<std::size_t>(plan.n_impulses - 1)];
  const double cycle_s = sim.guidance.cycle_s();
  const double burn_s =
      std::ceil(last.dv_rsw_mps.norm() / (sim.guidance.max_accel_mps2 * cycle_s)) * cycle_s;
  cfg.duration_s = epoch_s + last.t_s + burn_s + 2.0 * cycle_s + 1.0 + after_s;
  if (!(cfg.duration_s > 0.0 && cfg.duration_s <= 1e7))
    throw std::invalid_argument("plan run: the run would last " + std::to_string(cfg.duration_s) +
                                " s (plan epoch + last burn + after), outside (0, 1e7] s");
  return cfg;
}

}  // namespace evade::sim
