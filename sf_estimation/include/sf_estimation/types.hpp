// Eigen type aliases shared by every filter. Sizes are template parameters so the same
// algorithm runs on fixed-size types (no heap allocation) or on Eigen::Dynamic (the factory).
#pragma once

#include <Eigen/Core>

namespace estimation {

using Index = Eigen::Index;
constexpr int Dynamic = Eigen::Dynamic;

template <int Rows>
using Vector = Eigen::Matrix<double, Rows, 1>;

template <int Rows, int Cols>
using Matrix = Eigen::Matrix<double, Rows, Cols>;

/// Availability of each measurement entry (true = the sensor delivered a value this step).
template <int Rows>
using Mask = Eigen::Matrix<bool, Rows, 1>;

/// A flag per pair of measurement entries (covariances given for a step).
template <int Rows>
using PairMask = Eigen::Matrix<bool, Rows, Rows>;

/// Number of sigma points of the unscented transform for a state of size n.
constexpr int sigmaPointCount(int n) { return n == Dynamic ? Dynamic : 2 * n + 1; }

}  // namespace estimation
