// Conjunction screening across the ranks of an MpiSession (issue 13): rank r screens part r
// of the grid steps (conjunction::screen_robust_part), rank 0 gathers every part's events
// (MPI_Gatherv of fixed-size records) and sums the statistics (MPI_Reduce), then sorts. The
// events equal those of one process: a step's work does not depend on which rank does it.
#pragma once

#include <vector>

#include "evade/conjunction/robust_screen.hpp"
#include "evade/distributed/mpi_session.hpp"

namespace evade::distributed {

/// Replaces every entry of v by its sum over the ranks, in every rank (MPI_Allreduce with
/// MPI_SUM; the vector must have the same size in every rank). One process: v unchanged.
/// The SGP4 catalog screen splits its perturbation envelopes between the ranks with it
/// (conjunction::ScreenCatalogRequest::sum_over_ranks). Throws std::length_error above
/// INT_MAX entries.
void sum_over_ranks(std::vector<double>& v, const MpiSession& session);

/// On rank 0: the merged result of all ranks. On the others: their own part only.
conjunction::ScreenResult screen_distributed(const std::vector<conjunction::SpaceObject>& objects,
                                             double span_s, const conjunction::ScreenOptions& opt,
                                             const MpiSession& session);

}  // namespace evade::distributed
