// The time history of a closed-loop evasion run (paper 000 sec. 4, Figs. 3–4) as CSV: one row
// per guidance cycle (SimSample) with the truth, the measurement, the guidance's estimate and
// command and the applied acceleration, plus the true zero-effort miss
// ZEM = V_θ t_go = R² λ̇ / (−Ṙ) (paper 000 eq. 7 and 12 with the true range R, range rate Ṙ
// and LOS rate λ̇).
// scripts/plot_sim.py draws it.
#pragma once

#include <cstddef>
#include <ostream>

#include "evade/sim/simulator.hpp"

namespace evade::commands {

/// One column: its name (with its unit) and its value, a number (number != nullptr; flags as
/// 0/1) or a name (text != nullptr: the guidance mode and reason).
struct SimCsvColumn {
  const char* name;
  double (*number)(const sim::SimSample&);
  const char* (*text)(const sim::SimSample&);
};

/// The columns in order (*count of them): the one table of the CSV's columns.
const SimCsvColumn* sim_csv_columns(std::size_t* count) noexcept;

/// The header line (no newline): column names with their units.
const char* sim_csv_header() noexcept;

/// True ZEM [m] of a sample: R² · los_rate / (−range_rate) while closing, NaN otherwise.
double zem_true_m(const sim::SimSample& s) noexcept;

/// One row (15 significant digits, newline-terminated), columns as in sim_csv_header().
void write_sim_csv_row(std::ostream& os, const sim::SimSample& s);

}  // namespace evade::commands
