// Soccer robot, fusion block (thesis section 4.2.1, Figure 4.2; the vision/radar paper's
// decentralised filters): the per-sensor filter of the 1 kHz encoder position v alone.
// config/soccer_fusion_cwa.h fuses its output with config/soccer_vision_kf.h's.
//
// The encoder's error model is config/soccer_kf.h's (config/soccer/encoder_error.h): per axis
// the position p, the encoder's position error e = v - p and its rate bias b,
// x = (p_x, p_y, e_x, e_y, b_x, b_y), e' = e + b T + w_e, b' = a b + w_b, a = exp(-T/100 s).
// Without vision, e and b are not observable: the filter's position is the encoder's, and
// what it adds is the variance, which grows as the bias integrates,
//   var(p) ~ var(e(0)) + sb^2 t^2 + qw t,
// so that the fusion downstream can weight the encoder by how far it may have drifted.
// Numbers as in soccer_kf.h (sb = 0.006 m/s, qw = 1.6e-6 m^2/s, R_v = 1e-9 m^2), except
// two:
// - P0 of e: the encoder odometry is reset to the field position when the recording starts
//   (Wang et al. Fig. 1; doc/bags.md: e(0) = 0), so e(0) is known to 1 mm. soccer_kf.h can
//   leave e(0) open (1 m) because vision pins it down; here nothing would, and the encoder
//   would never get any weight.
// - The random walk of p: 1 m^2 per period instead of soccer_kf.h's (1.5 m/s x T)^2. With
//   only v = p + e observed, every encoder innovation is shared between p and e in the
//   ratio of their prior variances; with the small Q_p the growing variance of e took a
//   growing share of the robot's motion, and b learnt the robot's velocity as a rate bias
//   (on the first 10 s of soccer_seed1.bag e_y reached -0.41 m, and the position RMSE was
//   0.28 m against the raw encoder's 0.076 m). With Q_p = 1 m^2 the motion model of
//   p says nothing, each sample fixes p + e alone, e and b keep their prior means (0) and
//   only their variances grow, as they should without vision.
#include "soccer/encoder_error.h"

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 1
#define STATE_TRANSITION_MATRIX SOCCER_TRANSITION_MATRIX
#define OBSERVATION_MATRIX ((1)(0)(1)(0)(0)(0))((0)(1)(0)(1)(0)(0))
#define PROCESS_NOISE_COVARIANCE SOCCER_PROCESS_NOISE(1)
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((SOCCER_R_ENCODER)(SOCCER_R_ENCODER))
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((100)(100)(1e-6)(1e-6)(SOCCER_VAR_RATE_BIAS)(SOCCER_VAR_RATE_BIAS))
#define TOPICS_IN \
  ((encoder/pose)(geometry_msgs::PointStamped)(point.x)) \
  ((encoder/pose)(geometry_msgs::PointStamped)(point.y))
#define TOPICS_OUT ((encoder_kf/position/x)(0))((encoder_kf/position/y)(1))
