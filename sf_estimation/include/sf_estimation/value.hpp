// The values that flow in and out of an estimator (thesis section 4.3.3): a scalar with its
// variance and timestamp. Position in a collection is the value's identity: entry i of an
// Input is measurement z_i, entry i of an Output is state variable x_i.
#pragma once

#include <limits>
#include <ostream>
#include <vector>

#include <Eigen/Core>

namespace estimation {

class Value {
 public:
  Value() = default;
  Value(double value, double variance, double timestamp)
      : value_(value), variance_(variance), timestamp_(timestamp) {}

  double getValue() const { return value_; }
  double getVariance() const { return variance_; }
  /// Seconds; the library never interprets it, it is carried for the caller.
  double getTimestamp() const { return timestamp_; }

  void setValue(double value) { value_ = value; }
  void setVariance(double variance) { variance_ = variance; }
  void setTimestamp(double timestamp) { timestamp_ = timestamp; }

 private:
  double value_ = 0.0;
  double variance_ = 0.0;
  double timestamp_ = 0.0;
};

/// One measurement or control entry. A default-constructed InputValue is missing.
class InputValue : public Value {
 public:
  InputValue() = default;
  /// A present value whose noise is the filter's configured R(i,i).
  explicit InputValue(double value, double timestamp = 0.0) : Value(value, 0.0, timestamp), missing_(false) {}
  /// A present value with its own variance, used instead of R(i,i) for this step.
  InputValue(double value, double variance, double timestamp)
      : Value(value, variance, timestamp), missing_(false), varianceGiven_(true) {}

  static InputValue missing() { return InputValue(); }

  bool isMissing() const { return missing_; }
  bool hasVariance() const { return varianceGiven_; }
  void setMissing(bool missing) { missing_ = missing; }

 private:
  bool missing_ = true;
  bool varianceGiven_ = false;
};

/// One estimated entry: value and its variance (diagonal of the covariance).
class OutputValue : public Value {
 public:
  using Value::Value;
};

/// An ordered collection of values (the thesis's EstimatorInterface template).
template <class V>
class ValueCollection {
 public:
  ValueCollection() = default;
  explicit ValueCollection(std::vector<V> values) : values_(std::move(values)) {}

  void add(const V& value) { values_.push_back(value); }
  std::size_t size() const { return values_.size(); }
  const V& operator[](std::size_t i) const { return values_[i]; }
  V& operator[](std::size_t i) { return values_[i]; }
  typename std::vector<V>::const_iterator begin() const { return values_.begin(); }
  typename std::vector<V>::const_iterator end() const { return values_.end(); }

 private:
  std::vector<V> values_;
};

/// A measurement vector or a control vector.
using Input = ValueCollection<InputValue>;

/// An estimate: the state entries with their variances, plus the full covariance.
class Output : public ValueCollection<OutputValue> {
 public:
  Eigen::MatrixXd covariance;
};

inline std::ostream& operator<<(std::ostream& os, const Value& v) {
  return os << v.getValue() << " (var " << v.getVariance() << ")";
}

}  // namespace estimation
