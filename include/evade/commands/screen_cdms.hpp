// One CCSDS Conjunction Data Message per event of a conjunction screening (CCSDS 508.0-B-1,
// Blue Book, June 2013): what `evade screen ... --cdm-out DIR [--cdm-format kvn|xml]
// [--cov-rtn-sigma-m R,T,N] [--hbr-m H]` writes, for both of its input paths (the states of
// the events come from conjunction/screening_events.hpp).
//
// Each event becomes a message by cdm_from_event (cdm_from_event.hpp), with a unique
// deterministic file stem (cdm_event_file_stem, then "-2", "-3", ... for repeats). With
// assumed RTN position sigmas R, T, N every object gets the covariance diag(R^2, T^2, N^2) in
// its RTN frame (velocity terms 0; said in a COMMENT: it is not from an orbit determination)
// and the message carries the 2D Pc over the hard-body disk (Foster & Estes 1992); the
// hard-body radius is H, else the sum of the two objects' radii (AREA_PC = pi r^2 each).
// The messages are built here and returned as text; writing the files is the caller's.
#pragma once

#include <functional>

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/commands/cdm_from_event.hpp"
#include "evade/core/state.hpp"

namespace evade::commands {

struct ScreenCdmFile;

struct ScreenCdmOptions {
  std::string dir;                       ///< output directory (empty: no CDMs)
  std::string format = "kvn";            ///< kvn | xml
  std::string cov_rtn_sigma_text;        ///< "R,T,N" as given (empty: covariance not known)
  std::vector<double> cov_rtn_sigma_m;   ///< its numbers (empty when it is not a number list)
  double hbr_m = 0.0;                    ///< hard-body radius [m]; 0: the objects' radii
  /// The Pc method choice and its escalated Monte Carlo (assessment_params: the
  /// `assessment.*` keys; the CLI sets mc_max_samples with --mc-max-samples).
  assessment::AssessConfig assess;
  bool assess_given = false;             ///< a flag set `assess` (only with a covariance)
  std::optional<double> creation_utc_j2000_s;  ///< CREATION_DATE; empty: the clock now
  /// When set, each message goes here as soon as it is made (the CLI writes its file) and
  /// its text is not kept in the result (ScreenCdmFile::text empty).
  std::function<void(const ScreenCdmFile&)> sink;
};

/// diag(R^2, T^2, N^2) position block, velocity block 0 (RTN) [m^2]; empty without sigmas.
/// Throws std::invalid_argument "--cov-rtn-sigma-m = '...' is invalid: ..." unless there are
/// three finite sigmas in (0, 1e7] m.
std::optional<Mat6> assumed_rtn_covariance(const ScreenCdmOptions& o);

/// The options' consistency (before the screening starts, so that a bad flag fails at once):
/// --cdm-format, --cov-rtn-sigma-m and --hbr-m only with a directory, --hbr-m only with a
/// covariance, a covariance for objects without radii only with --hbr-m, valid sigmas.
/// Throws std::invalid_argument naming the flag.
void check_screen_cdm_options(const ScreenCdmOptions& o, bool objects_have_radii);

/// The screening run shared by every event.
struct ScreenCdmRun {
  double epoch_utc_j2000_s = 0.0;  ///< t = 0 of the screening (UTC s since J2000)
  double span_s = 0.0;             ///< screened span [s]
  double threshold_m = 0.0;        ///< screening threshold [m] (SCREEN_VOLUME)
  std::string source;              ///< the objects' source (header COMMENT)
};

struct ScreenCdmFile {
  std::string path;           ///< dir/<message_id>.cdm or .xml
  std::string message_id;     ///< MESSAGE_ID = file stem
  std::string text;           ///< the message (KVN or XML)
  std::optional<double> pc;   ///< COLLISION_PROBABILITY when the covariance is known
  std::string pc_method;      ///< its method (pc_method_choice.hpp): "2d", "3d_nc" or "mc"
};

struct ScreenCdms {
  std::string dir;
  std::string format;
  std::string covariance;            ///< "not known (no Pc)" or "assumed RTN sigmas R,T,N m"
  bool covariance_known = false;     ///< the messages carry a Pc
  std::vector<ScreenCdmFile> files;  ///< one per event, in the events' order
};

/// The messages of `events` (TCAs in UTC s since J2000, states in EME2000). Throws
/// std::invalid_argument for a covariance without a hard-body radius (objects without size
/// and no --hbr-m) and whatever cdm_from_event refuses.
ScreenCdms screen_event_cdms(const ScreenCdmOptions& o, const ScreenCdmRun& run,
                             std::vector<commands::ScreeningEvent> events);

/// {dir, format, count, covariance, files: [{file, message_id, pc}]}.
nlohmann::json to_json(const ScreenCdms& c);

}  // namespace evade::commands
