// A lower bound of the threat arc over a whole ball of evasion burns: the part of the sweep
// that threatens whatever burn of the ball the target makes.
//
// Paper 001 (Yu, Wang, Sun 2017) sec. 3.1: the arc (eq. 6–7) after the burn Δv_E (eq. 4–5)
// is minimized over the burn direction. This bound is ours; it certifies that search
// (direction_search.hpp): a cell of directions whose bound is above the best arc found cannot
// hold a better direction.
//
// Bound of the chaser's cost over a ball of burns. For departure time t the required change
// is d(t) = w(t) + B(t+ΔT) Δv_E (threat_area.hpp). Take any feasible plan P for d: cost c,
// first impulse a1 (at 0), last a2 (at ΔT). For the burn Δv'_E = Δv_E + V_E (e' − e) (unit
// directions e, e') the change moves by δ = V_E B (e' − e), and P stays feasible after adding
// the 2-impulse plan of δ (hcw_transfer.hpp) to its end impulses: a_i → a_i + G_i (e' − e)
// with G1 = V_E Φrv(ΔT)⁻¹ B_r, G2 = V_E (B_v − Φvv(ΔT) Φrv(ΔT)⁻¹ B_r). So
//     J*(t, Δv'_E) ≤ c − |a1| − |a2| + Σ_i |a_i + G_i (e' − e)|,
// and each term is bounded over the ball |e' − e| ≤ ρ (chord) by the smaller of
//     |a| + ‖G‖₂ ρ                                          (Lipschitz),
//     |a| + |h_tan| ρ + max(0, −h·e) ρ²/2 + ‖G‖₂² ρ² / (2|a|)  (second order),
// h = Gᵀ â: from |a + x| ≤ |a| + âᵀx + |x|²/(2|a|) (concavity of √) and, for unit e, e' at
// angle γ with chord ρ, |(e' − e)_tangential| = sin γ ≤ ρ and e·(e' − e) = −ρ²/2. The
// second form matters: at the edge of the optimal direction's arc the cost is stationary
// in the direction (else a neighbour would have a shorter arc), so h_tan ≈ 0 there and the
// bound loses only O(ρ²). t threatens for the whole ball ("certain") when the bound is
// ≤ ΔV_max. P is the 2-impulse plan (cheap, every grid point) or, at the points that decide
// an interval's edges, the full-effort SQP plan (ThreatAreaSolver::min_cost_plan).

// From certain points to an arc. Under the sweep's own model (one crossing of ΔV_max between
// neighbouring grid points, the assumption behind its edge bisection) every run of certain
// grid points lies inside one threatening interval of every burn of the ball; each run is
// extended at both ends by bisection (to the sweep's edge tolerance, keeping the certain
// side) and the bound is the sum of the run lengths. It bounds the true arc (exact minimum
// cost at every t); the sweep's reported arc differs from that by its edge tolerance.
#pragma once

#include <vector>

#include "evade/threat/threat_area.hpp"

namespace evade::threat {

/// Precomputed w(t), B(t+ΔT) and the end-impulse maps on the solver's sweep grid;
/// thread-safe const queries.
class ArcBound {
 public:
  explicit ArcBound(const ThreatAreaSolver& solver);

  /// Lower bound [s] of the arc of every burn V_E e' with |e' − e| ≤ chord, e = e_rsw (unit).
  /// With refine_edges the points next to certain runs and the edges use the SQP's plans
  /// (tighter, costlier); without, 2-impulse plans only.
  double lower_bound_s(const Vec3& e_rsw, double dv_mps, double chord, bool refine_edges) const;

 private:
  /// End-impulse maps at one departure time: G_i / V_E and their spectral norms.
  struct Maps {
    Mat3 m1, m2;
    double n1 = 0.0, n2 = 0.0;
  };
  struct Ball {
    Vec3 e;
    double dv_mps, chord;
  };
  Maps maps_at(double t_s) const;
  /// Upper bound of the minimum cost over the ball at departure t (plan from d).
  double cost_upper(const Vec6& d, const Maps& m, const Ball& ball, bool sqp, double t_s) const;
  bool certain(double t_s, const Ball& ball, bool sqp) const;
  /// Bisects between a certain time and an uncertain one; returns the certain end.
  double certain_edge(double certain_t, double other_t, const Ball& ball, bool sqp) const;
  /// Grid points certain with 2-impulse plans (1 = certain).
  std::vector<char> certain_points(const Ball& ball) const;
  /// Marks the points next to certain runs that are certain with the SQP's plans, until
  /// none is added.
  void grow_runs(std::vector<char>& sure, const Ball& ball) const;
  /// Sum of the lengths of the certain runs, each extended at both ends by bisection.
  double runs_length(const std::vector<char>& sure, const Ball& ball, bool refine_edges) const;

  const ThreatAreaSolver& solver_;
  std::vector<double> t_;
  std::vector<Vec6> w_;
  std::vector<Eigen::Matrix<double, 6, 3>> b_;
  std::vector<Maps> maps_;
};

}  // namespace evade::threat
