// EXPECT: OK
// valid_quaternions.h's attitude (QUATERNION_STATES (0), a gyro bias x[4..6]) that also reads
// the IMU's orientation as a measured quaternion (QUATERNION_INPUTS (3): TOPICS_IN entries 3..6
// are its w, x, y, z, compared on SO(3); R's w row zero, the rotation vector's rad^2 on x, y,
// z). The quaternion input cases include it (n = 7, m = 7).
#define SF_QUATERNION_EXTRA_ROWS (x[0])(x[1])(x[2])(x[3])
#define SF_QUATERNION_EXTRA_R (0)(1e-3)(1e-3)(1e-3)
#if !defined(SF_QUATERNION_EXTRA_TOPICS)
#define SF_QUATERNION_EXTRA_TOPICS \
  ((imu)(sensor_msgs::Imu)(orientation.w)) \
  ((imu)(sensor_msgs::Imu)(orientation.x)) \
  ((imu)(sensor_msgs::Imu)(orientation.y)) \
  ((imu)(sensor_msgs::Imu)(orientation.z))
#endif
#if !defined(SF_QUATERNION_INPUTS_CASE)
#define QUATERNION_INPUTS (3)
#endif
#if defined(SF_QUATERNION_STATES_CASE)
#define SF_QUATERNION_CASE
#endif
#include "valid_quaternions.h"
