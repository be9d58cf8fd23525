// Configuration header used by test_config_model.cpp: the moving train of the thesis (section
// 2.2.1, configured in section 4.3.5) with state x = (velocity, acceleration), measured by a
// wheel encoder (velocity) and an accelerometer (acceleration along its y axis).
//
// The message types are small stand-ins with the members of std_msgs/Float32 and
// geometry_msgs/Vector3Stamped, so that the test builds without ROS message headers.
#pragma once

namespace sf_test_msgs {
struct Float32 {
  float data = 0.0f;
};
struct Vector3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct Vector3Stamped {
  Vector3 vector;
};
}  // namespace sf_test_msgs

// clang-format off
#define METHOD EXTENDED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(T))
#define MEASUREMENT_NOISE_COVARIANCE ((0.5)(0))((0)(0.2))
#define INITIAL_STATE (1)(0)
#define TOPICS_IN \
  ((velocity_wheel_left)(sf_test_msgs::Float32)(data)) \
  ((acceleration)(sf_test_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_estimate)(1))
// clang-format on
