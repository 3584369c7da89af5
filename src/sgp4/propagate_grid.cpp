// SGP4 of N objects x T instants into caller-owned arrays (see propagate_grid.hpp): one
// propagator per object, objects dealt to worker threads in turn; every (object, instant) is
// evaluated on its own; an error writes its code there, and NaN states unless the theory
// computed one (decay).
#include "evade/sgp4/propagate_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "evade/core/epoch.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

namespace evade::sgp4 {
namespace {

constexpr double kMaxStates = 1e9;  // 48 GB of r and v: far past any machine this runs on

void propagate_object(const MeanElements& m, const StateGridRequest& req, std::size_t row,
                      const StateGridOut& out) {
  const Sgp4Propagator prop(m, OperationMode::kImproved);
  const double offset_s = req.start_j2000_s - epoch_seconds_since_j2000(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < req.n_times; ++k) {
    const std::size_t i = row * req.n_times + k;
    double* r = out.r_m + 3 * i;
    double* v = out.v_mps + 3 * i;
    Sgp4State s;
    if (prop.init_error() != Sgp4Error::kNone) s.error = prop.init_error();
    else s = prop.propagate_s(offset_s + req.t_s[k]);
    out.error[i] = static_cast<std::int32_t>(s.error);
    // kDecayed keeps the state the theory computed (the reference and python sgp4 do too).
    if (s.error != Sgp4Error::kNone && s.error != Sgp4Error::kDecayed) {
      std::fill(r, r + 3, nan);
      std::fill(v, v + 3, nan);
      continue;
    }
    Eigen::Vector3d r_m = s.r_teme_m, v_mps = s.v_teme_mps;
    if (req.j2000) teme_to_j2000(req.start_j2000_s + req.t_s[k], s.r_teme_m, s.v_teme_mps, r_m, v_mps);
    std::copy(r_m.data(), r_m.data() + 3, r);
    std::copy(v_mps.data(), v_mps.data() + 3, v);
  }
}

}  // namespace

double start_j2000_s_from_utc(const std::string& start_utc, const Catalog& catalog) {
  if (start_utc.empty()) return latest_epoch_seconds_since_j2000(catalog.objects);
  std::string text = start_utc;
  if (text.back() == 'Z' || text.back() == 'z') text.pop_back();  // ISO 8601 "Zulu" = UTC
  return seconds_since_j2000_from_calendar(parse_calendar_utc(text));
}

bool frame_is_j2000(const std::string& frame) {
  if (frame == "teme") return false;
  if (frame == "eci") return true;
  throw std::invalid_argument("--frame = '" + frame + "' is invalid: expected teme or eci");
}

void check_state_grid_request(const Catalog& catalog, const StateGridRequest& req) {
  if (catalog.objects.empty()) {
    throw std::invalid_argument("no valid element set in the file (" +
                                std::to_string(catalog.bad_entries) + " bad entries)");
  }
  if (!std::isfinite(req.start_j2000_s))
    throw std::invalid_argument("start is not a finite time");
  if (req.n_times > 0 && req.t_s == nullptr) throw std::invalid_argument("t_s is missing");
  for (std::size_t k = 0; k < req.n_times; ++k) {
    if (!std::isfinite(req.t_s[k])) {
      throw std::invalid_argument("t_s[" + std::to_string(k) + "] = " + std::to_string(req.t_s[k]) +
                                  " is invalid: expected a finite number of seconds");
    }
  }
  const double states = static_cast<double>(catalog.objects.size()) * static_cast<double>(req.n_times);
  if (states > kMaxStates) {
    throw std::invalid_argument(std::to_string(catalog.objects.size()) + " objects x " +
                                std::to_string(req.n_times) + " instants is more than 1e9 states");
  }
  if (req.threads < 0 || req.threads > 1024)
    throw std::invalid_argument("threads = " + std::to_string(req.threads) + " is invalid: expected 0..1024");
}

void propagate_grid(const Catalog& catalog, const StateGridRequest& req, const StateGridOut& out) {
  check_state_grid_request(catalog, req);
  const std::size_t n = catalog.objects.size();
  if (req.n_times == 0) return;
  if (out.r_m == nullptr || out.v_mps == nullptr || out.error == nullptr)
    throw std::invalid_argument("propagate_grid: an output array is missing");
  int threads = req.threads > 0 ? req.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), n));
  auto work = [&](std::size_t first) {
    for (std::size_t i = first; i < n; i += static_cast<std::size_t>(threads))
      propagate_object(catalog.objects[i], req, i, out);
  };
  if (threads == 1) {
    work(0);
    return;
  }
  std::vector<std::thread> pool;
  for (int j = 1; j < threads; ++j) pool.emplace_back(work, static_cast<std::size_t>(j));
  work(0);
  for (std::thread& th : pool) th.join();
}

}  // namespace evade::sgp4
