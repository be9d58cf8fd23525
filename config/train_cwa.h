// Confidence-weighted averaging of two speedometers of the train: each period's values are
// fused by the inverse of their variances (R's diagonal).
#include <std_msgs/Float64.h>

#define METHOD CONFIDENCE_WEIGHTED_AVERAGING
#define MEASUREMENT_NOISE_COVARIANCE ((0.25)(0))((0)(1.0))
#define TOPICS_IN \
  ((train/velocity)(std_msgs::Float64)(data)) \
  ((train/velocity_backup)(std_msgs::Float64)(data))
#define TOPICS_OUT ((train/fused/velocity)(0))
