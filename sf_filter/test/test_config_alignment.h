// Configuration header used by test_config_alignment.cpp: a Kalman filter whose inputs use
// every alignment policy, two gates, alignment by stamp for the stamped inputs and a lag.
#pragma once

namespace sf_test_alignment_msgs {
struct Header {
  double stamp = 0.0;
};
struct Stamped {  // e.g. a vision fix
  Header header;
  double x = 0.0;
};
struct Plain {  // e.g. an encoder reading
  double data = 0.0;
};
}  // namespace sf_test_alignment_msgs

// clang-format off
#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 1
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))((0)(1))((1)(0))((1)(0))
#define PROCESS_NOISE_COVARIANCE ((1e-4)(0))((0)(1e-3))
#define MEASUREMENT_NOISE_COVARIANCE \
  ((0.1)(0)(0)(0)(0))((0)(0.2)(0)(0)(0))((0)(0)(0.3)(0)(0))((0)(0)(0)(0.4)(0))((0)(0)(0)(0)(0.5))
#define TOPICS_IN \
  ((vision)(sf_test_alignment_msgs::Stamped)(x)) \
  ((encoder)(sf_test_alignment_msgs::Plain)(data)) \
  ((encoder2)(sf_test_alignment_msgs::Plain)(data)) \
  ((gps)(sf_test_alignment_msgs::Stamped)(x)) \
  ((beacon)(sf_test_alignment_msgs::Stamped)(x))
#define TOPICS_OUT ((position)(0))
#define INPUT_ALIGNMENT \
  ((0)(FILL)(0.001)(5)(0.05)) \
  ((1)(HOLD)(BEZIER)(2)) \
  ((2)(LAST)) \
  ((3)(SAMPLED))
#define INPUT_GATE ((0)(9))((3)(6.63))
#define ALIGN_BY_STAMP (0)(3)
#define MAX_MEASUREMENT_LAG 40
// clang-format on
