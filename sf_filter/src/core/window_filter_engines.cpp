// The fusion cores of the window filters (moving average, moving median, confidence-weighted
// averaging), compiled once here for every header that uses them (fusion_engine_of.hpp).
#define SF_FILTER_INSTANTIATING_WINDOW_FILTER_ENGINES
#include "sf_filter/core/fusion_engine_of.hpp"

namespace sf_filter {

template class FusionCore<estimation::MovingAverage>;
template class FusionCore<estimation::MovingMedian>;
template class FusionCore<estimation::ConfidenceWeightedAveraging>;
template class FusionEngineOf<estimation::MovingAverage>;
template class FusionEngineOf<estimation::MovingMedian>;
template class FusionEngineOf<estimation::ConfidenceWeightedAveraging>;

}  // namespace sf_filter
