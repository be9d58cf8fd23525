// Translation unit of the configuration tests: the configuration header is given with
// -include <header>; this file plays the generated .cpp of the node and, when the configuration
// is usable, instantiates every generated template once.
#include <cmath>

#include <sf_filter/config/configuration.hpp>

#if SF_CONFIG_OK
#include <unsupported/Eigen/AutoDiff>

namespace {

template <class Model>
void exerciseModel() {
  constexpr int n = Model::StateSize;
  constexpr int m = Model::MeasurementSize;
  constexpr int l = Model::ControlSize;
  const Model model;
  Eigen::Matrix<double, n, 1> x = Eigen::Matrix<double, n, 1>::Zero();
  Eigen::Matrix<double, n, 1> next;
  Eigen::Matrix<double, l, 1> u = Eigen::Matrix<double, l, 1>::Zero();
  Eigen::Matrix<double, m, 1> z;
  model.transition(x, u, next);
  model.observation(x, z);
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, n, 1>>;
  Eigen::Matrix<AD, n, 1> ax = x.template cast<AD>();
  Eigen::Matrix<AD, n, 1> anext;
  Eigen::Matrix<AD, m, 1> az;
  model.transition(ax, u, anext);
  model.observation(ax, az);
  if constexpr (sf_config::kHasTransitionJacobian) {
    Eigen::Matrix<double, n, n> A;
    model.transitionJacobian(x, u, A);
  }
  if constexpr (sf_config::kHasObservationJacobian) {
    Eigen::Matrix<double, m, n> H;
    model.observationJacobian(x, H);
  }
}

[[maybe_unused]] void instantiateEverything() {
  const sf_config::Parameters p = sf_config::defaultParameters();
  static_cast<void>(p);
  sf_config::forEachInput([](auto in) {
    using In = decltype(in);
    const typename In::Message msg{};
    static_cast<void>(In::value(msg) + In::variance(msg));
    static_assert(In::first_same_topic <= In::index, "first_same_topic");
  });
  sf_config::forEachControl([](auto in) {
    using In = decltype(in);
    static_cast<void>(In::value(typename In::Message{}));
  });
  sf_config::forEachOutput([](auto out) { static_cast<void>(decltype(out)::state_index); });
  static_cast<void>(sf_config::defaultInputOptions());
#if METHOD == KALMAN_FILTER || METHOD == EXTENDED_KALMAN_FILTER || \
    METHOD == UNSCENTED_KALMAN_FILTER || METHOD == PARTICLE_FILTER_SIR
  exerciseModel<sf_config::Model>();
#endif
}

}  // namespace
#endif
