// `evade screen` as library calls (paper 002: Wang Xiaoyu, "Space entity collision
// prediction algorithm and self-adaptive simulation step design", J. Air Force Eng. Univ.
// 7(6), 2006; issues 6, 12, 13). Two modes:
//   objects (scenario `objects`, a CSV file or a seeded synthetic population):
//     --method paper : the paper's adaptive Step rule (paper_step.hpp; corrected reading),
//                      optionally every sample (the paper's Table 2 rows);
//     --method robust: the screening that cannot miss an approach below the threshold
//                      (robust_screen.hpp), optionally split over MPI ranks by the caller;
//   catalog (--tle/--omm): every object moves by SGP4 (sgp4_motion.hpp), robust screening.
// Both can write one CCSDS CDM per event (screening_events.hpp, assessment/screen_cdms.hpp).
// Request -> run -> result; to_json is the command's JSON (the keys and number formatting of
// `evade screen --json`), to_text its table. The callers do the I/O: reading the CSV or the
// catalog file, writing the CSV and the CDM files, printing.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/commands/screen_cdms.hpp"
#include "evade/config/scenario.hpp"
#include "evade/conjunction/primary_prefilter.hpp"
#include "evade/conjunction/primary_window_screen.hpp"
#include "evade/conjunction/paper_step.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/sgp4/catalog.hpp"

namespace evade::commands {

/// Text sink for progress and diagnostics (e.g. stderr); empty: silent.
using ScreenTextSink = std::function<void(const std::string&)>;

/// The robust screening of the objects mode (default screen_robust; the CLI passes the
/// MPI-distributed one).
using RobustScreener =
    std::function<conjunction::ScreenResult(const std::vector<conjunction::SpaceObject>&, double, const conjunction::ScreenOptions&)>;

// ---------------------------------------------------------------- objects mode

/// Where the objects come from (the command's flags).
struct ScreenObjectsSource {
  std::string method = "robust";  ///< "paper" or "robust" (paper: robust.* keys not read)
  long population = 0;            ///< > 0: a synthetic population of this many objects
  long seed = 1;                  ///< its seed
  std::string objects_csv_path;   ///< non-empty: objects from this CSV file (echoed)
  std::string objects_csv_text;   ///< its text
};

struct ScreenObjectsRequest {
  std::string method = "robust";  ///< "paper" | "robust"
  bool trace = false;             ///< paper: record every sample (Table 2 rows)
  int threads = 0;                ///< robust: worker threads; 0: hardware concurrency
  ScreenScenario scenario;        ///< epoch, span, force model, paper_step.*, robust.*
  std::vector<conjunction::SpaceObject> objects;
  std::string objects_source;     ///< echoed as objects_source
  nlohmann::json scenario_used = nlohmann::json::object();  ///< every scenario value read
  commands::ScreenCdmOptions cdm;  ///< dir empty: no CDMs (robust only)
  int ranks = 1;                  ///< MPI ranks of robust_screener (echoed in stats)
  int rank = 0;                   ///< this process's rank: only rank 0 builds the CDMs
  RobustScreener robust_screener; ///< empty: screen_robust in this process
  ScreenTextSink progress;        ///< progress text; empty: none
  /// Before any output is prepared: --cdm-out only with robust, the CDM options
  /// (commands::check_screen_cdm_options), --trace only with paper. Throws
  /// std::invalid_argument naming the flag.
  void validate() const;
};

/// Reads the scenario (read_screen_scenario) and the objects (population, CSV text or the
/// scenario's `objects`), checks that every scenario key was used. Throws config::ConfigError
/// or std::invalid_argument naming the key, line or flag.
ScreenObjectsRequest read_screen_objects_request(const config::Scenario& sc,
                                                 const ScreenObjectsSource& src);

struct ScreenObjectsResult {
  std::string method;
  std::string objects_source;
  std::vector<conjunction::SpaceObject> objects;  ///< screened (names for the events)
  std::string epoch_utc;             ///< t = 0, as the scenario writes it
  double epoch_j2000_s = 0.0;        ///< t = 0, UTC s since J2000
  double span_s = 0.0;
  nlohmann::json scenario_used = nlohmann::json::object();
  double warning_multiple = 0.0;     ///< N: WARNING when miss <= N R_c
  std::vector<conjunction::Conjunction> events;   ///< by TCA; paper: flagged samples
  long steps = 0;                    ///< paper: samples after t = 0; robust: grid steps
  bool robust = false;               ///< the stats below are set
  conjunction::ScreenStats stats;
  int threads = 0;
  int ranks = 1;
  double grid_step_s = 0.0;          ///< robust grid step (auto_step_s(N) when 0 was asked)
  bool traced = false;               ///< the trace below was recorded
  std::vector<conjunction::TraceRow> trace;
  double wall_time_s = 0.0;          ///< the screening's wall-clock time [s]
  std::optional<commands::ScreenCdms> cdm;  ///< one CDM per event, when asked for
};

/// Screens (after validate()). Throws std::invalid_argument for the paper method on more
/// than 2000 objects and for invalid objects.
ScreenObjectsResult run_screen_objects(const ScreenObjectsRequest& req);

nlohmann::json to_json(const ScreenObjectsResult& r);
std::string to_text(const ScreenObjectsResult& r);

// ---------------------------------------------------------------- catalog mode

/// The screener's options for a catalog: threshold 5000 m, automatic grid step, WGS-72 (the
/// elements' Earth), no warning radius (catalogs carry no sizes: the threshold alone).
conjunction::ScreenOptions catalog_screen_options();

struct ScreenCatalogRequest {
  sgp4::Catalog catalog;          ///< the element sets read (bad entries counted)
  std::string source;             ///< the file (echoed)
  long primary_norad = -1;        ///< >= 0: screen this object against the catalog
  double span_s = 86400.0;        ///< from the start, (0, 31 d]
  /// The screener's options themselves (robust_screen.hpp), not a copy of some of them:
  /// robust.threshold_m reports misses <= this, (0, 1e8]; robust.step_s is the grid step,
  /// 0: auto_step_s(N), else [1, 600]. The screen sets their motion, primary, threads and
  /// progress from the fields of this request.
  conjunction::ScreenOptions robust = catalog_screen_options();
  std::string start_utc;          ///< empty: the latest element epoch
  int threads = 0;                ///< 0: hardware concurrency
  /// With a primary: set aside the objects that can never come within robust.threshold_m of it
  /// before propagating (primary_prefilter.hpp); false screens every object.
  bool prefilter = true;
  /// With a primary and the prefilter: the orbit-path filter after the perigee/apogee one
  /// (primary_path_filter.hpp); false keeps every object the perigee/apogee filter keeps.
  bool path_filter = true;
  /// With a primary and the prefilter: screen each object only inside the time filter's
  /// windows (primary_window_screen.hpp; in this process, not with robust_screener); false
  /// screens the prefilter's objects over the whole span.
  bool time_filter = true;
  int ranks = 1;                  ///< MPI ranks of robust_screener (echoed in stats)
  int rank = 0;                   ///< this process's rank: only rank 0 builds the CDMs
  RobustScreener robust_screener; ///< empty: screen_robust in this process
  /// With ranks > 1: replaces each entry of a vector by its sum over the ranks, in every
  /// rank (MPI_Allreduce, MPI_SUM); the setup's perturbation envelopes are then split
  /// between the ranks (Sgp4MotionOptions::sum_over_parts). Empty: each rank samples all.
  std::function<void(std::vector<double>&)> sum_over_ranks;
  commands::ScreenCdmOptions cdm;
  ScreenTextSink progress;        ///< progress text; empty: none
  ScreenTextSink diagnostic;      ///< one line per rejected element set; empty: none
  /// Throws std::invalid_argument naming --span-s, --threshold-m, --step-s or a CDM flag
  /// (commands::check_screen_cdm_options; catalog objects have no radii).
  void validate() const;
};

/// Sets the parameter flags' values (evade/config/param_flags.hpp: span_s,
/// robust.threshold_m, robust.step_s) in req, each checked against its key's declaration
/// (screen_scenario_params, screen_options_params) and stored as the double given; any
/// other key is refused (config::ConfigError). The catalog's own limits are validate()'s.
void apply_param_values(const std::vector<ParamValue>& values, ScreenCatalogRequest* req);

struct CatalogEvent {
  long norad_i = 0;
  long norad_j = 0;
  std::string name_i;
  std::string name_j;
  double tca_s = 0.0;             ///< since the start [s]
  std::string tca_utc;
  double miss_m = 0.0;
  double rel_speed_mps = 0.0;
};

struct ScreenCatalogResult {
  std::string frame;              ///< of the motion ("TEME")
  std::string source;
  std::string start_utc;
  double start_j2000_s = 0.0;     ///< UTC s since J2000
  double span_s = 0.0;
  double threshold_m = 0.0;
  long objects = 0;               ///< screened
  long bad_entries = 0;
  std::vector<std::string> rejections;  ///< "NORAD id (NAME): reason"
  std::optional<long> primary_norad;
  std::optional<conjunction::PrimaryPrefilterCounts> prefilter;  ///< with a primary and the prefilter
  std::optional<conjunction::TimeFilterCounts> time_filter;      ///< with the time filter
  conjunction::ScreenStats stats;
  int threads = 0;
  int ranks = 1;
  double grid_step_s = 0.0;
  long envelopes_sampled = 0;     ///< perturbation envelopes this process sampled
  double motion_setup_wall_s = 0.0;
  double screen_wall_s = 0.0;
  std::vector<CatalogEvent> events;
  std::optional<commands::ScreenCdms> cdm;
};

/// Builds the SGP4 motion and screens it. Throws std::invalid_argument for bad options, an
/// unknown or rejected --primary, or fewer than two usable element sets.
ScreenCatalogResult run_screen_catalog(const ScreenCatalogRequest& req);

nlohmann::json to_json(const ScreenCatalogResult& r);
std::string to_text(const ScreenCatalogResult& r);

/// "YYYY-MM-DD hh:mm:ss.fff UTC": an instant (UTC s since J2000) rounded to the millisecond.
std::string utc_text_ms(double utc_j2000_s);

}  // namespace evade::commands
