// `evade propagate --tle/--omm` written as it goes (include/evade/commands/propagate_catalog_stream.hpp
// gives the method and the formats).
#include "evade/commands/propagate_catalog_stream.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <thread>

#include "catalog_instants.hpp"

namespace evade::commands {
namespace {

struct Task {
  std::size_t object = 0;
  long k0 = 0, k1 = 0;  ///< instants [k0, k1)
};

struct TaskOut {
  std::string bytes;  ///< reused from wave to wave
  long states = 0;
  CatalogState last;
  sgp4::Sgp4Error error = sgp4::Sgp4Error::kNone;
  double error_t_s = 0.0;
};

struct Plan {
  const PropagateCatalogRequest* req = nullptr;
  double start_j2000_s = 0.0;
  bool j2000 = false;
  StateFormat format = StateFormat::kNone;
  long last_k = 0;  ///< instants 0..last_k (detail::last_instant)
};

void append(std::string& s, double x) {
  char b[32];
  const std::to_chars_result r = std::to_chars(b, b + sizeof b, x);  // 24 chars at most
  s.append(b, r.ptr);
}

void append(std::string& s, long x) {
  char b[24];
  const std::to_chars_result r = std::to_chars(b, b + sizeof b, x);
  s.append(b, r.ptr);
}

void append_state(std::string& s, long id, long k, const CatalogState& st, StateFormat f) {
  if (f == StateFormat::kCsv) {
    append(s, id);
    s += ',';
    append(s, st.t_s);
    for (int i = 0; i < 3; ++i) s += ',', append(s, st.r_m(i));
    for (int i = 0; i < 3; ++i) s += ',', append(s, st.v_mps(i));
    s += '\n';
    return;
  }
  s += k > 0 ? ",\n{\"t_s\":" : "\n{\"t_s\":";
  append(s, st.t_s);
  s += ",\"r_m\":[";
  for (int i = 0; i < 3; ++i) append(s, st.r_m(i)), s += i < 2 ? ',' : ']';
  s += ",\"v_mps\":[";
  for (int i = 0; i < 3; ++i) append(s, st.v_mps(i)), s += i < 2 ? ',' : ']';
  s += '}';
}

void run_task(const Plan& p, const Task& t, TaskOut* out) {
  const sgp4::MeanElements& m = p.req->catalog.objects[t.object];
  out->bytes.clear();
  out->states = 0;
  out->error = sgp4::Sgp4Error::kNone;
  const sgp4::Sgp4Propagator prop(m, sgp4::OperationMode::kImproved);
  const double offset_s = p.start_j2000_s - sgp4::epoch_seconds_since_j2000(m);
  for (long k = t.k0; k < t.k1; ++k) {
    const double t_s = detail::instant_s(*p.req, k);
    CatalogState st;
    const sgp4::Sgp4Error e = detail::catalog_state(prop, offset_s, p.start_j2000_s, t_s, p.j2000, &st);
    if (e != sgp4::Sgp4Error::kNone) {
      out->error = e;
      out->error_t_s = t_s;
      return;
    }
    if (p.format != StateFormat::kNone) append_state(out->bytes, m.norad_id, k, st, p.format);
    out->last = st;
    ++out->states;
  }
}

// A JSON string literal (names come from catalog files: escape what JSON requires).
std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      (void)std::snprintf(b, sizeof b, "\\u%04x", static_cast<unsigned>(c));
      o += b;
    } else o += c;
  }
  return o + "\"";
}

std::string json_head(const StreamedCatalog& r) {
  std::string s = "{\"bad_entries\":" + std::to_string(r.bad_entries) + ",\"frame\":" +
                  (r.j2000 ? "\"J2000\"" : "\"TEME\"") + ",\"issues\":[";
  for (std::size_t i = 0; i < r.issues.size(); ++i)
    s += (i ? "," : "") + json_string(r.issues[i]);
  return s + "],\"start_utc\":" + json_string(detail::utc_text(r.start_j2000_s)) + ",\"objects\":[";
}

std::string json_object_head(const StreamedTrack& t, bool first) {
  std::string s = first ? "\n" : ",\n";
  s += "{\"epoch_utc\":" + json_string(detail::utc_text(t.epoch_j2000_s)) + ",\"id\":";
  append(s, t.id);
  return s + ",\"name\":" + json_string(t.name) + ",\"states\":[";
}

std::string json_object_tail(const StreamedTrack& t) {
  std::string s = "\n]";
  if (t.error != sgp4::Sgp4Error::kNone) {
    s += ",\"sgp4_error\":{\"code\":" + std::to_string(static_cast<int>(t.error)) + ",\"t_s\":";
    append(s, t.error_t_s);
    s += ",\"text\":" + json_string(sgp4_error_text(t.error)) + "}";
  }
  return s + "}";
}

std::string csv_head(bool j2000) {
  const std::string f = j2000 ? "j2000" : "teme";
  return "id,t_s," + f + "_x_m," + f + "_y_m," + f + "_z_m," + f + "_vx_mps," + f + "_vy_mps," +
         f + "_vz_mps\n";
}

// The tasks in order: every object's instants cut into chunks.
class TaskList {
 public:
  TaskList(std::size_t objects, long last_k) : n_(objects), last_k_(last_k) {}
  bool next(Task* t) {
    if (obj_ >= n_) return false;
    *t = {obj_, k_, std::min(k_ + kStreamChunkSteps, last_k_ + 1)};
    k_ = t->k1;
    if (k_ > last_k_) ++obj_, k_ = 0;
    return true;
  }

 private:
  std::size_t n_, obj_ = 0;
  long last_k_, k_ = 0;
};

void compute_wave(const Plan& p, const std::vector<Task>& wave, int threads,
                  std::vector<TaskOut>* outs) {
  const auto work = [&](std::size_t first) {
    for (std::size_t i = first; i < wave.size(); i += static_cast<std::size_t>(threads))
      run_task(p, wave[i], &(*outs)[i]);
  };
  if (wave.empty()) return;
  if (threads == 1 || wave.size() == 1) {
    work(0);
    return;
  }
  std::vector<std::thread> pool;
  for (int j = 1; j < threads; ++j) pool.emplace_back(work, static_cast<std::size_t>(j));
  work(0);
  for (std::thread& th : pool) th.join();
}

// Writes one computed task in order (the object head first, its tail after its last task).
void write_task(const Plan& p, const Task& t, const TaskOut& o, StreamedCatalog* r,
                std::vector<char>* done, const ByteSink& sink) {
  if ((*done)[t.object]) return;  // stopped at an SGP4 error in an earlier task
  StreamedTrack& tr = r->objects[t.object];
  const bool json = p.format == StateFormat::kJson;
  if (json && t.k0 == 0) {
    const std::string h = json_object_head(tr, t.object == 0);
    sink(h.data(), h.size());
  }
  if (!o.bytes.empty()) sink(o.bytes.data(), o.bytes.size());
  tr.states += o.states;
  r->states += o.states;
  if (o.states > 0) tr.last = o.last;
  if (o.error != sgp4::Sgp4Error::kNone) tr.error = o.error, tr.error_t_s = o.error_t_s;
  if (o.error == sgp4::Sgp4Error::kNone && t.k1 <= p.last_k) return;
  (*done)[t.object] = 1;
  if (!json) return;
  const std::string tail = json_object_tail(tr);
  sink(tail.data(), tail.size());
}

StreamedCatalog summary_of(const PropagateCatalogRequest& req) {
  const PropagateCatalogResult h = detail::catalog_result_header(req);
  StreamedCatalog r;
  r.start_j2000_s = h.start_j2000_s;
  r.j2000 = h.j2000;
  r.bad_entries = h.bad_entries;
  r.issues = h.issues;
  r.objects.resize(req.catalog.objects.size());
  for (std::size_t i = 0; i < r.objects.size(); ++i) {
    const sgp4::MeanElements& m = req.catalog.objects[i];
    r.objects[i].id = m.norad_id;
    r.objects[i].name = m.name;
    r.objects[i].epoch_j2000_s = sgp4::epoch_seconds_since_j2000(m);
  }
  return r;
}

}  // namespace

StreamedCatalog stream_propagate_catalog(const PropagateCatalogRequest& req, StateFormat format,
                                         int threads, const ByteSink& sink) {
  StreamedCatalog r = summary_of(req);
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const Plan p{&req, r.start_j2000_s, r.j2000, format, detail::last_instant(req)};
  const std::string head = format == StateFormat::kJson  ? json_head(r)
                           : format == StateFormat::kCsv ? csv_head(r.j2000)
                                                         : std::string();
  if (!head.empty()) sink(head.data(), head.size());
  const std::size_t wave_size = static_cast<std::size_t>(threads) * 2;
  std::vector<TaskOut> outs(wave_size);
  std::vector<Task> wave;
  std::vector<char> done(r.objects.size(), 0);
  TaskList tasks(r.objects.size(), p.last_k);
  Task t;
  while (tasks.next(&t)) {
    wave.push_back(t);
    if (wave.size() < wave_size) continue;
    compute_wave(p, wave, threads, &outs);
    for (std::size_t i = 0; i < wave.size(); ++i) write_task(p, wave[i], outs[i], &r, &done, sink);
    wave.clear();
  }
  compute_wave(p, wave, threads, &outs);
  for (std::size_t i = 0; i < wave.size(); ++i) write_task(p, wave[i], outs[i], &r, &done, sink);
  if (format == StateFormat::kJson) sink("\n]}\n", 4);
  return r;
}

std::string to_text(const StreamedCatalog& r) {
  char buf[512];
  // Fixed formats of finite numbers and bounded names (%.*s): the counts are not needed.
  (void)std::snprintf(buf, sizeof buf,
                      "evade propagate: %zu objects (%d bad entries), frame %s, from %s UTC\n",
                      r.objects.size(), r.bad_entries, r.j2000 ? "J2000" : "TEME",
                      detail::utc_text(r.start_j2000_s).c_str());
  std::string text = buf;
  for (const StreamedTrack& t : r.objects) {
    (void)std::snprintf(buf, sizeof buf, "  %6ld %-24.200s %ld states", t.id, t.name.c_str(),
                        t.states);
    text += buf;
    if (t.states > 0) {
      (void)std::snprintf(buf, sizeof buf, ", at t = %.0f s r_m = [%.1f, %.1f, %.1f]", t.last.t_s,
                          t.last.r_m.x(), t.last.r_m.y(), t.last.r_m.z());
      text += buf;
    }
    if (t.error != sgp4::Sgp4Error::kNone) text += std::string(" (stopped: ") + sgp4_error_text(t.error) + ")";
    text += '\n';
  }
  return text;
}

}  // namespace evade::commands
