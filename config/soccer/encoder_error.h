// The soccer robot's encoder error model (Wang et al. eqs. 1, 3, 4), shared by the
// centralised filter (config/soccer_kf.h, which explains the model and its numbers) and the
// fusion block's encoder filter (config/soccer_encoder_kf.h). Per field axis the position p,
// the encoder's position error e = v - p and its rate bias b; x = (p_x, p_y, e_x, e_y, b_x,
// b_y), e' = e + b T + w_e, b' = a b + w_b with a = exp(-T / Tb), Tb = 100 s.
#pragma once

#include <geometry_msgs/PointStamped.h>
#include <sf_filter/config/diagonal.hpp>

/// p' = p (a random walk), e' = e + b T, b' = a b.
#define SOCCER_TRANSITION_MATRIX \
  ((1)(0)(0)(0)(0)(0)) \
  ((0)(1)(0)(0)(0)(0)) \
  ((0)(0)(1)(0)(T)(0)) \
  ((0)(0)(0)(1)(0)(T)) \
  ((0)(0)(0)(0)(exp(-T / 100.0))(0)) \
  ((0)(0)(0)(0)(0)(exp(-T / 100.0)))
/// Variance of w_e per period: qw T with qw = 1.6e-6 m^2/s.
#define SOCCER_Q_ENCODER_ERROR (1.6e-6 * T)
/// Variance of w_b per period: sb^2 (1 - a^2) with sb = 0.006 m/s keeps var(b) at sb^2.
#define SOCCER_Q_RATE_BIAS (3.6e-5 * (1.0 - exp(-2.0 * T / 100.0)))
/// Stationary variance of b, sb^2 [m^2/s^2]: its initial variance.
#define SOCCER_VAR_RATE_BIAS 3.6e-5
/// Variance of an encoder position sample [m^2] (0.03 mm, an encoder increment).
#define SOCCER_R_ENCODER 1e-9
/// Q: the position's random walk q_p per period, then w_e and w_b of both axes.
#define SOCCER_PROCESS_NOISE(q_p) \
  SF_DIAGONAL((q_p)(q_p)(SOCCER_Q_ENCODER_ERROR)(SOCCER_Q_ENCODER_ERROR)(SOCCER_Q_RATE_BIAS) \
              (SOCCER_Q_RATE_BIAS))
