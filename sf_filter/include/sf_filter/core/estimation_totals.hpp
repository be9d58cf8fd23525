// The fusion core's running totals of its estimation steps: kept by the core, copied into its
// statistics snapshot (fusion_statistics.hpp), and compared between two diagnostics reports
// (health.hpp). One struct, so that the three read the same fields.
#pragma once

#include <cstdint>

#include <sf_estimation/numerical_repairs.hpp>

namespace sf_filter {

struct EstimationTotals {
  std::uint64_t estimates = 0;  ///< successful estimator steps
  std::uint64_t estimationFailures = 0;
  std::uint64_t filterResets = 0;        ///< restarts after too many failed steps in a row
  std::uint64_t clockResets = 0;         ///< clock jumps backwards
  std::uint64_t nisFailures = 0;         ///< periods whose NIS could not be computed
  std::uint64_t controlNonFinite = 0;    ///< control values dropped as not finite
  estimation::NumericalRepairs repairs;  ///< by the filter, across its restarts
  double estimatorSeconds = 0.0;         ///< wall time in the estimator's steps
};

}  // namespace sf_filter
