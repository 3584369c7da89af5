// `evade screen ... --cdm-out DIR [--cdm-format kvn|xml] [--cov-rtn-sigma-m R,T,N]
// [--hbr-m H]`: one CCSDS CDM per screening event (assessment::cdm_from_event), for both
// input paths (population/objects: cmd_screen.cpp; --tle/--omm: cmd_screen_catalog.cpp).
// The flags are checked and DIR created before the screening starts, so a bad flag or an
// unwritable directory fails at once.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evade/assessment/cdm_from_event.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/sgp4/mean_elements.hpp"

namespace evade::cli {

struct CdmOutOptions {
  std::string dir;              ///< --cdm-out (empty: no CDMs)
  std::string format = "kvn";   ///< --cdm-format kvn|xml
  std::string cov_sigma;        ///< --cov-rtn-sigma-m R,T,N (empty: covariance not known)
  double hbr_m = 0.0;           ///< --hbr-m (0: the objects' radii where known)
};

void add_cdm_out_options(CLI::App& app, CdmOutOptions& o);

/// Checks the flags (catalog: whether the objects carry radii) and creates DIR. Throws
/// std::invalid_argument naming the flag.
void prepare_cdm_out(const CdmOutOptions& o, bool objects_have_radii);

/// Screening context shared by every event of one run.
struct CdmRunInfo {
  double epoch_utc_j2000_s = 0.0;  ///< t = 0 of the screening
  double span_s = 0.0;
  double threshold_m = 0.0;
  std::string source;              ///< header COMMENT
};

/// Population / objects path: states from the force model (EME2000 = the objects' ECI).
nlohmann::json write_population_cdms(const CdmOutOptions& o, const CdmRunInfo& run,
                                     const std::vector<conjunction::Conjunction>& events,
                                     const std::vector<conjunction::SpaceObject>& objects,
                                     const conjunction::ScreenOptions& so);

/// Catalog path: SGP4 states (TEME) rotated to EME2000 at the TCA.
nlohmann::json write_catalog_cdms(const CdmOutOptions& o, const CdmRunInfo& run,
                                  const conjunction::ScreenResult& r,
                                  const conjunction::Sgp4Screening& s,
                                  const std::vector<sgp4::MeanElements>& elements,
                                  const conjunction::ScreenOptions& so);

}  // namespace evade::cli
