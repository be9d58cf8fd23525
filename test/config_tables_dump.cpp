// Prints every table a configuration header generates (sizes, inputs, parameters, the
// observation model at fixed states, per-input options, frame alignment, derivations,
// covariance sources, angles, outputs) in a fixed text form: built once per header
// (-DSF_CONFIG_HEADER), so that two headers can be compared for identical generated tables
// (test/robots/test_input_records_replay.py compares an INPUTS header with its thesis-syntax
// original). The record names (kInputNames) are left out: only they may differ.
#include SF_CONFIG_HEADER
#include <sf_filter/config/configuration.hpp>
#include <sf_filter/config/frame_alignment.hpp>

#include <cstdio>
#include <string>

#include <Eigen/Core>

namespace {

void print(const char* name, double v) { std::printf("%s %.17g\n", name, v); }

void print(const char* name, const Eigen::MatrixXd& m) {
  std::printf("%s %ldx%ld", name, static_cast<long>(m.rows()), static_cast<long>(m.cols()));
  for (Eigen::Index i = 0; i < m.size(); ++i) std::printf(" %.17g", m(i));
  std::printf("\n");
}

void printSizesAndParameters() {
  std::printf("method %s n %d m %d l %d outputs %d\n", sf_config::kMethodName,
              sf_config::kStateSize, sf_config::kMeasurementSize, sf_config::kControlSize,
              sf_config::kOutputCount);
  const sf_config::Parameters p = sf_config::defaultParameters();
  print("period_ms", p.estimation_period_ms);
  print("Q", p.process_noise_covariance);
  print("R", p.measurement_noise_covariance);
  print("x0", p.initial_state);
  print("P0", p.initial_error_covariance);
  print("max_lag_ms", sf_config::kMaxMeasurementLagMs);
  std::printf("base_frame '%s'\n", std::string(sf_config::kBaseFrame).c_str());
  for (int i = 0; i < sf_config::kStateSize; ++i)
    std::printf("angle_state %d %d\n", i, sf_config::kAngleStates[i]);
}

/// The observation model at states whose entries are distinct non-round numbers.
void printObservations() {
#if defined(STATE_TRANSITION_MODEL)
  using Model = sf_config::Model;
  const Model model;
  for (int k = 0; k < 3; ++k) {
    Eigen::Matrix<double, Model::StateSize, 1> x;
    for (int i = 0; i < Model::StateSize; ++i) x(i) = 0.1 * (k + 1) * (i + 1) - 0.037 * k;
    Eigen::Matrix<double, Model::MeasurementSize, 1> z;
    model.observation(x, z);
    print("h(x)", Eigen::MatrixXd(z));
  }
#endif
}

void printInputs() {
  const auto options = sf_config::defaultInputOptions();
  sf_config::forEachInput([&](auto in) {
    using In = decltype(in);
    using Align = sf_config::FrameAlignment<In::index>;
    using Derivation = sf_config::Derivation<In::index>;
    using Covariance = sf_config::CovarianceSource<In::index>;
    const auto& o = options[static_cast<std::size_t>(In::index)];
    std::printf(
        "input %d topic %s type %s field %s variance_field %s has_variance %d first %d "
        "owns %d stamp %d\n",
        In::index, std::string(In::topic).c_str(), std::string(In::message_type).c_str(),
        std::string(In::field).c_str(), std::string(In::variance_field).c_str(), In::has_variance,
        In::first_same_topic, In::owns_subscription, sf_config::kInputHasStamp[In::index]);
    std::printf("  options %s gate %.17g by_stamp %d timeout %.17g range %.17g %.17g angle %d\n",
                sf_filter::toString(o.alignment).c_str(), o.gateThreshold, o.alignByStamp,
                o.timeout, o.minimum, o.maximum, o.angle);
    if constexpr (Align::aligned) {
      std::printf("  aligned %s %s\n", std::string(Align::member).c_str(),
                  std::string(Align::axis_name).c_str());
    }
    std::printf("  derived %d quantity %d differential %d covariance %d\n", Derivation::derived,
                static_cast<int>(Derivation::quantity), Derivation::differential,
                Covariance::given);
  });
  sf_config::forEachOutput([](auto out) {
    using Out = decltype(out);
    std::printf("output %d %s %d\n", Out::index, std::string(Out::topic).c_str(), Out::state_index);
  });
}

}  // namespace

int main() {
  printSizesAndParameters();
  printObservations();
  printInputs();
  return 0;
}
