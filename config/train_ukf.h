// The moving train with a commanded acceleration (see train_kf.h), written as a nonlinear
// model for the UNSCENTED_KALMAN_FILTER; the same model as the Kalman filter's, so the results can be compared.
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float64.h>

#define METHOD UNSCENTED_KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(u[0])
#define OBSERVATION_MODEL (x[0])(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.001)(0))((0)(0.01))
#define MEASUREMENT_NOISE_COVARIANCE ((0.25)(0))((0)(0.04))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define UKF_ALPHA 1e-3
#define UKF_BETA 2
#define UKF_KAPPA 0
#define TOPICS_IN \
  ((train/velocity)(std_msgs::Float64)(data)) \
  ((train/acceleration)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_IN_CTRL ((train/command)(std_msgs::Float64)(data))
#define TOPICS_OUT ((train/estimate/velocity)(0))((train/estimate/acceleration)(1))
