// `evade screen ... --cdm-out DIR`: flags, directory and files (screen_cdm_out.hpp).
#include "screen_cdm_out.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "evade/config/read_params.hpp"
#include "number_list.hpp"
#include "param_flag_option.hpp"

namespace evade::cli {

void add_cdm_out_options(CLI::App& app, CdmOutOptions& o) {
  app.add_option("--cdm-out", o.dir, "write one CCSDS CDM per event into this directory (created)");
  app.add_option("--cdm-format", o.format, "CDM form: kvn or xml")
      ->check(CLI::IsMember({"kvn", "xml"}))
      ->capture_default_str();
  app.add_option("--cov-rtn-sigma-m", o.cov_sigma,
                 "with --cdm-out: assumed RTN position sigmas R,T,N [m] of every object; the CDMs then carry a Pc");
  app.add_option("--hbr-m", o.hbr_m, "with --cdm-out: hard-body radius for the Pc [m] (default: the objects' radii)")
      ->check(CLI::PositiveNumber);
  (void)add_param_flag(app, assessment::assess_params(), "assessment.",
                       "assessment.mc_max_samples", &o.assess_values);
}

commands::ScreenCdmOptions screen_cdm_options(const CdmOutOptions& o) {
  commands::ScreenCdmOptions c;
  c.dir = o.dir;
  c.format = o.format;
  c.cov_rtn_sigma_text = o.cov_sigma;
  if (!o.cov_sigma.empty()) c.cov_rtn_sigma_m = parse_number_list(o.cov_sigma, ',');
  c.hbr_m = o.hbr_m;
  // The assessment flags, read through the assessment table (checked when parsed).
  config::Scenario sets = config::Scenario::empty("--mc-max-samples");
  for (const ParamValue& v : o.assess_values) sets.set_value(v);
  config::read_params(sets, "assessment.", assessment::assess_params(), &c.assess);
  c.assess_given = !o.assess_values.empty();
  c.sink = [](const commands::ScreenCdmFile& m) { write_cdm_file(m); };  // as each is made
  return c;
}

void create_cdm_dir(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::invalid_argument("--cdm-out: cannot create directory '" + dir + "': " +
                                (ec ? ec.message() : std::string("not a directory")));
  // One probe per process: MPI ranks check the same directory at the same time.
  const std::filesystem::path probe =
      std::filesystem::path(dir) / (".evade-write-test-" + std::to_string(::getpid()));
  std::ofstream(probe.string()) << "";
  if (!std::filesystem::exists(probe)) throw std::invalid_argument("--cdm-out: cannot write into '" + dir + "'");
  std::filesystem::remove(probe, ec);
}

void write_cdm_file(const commands::ScreenCdmFile& m) {
  std::ofstream f(m.path);
  f << m.text;
  f.close();
  if (!f) throw std::runtime_error("--cdm-out: cannot write '" + m.path + "'");
}

void write_cdm_files(const commands::ScreenCdms& cdms) {
  for (const auto& m : cdms.files)
    if (!m.text.empty()) write_cdm_file(m);  // the sink wrote the others as they were made
  if (!cdms.files.empty())
    (void)std::fprintf(stderr, "evade screen: wrote %zu CDMs (%s) to %s\n", cdms.files.size(),
                       cdms.format.c_str(), cdms.dir.c_str());
}

}  // namespace evade::cli
