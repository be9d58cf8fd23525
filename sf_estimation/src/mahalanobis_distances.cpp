// The innovation likelihood terms (squared Mahalanobis distance, log det S) of a whole
// measurement vector for the measurement sizes 1..6 and the run-time size of the window filters
// (moving average, median, confidence-weighted averaging), compiled once
// (measurement_prediction.hpp).
#define SF_ESTIMATION_INSTANTIATING_MAHALANOBIS
#include "sf_estimation/measurement_prediction.hpp"

namespace estimation {
template InnovationLikelihood innovationLikelihood<1>(const MeasurementPrediction<1>&,
                                                      const Measurement<1>&);
template InnovationLikelihood innovationLikelihood<2>(const MeasurementPrediction<2>&,
                                                      const Measurement<2>&);
template InnovationLikelihood innovationLikelihood<3>(const MeasurementPrediction<3>&,
                                                      const Measurement<3>&);
template InnovationLikelihood innovationLikelihood<4>(const MeasurementPrediction<4>&,
                                                      const Measurement<4>&);
template InnovationLikelihood innovationLikelihood<5>(const MeasurementPrediction<5>&,
                                                      const Measurement<5>&);
template InnovationLikelihood innovationLikelihood<6>(const MeasurementPrediction<6>&,
                                                      const Measurement<6>&);
template InnovationLikelihood innovationLikelihood<Dynamic>(const MeasurementPrediction<Dynamic>&,
                                                            const Measurement<Dynamic>&);
}  // namespace estimation
