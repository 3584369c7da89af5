// Bindings of `evade sim` (sim/sim_command.hpp); the paper-000 guidance law's are
// bind_guidance_law.cpp (registered by bind_sim below).
//
// simulate: the request built as the CLI builds it (scenario, --set overrides, the same checks
// of runs/threads/seed), the lockstep run with the in-process law and the optional Monte Carlo
// in this process, the GIL released; the command's JSON, the single run's time history as one
// numpy array per column of `evade sim --csv` (same names, same units) and the per-run misses.
#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/commands/sim_command.hpp"
#include "evade/commands/sim_csv.hpp"

namespace evade::python {
namespace {

using sim::SimSample;

// ---------------------------------------------------------------------------------------
// Run options

// The CLI's checks of --runs, --threads and --seed, the keyword's name for its flag.
void check_run_options(int runs, int threads, long long seed) {
  if (runs < 0 || runs > 1000000) {
    throw std::invalid_argument("runs = " + std::to_string(runs) + " outside [0, 1000000]");
  }
  if (threads < 1 || threads > 64) {
    throw std::invalid_argument("threads = " + std::to_string(threads) + " outside [1, 64]");
  }
  if (seed < 0) throw std::invalid_argument("seed = " + std::to_string(seed) + " < 0");
}

// ---------------------------------------------------------------------------------------
// The time history as columns (sim_csv.hpp's one table of the CSV's columns)

// {CSV column name: values}, in the CSV's order: numbers as float64 arrays (has_meas and
// fallback as 0/1, turned into bool by the Python side), mode and reason as lists of names.
nb::dict series_columns(const std::vector<SimSample>& samples) {
  nb::dict out;
  std::size_t n = 0;
  const commands::SimCsvColumn* columns = commands::sim_csv_columns(&n);
  for (std::size_t k = 0; k < n; ++k) {
    const commands::SimCsvColumn& c = columns[k];
    if (c.text != nullptr) {
      nb::list names;
      for (const SimSample& s : samples) names.append(c.text(s));
      out[c.name] = names;
      continue;
    }
    std::vector<double> v;
    v.reserve(samples.size());
    for (const SimSample& s : samples) v.push_back(c.number(s));
    out[c.name] = numpy_from_vector(std::move(v), {samples.size()});
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// simulate

nb::tuple simulate(const std::string& scenario, const std::string& path,
                   const std::vector<std::string>& sets, int runs, long long seed, int threads,
                   bool series) {
  std::vector<SimSample> samples;
  commands::SimCommandResult r;
  {
    nb::gil_scoped_release unlocked;  // reading the scenario too: runs in threads run in parallel
    const config::Scenario sc = load_named_scenario(scenario, path, sets);
    check_run_options(runs, threads, seed);
    commands::SimCommandRequest req = commands::read_sim_command_request(sc);
    req.runs = runs;
    req.seed = static_cast<std::uint64_t>(seed);
    req.threads = threads;
    if (series) req.on_sample = [&samples](const SimSample& s) { samples.push_back(s); };
    r = commands::run_sim_command(req);
  }
  nb::object miss = nb::none(), dv = nb::none();
  if (r.monte_carlo) {
    const sim::MonteCarloResult& m = r.monte_carlo->result;
    miss = nb::cast(numpy_from_vector(m.miss_m, {m.miss_m.size()}));
    dv = nb::cast(numpy_from_vector(m.dv_mps, {m.dv_mps.size()}));
  }
  return nb::make_tuple(json_to_python(commands::to_json(r)), r.run.closest_approach_found,
                        r.warnings, series ? nb::object(series_columns(samples)) : nb::none(),
                        miss, dv);
}

}  // namespace

void bind_sim(nb::module_& m) {
  m.def("simulate", &simulate, nb::arg("scenario"), nb::arg("path"), nb::arg("sets"),
        nb::arg("runs"), nb::arg("seed"), nb::arg("threads"), nb::arg("series"),
        "(JSON of `evade sim --json`, closest approach found, warnings, {CSV column: values} "
        "or None, per-run miss_m or None, per-run dv_mps or None)");
  m.def("monte_carlo_run_seeds", [](std::uint64_t seed, std::uint64_t run) {
        const sim::MonteCarloRunSeeds s = sim::monte_carlo_run_seeds(seed, run);
        return nb::make_tuple(s.sensor, s.actuator);
      }, nb::arg("seed"), nb::arg("run"), "(sensor seed, actuator seed) of Monte Carlo run `run`");
  bind_thrust_command(m);
  bind_guidance_law(m);
}

}  // namespace evade::python
