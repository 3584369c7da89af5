// One satellite against a catalog, screened only inside the time filter's windows
// (primary_window_screen.hpp gives the argument).
#include "evade/conjunction/primary_window_screen.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <thread>
#include <utility>

#include "evade/conjunction/primary_prefilter.hpp"

namespace evade::conjunction {
namespace {

Sgp4MotionOptions motion_options(double start_j2000_s, double span_s, int threads, bool envelopes) {
  Sgp4MotionOptions mo;
  mo.span_s = span_s;
  mo.start_at_latest_epoch = false;
  mo.start_j2000_s = start_j2000_s;
  mo.threads = threads;
  mo.envelopes = envelopes;
  return mo;
}

// One object against the primary: the filter's windows and what their screens found.
struct ObjectResult {
  ObjectWindows filter;
  ScreenResult screened;            // events: i = 0 (the primary), j = 1 (the object)
  std::string rejected;             // the object's rejection in a window, if any
  std::string primary_rejected;     // the primary's (an error)
};

// The pair (primary, object) over one window alone: the motion of the two from the window's
// start, its envelope sampled over the window, screened by the robust screener.
void screen_window(const sgp4::MeanElements& p, const sgp4::MeanElements& o, double start_j2000_s,
                   const TimeWindow& w, const ScreenOptions& base, ObjectResult& out) {
  const double span_s = w.t1_s - w.t0_s;
  const Sgp4Screening sub = sgp4_screening({p, o}, motion_options(start_j2000_s + w.t0_s, span_s, 1, true));
  for (const RejectedElementSet& r : sub.rejected)
    (r.norad_id == p.norad_id && r.name == p.name ? out.primary_rejected : out.rejected) = r.reason;
  if (sub.objects.size() < 2) return;
  ScreenOptions so = base;
  so.motion = sub.motion;
  so.primary = 0;
  so.threads = 1;
  so.progress = nullptr;
  ScreenResult r = screen_robust(sub.objects, span_s, so);
  for (Conjunction& c : r.events) c.tca_s += w.t0_s;
  merge_screen_results(out.screened, r);
}

struct Job {
  const std::vector<sgp4::MeanElements>* elements;
  const Sgp4Screening* s;
  std::size_t primary;
  double start_j2000_s, span_s;
  const ScreenOptions* screen;
  const TimeFilterOptions* filter;
};

FilterObject filter_object(const Job& job, const sgp4::Sgp4Propagator& prop, const sgp4::MeanElements& m) {
  const double offset_s = job.start_j2000_s - sgp4::epoch_seconds_since_j2000(m);
  FilterObject f = sgp4_motion_bounds(prop, m, offset_s - kPrefilterPadS, offset_s + job.span_s + kPrefilterPadS);
  f.prop = &prop;
  f.offset_s = offset_s;
  return f;
}

void run_object(const Job& job, const PrimaryTrack& p, std::size_t k, ObjectResult& out) {
  const sgp4::MeanElements& pe = (*job.elements)[job.s->element_index[job.primary]];
  const sgp4::MeanElements& m = (*job.elements)[job.s->element_index[k]];
  const sgp4::Sgp4Propagator prop(m, sgp4::OperationMode::kImproved);
  out.filter = primary_time_windows(p, filter_object(job, prop, m), *job.filter);
  for (const TimeWindow& w : out.filter.windows) {
    screen_window(pe, m, job.start_j2000_s, w, *job.screen, out);
    if (!out.rejected.empty() || !out.primary_rejected.empty()) return;
  }
}

std::vector<ObjectResult> run_objects(const Job& job) {
  const std::size_t n = job.s->objects.size();
  std::vector<ObjectResult> res(n);
  const sgp4::MeanElements& pe = (*job.elements)[job.s->element_index[job.primary]];
  const sgp4::Sgp4Propagator pprop(pe, sgp4::OperationMode::kImproved);
  const PrimaryTrack p = primary_track(filter_object(job, pprop, pe), job.span_s, *job.filter);
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(std::max(1, job.screen->threads)));
  const auto work = [&](std::size_t first, std::size_t stride) {
    try {
      for (std::size_t k = first; k < n; k += stride) {
        if (k != job.primary) run_object(job, p, k, res[k]);
        if (first == 0 && job.screen->progress && k % 64 == 0) job.screen->progress(static_cast<double>(k) / static_cast<double>(n));
      }
    } catch (...) {
      failed[first] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < failed.size(); ++t) pool.emplace_back(work, t, failed.size());
  work(0, failed.size());
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return res;
}

TimeFilterCounts count(const std::vector<ObjectResult>& res, std::size_t primary) {
  TimeFilterCounts c;
  for (std::size_t k = 0; k < res.size(); ++k) {
    if (k == primary) continue;
    const ObjectWindows& f = res[k].filter;
    ++c.objects;
    c.evaluations += f.evaluations;
    c.unfiltered += f.unfiltered ? 1 : 0;
    (f.windows.empty() ? c.removed : c.screened) += 1;
    c.windows += static_cast<long>(f.windows.size());
    for (const TimeWindow& w : f.windows) c.window_s += w.t1_s - w.t0_s;
  }
  return c;
}

std::invalid_argument primary_rejected(long norad, const std::string& reason) {
  return std::invalid_argument("--primary " + std::to_string(norad) + ": rejected: " + reason);
}

}  // namespace

std::size_t primary_index(const Sgp4Screening& s, long norad) {
  for (std::size_t k = 0; k < s.norad_ids.size(); ++k)
    if (s.norad_ids[k] == norad) return k;
  for (const auto& r : s.rejected)
    if (r.norad_id == norad) throw primary_rejected(norad, r.reason);
  throw std::invalid_argument("--primary " + std::to_string(norad) + ": no such object in the catalog");
}

PrimaryWindowScreen screen_primary_windows(const std::vector<sgp4::MeanElements>& elements,
                                           long primary_norad, double start_j2000_s,
                                           double span_s, const ScreenOptions& screen,
                                           const TimeFilterOptions& filter) {
  const int threads = std::max(1, screen.threads);
  PrimaryWindowScreen out;
  out.screening = sgp4_screening(elements, motion_options(start_j2000_s, span_s, threads, false));
  const std::size_t pi = primary_index(out.screening, primary_norad);
  const sgp4::MeanElements& pe = elements[out.screening.element_index[pi]];
  const Sgp4Screening whole = sgp4_screening({pe}, motion_options(start_j2000_s, span_s, 1, true));
  if (!whole.rejected.empty())  // the primary over the whole span, as the full screen checks it
    throw primary_rejected(primary_norad, whole.rejected[0].reason);
  ScreenOptions so = screen;
  if (!(so.step_s > 0.0))
    so.step_s = auto_step_s(out.screening.objects.size(), out.screening.motion->has_grid_states());
  out.step_s = so.step_s;
  const Job job{&elements, &out.screening, pi, start_j2000_s, span_s, &so, &filter};
  const std::vector<ObjectResult> res = run_objects(job);
  out.counts = count(res, pi);
  // Element sets rejected inside a window leave the screening (as a whole-span screen drops them).
  std::vector<sgp4::MeanElements> kept;
  std::vector<RejectedElementSet> rejected;
  for (std::size_t k = 0; k < res.size(); ++k) {
    if (!res[k].primary_rejected.empty())
      throw primary_rejected(primary_norad, res[k].primary_rejected);
    const sgp4::MeanElements& m = elements[out.screening.element_index[k]];
    if (res[k].rejected.empty()) kept.push_back(m);
    else rejected.push_back(RejectedElementSet{m.norad_id, m.name, res[k].rejected});
  }
  std::vector<std::size_t> index(res.size());  // old object index -> new
  if (!rejected.empty()) {
    std::vector<RejectedElementSet> before = out.screening.rejected;
    out.screening = sgp4_screening(kept, motion_options(start_j2000_s, span_s, threads, false));
    out.screening.rejected = before;
    out.screening.rejected.insert(out.screening.rejected.end(), rejected.begin(), rejected.end());
  }
  for (std::size_t k = 0, next = 0; k < res.size(); ++k) index[k] = res[k].rejected.empty() ? next++ : k;
  for (std::size_t k = 0; k < res.size(); ++k) {
    ScreenResult part = res[k].screened;
    if (!res[k].rejected.empty()) part.events.clear();  // left out, as a whole-span screen leaves it
    for (Conjunction& c : part.events) {
      c.i = std::min(index[pi], index[k]);
      c.j = std::max(index[pi], index[k]);
    }
    merge_screen_results(out.result, part);
  }
  return out;
}

}  // namespace evade::conjunction
