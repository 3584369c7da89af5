// `evade screen ... --cdm-out DIR [--cdm-format kvn|xml] [--cov-rtn-sigma-m R,T,N]
// [--hbr-m H] [--mc-max-samples N]`: the flags, the directory and the files. The messages
// (one CCSDS CDM per event) are built by the library (assessment/screen_cdms.hpp,
// conjunction/screen_command.hpp) for both input paths; DIR is created before the screening
// starts, so an unwritable directory fails at once.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evade/commands/screen_cdms.hpp"
#include "evade/core/param.hpp"

namespace evade::cli {

struct CdmOutOptions {
  std::string dir;              ///< --cdm-out (empty: no CDMs)
  std::string format = "kvn";   ///< --cdm-format kvn|xml
  std::string cov_sigma;        ///< --cov-rtn-sigma-m R,T,N (empty: covariance not known)
  double hbr_m = 0.0;           ///< --hbr-m (0: the objects' radii where known)
  std::vector<ParamValue> assess_values;  ///< --mc-max-samples, typed
};

void add_cdm_out_options(CLI::App& app, CdmOutOptions& o);

/// The library's options from the flags (R,T,N read as a number list), with a sink that
/// writes each message's file as soon as the library makes it.
commands::ScreenCdmOptions screen_cdm_options(const CdmOutOptions& o);

/// Creates DIR (when given) and checks that a file can be written there. Throws
/// std::invalid_argument naming --cdm-out.
void create_cdm_dir(const std::string& dir);

/// One message's file. Throws std::runtime_error when it cannot be written.
void write_cdm_file(const commands::ScreenCdmFile& m);

/// Writes the messages the sink has not written (those still holding their text) and says
/// on stderr how many there are. Throws std::runtime_error when a file cannot be written.
void write_cdm_files(const commands::ScreenCdms& cdms);

}  // namespace evade::cli
