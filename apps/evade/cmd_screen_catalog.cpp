// `evade screen --tle FILE | --omm FILE [--primary ID] [--span-s S] [--threshold-m D]
// [--step-s H] [--start UTC] [--threads N] [--json]`: reads the file (the only input I/O),
// screens it by commands::run_screen_catalog and prints its JSON or text. Under
// `mpirun -np N` the perturbation envelopes of the setup and the grid steps are split between
// the ranks (distributed_screen.hpp) and rank 0 prints the merged result.
#include "cmd_screen_catalog.hpp"

#include <cstdio>

#include "cli.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/distributed/distributed_screen.hpp"

namespace evade::cli {

int run_catalog_screen(const CatalogScreenOptions& o) {
  commands::ScreenCatalogRequest req;
  req.source = o.tle_path.empty() ? o.omm_path : o.tle_path;
  req.primary_norad = o.primary_norad;
  commands::apply_param_values(o.param_values, &req);
  req.start_utc = o.start_utc;
  req.threads = o.threads;
  req.prefilter = !o.no_prefilter;
  req.time_filter = !o.no_time_filter;
  req.path_filter = !o.no_path_filter;
  req.cdm = screen_cdm_options(o.cdm);
  req.validate();
  req.catalog = read_catalog_file(o.tle_path, o.omm_path);
  const distributed::MpiSession mpi;  // one process unless started by mpirun
  const bool lead = mpi.rank() == 0;  // rank 0 reports, prints and writes
  for (const auto& is : req.catalog.issues)
    if (lead) (void)std::fprintf(stderr, "evade screen: bad entry: %s\n", is.message().c_str());
  auto to_stderr = [](const std::string& s) { (void)std::fputs(s.c_str(), stderr); };
  if (lead) req.diagnostic = to_stderr;
  if (!o.quiet && lead) req.progress = to_stderr;
  req.ranks = mpi.size();
  req.rank = mpi.rank();
  if (mpi.size() > 1) {  // else the time filter may run (it is not split between ranks)
    req.robust_screener = [&mpi](const std::vector<conjunction::SpaceObject>& objects, double span_s,
                                 const conjunction::ScreenOptions& so) {
      return distributed::screen_distributed(objects, span_s, so, mpi);
    };
    req.sum_over_ranks = [&mpi](std::vector<double>& v) { distributed::sum_over_ranks(v, mpi); };
  }
  const commands::ScreenCatalogResult r = commands::run_screen_catalog(req);
  if (!lead) return 0;  // rank 0 holds the merged result
  if (r.cdm) write_cdm_files(*r.cdm);
  if (o.json) print_json(to_json(r));
  else (void)std::fputs(to_text(r).c_str(), stdout);
  return 0;
}

}  // namespace evade::cli
