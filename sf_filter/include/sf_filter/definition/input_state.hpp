// What reading the inputs keeps from one message to the next, per node or replay run: the
// extractor objects (a differential input's previous pose, ...), the extractor kinds'
// parameters, the GPS inputs' datum and counters, and the messages whose covariance was
// unknown. The topic readers are given it beside the MessageSink, so that the sink stays the
// narrow interface of where values go, and a new run (a new InputState) starts anew.
// ROS-free and header-only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <sf_estimation/types.hpp>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/gps/gps_inputs.hpp"

namespace sf_filter {

class InputState {
 public:
  /// The extractor of input `input`, of kind Kind (config/extractors/kinds.hpp; one per input,
  /// created on first use).
  template <class Kind>
  Kind& extractor(estimation::Index input) {
    const auto i = static_cast<std::size_t>(input);
    if (extractors_.size() <= i) extractors_.resize(i + 1);
    if (!extractors_[i]) extractors_[i] = std::make_unique<Kind>();
    return static_cast<Kind&>(*extractors_[i]);  // an input is read by one kind only
  }
  /// Forgets the extractors' state, e.g. the previous poses of the differential inputs.
  void forgetExtractors() { extractors_.clear(); }

  /// The extractor kinds' private parameters given to the node or replay (defaults if not).
  sf_config::extractors::ParameterValues& extractorParameters() { return parameters_; }
  const sf_config::extractors::ParameterValues& extractorParameters() const { return parameters_; }

  /// Counts a message of `input` whose covariance was unknown (all zero or -1 first), so that
  /// the header's R was used.
  void countCovarianceFallback(estimation::Index input) {
    const auto i = static_cast<std::size_t>(input);
    if (covarianceFallbacks_.size() <= i) covarianceFallbacks_.resize(i + 1, 0);
    ++covarianceFallbacks_[i];
  }
  /// Messages of `input` whose unknown covariance fell back to the header's R.
  std::uint64_t covarianceFallbacks(estimation::Index input) const {
    const auto i = static_cast<std::size_t>(input);
    return i < covarianceFallbacks_.size() ? covarianceFallbacks_[i] : 0;
  }

  /// The GPS inputs' datum, yaw offset and counters (DERIVED_INPUTS EAST, NORTH, UP).
  gps::GpsInputs& gps() { return gps_; }
  const gps::GpsInputs& gps() const { return gps_; }

 private:
  std::vector<std::unique_ptr<sf_config::extractors::ExtractorState>> extractors_;
  sf_config::extractors::ParameterValues parameters_;
  std::vector<std::uint64_t> covarianceFallbacks_;
  gps::GpsInputs gps_;
};

}  // namespace sf_filter
