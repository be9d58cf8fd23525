// Configuration header used by test_config_stamp_default_lag.cpp: an input aligned by stamp
// and no MAX_MEASUREMENT_LAG, which used to mean a lag of 0 ms (every value arriving after its
// period's end dropped as late); the default is now one estimation period.
#pragma once

namespace sf_test_stamp_lag_msgs {
struct Header {
  double stamp = 0.0;
};
struct Stamped {
  Header header;
  double x = 0.0;
};
}  // namespace sf_test_stamp_lag_msgs

// clang-format off
#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 25
#define STATE_TRANSITION_MATRIX ((1))
#define OBSERVATION_MATRIX ((1))
#define PROCESS_NOISE_COVARIANCE ((1e-4))
#define MEASUREMENT_NOISE_COVARIANCE ((0.1))
#define TOPICS_IN ((vision)(sf_test_stamp_lag_msgs::Stamped)(x))
#define TOPICS_OUT ((position)(0))
#define ALIGN_BY_STAMP (0)
// clang-format on
