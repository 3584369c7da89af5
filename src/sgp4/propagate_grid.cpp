// SGP4 of N objects x T instants into caller-owned arrays (see propagate_grid.hpp). Objects
// go to the worker threads in blocks of kBlockObjects (an atomic counter deals them, so a
// block of deep-space objects does not hold one thread back); in a block, the objects the
// four-lane path takes (sgp4_x4_vectorized(), no init error) are propagated four at a time
// (propagate_x4, the path the screener uses), near-Earth and deep-space groups apart, the
// others one at a time; instants go in chunks of kChunkInstants (a block's lanes stay in
// cache over a chunk). The TEME -> J2000 matrices are computed once per request, one per
// instant (72 bytes each: at most 1.5 times what the states of one object take). A lane the
// four-lane path cannot take at an instant (ok false: an error, a decay, a correction out of
// its range) is redone by propagate_s, so the error codes are the scalar theory's. An error writes its code and NaN states unless
// the theory computed one (decay).
#include "evade/sgp4/propagate_grid.hpp"

#include <algorithm>
#include <atomic>
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
constexpr std::size_t kBlockObjects = 64;
constexpr std::size_t kChunkInstants = 256;

// The instants [k0, k1) of a request, with the J2000 matrices of all its instants when the
// frame is J2000 (m[k] at req.t_s[k]).
struct Chunk {
  std::size_t k0 = 0, k1 = 0;
  const Eigen::Matrix3d* m = nullptr;
};

// One object of a block: its propagator, the offset of the request's start from its epoch,
// its row in the outputs and its path (0: one at a time; 1: near-Earth lanes; 2: deep-space
// lanes).
struct Row {
  Sgp4Propagator prop;
  double offset_s;
  std::size_t row;
  int kind;
};

void write_state(const StateGridRequest& req, const StateGridOut& out, const Chunk& c,
                 std::size_t row, std::size_t k, const double r[3], const double v[3]) {
  const std::size_t i = row * req.n_times + k;
  double* ro = out.r_m + 3 * i;
  double* vo = out.v_mps == nullptr ? nullptr : out.v_mps + 3 * i;
  if (!req.j2000) {
    std::copy(r, r + 3, ro);
    if (vo != nullptr) std::copy(v, v + 3, vo);
    return;
  }
  const Eigen::Matrix3d& m = c.m[k];
  const Eigen::Vector3d rj = m * Eigen::Vector3d(r[0], r[1], r[2]);
  std::copy(rj.data(), rj.data() + 3, ro);
  if (vo == nullptr) return;
  const Eigen::Vector3d vj = m * Eigen::Vector3d(v[0], v[1], v[2]);
  std::copy(vj.data(), vj.data() + 3, vo);
}

// One (object, instant) by the scalar theory: its code, and its state or NaN.
void scalar_state(const StateGridRequest& req, const StateGridOut& out, const Chunk& c,
                  const Row& o, std::size_t k) {
  Sgp4State s;
  if (o.prop.init_error() != Sgp4Error::kNone) s.error = o.prop.init_error();
  else s = o.prop.propagate_s(o.offset_s + req.t_s[k]);
  out.error[o.row * req.n_times + k] = static_cast<std::int32_t>(s.error);
  // kDecayed keeps the state the theory computed (the reference and python sgp4 do too).
  if (s.error != Sgp4Error::kNone && s.error != Sgp4Error::kDecayed) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double r[3] = {nan, nan, nan};
    write_state(req, out, c, o.row, k, r, r);
    return;
  }
  write_state(req, out, c, o.row, k, s.r_teme_m.data(), s.v_teme_mps.data());
}

// Four rows of one kind (the last repeated where fewer than four remain) over a chunk.
void lane_states(const StateGridRequest& req, const StateGridOut& out, const Chunk& c,
                 const Row* const rows[4], std::size_t n) {
  const Sgp4Propagator* p[4];
  double offset_s[4];
  for (std::size_t j = 0; j < 4; ++j) p[j] = &rows[j]->prop, offset_s[j] = rows[j]->offset_s;
  const Sgp4X4Lanes lanes(p);
  for (std::size_t k = c.k0; k < c.k1; ++k) {
    double tsince_min[4], r[4][3], v[4][3];
    bool ok[4];
    for (std::size_t j = 0; j < 4; ++j) tsince_min[j] = (offset_s[j] + req.t_s[k]) / 60.0;  // as propagate_s
    propagate_x4(lanes, p, tsince_min, r, v, ok);
    for (std::size_t j = 0; j < n; ++j) {
      if (!ok[j]) {
        scalar_state(req, out, c, *rows[j], k);
        continue;
      }
      out.error[rows[j]->row * req.n_times + k] = 0;
      write_state(req, out, c, rows[j]->row, k, r[j], v[j]);
    }
  }
}

// 0: one at a time; 1: near-Earth lanes; 2: deep-space lanes.
int lane_kind(const Sgp4Propagator& p) {
  if (!sgp4_x4_vectorized() || p.init_error() != Sgp4Error::kNone) return 0;
  return p.deep_space() ? 2 : 1;
}

// The rows of one block over one chunk: each kind's rows in groups of four, the rest alone.
void block_chunk(const StateGridRequest& req, const StateGridOut& out, const Chunk& c,
                 const std::vector<Row>& rows) {
  for (const int kind : {1, 2}) {
    const Row* group[4];
    std::size_t n = 0;
    for (const Row& o : rows) {
      if (o.kind != kind) continue;
      group[n++] = &o;
      if (n < 4) continue;
      lane_states(req, out, c, group, 4);
      n = 0;
    }
    if (n == 0) continue;
    for (std::size_t j = n; j < 4; ++j) group[j] = group[n - 1];
    lane_states(req, out, c, group, n);
  }
  for (const Row& o : rows)
    if (o.kind == 0)
      for (std::size_t k = c.k0; k < c.k1; ++k) scalar_state(req, out, c, o, k);
}

void propagate_block(const Catalog& catalog, const StateGridRequest& req, const StateGridOut& out,
                     std::size_t first, std::size_t last, const Eigen::Matrix3d* j2000_m) {
  std::vector<Row> rows;
  rows.reserve(last - first);
  for (std::size_t i = first; i < last; ++i) {
    const MeanElements& m = catalog.objects[i];
    const Sgp4Propagator prop(m, OperationMode::kImproved);
    rows.push_back({prop, req.start_j2000_s - epoch_seconds_since_j2000(m), i, lane_kind(prop)});
  }
  for (std::size_t k0 = 0; k0 < req.n_times; k0 += kChunkInstants)
    block_chunk(req, out, Chunk{k0, std::min(req.n_times, k0 + kChunkInstants), j2000_m}, rows);
}

// work(j) on threads j = 1 .. threads - 1 and on this one (j = 0).
template <typename Work>
void run_on_threads(int threads, const Work& work) {
  std::vector<std::thread> pool;
  for (int j = 1; j < threads; ++j) pool.emplace_back(work, j);
  work(0);
  for (std::thread& th : pool) th.join();
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
  if (out.r_m == nullptr || out.error == nullptr)
    throw std::invalid_argument("propagate_grid: an output array is missing");
  const std::size_t blocks = (n + kBlockObjects - 1) / kBlockObjects;
  int threads = req.threads > 0 ? req.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), blocks));
  std::vector<Eigen::Matrix3d> m(req.j2000 ? req.n_times : 0);
  run_on_threads(threads, [&](int j) {  // the matrices, instants split between the threads
    for (std::size_t k = static_cast<std::size_t>(j); k < m.size(); k += static_cast<std::size_t>(threads))
      m[k] = teme_to_j2000_matrix(req.start_j2000_s + req.t_s[k]);
  });
  std::atomic<std::size_t> next{0};
  run_on_threads(threads, [&](int) {
    for (std::size_t b = next++; b < blocks; b = next++)
      propagate_block(catalog, req, out, b * kBlockObjects, std::min(n, (b + 1) * kBlockObjects), m.data());
  });
}

}  // namespace evade::sgp4
