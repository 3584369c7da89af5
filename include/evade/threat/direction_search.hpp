// The default search of the evasion burn direction: a coarse sweep of directions, local
// refinement from the best few, and a branch-and-bound certificate of the result.
//
// Paper 001 (Yu, Wang, Sun 2017) sec. 3.1–3.2: minimize the threat arc (eq. 7) over the burn
// direction (pitch α, yaw θ of eq. 4) at fixed V_E; the paper uses a GA (population 60,
// 20 generations), kept here as NLopt GN_ISRES (evasion.hpp). The problem has two variables,
// so this search exploits it:
//  1. Sweep: the direction box is cut into na × nθ cells of equal area (uniform in sin α and
//     θ); one exact arc evaluation per cell, at the same fractional position in every cell
//     (drawn from the seed in [0.1, 0.9]², so the seed moves the sampled points, not the cells).
//     These evaluations only rank the cells, so their interval edges are bisected to the
//     coarser sweep_edge_tol_s; every arc that can become the result is evaluated with the
//     solver's own edge tolerance.
//  2. Local refinement: NLopt LN_BOBYQA in (sin α, θ) from the best `local_starts` cells that
//     are not neighbours of a better chosen one, initial step half a cell, to local_xtol_rad.
//  3. Certificate (arc_bound.hpp): every cell gets a lower bound of the arc of every
//     direction in it (the chord from its sample point to its farthest corner is the radius
//     of the burn ball; the farthest point of a cell narrower than 90° in θ is a corner).
//     Cells whose bound is below (1 − certify_rel_tol) × best are split in four, level by
//     level, until none is left or certify_max_cells bounds were spent. The reported lower
//     bound is the smallest bound over the final cells: no direction of the box has a (true)
//     arc below it. When it reaches (1 − tol) × best the result is certified optimal to tol.
#pragma once

#include "evade/threat/evasion.hpp"

namespace evade::threat {

/// Sweep + BOBYQA + certificate at fixed V_E > 0 (options as in optimize_evasion).
EvasionResult sweep_direction_search(const ThreatAreaSolver& solver, double dv_mps,
                                     const EvasionOptions& opt);

/// Chord radius [unit vectors] of the cell [u1, u2] × [θ1, θ2] (u = sin α) around the
/// direction (u, θ) inside it: max over the cell's corners of |e(corner) − e(u, θ)|.
double cell_chord_radius(double u1, double u2, double theta1, double theta2, double u,
                         double theta);

}  // namespace evade::threat
