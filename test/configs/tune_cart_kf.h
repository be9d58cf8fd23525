// Test configuration of the noise identification (test/robots/test_noise_tuning.py,
// doc/tuning.md): the cart of tools/sim/cart_sim.py, x = (position, speed), the discrete
// nearly-constant-velocity model, a position and a speed reading per period. Its Q is 10
// times the simulator's and its R a tenth of it, on purpose: --tune must find the
// simulator's values (Q = diag(4e-4, 1e-3), R = diag(2.5e-3, 2.5e-3)) from these.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 100
#define STATE_TRANSITION_MATRIX ((1)(T))((0)(1))
#define OBSERVATION_MATRIX ((1)(0))((0)(1))
#define PROCESS_NOISE_COVARIANCE ((4e-3)(0))((0)(1e-2))
#define MEASUREMENT_NOISE_COVARIANCE ((2.5e-4)(0))((0)(2.5e-4))
#define INITIAL_STATE (0)(0)
#define INITIAL_ERROR_COVARIANCE ((1)(0))((0)(1))
#define TOPICS_IN \
  ((cart/position)(geometry_msgs::PointStamped)(point.x)) \
  ((cart/speed)(geometry_msgs::Vector3Stamped)(vector.x))
#define TOPICS_OUT ((cart/estimate/position)(0))((cart/estimate/speed)(1))
