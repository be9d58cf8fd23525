// Steps of the filters on a state layout with a rotation (issue 34: "the SO(3) EKF and UKF
// steps measured and listed", doc/benchmarks.md): the error-state EKF and UKF-M over
//  - attitude: the IMU attitude filter's model (unit quaternion + gyro bias, 7 stored numbers,
//    6 tangent), the gyro as control, one accelerometer direction per step;
//  - inertial3d: a 3D inertial navigation model (quaternion, position, velocity, gyro bias:
//    13 stored, 12 tangent), gyro and accelerometer as controls, a vision pose (position and
//    quaternion, compared on SO(3)) every step.
// One step is a predict and an update, as a node's period with a measurement. The measured
// values come from a precomputed constant-rate rotation, so that the filters stay near the
// truth and every step does the same work.
#include <vector>

#include <benchmark/benchmark.h>

#include <sf_estimation/attitude_filter.hpp>
#include <sf_estimation/manifold_extended_kalman_filter.hpp>
#include <sf_estimation/manifold_unscented_kalman_filter.hpp>

#include "support/allocation_counter.hpp"

namespace {

using estimation::Matrix;
using estimation::Vector;
namespace mf = estimation::manifold;

constexpr double kDt = 0.01;
constexpr int kSteps = 400;
const Eigen::Vector3d kRate(0.3, -0.2, 0.5);  // rad/s, body frame
const Eigen::Vector3d kGravity(0.0, 0.0, 9.81);

/// A sensor turning at kRate and moving on a circle-like path driven by a constant body
/// acceleration: the orientation, position and velocity at each step.
struct Motion {
  std::vector<Eigen::Quaterniond> q;
  std::vector<Eigen::Vector3d> p, v;
};

const Motion& motion() {
  static const Motion m = [] {
    Motion out;
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    Eigen::Vector3d p = Eigen::Vector3d::Zero(), v(1.0, 0.0, 0.0);
    const Eigen::Vector3d bodyAcceleration(0.0, 0.5, 0.0);
    for (int k = 0; k < kSteps; ++k) {
      out.q.push_back(q);
      out.p.push_back(p);
      out.v.push_back(v);
      const Eigen::Vector3d a = q * bodyAcceleration;
      p += v * kDt + 0.5 * a * kDt * kDt;
      v += a * kDt;
      q = mf::so3Plus<double>(q, Eigen::Vector3d(kRate * kDt));
    }
    return out;
  }();
  return m;
}

/// q, p, v, gyro bias; controls (gyro, accelerometer); noise (gyro, accelerometer, bias walk).
struct Inertial3d {
  using StateSpace = mf::StateLayout<mf::So3Block, mf::VectorBlock<9>>;
  using MeasurementSpace = mf::StateLayout<mf::VectorBlock<3>, mf::So3Block>;
  static constexpr int NoiseSize = 9, ControlSize = 6;
  double dt = kDt;

  template <class S>
  void transition(const Eigen::Matrix<S, 13, 1>& x, const Vector<6>& u,
                  const Eigen::Matrix<S, 9, 1>& w, Eigen::Matrix<S, 13, 1>& next) const {
    const mf::Quaternion<S> q = mf::storedQuaternion(x.template head<4>());
    const mf::Vector3<S> rate = u.head<3>().cast<S>() - x.template tail<3>() + w.template head<3>();
    const mf::Vector3<S> force = u.tail<3>().cast<S>() + w.template segment<3>(3);
    const mf::Vector3<S> a = mf::so3Rotate<S>(q, force) - kGravity.cast<S>();
    auto head = next.template head<4>();
    mf::storeQuaternion<S>(mf::so3Plus<S>(q, mf::Vector3<S>(rate * S(dt))), head);
    next.template segment<3>(4) =
        x.template segment<3>(4) + x.template segment<3>(7) * S(dt) + a * S(0.5 * dt * dt);
    next.template segment<3>(7) = x.template segment<3>(7) + a * S(dt);
    next.template tail<3>() = x.template tail<3>() + w.template tail<3>() * S(dt);
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 13, 1>& x, Eigen::Matrix<S, 7, 1>& z) const {
    z.template head<3>() = x.template segment<3>(4);
    z.template tail<4>() = x.template head<4>();
  }
};

struct AttitudeCase {
  using Model = estimation::AttitudeModel;
  static Vector<7> start() {
    Vector<7> x = Vector<7>::Zero();
    x(0) = 1.0;
    return x;
  }
  static Matrix<6, 6> P0() { return 0.01 * Matrix<6, 6>::Identity(); }
  static Matrix<6, 6> Q() { return 1e-4 * Matrix<6, 6>::Identity(); }
  static Matrix<3, 3> R() { return 0.0025 * Matrix<3, 3>::Identity(); }
  static Vector<4> control(int) {
    Vector<4> u;
    u << kRate, kDt;
    return u;
  }
  static Vector<3> measurement(int k) {
    return mf::so3RotateInverse<double>(motion().q[k], Eigen::Vector3d::UnitZ());
  }
};

struct Inertial3dCase {
  using Model = Inertial3d;
  static Vector<13> start() {
    Vector<13> x = Vector<13>::Zero();
    x(0) = 1.0;
    x(7) = 1.0;  // the motion's initial velocity
    return x;
  }
  static Matrix<12, 12> P0() { return 0.01 * Matrix<12, 12>::Identity(); }
  static Matrix<9, 9> Q() { return 1e-4 * Matrix<9, 9>::Identity(); }
  static Matrix<6, 6> R() { return 1e-4 * Matrix<6, 6>::Identity(); }
  static Vector<6> control(int k) {
    Vector<6> u;
    u << kRate, mf::so3RotateInverse<double>(motion().q[k], kGravity) + Eigen::Vector3d(0, 0.5, 0);
    return u;
  }
  static Vector<7> measurement(int k) {
    const Eigen::Quaterniond& q = motion().q[k + 1 < kSteps ? k + 1 : k];
    Vector<7> z;
    z << motion().p[k + 1 < kSteps ? k + 1 : k], q.w(), q.x(), q.y(), q.z();
    return z;
  }
};

template <template <class> class Filter, class Case>
void ManifoldStep(benchmark::State& state) {
  using F = Filter<typename Case::Model>;
  F filter(typename Case::Model{}, Case::Q(), Case::R(), Case::start(), Case::P0());
  int k = 0;
  std::size_t resetAllocations = 0;
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    if (k == kSteps - 1) {  // end of the motion: start again, untimed
      state.PauseTiming();
      const std::size_t start = sf_bench::heapAllocations();
      filter.setBelief(Case::start(), Case::P0());
      k = 0;
      resetAllocations += sf_bench::heapAllocations() - start;
      state.ResumeTiming();
    }
    filter.predict(Case::control(k));
    filter.update(Case::measurement(k));
    ++k;
    benchmark::DoNotOptimize(filter.state().data());
    benchmark::ClobberMemory();
  }
  const auto allocations =
      static_cast<double>(sf_bench::heapAllocations() - before - resetAllocations);
  state.counters["allocs_per_step"] =
      benchmark::Counter(allocations, benchmark::Counter::kAvgIterations);
}

template <class Model>
using Ekf = estimation::ManifoldExtendedKalmanFilter<Model>;
template <class Model>
using Ukf = estimation::ManifoldUnscentedKalmanFilter<Model>;

void SO3_EKF_attitude_fixed(benchmark::State& s) { ManifoldStep<Ekf, AttitudeCase>(s); }
void SO3_UKF_attitude_fixed(benchmark::State& s) { ManifoldStep<Ukf, AttitudeCase>(s); }
void SO3_EKF_inertial3d_fixed(benchmark::State& s) { ManifoldStep<Ekf, Inertial3dCase>(s); }
void SO3_UKF_inertial3d_fixed(benchmark::State& s) { ManifoldStep<Ukf, Inertial3dCase>(s); }

}  // namespace

BENCHMARK(SO3_EKF_attitude_fixed);
BENCHMARK(SO3_UKF_attitude_fixed);
BENCHMARK(SO3_EKF_inertial3d_fixed);
BENCHMARK(SO3_UKF_inertial3d_fixed);
