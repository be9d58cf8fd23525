// Configuration header used by test_config_linear.cpp: a KALMAN_FILTER for the train with the
// commanded acceleration as control input, a topic providing two inputs and a variance field.
#pragma once

namespace sf_test_linear_msgs {
struct Float64 {
  double data = 0.0;
};
struct TrainState {  // e.g. published by a train controller
  double velocity = 0.0;
  double velocity_variance = 0.0;
  float acceleration = 0.0f;
};
}  // namespace sf_test_linear_msgs

// clang-format off
#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 50
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define CONTROL_INPUT_MATRIX ((0.5 * T * T))((T))
#define OBSERVATION_MATRIX ((1)(0))((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((1e-4)(0))((0)(1e-3))
#define MEASUREMENT_NOISE_COVARIANCE ((0.1)(0)(0))((0)(0.2)(0))((0)(0)(0.3))
#define INITIAL_ERROR_COVARIANCE ((5)(0))((0)(5))
#define TOPICS_IN \
  ((train_state)(sf_test_linear_msgs::TrainState)(velocity)(velocity_variance)) \
  ((wheel_velocity)(sf_test_linear_msgs::Float64)(data)) \
  ((train_state)(sf_test_linear_msgs::TrainState)(acceleration))
#define TOPICS_IN_CTRL ((acceleration_command)(sf_test_linear_msgs::Float64)(data))
#define TOPICS_OUT ((velocity)(0))((acceleration)(1))
// clang-format on
