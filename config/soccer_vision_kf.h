// Soccer robot, fusion block (thesis section 4.2.1, Figure 4.2; the vision/radar paper's
// decentralised multi-rate Kalman filters, its section 4.1): the per-sensor filter of the
// 32 Hz omnivision position u, run at the encoder's fast rate (1 kHz), so that it has an
// estimate with a variance at every instant the fusion needs one. Between frames it
// predicts; a frame corrects it (the vision input is SAMPLED: Armesto's multi-rate sampler,
// the size-varying measurement of the paper's eq. (4)-(b)). It knows nothing of the
// encoder; config/soccer_fusion_cwa.h fuses its output with config/soccer_encoder_kf.h's.
//
// Model per field axis i in {x, y}: constant velocity, x = (p_x, p_y, v_x, v_y),
//   p' = p + v T,  v' = v + w,  w the white acceleration noise of density q [m^2/s^3]:
//   Q = q ((T^3/3, T^2/2), (T^2/2, T)) per axis (the exact discretisation).
// The robot's figure-eight (doc/bags.md) accelerates by up to about 0.35 m/s^2 and changes
// its acceleration over seconds. q = 0.02 m^2/s^3 is the best of the scan
// q = 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5 (position RMSE of this filter alone on
// soccer_seed1.bag, doc/fusion_block.md): smaller q smooths the noise better but lags the
// curves, larger follows the noise.
// R = 0.0112^2 m^2 (Wang et al. section VI, the simulator's vision noise).
// P0: position unknown on the field (10 m std), speed within 2 m/s.
//
// Clock input. The filter must predict at 1 kHz through a stretch of lost frames, so that
// its variance grows and the fusion turns to the encoder. Online /clock drives the node's
// schedule. The offline replay's clock advances only with the messages of the topics the
// header reads, and a gap of more than 100 periods is skipped with a single estimate
// (FusionCore::Options::maxCatchUpPeriods), which would freeze this filter's prediction
// through the gap. So the header also reads the encoder topic, as a control whose column
// of B is zero: its messages tick the replay's clock at 1 kHz, its values never enter the
// filter (x' = A x + 0 u), and the filter stays a filter of vision alone.
#include <geometry_msgs/PointStamped.h>
#include <sf_filter/config/diagonal.hpp>

#define SOCCER_VISION_Q 0.02
#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 1
#define STATE_TRANSITION_MATRIX \
  ((1)(0)(T)(0)) \
  ((0)(1)(0)(T)) \
  ((0)(0)(1)(0)) \
  ((0)(0)(0)(1))
#define OBSERVATION_MATRIX ((1)(0)(0)(0))((0)(1)(0)(0))
#define PROCESS_NOISE_COVARIANCE \
  ((SOCCER_VISION_Q * T * T * T / 3)(0)(SOCCER_VISION_Q * T * T / 2)(0)) \
  ((0)(SOCCER_VISION_Q * T * T * T / 3)(0)(SOCCER_VISION_Q * T * T / 2)) \
  ((SOCCER_VISION_Q * T * T / 2)(0)(SOCCER_VISION_Q * T)(0)) \
  ((0)(SOCCER_VISION_Q * T * T / 2)(0)(SOCCER_VISION_Q * T))
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((1.2544e-4)(1.2544e-4))
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((100)(100)(4)(4))
#define TOPICS_IN \
  ((vision/pose)(geometry_msgs::PointStamped)(point.x)) \
  ((vision/pose)(geometry_msgs::PointStamped)(point.y))
#define INPUT_ALIGNMENT ((0)(SAMPLED))((1)(SAMPLED))
#define TOPICS_IN_CTRL ((encoder/pose)(geometry_msgs::PointStamped)(point.z))
#define CONTROL_INPUT_MATRIX ((0))((0))((0))((0))
#define TOPICS_OUT \
  ((vision_kf/position/x)(0))((vision_kf/position/y)(1)) \
  ((vision_kf/velocity/x)(2))((vision_kf/velocity/y)(3))
