// Soccer robot (Wang et al., "Filling the gap ...", sections II-B, III and VI): the
// Kalman filter of their reference [10] that fuses the 32 Hz omnivision position u with the
// 1000 Hz encoder-based position v of a Tech United middle-size-league robot. The two field
// axes are independent and identical; per axis i in {x, y} the state is
//   p_i  position on the field [m]
//   e_i  encoder position bias, e = v - p [m]: how far the encoder's position is off
//   b_i  bias of the encoder's rate [m/s], the b_x of their eq. (1)
// so x = (p_x, p_y, e_x, e_y, b_x, b_y).
//
// Model. Eq. (1), dv/dt = dp/dt + b + w, says de/dt = b + w; eqs. (3)-(4) make b white noise
// nu through the low pass 1/(1 + Tb s), db/dt = -b/Tb + nu/Tb, with Tb = 100 s (their T,
// footnotes 2-3). Discretised exactly over one period T:
//   p' = p + w_p                  the motion (see below)
//   e' = e + b T + w_e            eq. (1), Q_e = qw T
//   b' = a b + w_b, a = exp(-T/Tb) eq. (4), Q_b = sb^2 (1 - a^2) keeps var(b) at sb^2
// Observations: vision u = p (eq. for u: white noise, std 0.0112 m, section VI) and encoder
// v = p + e. Their KF takes dv/dt (differenced encoder positions) as the input that drives p;
// here v is an observation with a tiny R and p a random walk whose step covers the robot's
// motion in one period, which is the same filter in the limit and needs no differencing:
// every encoder sample fixes p + e to R_v, vision fixes p, and e and b are what vision and
// encoder disagree on, changing slowly. A lost vision frame or encoder sample is a missing
// input of the period, nothing more (their section VI-B).
//
// Numbers. R_u = 0.0112^2 (section VI). Tb = 100 s (footnotes). The paper gives no rate
// bias or white rate noise in the units of this model ("sigma_b around 0.2 m", section V),
// so sb = 0.006 m/s and qw = 0.04^2 * 0.001 m^2/s are those of the simulator
// (tools/sim/soccer_sim.py, doc/bags.md): tuned for the shipped bags; on a real robot take
// them from a recording. R_v = 1e-9 m^2 (0.03 mm, an encoder increment). The random walk of
// p allows 1.5 m/s (the robots reach 1.3 m/s in the bags) per period: Q_p = (1.5 T)^2.
// Their footnote-3 values (R = 0.1, Q = diag(0.5, 0.1)) belong to their scaling of the
// input-driven 2-state filter and are not used.
// P0: p unknown on the field (10 m std); e within 1 m (the encoder's odometry is reset to
// the field position, their Fig. 1); b at its stationary spread.
//
// Estimation period 1 ms, the encoder's rate (as their KF, which "runs state-update at the
// sampling frequency of v"): every encoder sample is its own observation. A longer period
// would average the encoder positions of the period, and the mean of a moving robot's
// positions lags the period's end by half a period (15 mm at 1.3 m/s for 1/32 s); one
// period's latency remains, 1 ms, 1.3 mm at most. Each step of this 6-state KF costs a few
// microseconds (doc/evaluation.md).
#include "soccer/encoder_error.h"

#define METHOD KALMAN_FILTER
#define ESTIMATION_PERIOD 1
#define STATE_TRANSITION_MATRIX SOCCER_TRANSITION_MATRIX
#define OBSERVATION_MATRIX \
  ((1)(0)(0)(0)(0)(0)) \
  ((0)(1)(0)(0)(0)(0)) \
  ((1)(0)(1)(0)(0)(0)) \
  ((0)(1)(0)(1)(0)(0))
#define PROCESS_NOISE_COVARIANCE SOCCER_PROCESS_NOISE((1.5 * T) * (1.5 * T))
#define MEASUREMENT_NOISE_COVARIANCE \
  SF_DIAGONAL((1.2544e-4)(1.2544e-4)(SOCCER_R_ENCODER)(SOCCER_R_ENCODER))
#define INITIAL_STATE (0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE SF_DIAGONAL((100)(100)(1)(1)(SOCCER_VAR_RATE_BIAS)(SOCCER_VAR_RATE_BIAS))
#define TOPICS_IN \
  ((vision/pose)(geometry_msgs::PointStamped)(point.x)) \
  ((vision/pose)(geometry_msgs::PointStamped)(point.y)) \
  ((encoder/pose)(geometry_msgs::PointStamped)(point.x)) \
  ((encoder/pose)(geometry_msgs::PointStamped)(point.y))
#define TOPICS_OUT \
  ((position/x)(0))((position/y)(1)) \
  ((encoder_bias/x)(2))((encoder_bias/y)(3)) \
  ((encoder_rate_bias/x)(4))((encoder_rate_bias/y)(5))
