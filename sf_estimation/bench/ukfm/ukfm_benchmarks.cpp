// UKF-M's two published benchmarks (Brossard, Barrau, Bonnabel 2020; the ukfm repository's
// docs/benchmarks), re-simulated with their set-ups and run through the library's filters:
//   2D: wheeled robot on a 5 m radius circle for 40 s, odometry (body velocity, gyro) at 100 Hz
//       with sigma 0.01 m/s and 1 deg/s, GPS at 1 Hz with sigma 1 m, initial heading error
//       drawn with sigma 45 deg (position known, P0 = diag(45 deg^2, 0, 0)); 100 runs. RMSE of
//       heading and position over all runs and steps, NEES of heading and of position (per
//       dimension) averaged over runs and over the steps after 20 s, as ukfm does.
//   3D: attitude for 100 s, gyro at 100 Hz with sigma 5 deg/s, accelerometer (sigma 0.4 m/s^2)
//       and magnetometer (sigma 0.3) at every step, 2 s at rest then 10 deg/s about gravity;
//       P0 = (10 deg)^2 I with the true initial attitude, as in ukfm's script; 100 runs. RMSE per
//       axis of the attitude error (ukfm's figure), NEES per dimension over all steps.
// Usage: sf_estimation_ukfm_benchmarks [runs [seed]] (default 100 runs, seed 1). doc/manifolds.md
// lists the output.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "../support/allocation_counter.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/manifold/se2.hpp"
#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/manifold_unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

namespace mf = estimation::manifold;
using estimation::Index;
using estimation::Matrix;
using estimation::Vector;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// ---------------------------------------------------------------- 2D localization ----------
constexpr double kDt2 = 0.01;
constexpr int kSteps2 = 4000;
constexpr int kGpsEvery = 100;
constexpr int kNeesFrom2 = 2000;  // after 20 s
const Vector<3> kOdometrySigma(0.01, 0.01, 1.0 * kDeg);
constexpr double kGpsSigma = 1.0;
constexpr double kHeadingSigma0 = 45.0 * kDeg;

/// ukfm's LOCALIZATION model: u = (v_x, v_y, gyro) in the body frame, noise w on u.
template <class Space>
struct Localization {
  using StateSpace = Space;
  using MeasurementSpace = mf::FlatLayout<2>;
  static constexpr int NoiseSize = 3, ControlSize = 3;
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<3>& u,
                  const Eigen::Matrix<S, 3, 1>& w, Eigen::Matrix<S, 3, 1>& next) const {
    const Eigen::Matrix<S, 2, 1> v = u.head<2>().cast<S>() + w.template head<2>();
    next(0) = mf::so2Plus<S>(x(0), (S(u(2)) + w(2)) * kDt2);
    next.template tail<2>() = x.template tail<2>() + mf::rotate2<S>(x(0), v) * kDt2;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = x.template tail<2>();
  }
};

/// The same model for the library's flat filters: additive noise in the state,
/// Q = dt^2 diag(sigma_gyro^2, sigma_v^2, sigma_v^2) exactly (sigma_v equal on both axes).
struct FlatLocalization {
  static constexpr int StateSize = 3, MeasurementSize = 2, ControlSize = 3;
  Index stateSize() const { return 3; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 3; }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<3>& u,
                  Eigen::Matrix<S, 3, 1>& next) const {
    next(0) = x(0) + S(u(2) * kDt2);
    next.template tail<2>() =
        x.template tail<2>() + mf::rotate2<S>(x(0), u.head<2>().cast<S>()) * kDt2;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = x.template tail<2>();
  }
};

struct Run2D {
  std::vector<Vector<3>> truth;     // theta, x, y at every step
  std::vector<Vector<3>> controls;  // noisy odometry of step n -> n + 1
  std::vector<Vector<2>> gps;       // at steps 0, 100, ...
  Vector<3> start;                  // the filters' initial state
};

Run2D simulate2D(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const double radius = 5.0, T = 40.0;
  const Vector<3> nominal(2.0 * kPi * radius / T, 0.0, 2.0 * kPi / T);
  Run2D run;
  run.truth.push_back(Vector<3>::Zero());
  const Localization<mf::StateLayout<mf::So2Block, mf::VectorBlock<2>>> model;
  for (int n = 1; n < kSteps2; ++n) {
    Vector<3> next;
    model.transition<double>(run.truth.back(), nominal, Vector<3>::Zero(), next);
    run.truth.push_back(next);
    Vector<3> noisy = nominal;
    for (int i = 0; i < 3; ++i) noisy(i) += kOdometrySigma(i) * normal(rng);
    run.controls.push_back(noisy);
  }
  for (int n = 0; n < kSteps2; n += kGpsEvery) {
    run.gps.push_back(run.truth[n].tail<2>() + kGpsSigma * Vector<2>(normal(rng), normal(rng)));
  }
  run.start = run.truth[0];
  run.start(0) = mf::wrap(run.start(0) + kHeadingSigma0 * normal(rng));
  return run;
}

/// Sums over runs and steps of the squared errors and the NEES terms.
struct Scores {
  std::string name;
  double headingSquares = 0.0, positionSquares = 0.0;
  double headingNees = 0.0, positionNees = 0.0;
  long count = 0, neesCount = 0;
  int failures = 0;             // runs a filter refused a step of (excluded)
  std::size_t allocations = 0;  // heap allocations inside the filter steps

  void add(int n, const Vector<3>& truth, const Vector<3>& estimate, const Matrix<3, 3>& P,
           double positionRotation) {
    const double eTheta = mf::so2Minus(truth(0), estimate(0));
    const Vector<2> eP = truth.tail<2>() - estimate.tail<2>();
    headingSquares += eTheta * eTheta;
    positionSquares += eP.squaredNorm();
    ++count;
    if (n < kNeesFrom2) return;
    // The position block in the world frame: an SE(2) filter's rho is in the body frame.
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(positionRotation).toRotationMatrix();
    const Eigen::Matrix2d Pp = R * P.bottomRightCorner<2, 2>() * R.transpose();
    headingNees += eTheta * eTheta / P(0, 0);
    positionNees += eP.dot(Pp.ldlt().solve(eP)) / 2.0;
    ++neesCount;
  }
  void print() const {
    std::printf("  %-34s %8.2f %8.2f %10.2f %10.2f %5d %11.3f\n", name.c_str(),
                std::sqrt(headingSquares / count) / kDeg, std::sqrt(positionSquares / count),
                headingNees / neesCount, positionNees / neesCount, failures,
                static_cast<double>(allocations) / count);
  }
};

/// Runs a filter with predict(u) and update(z) (the manifold filters) over one run.
template <class Filter>
void runManifold2D(Filter& filter, const Run2D& run, bool se2, Scores& scores) {
  Scores local = scores;
  try {
    for (int n = 0; n < kSteps2; ++n) {
      const std::size_t before = sf_bench::heapAllocations();
      if (n > 0) filter.predict(run.controls[n - 1]);
      if (n > 0 && n % kGpsEvery == 0) filter.update(run.gps[n / kGpsEvery]);
      local.allocations += sf_bench::heapAllocations() - before;
      local.add(n, run.truth[n], filter.state(), filter.covariance(),
                se2 ? filter.state()(0) : 0.0);
    }
  } catch (const std::exception&) {
    ++scores.failures;
    return;
  }
  scores = local;
}

/// The library's flat filters: estimate() is a time update and, when present, a correction.
template <class Filter>
void runFlat2D(Filter& filter, const Run2D& run, Scores& scores) {
  Scores local = scores;
  try {
    for (int n = 0; n < kSteps2; ++n) {
      if (n > 0) {
        const auto z = n % kGpsEvery == 0
                           ? estimation::Measurement<2>::complete(run.gps[n / kGpsEvery])
                           : estimation::Measurement<2>::missing();
        const std::size_t before = sf_bench::heapAllocations();
        filter.setControl(run.controls[n - 1]);
        filter.estimate(z);
        local.allocations += sf_bench::heapAllocations() - before;
      }
      local.add(n, run.truth[n], filter.state(), filter.covariance(), 0.0);
    }
  } catch (const std::exception&) {
    ++scores.failures;
    return;
  }
  scores = local;
}

void benchmark2D(int runs, unsigned seed) {
  using So2Space = mf::StateLayout<mf::So2Block, mf::VectorBlock<2>>;
  using Se2Space = mf::StateLayout<mf::Se2Block>;
  std::vector<Scores> scores(6);
  const char* names[] = {"flat UKF (UnscentedKalmanFilter)",
                         "flat EKF (ExtendedKalmanFilter)",
                         "SO(2) x R^2 UKF-M",
                         "SO(2) x R^2 error-state EKF",
                         "SE(2) UKF-M (body perturbation)",
                         "SE(2) error-state EKF"};
  for (int i = 0; i < 6; ++i) scores[i].name = names[i];
  const Matrix<3, 3> Qnoise = kOdometrySigma.array().square().matrix().asDiagonal();
  const Matrix<3, 3> Qflat = kDt2 * kDt2 * Qnoise;
  const Matrix<2, 2> R = kGpsSigma * kGpsSigma * Matrix<2, 2>::Identity();
  Matrix<3, 3> P0 = Matrix<3, 3>::Zero();
  P0(0, 0) = kHeadingSigma0 * kHeadingSigma0;
  const estimation::AngularComponents angles{{0}, {}};
  std::mt19937_64 rng(seed);
  for (int r = 0; r < runs; ++r) {
    const Run2D run = simulate2D(rng);
    estimation::UnscentedKalmanFilter<FlatLocalization> ukf(FlatLocalization(), Qflat, R, run.start,
                                                            P0, {}, angles);
    estimation::ExtendedKalmanFilter<FlatLocalization> ekf(FlatLocalization(), Qflat, R, run.start,
                                                           P0, angles);
    estimation::ManifoldUnscentedKalmanFilter<Localization<So2Space>> so2Ukf({}, Qnoise, R,
                                                                             run.start, P0);
    estimation::ManifoldExtendedKalmanFilter<Localization<So2Space>> so2Ekf({}, Qnoise, R,
                                                                            run.start, P0);
    // P0 has no position part, so that it is the same in the SE(2) chart.
    estimation::ManifoldUnscentedKalmanFilter<Localization<Se2Space>> se2Ukf({}, Qnoise, R,
                                                                             run.start, P0);
    estimation::ManifoldExtendedKalmanFilter<Localization<Se2Space>> se2Ekf({}, Qnoise, R,
                                                                            run.start, P0);
    runFlat2D(ukf, run, scores[0]);
    runFlat2D(ekf, run, scores[1]);
    runManifold2D(so2Ukf, run, false, scores[2]);
    runManifold2D(so2Ekf, run, false, scores[3]);
    runManifold2D(se2Ukf, run, true, scores[4]);
    runManifold2D(se2Ekf, run, true, scores[5]);
  }
  std::printf(
      "2D wheeled-robot localization, %d runs (ukfm: flat-state UKF 0.75 m / NEES 49, "
      "EKF 0.76 m / 275, SE(2) UKF 0.45 m / 1.0)\n",
      runs);
  std::printf("  %-34s %8s %8s %10s %10s %5s %11s\n", "filter", "head deg", "pos m", "NEES head",
              "NEES pos", "fail", "allocs/step");
  for (const Scores& s : scores) s.print();
}

// ---------------------------------------------------------------- 3D attitude --------------
constexpr double kDt3 = 0.01;
constexpr int kSteps3 = 10000;
const Vector<3> kGravity(0.0, 0.0, -9.82);
const Vector<3> kMagnetic(0.33, 0.0, -0.95);
constexpr double kGyroSigma = 5.0 * kDeg, kAccSigma = 0.4, kMagSigma = 0.3;

/// ukfm's ATTITUDE model: q' = q exp((gyro + w) dt); z = (R^T g, R^T b).
struct Attitude {
  using StateSpace = mf::StateLayout<mf::So3Block>;
  using MeasurementSpace = mf::FlatLayout<6>;
  static constexpr int NoiseSize = 3, ControlSize = 3;
  template <class S>
  void transition(const Eigen::Matrix<S, 4, 1>& x, const Vector<3>& u,
                  const Eigen::Matrix<S, 3, 1>& w, Eigen::Matrix<S, 4, 1>& next) const {
    const mf::Vector3<S> phi = (u.cast<S>() + w) * S(kDt3);
    mf::storeQuaternion(mf::so3Plus<S>(mf::storedQuaternion(x), phi), next);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 4, 1>& x, Eigen::Matrix<S, 6, 1>& z) const {
    const mf::Quaternion<S> q = mf::storedQuaternion(x);
    z.template head<3>() = mf::so3RotateInverse<S>(q, kGravity.cast<S>());
    z.template tail<3>() = mf::so3RotateInverse<S>(q, kMagnetic.cast<S>());
  }
};

struct Run3D {
  std::vector<Vector<4>> truth;
  std::vector<Vector<3>> gyro;
  std::vector<Vector<6>> measurements;
};

Run3D simulate3D(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const auto noise3 = [&](double sigma) {
    return Vector<3>(sigma * normal(rng), sigma * normal(rng), sigma * normal(rng));
  };
  const Attitude model;
  Run3D run;
  run.truth.push_back(Vector<4>(1.0, 0.0, 0.0, 0.0));
  double t = 0.0;
  for (int n = 1; n < kSteps3; ++n) {
    const Vector<3> rate = t > 2.0 ? Vector<3>(0.0, 0.0, 10.0 * kDeg) : Vector<3>::Zero();
    t += kDt3;
    Vector<4> next;
    model.transition<double>(run.truth.back(), rate, Vector<3>::Zero(), next);
    run.truth.push_back(next);
    run.gyro.push_back(rate + noise3(kGyroSigma));
  }
  for (int n = 0; n < kSteps3; ++n) {
    const mf::Quaternion<double> q = mf::storedQuaternion(run.truth[n]);
    Vector<6> z;
    z.head<3>() = mf::so3RotateInverse<double>(q, kGravity + noise3(kAccSigma));
    z.tail<3>() = mf::so3RotateInverse<double>(q, kMagnetic + noise3(kMagSigma));
    run.measurements.push_back(z);
  }
  return run;
}

struct Scores3D {
  std::string name;
  double squares = 0.0, nees = 0.0;
  long count = 0, neesCount = 0;
  int failures = 0;
  std::size_t allocations = 0;
};

template <class Filter>
void run3D(Filter& filter, const Run3D& run, Scores3D& scores) {
  Scores3D local = scores;
  try {
    for (int n = 0; n < kSteps3; ++n) {
      if (n > 0) {
        const std::size_t before = sf_bench::heapAllocations();
        filter.predict(run.gyro[n - 1]);
        filter.update(run.measurements[n]);
        local.allocations += sf_bench::heapAllocations() - before;
      }
      // Body-frame error: truth = estimate [+] e.
      const Vector<3> e = Attitude::StateSpace::minus<double>(run.truth[n], filter.state());
      local.squares += e.squaredNorm() / 3.0;
      ++local.count;
      if (n == 0) continue;
      local.nees += e.dot(filter.covariance().ldlt().solve(e)) / 3.0;
      ++local.neesCount;
    }
  } catch (const std::exception&) {
    ++scores.failures;
    return;
  }
  scores = local;
}

void benchmark3D(int runs, unsigned seed) {
  Scores3D ukf{"SO(3) UKF-M (body perturbation)"}, ekf{"SO(3) error-state EKF"};
  const Matrix<3, 3> Q = kGyroSigma * kGyroSigma * Matrix<3, 3>::Identity();
  Matrix<6, 6> R = Matrix<6, 6>::Zero();
  R.topLeftCorner<3, 3>() = kAccSigma * kAccSigma * Matrix<3, 3>::Identity();
  R.bottomRightCorner<3, 3>() = kMagSigma * kMagSigma * Matrix<3, 3>::Identity();
  const Matrix<3, 3> P0 = (10.0 * kDeg) * (10.0 * kDeg) * Matrix<3, 3>::Identity();
  std::mt19937_64 rng(seed + 1000);
  for (int r = 0; r < runs; ++r) {
    const Run3D run = simulate3D(rng);
    estimation::ManifoldUnscentedKalmanFilter<Attitude> u({}, Q, R, run.truth[0], P0);
    estimation::ManifoldExtendedKalmanFilter<Attitude> e({}, Q, R, run.truth[0], P0);
    run3D(u, run, ukf);
    run3D(e, run, ekf);
  }
  std::printf("\n3D attitude, %d runs (ukfm: RMSE 1.05 deg per axis, NEES about 1)\n", runs);
  std::printf("  %-34s %12s %8s %5s %11s\n", "filter", "RMSE deg/axis", "NEES", "fail",
              "allocs/step");
  for (const Scores3D* s : {&ukf, &ekf}) {
    std::printf("  %-34s %12.3f %8.2f %5d %11.3f\n", s->name.c_str(),
                std::sqrt(s->squares / s->count) / kDeg, s->nees / s->neesCount, s->failures,
                static_cast<double>(s->allocations) / s->count);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 100;
  const long seed = argc > 2 ? std::atol(argv[2]) : 1;
  if (runs <= 0 || seed < 0) {
    std::fprintf(stderr, "usage: %s [runs > 0 [seed >= 0]]\n", argv[0]);
    return 2;
  }
  std::printf("seed %ld\n", seed);
  benchmark2D(runs, static_cast<unsigned>(seed));
  benchmark3D(runs, static_cast<unsigned>(seed));
  return 0;
}
