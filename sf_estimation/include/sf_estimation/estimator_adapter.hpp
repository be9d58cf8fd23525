// Wraps any filter of the library (fixed or dynamic size) behind IEstimator, converting the
// thesis's Input/Output collections to Eigen vectors and back.
//
// A filter class F used here provides:
//   static constexpr int StateSize, MeasurementSize, ControlSize;   (Eigen::Dynamic allowed)
//   Index stateSize() const, measurementSize() const, controlSize() const;
//   void setControl(const Vector<ControlSize>&);              throws InvalidInputError
//   void estimate(const Measurement<MeasurementSize>&);       strong exception guarantee
//   const Vector<StateSize>& state() const;
//   Matrix<StateSize, StateSize> covariance() const;          (or a const reference)
//   const Vector<ControlSize>& control() const;
//   void reset();
//   std::string description() const;
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/numerical_repairs.hpp"

namespace estimation {

template <class Filter>
class EstimatorAdapter : public IEstimator {
 public:
  static constexpr int N = Filter::StateSize;
  static constexpr int M = Filter::MeasurementSize;
  static constexpr int L = Filter::ControlSize;

  explicit EstimatorAdapter(Filter filter)
      : filter_(std::move(filter)), measurement_(filter_.measurementSize()) {
    fillOutput(0.0);
  }

  Output estimate(const Input& measurements) override {
    const Index m = filter_.measurementSize();
    if (static_cast<Index>(measurements.size()) != m) {
      throw InvalidInputError("input has " + std::to_string(measurements.size()) +
                              " measurements, " + filter_.description() + " expects " +
                              std::to_string(m));
    }
    double stamp = -std::numeric_limits<double>::infinity();
    for (Index i = 0; i < m; ++i) {
      const InputValue& in = measurements[static_cast<std::size_t>(i)];
      measurement_.available(i) = !in.isMissing();
      measurement_.value(i) = in.isMissing() ? 0.0 : in.getValue();
      measurement_.varianceGiven(i) = !in.isMissing() && in.hasVariance();
      measurement_.variance(i) = in.getVariance();
      if (!in.isMissing()) stamp = std::max(stamp, in.getTimestamp());
    }
    filter_.estimate(measurement_);
    fillOutput(std::isfinite(stamp) ? stamp : last_.size() ? last_[0].getTimestamp() : 0.0);
    return last_;
  }

  void setControlInput(const Input& controls) override {
    const Index l = filter_.controlSize();
    if (static_cast<Index>(controls.size()) != l) {
      throw InvalidInputError("input has " + std::to_string(controls.size()) + " controls, " +
                              filter_.description() + " expects " + std::to_string(l));
    }
    Vector<L> u = filter_.control();
    for (Index i = 0; i < l; ++i) {
      const InputValue& in = controls[static_cast<std::size_t>(i)];
      if (!in.isMissing()) u(i) = in.getValue();
    }
    filter_.setControl(u);
  }

  const Output& getLastEstimate() const override { return last_; }
  std::string description() const override { return filter_.description(); }
  void reset() override {
    filter_.reset();
    fillOutput(0.0);
  }
  NumericalRepairs numericalRepairs() const override {
    if constexpr (HasNumericalRepairs<Filter>::value) {
      return filter_.numericalRepairs();
    } else {
      return {};
    }
  }

  const Filter& filter() const { return filter_; }
  Filter& filter() { return filter_; }

 private:
  void fillOutput(double stamp) {
    const auto& x = filter_.state();
    Output out;
    out.covariance = filter_.covariance();
    for (Index i = 0; i < x.size(); ++i) out.add(OutputValue(x(i), out.covariance(i, i), stamp));
    last_ = std::move(out);
  }

  Filter filter_;
  Measurement<M> measurement_;
  Output last_;
};

}  // namespace estimation
