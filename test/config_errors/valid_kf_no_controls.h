// EXPECT: OK
// Linear Kalman filter without controls (B is n x 0).
#include "fake_msgs.h"

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((0)(1))
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define MEASUREMENT_NOISE_COVARIANCE ((0.2))
#define TOPICS_IN ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define TOPICS_OUT ((velocity)(0))((acceleration_filtered)(1))
