// One estimation step of sf_estimation's fixed-size filters side by side with mherb/kalman
// (github.com/mherb/kalman, header-only, MIT; not shipped here: built only when
// SF_ESTIMATION_MHERB_KALMAN_INCLUDE names its include directory, doc/benchmarks.md). Both
// filter the same models on the same simulated drive (support/nav3_drive.hpp), compiled with
// the same flags in one program, so that --benchmark_enable_random_interleaving runs them in
// turn and the minimum over the repetitions ("_min") compares the least disturbed runs:
//   KF  nav3red   sf: KalmanFilter<3, 4, 2>;  mherb: its EKF with constant Jacobians (it has
//                 no linear KF)
//   EKF nav3ctrl  sf: automatic Jacobians (the model has none);  mherb: hand-written ones
//   EKF nav3red   sf: automatic Jacobians;  mherb: constant ones
//   UKF nav3ctrl  alpha 1e-3, beta 2, kappa 0 in both; mherb's update changed to redraw its
//                 sigma points from the predicted belief as sf does (as shipped it reuses the
//                 propagated ones and never corrects omega = u1)
// The counter state_gap is the largest difference between the two libraries' states after
// one pass over the drive (untimed): the models are the same, not just the sizes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <benchmark/benchmark.h>
#include <kalman/ExtendedKalmanFilter.hpp>
#include <kalman/LinearizedMeasurementModel.hpp>
#include <kalman/LinearizedSystemModel.hpp>
#include <kalman/UnscentedKalmanFilter.hpp>

#include "../support/nav3_drive.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using sf_bench::kPeriod;
using sf_bench::kRadius;

// -----------------------------------------------------------------------------
// The drive, as each library takes it.
// -----------------------------------------------------------------------------
struct Drive {
  std::vector<estimation::Vector<2>> controls;
  std::vector<estimation::Measurement<4>> measurements;  // sf
  std::vector<Kalman::Vector<double, 4>> readings;       // mherb
};

const Drive& drive() {
  static const Drive instance = [] {
    const sf_bench::Nav3Drive simulated = sf_bench::simulateNav3Drive();
    Drive d;
    d.controls = simulated.controls;
    for (const auto& z : simulated.readings) {
      d.measurements.push_back(estimation::Measurement<4>::complete(z));
      d.readings.emplace_back(z);
    }
    return d;
  }();
  return instance;
}

// -----------------------------------------------------------------------------
// The models in mherb/kalman's form.
// -----------------------------------------------------------------------------
template <int N>
using PeerState = Kalman::Vector<double, N>;
using PeerControl = Kalman::Vector<double, 2>;
using PeerReading = Kalman::Vector<double, 4>;

/// nav3ctrl's transition; F holds its constant entries from the start, updateJacobians()
/// sets the four that depend on the state.
struct PeerNav3Ctrl : Kalman::LinearizedSystemModel<PeerState<7>, PeerControl> {
  PeerNav3Ctrl() {
    F.setZero();
    F(0, 0) = F(1, 1) = F(2, 2) = F(5, 5) = 1.0;
    F(2, 3) = F(4, 5) = F(5, 6) = kPeriod;
    F(6, 5) = -1.0 / kPeriod;
  }
  PeerState<7> f(const PeerState<7>& x, const PeerControl& u) const override {
    PeerState<7> next;
    next(0) = x(0) + x(4) * std::cos(x(2));
    next(1) = x(1) + x(4) * std::sin(x(2));
    next(2) = x(2) + x(3) * kPeriod;
    next(3) = u(1);
    next(4) = x(5) * kPeriod;
    next(5) = x(5) + x(6) * kPeriod;
    next(6) = (u(0) - x(5)) / kPeriod;
    return next;
  }
  void updateJacobians(const PeerState<7>& x, const PeerControl&) override {
    const double c = std::cos(x(2)), s = std::sin(x(2));
    F(0, 2) = -x(4) * s;
    F(0, 4) = c;
    F(1, 2) = x(4) * c;
    F(1, 4) = s;
  }
};

/// nav3red's transition: linear, F constant.
struct PeerNav3Reduced : Kalman::LinearizedSystemModel<PeerState<3>, PeerControl> {
  PeerNav3Reduced() { F = estimation::models::Nav3Reduced{kPeriod, kRadius}.transitionMatrix(); }
  PeerState<3> f(const PeerState<3>& x, const PeerControl& u) const override {
    PeerState<3> next;
    next(0) = u(1);
    next(1) = x(1) + x(2) * kPeriod;
    next(2) = (u(0) - x(1)) / kPeriod;
    return next;
  }
};

/// Gyro, accelerometer and wheels from omega, v and a at the given indices: linear, H constant.
template <int N, int Omega, int Speed, int Acceleration>
struct PeerWheels : Kalman::LinearizedMeasurementModel<PeerState<N>, PeerReading> {
  PeerWheels() {
    this->H.setZero();
    this->H(0, Omega) = 1.0;
    this->H(1, Acceleration) = 1.0;
    this->H(2, Speed) = this->H(3, Speed) = 1000.0;
    this->H(2, Omega) = -1000.0 * kRadius;
    this->H(3, Omega) = 1000.0 * kRadius;
  }
  PeerReading h(const PeerState<N>& x) const override {
    PeerReading z;
    z(0) = x(Omega);
    z(1) = x(Acceleration);
    z(2) = (x(Speed) - x(Omega) * kRadius) * 1000.0;
    z(3) = (x(Speed) + x(Omega) * kRadius) * 1000.0;
    return z;
  }
};

/// mherb's UKF with the correction's sigma points drawn afresh from the predicted belief.
template <int N>
class RedrawingUkf : public Kalman::UnscentedKalmanFilter<PeerState<N>> {
  using Base = Kalman::UnscentedKalmanFilter<PeerState<N>>;

 public:
  using Base::Base;
  template <class Model>
  const PeerState<N>& update(const Model& m, const PeerReading& z) {
    this->computeSigmaPoints();
    return Base::update(m, z);
  }
};

/// A mherb filter with its models, stepped and reset like sf's.
template <class Filter, class System, class Sensor>
struct Peer {
  static constexpr int N = System::State::RowsAtCompileTime;
  Filter filter;
  System system;
  Sensor sensor;
  PeerControl u;

  template <class... FilterArgs>
  Peer(const estimation::Matrix<N, N>& Q, FilterArgs... args) : filter(args...) {
    system.setCovariance(Q);
    sensor.setCovariance(estimation::models::nav3MeasurementNoise());
    reset();
  }
  void reset() {
    filter.init(PeerState<N>::Zero());
    filter.setCovariance(estimation::Matrix<N, N>::Identity());
  }
  void setControl(const estimation::Vector<2>& control) { u = control; }
  void estimate(const PeerReading& z) {
    filter.predict(system, u);
    filter.update(sensor, z);
  }
  const PeerState<N>& state() const { return filter.getState(); }
};

// -----------------------------------------------------------------------------
// The timed loop, the same for both libraries.
// -----------------------------------------------------------------------------
template <class Filter>
void step(Filter& filter, const estimation::Vector<2>& u, const estimation::Measurement<4>& z) {
  filter.setControl(u);
  filter.estimate(z);
}

template <class F, class Sy, class Se>
void step(Peer<F, Sy, Se>& peer, const estimation::Vector<2>& u, const PeerReading& z) {
  peer.setControl(u);
  peer.estimate(z);
}

template <class Filter, class Readings>
void runSteps(benchmark::State& state, Filter& filter, const Readings& readings) {
  const Drive& d = drive();
  std::size_t k = 0;
  for (auto _ : state) {
    if (k == d.controls.size()) {  // end of the drive: start again, untimed
      state.PauseTiming();
      filter.reset();
      k = 0;
      state.ResumeTiming();
    }
    step(filter, d.controls[k], readings[k]);
    benchmark::DoNotOptimize(filter.state().data());
    benchmark::ClobberMemory();
    ++k;
  }
}

/// Runs both over the whole drive (untimed) and returns the largest difference of their states.
template <class Sf, class PeerFilter>
double stateGap(Sf sf, PeerFilter peer) {
  const Drive& d = drive();
  double gap = 0.0;
  for (std::size_t k = 0; k < d.controls.size(); ++k) {
    step(sf, d.controls[k], d.measurements[k]);
    step(peer, d.controls[k], d.readings[k]);
    gap = std::max(gap, (sf.state() - peer.state()).cwiseAbs().maxCoeff());
  }
  return gap;
}

// -----------------------------------------------------------------------------
// The filters.
// -----------------------------------------------------------------------------
using estimation::models::Nav3Ctrl;
using estimation::models::Nav3Reduced;
using KalmanEkf3 = Kalman::ExtendedKalmanFilter<PeerState<3>>;
using KalmanEkf7 = Kalman::ExtendedKalmanFilter<PeerState<7>>;
using PeerKf = Peer<KalmanEkf3, PeerNav3Reduced, PeerWheels<3, 0, 1, 2>>;
using PeerEkfCtrl = Peer<KalmanEkf7, PeerNav3Ctrl, PeerWheels<7, 3, 5, 6>>;
using PeerUkfCtrl = Peer<RedrawingUkf<7>, PeerNav3Ctrl, PeerWheels<7, 3, 5, 6>>;

const estimation::Matrix<3, 3> kReducedQ = estimation::models::nav3ReducedProcessNoise();
const estimation::Matrix<7, 7> kQ = estimation::models::nav3ProcessNoise();
const estimation::Matrix<4, 4> kR = estimation::models::nav3MeasurementNoise();
constexpr double kAlpha = 1e-3, kBeta = 2.0, kKappa = 0.0;  // sf's UnscentedParameters{}

estimation::KalmanFilter<3, 4, 2> sfKf() {
  const Nav3Reduced m{kPeriod, kRadius};
  return {m.transitionMatrix(), m.controlMatrix(), m.observationMatrix(), kReducedQ, kR};
}
estimation::ExtendedKalmanFilter<Nav3Ctrl> sfEkfCtrl() {
  return {Nav3Ctrl{kPeriod, kRadius}, kQ, kR};
}
estimation::ExtendedKalmanFilter<Nav3Reduced> sfEkfRed() {
  return {Nav3Reduced{kPeriod, kRadius}, kReducedQ, kR};
}
estimation::UnscentedKalmanFilter<Nav3Ctrl> sfUkfCtrl() {
  return {Nav3Ctrl{kPeriod, kRadius}, kQ, kR, estimation::Vector<7>::Zero(),
          estimation::Matrix<7, 7>::Identity()};
}
/// nav3ctrl and nav3red with hand-written Jacobians, as mherb's models have them (the heading's
/// four entries computed, the rest constant): the same model information on both sides. With
/// them sf's EKF evaluates f and h and copies the Jacobians instead of differentiating.
struct Nav3CtrlWithJacobians : Nav3Ctrl {
  Nav3CtrlWithJacobians() : Nav3Ctrl{kPeriod, kRadius} {
    F_.setZero();
    F_(0, 0) = F_(1, 1) = F_(2, 2) = F_(5, 5) = 1.0;
    F_(2, 3) = F_(4, 5) = F_(5, 6) = kPeriod;
    F_(6, 5) = -1.0 / kPeriod;
    H_.setZero();
    H_.col(3) << 1.0, 0.0, -1000.0 * kRadius, 1000.0 * kRadius;
    H_(1, 6) = 1.0;
    H_(2, 5) = H_(3, 5) = 1000.0;
  }
  void transitionJacobian(const estimation::Vector<7>& x, const estimation::Vector<2>&,
                          estimation::Matrix<7, 7>& A) const {
    const double c = std::cos(x(2)), s = std::sin(x(2));
    A = F_;
    A(0, 2) = -x(4) * s;
    A(0, 4) = c;
    A(1, 2) = x(4) * c;
    A(1, 4) = s;
  }
  void observationJacobian(const estimation::Vector<7>&, estimation::Matrix<4, 7>& H) const {
    H = H_;
  }
  estimation::Matrix<7, 7> F_;
  estimation::Matrix<4, 7> H_;
};
struct Nav3ReducedWithJacobians : Nav3Reduced {
  Nav3ReducedWithJacobians()
      : Nav3Reduced{kPeriod, kRadius}, A_(transitionMatrix()), H_(observationMatrix()) {}
  void transitionJacobian(const estimation::Vector<3>&, const estimation::Vector<2>&,
                          estimation::Matrix<3, 3>& A) const {
    A = A_;
  }
  void observationJacobian(const estimation::Vector<3>&, estimation::Matrix<4, 3>& H) const {
    H = H_;
  }
  estimation::Matrix<3, 3> A_;
  estimation::Matrix<4, 3> H_;
};
estimation::ExtendedKalmanFilter<Nav3CtrlWithJacobians> sfEkfCtrlJacobians() {
  return {Nav3CtrlWithJacobians(), kQ, kR};
}
estimation::ExtendedKalmanFilter<Nav3ReducedWithJacobians> sfEkfRedJacobians() {
  return {Nav3ReducedWithJacobians(), kReducedQ, kR};
}

PeerKf peerKf() { return PeerKf(kReducedQ); }
PeerEkfCtrl peerEkfCtrl() { return PeerEkfCtrl(kQ); }
PeerUkfCtrl peerUkfCtrl() { return PeerUkfCtrl(kQ, kAlpha, kBeta, kKappa); }

/// Registers <name>_sf and <name>_mherb, each with the minimum over repetitions.
template <class MakeSf, class MakePeer>
void registerPair(const char* name, MakeSf makeSf, MakePeer makePeer) {
  const auto minimum = [](const std::vector<double>& v) {
    return *std::min_element(v.begin(), v.end());
  };
  const double gap = stateGap(makeSf(), makePeer());
  benchmark::RegisterBenchmark((std::string(name) + "_sf").c_str(), [=](benchmark::State& state) {
    auto filter = makeSf();
    runSteps(state, filter, drive().measurements);
    state.counters["state_gap"] = gap;
  })->ComputeStatistics("min", minimum);
  benchmark::RegisterBenchmark((std::string(name) + "_mherb").c_str(),
                               [=](benchmark::State& state) {
                                 auto peer = makePeer();
                                 runSteps(state, peer, drive().readings);
                                 state.counters["state_gap"] = gap;
                               })
      ->ComputeStatistics("min", minimum);
}

}  // namespace

int main(int argc, char** argv) {
  registerPair("KF_nav3red", sfKf, peerKf);
  registerPair("EKF_nav3ctrl", sfEkfCtrl, peerEkfCtrl);
  registerPair("EKF_nav3red", sfEkfRed, peerKf);  // mherb's KF is its EKF
  registerPair("UKF_nav3ctrl", sfUkfCtrl, peerUkfCtrl);
  registerPair("EKF_nav3ctrl_jacobians", sfEkfCtrlJacobians, peerEkfCtrl);
  registerPair("EKF_nav3red_jacobians", sfEkfRedJacobians, peerKf);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
