// libFuzzer target: EstimatorFactory and the filters behind IEstimator driven by arbitrary
// parameter maps (names, types, sizes, values including NaN, +-inf and extremes), models of
// several shapes, and sequences of steps, controls, resets and measurement predictions with
// missing, wrongly sized and non-finite entries.
//
// The contract checked: nothing but the documented EstimationError types leaves the library
// (any other exception aborts, which libFuzzer reports), no sanitizer report, no hang, and
// every accepted step returns finite values with variances that are not NaN.
//
// Built by sf_estimation/CMakeLists.txt with -DSF_ESTIMATION_FUZZ=ON (clang); run with
// sf_estimation/scripts/sanitizer_checks.py fuzz (doc/reliability.md).
#include <fuzzer/FuzzedDataProvider.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_adapter.hpp"
#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement_prediction.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using namespace estimation;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A contract violation: abort so that libFuzzer saves the input.
[[noreturn]] void violation(const char* what) {
  std::fprintf(stderr, "contract violation: %s\n", what);
  std::abort();
}

class Generator {
 public:
  explicit Generator(FuzzedDataProvider& in) : in_(in) {}

  bool flag() { return in_.ConsumeBool(); }
  int small(int lo, int hi) { return in_.ConsumeIntegralInRange(lo, hi); }

  /// Mostly moderate numbers, sometimes the values that break arithmetic.
  double number() {
    static const double special[] = {
        0.0,          1.0,      -1.0,  1e-300,           -1e-300,           1e300,
        -1e300,       4.9e-324, 1e154, 3.14159265358979, -3.14159265358979, 1e9,
        std::nan(""), kInf,     -kInf};
    if (in_.ConsumeIntegralInRange(0, 7) == 0) return in_.PickValueInArray(special);
    return in_.ConsumeFloatingPointInRange(-10.0, 10.0);
  }

  int integer() {
    static const int special[] = {0, 1, 2, 3, 5, 10, 50, 200, -1, INT_MAX, INT_MIN, 1000001};
    return in_.PickValueInArray(special);
  }

  /// A size near `expected` (mostly equal) so that most maps are accepted.
  Index sizeNear(Index expected) {
    return in_.ConsumeIntegralInRange(0, 5) != 0 ? expected : in_.ConsumeIntegralInRange(0, 5);
  }

  Eigen::MatrixXd matrix(Index rows, Index cols) {
    Eigen::MatrixXd a(rows, cols);
    for (Index i = 0; i < a.size(); ++i) a(i) = number();
    return a;
  }

  /// Mostly a valid covariance (B B^T + d I), sometimes an arbitrary matrix.
  Eigen::MatrixXd covariance(Index size) {
    const Index n = sizeNear(size);
    if (in_.ConsumeIntegralInRange(0, 4) == 0) return matrix(n, in_.ConsumeBool() ? n : size);
    Eigen::MatrixXd b(n, n);
    for (Index i = 0; i < b.size(); ++i) b(i) = in_.ConsumeFloatingPointInRange(-2.0, 2.0);
    const double diagonal = in_.PickValueInArray({0.0, 1e-12, 1e-3, 0.1, 1.0, 1e6});
    return b * b.transpose() + diagonal * Eigen::MatrixXd::Identity(n, n);
  }

  Eigen::VectorXd indices(Index bound) {
    Eigen::VectorXd v(in_.ConsumeIntegralInRange(0, 3));
    for (Index i = 0; i < v.size(); ++i) {
      v(i) = in_.ConsumeIntegralInRange(0, 7) == 0 ? number()
                                                   : in_.ConsumeIntegralInRange<int>(-1, bound);
    }
    return v;
  }

  /// Models of several shapes over coefficient matrices F (n x n) and G (m x n).
  FunctionModel model(Index n, Index m, Index l) {
    const Eigen::MatrixXd F = matrix(n, n), G = matrix(m, n);
    const Eigen::MatrixXd Bu = matrix(n, l);
    const int shape = in_.ConsumeIntegralInRange(0, 5);
    const bool withJacobians = in_.ConsumeIntegralInRange(0, 5) != 0;
    const Index declaredN = sizeNear(n), declaredM = sizeNear(m), declaredL = sizeNear(l);
    auto transition = [F, Bu, shape](const auto& x, const auto& u, auto& next) {
      using std::atan2;
      using std::cos;
      using std::exp;
      using std::sin;
      using std::sqrt;
      using std::tanh;
      for (Index i = 0; i < next.size() && x.size() > 0; ++i) {
        typename std::decay_t<decltype(x)>::Scalar s(0.0);
        for (Index j = 0; j < x.size() && j < F.cols(); ++j) s += F(i % F.rows(), j) * x(j);
        for (Index j = 0; j < u.size() && j < Bu.cols(); ++j) s += Bu(i % Bu.rows(), j) * u(j);
        switch (shape) {
          case 0:
            next(i) = s;
            break;
          case 1:
            next(i) = sin(s) + x(i % x.size());
            break;
          case 2:
            next(i) = s * s;
            break;
          case 3:
            next(i) = exp(s);
            break;
          case 4:
            next(i) = atan2(sin(s), cos(s));
            break;
          default:
            next(i) = tanh(s) + sqrt(x(i % x.size()) * x(i % x.size()) + 1e-9);
            break;
        }
      }
    };
    auto observation = [G, shape](const auto& x, auto& z) {
      using std::log;
      using std::sqrt;
      for (Index i = 0; i < z.size(); ++i) {
        typename std::decay_t<decltype(x)>::Scalar s(0.0);
        for (Index j = 0; j < x.size() && j < G.cols(); ++j) s += G(i % G.rows(), j) * x(j);
        if (shape == 2) {
          z(i) = sqrt(s);
        } else if (shape == 3) {
          z(i) = log(s);
        } else if (shape == 5) {
          z(i) = 1.0 / s;
        } else {
          z(i) = s;
        }
      }
    };
    if (n == 0 || m == 0 || F.rows() == 0 || G.rows() == 0 || (l > 0 && Bu.rows() == 0)) {
      // No coefficient to index: a model of zeros (still of the declared sizes).
      auto zeroTransition = [](const auto& x, const auto&, auto& next) {
        for (Index i = 0; i < next.size(); ++i)
          next(i) = typename std::decay_t<decltype(x)>::Scalar(0.0);
      };
      auto zeroObservation = [](const auto& x, auto& z) {
        for (Index i = 0; i < z.size(); ++i) z(i) = typename std::decay_t<decltype(x)>::Scalar(0.0);
      };
      return makeFunctionModel(declaredN, declaredM, declaredL, zeroTransition, zeroObservation);
    }
    FunctionModel model =
        makeFunctionModel(declaredN, declaredM, declaredL, transition, observation);
    if (!withJacobians) model.setJacobians({}, {});
    return model;
  }

  /// A parameter of the expected kind most of the time, of another kind sometimes.
  Parameter parameter(const std::string& name, Index n, Index m, Index l) {
    const int kind = in_.ConsumeIntegralInRange(0, 9);
    if (kind == 0) return integer();
    if (kind == 1) return number();
    if (kind == 2) return std::string("x");
    if (name == "model") return model(n, m, l);
    if (name == "A") return matrix(sizeNear(n), sizeNear(n));
    if (name == "B") return matrix(sizeNear(n), sizeNear(l));
    if (name == "H") return matrix(sizeNear(m), sizeNear(n));
    if (name == "Q" || name == "P0") return covariance(n);
    if (name == "R") return covariance(m);
    if (name == "x0") return Eigen::VectorXd(matrix(sizeNear(n), 1));
    if (name == "angle-states") return indices(n);
    if (name == "angle-measurements") return indices(m);
    if (name == "weights" || name == "variances") return Eigen::VectorXd(matrix(sizeNear(m), 1));
    if (name == "particles" || name == "seed" || name == "window-size" || name == "input-count") {
      return in_.ConsumeBool() ? in_.ConsumeIntegralInRange(1, 64) : integer();
    }
    return number();  // alpha, beta, kappa, resampling-threshold, unknown names
  }

  Input input(Index size) {
    Input values;
    const Index count = sizeNear(size);
    for (Index i = 0; i < count; ++i) {
      switch (in_.ConsumeIntegralInRange(0, 3)) {
        case 0:
          values.add(InputValue::missing());
          break;
        case 1:
          values.add(InputValue(number(), number(), number()));
          break;
        default:
          values.add(InputValue(number(), in_.ConsumeFloatingPointInRange(0.0, 100.0)));
          break;
      }
    }
    return values;
  }

  std::size_t remaining() const { return in_.remaining_bytes(); }

 private:
  FuzzedDataProvider& in_;
};

const std::vector<std::string> kNames = {"A",
                                         "B",
                                         "H",
                                         "Q",
                                         "R",
                                         "x0",
                                         "P0",
                                         "model",
                                         "alpha",
                                         "beta",
                                         "kappa",
                                         "particles",
                                         "seed",
                                         "resampling-threshold",
                                         "input-count",
                                         "window-size",
                                         "weights",
                                         "variances",
                                         "angle-states",
                                         "angle-measurements",
                                         "bogus"};

void checkOutput(const Output& out) {
  for (const OutputValue& v : out) {
    if (!std::isfinite(v.getValue())) violation("an accepted step returned a non-finite value");
    if (std::isnan(v.getVariance())) violation("an accepted step returned a NaN variance");
  }
  if (out.covariance.hasNaN()) violation("an accepted step returned a NaN covariance");
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

bool sameOutput(const Output& a, const Output& b) {
  if (a.size() != b.size() || a.covariance.rows() != b.covariance.rows() ||
      a.covariance.cols() != b.covariance.cols()) {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a[i].getValue(), b[i].getValue()) || !same(a[i].getVariance(), b[i].getVariance())) {
      return false;
    }
  }
  for (Index i = 0; i < a.covariance.size(); ++i) {
    if (!same(a.covariance(i), b.covariance(i))) return false;
  }
  return true;
}

/// The gate's path: the predicted measurement and Mahalanobis distances of the filters that
/// have one (the concrete types EstimatorFactory builds).
template <class Filter>
bool predict(IEstimator& estimator, Generator& g) {
  auto* adapter = dynamic_cast<EstimatorAdapter<Filter>*>(&estimator);
  if (adapter == nullptr) return false;
  const Filter& filter = adapter->filter();
  MeasurementPrediction<Dynamic> p;
  filter.predictMeasurement(p);
  const Index m = filter.measurementSize();
  if (p.mean.size() != m || p.covariance.rows() != m || p.noise.rows() != m) {
    violation("prediction of the wrong size");
  }
  Measurement<Dynamic> z(m);
  for (Index i = 0; i < m; ++i) {
    z.value(i) = g.number();
    z.available(i) = g.flag();
  }
  if (m > 0) {
    static_cast<void>(
        squaredMahalanobisDistance(p, g.small(0, static_cast<int>(m) - 1), g.number()));
  }
  z.validate(m);  // the caller's check before a distance
  static_cast<void>(squaredMahalanobisDistance(p, z));
  return true;
}

void run(FuzzedDataProvider& provider) {
  Generator g(provider);
  const std::vector<std::string>& methods = EstimatorFactory::methods();
  const std::string method =
      g.small(0, 15) == 0
          ? std::string("NoSuchMethod")
          : methods[static_cast<std::size_t>(g.small(0, static_cast<int>(methods.size()) - 1))];
  const Index n = g.small(0, 4), m = g.small(0, 4), l = g.small(0, 2);
  ParameterMap map;
  for (const std::string& name : kNames) {
    if (g.flag()) map[name] = g.parameter(name, n, m, l);
  }
  std::unique_ptr<IEstimator> estimator = EstimatorFactory::create(method, map);
  if (!estimator) violation("create() returned null");
  const Index measurements = static_cast<Index>(estimator->getLastEstimate().size());
  static_cast<void>(estimator->description());
  for (int step = 0; step < 48 && g.remaining() > 0; ++step) {
    try {
      switch (g.small(0, 7)) {
        case 0:
          estimator->setControlInput(g.input(l));
          break;
        case 1:
          estimator->reset();
          break;
        case 2:
          if (!predict<KalmanFilter<Dynamic, Dynamic, Dynamic>>(*estimator, g) &&
              !predict<ExtendedKalmanFilter<FunctionModel>>(*estimator, g) &&
              !predict<UnscentedKalmanFilter<FunctionModel>>(*estimator, g)) {
            predict<ParticleFilterSIR<FunctionModel>>(*estimator, g);
          }
          break;
        default: {
          const Output before = estimator->getLastEstimate();
          try {
            checkOutput(estimator->estimate(g.input(std::max<Index>(m, measurements))));
          } catch (const EstimationError&) {
            if (!sameOutput(before, estimator->getLastEstimate())) {
              violation("a refused step changed the estimate");
            }
          }
          break;
        }
      }
    } catch (const EstimationError&) {
      // Documented: the step was refused and the estimator is unchanged.
    }
    static_cast<void>(estimator->numericalRepairs());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider provider(data, size);
  try {
    run(provider);
  } catch (const estimation::EstimationError&) {
    // Documented error types (a refused parameter map): fine.
  }
  return 0;
}
