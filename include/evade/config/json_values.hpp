// JSON forms of the library's value types, shared by every result serializer (one place
// for the layout of a vector or a matrix in every command's JSON output).
#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "evade/core/burn_plan.hpp"

namespace evade::config {

/// [x, y, z] (or [v0, ..., vn-1]) of any Eigen column vector.
template <class Derived>
nlohmann::json vec_json(const Eigen::MatrixBase<Derived>& v) {
  nlohmann::json j = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) j.push_back(v(i));
  return j;
}

/// [[row 0], [row 1], ...] of any Eigen matrix.
template <class Derived>
nlohmann::json matrix_json(const Eigen::MatrixBase<Derived>& m) {
  nlohmann::json j = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    j.push_back(std::move(row));
  }
  return j;
}

/// The impulses of plan: [{"t_s", "dv_rsw_mps", "dv_eci_mps" (null when not set)}, ...],
/// the form of the plan file and of every planner's JSON.
nlohmann::json impulses_json(const BurnPlan& plan);

}  // namespace evade::config
