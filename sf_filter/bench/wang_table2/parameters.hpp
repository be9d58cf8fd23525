// Wang et al.'s simulation set-up (section V and footnotes 2-4), as sf_wang_table2 implements
// it. doc/wang_table2.md states which numbers come from the paper and which readings of it
// were needed; every such reading is marked "reading:" below.
#pragma once

#include <array>
#include <string>

namespace wang_table2 {

/// The vision noise levels of Table II's columns [m].
constexpr std::array<double, 5> kVisionStds = {0.010, 0.049, 0.099, 0.150, 0.202};

struct Parameters {
  // --- Sensors (section V) ---
  double encoderPeriod = 0.001;      ///< v at 1000 Hz; also the filters' period [s]
  double visionPeriod = 1.0 / 32.0;  ///< u at 32 Hz [s]
  /// sigma_b: stationary std of the bias b_x of eq. 1 [m/s] (reading: the paper writes m).
  double biasStd = 0.2;
  double biasTimeConstant = 100.0;  ///< T of the bias's low pass (eqs. 3, 4) [s]
  /// Spectral density of the white noise omega_x on the encoder's rate (eq. 1) [m^2/s].
  /// reading: the paper gives no value; see doc/wang_table2.md for how it was chosen.
  double encoderNoiseDensity = 0.017;
  /// reading: footnote 2's d is the distance of the backward difference that gives v' from
  /// the encoder positions, v'(k) = (v(k) - v(k - d)) / (d Delta_v).
  int differenceSteps = 5;

  // --- The robot's motion (reading: "similar to Fig. 1"; the paper gives no model) ---
  double speedStd = 1.0;           ///< stationary std of the speed [m/s]
  double speedTimeConstant = 2.0;  ///< correlation time of the speed [s]

  // --- Filters (footnotes 2-4; reading: Q is a spectral density, Q_d = Q Delta_v) ---
  double positionNoiseDensity = 0.5;  ///< Q(1,1), all three filters
  double biasNoiseDensity = 0.1;      ///< Q(2,2), all three filters
  double initialVariance = 0.1;       ///< P(0) = diag(0.1, 0.1), all three filters
  double kalmanR = 0.1;               ///< R_K, plain Kalman filter
  double holdR = 1.0;                 ///< R_m, multi-rate hold
  double fillR = 0.1;                 ///< R, filling
  int holdSamples = 5;                ///< N_m: stored samples of the hold (order N_m - 1)
  int fillSamples = 5;                ///< N: stored samples of the filling
  double omega = 0.001;               ///< omega of the filling [s]

  // --- Monte Carlo ---
  double duration = 30.0;  ///< simulated time per run [s]
  double warmup = 2.0;     ///< errors before this time are not counted [s]
};

/// What is wrong with the parameters, empty if nothing. (The filling's omega and N and
/// the hold's N_m are checked by the fusion core's own alignmentPolicyProblem.)
inline std::string parametersProblem(const Parameters& s) {
  if (!(s.warmup >= 0.0)) return "the warm-up must not be negative";
  if (!(s.duration > s.warmup)) return "the duration must be longer than the warm-up";
  if (s.differenceSteps < 1) return "the difference distance d must be at least 1";
  if (!(s.encoderNoiseDensity >= 0.0)) return "the encoder noise density must not be negative";
  if (!(s.speedStd >= 0.0)) return "the speed std must not be negative";
  return {};
}

}  // namespace wang_table2
