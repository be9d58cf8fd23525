// Input extractor: roll, pitch and yaw of a unit quaternion (DERIVED_INPUTS ROLL, PITCH, YAW).
//
// The angles are the Z-Y-X (yaw-pitch-roll) Euler angles of ROS (REP 103, tf2's getRPY):
// the rotation is Rz(yaw) Ry(pitch) Rx(roll), roll and yaw in (-pi, pi], pitch in
// [-pi/2, pi/2]. The quaternion is normalised first (a zero or non-finite one gives NaN,
// which the fusion core drops and counts as not finite).
//
// Gimbal lock (pitch = +-pi/2, |R20| >= 1 - kGimbalTolerance): only yaw - roll (pitch +pi/2) or
// yaw + roll (pitch -pi/2) is defined. The whole angle is given to yaw and roll is 0, so that
// the heading a ground robot fuses stays continuous (tf2 does the opposite: yaw 0).
// ROS-free and header-only; unit-tested in test_extractors.cpp.
#pragma once

#include <cmath>
#include <limits>

namespace sf_config {
namespace extractors {

struct Quaternion {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
};

struct EulerAngles {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
};

/// |R20| above 1 - kGimbalTolerance counts as gimbal lock.
inline constexpr double kGimbalTolerance = 1e-12;

/// q / |q|; NaN components when |q| is zero or not finite.
inline Quaternion normalized(const Quaternion& q) {
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  return {q.x / norm, q.y / norm, q.z / norm, q.w / norm};
}

/// Roll, pitch and yaw of q (see above).
inline EulerAngles eulerAngles(const Quaternion& quaternion) {
  const Quaternion q = normalized(quaternion);
  // The rotation matrix entries that are needed.
  const double r00 = 1.0 - 2.0 * (q.y * q.y + q.z * q.z);
  const double r01 = 2.0 * (q.x * q.y - q.w * q.z);
  const double r10 = 2.0 * (q.x * q.y + q.w * q.z);
  const double r11 = 1.0 - 2.0 * (q.x * q.x + q.z * q.z);
  const double r20 = 2.0 * (q.x * q.z - q.w * q.y);
  const double r21 = 2.0 * (q.y * q.z + q.w * q.x);
  const double r22 = 1.0 - 2.0 * (q.x * q.x + q.y * q.y);
  EulerAngles a;
  if (!std::isfinite(r20)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  if (std::abs(r20) >= 1.0 - kGimbalTolerance) {
    // R = [[0, -sin(yaw -+ roll), .], [0, cos(yaw -+ roll), .], [-+1, 0, 0]].
    a.pitch = r20 < 0.0 ? M_PI / 2.0 : -M_PI / 2.0;
    a.roll = 0.0;
    a.yaw = std::atan2(-r01, r11);
  } else {
    a.pitch = std::asin(-r20);
    a.roll = std::atan2(r21, r22);
    a.yaw = std::atan2(r10, r00);
  }
  // atan2 gives [-pi, pi]; the configuration's angles are in (-pi, pi].
  if (a.roll <= -M_PI) a.roll += 2.0 * M_PI;
  if (a.yaw <= -M_PI) a.yaw += 2.0 * M_PI;
  return a;
}

/// The conjugate of a unit quaternion: its inverse rotation.
inline Quaternion conjugate(const Quaternion& q) { return {-q.x, -q.y, -q.z, q.w}; }

/// The product a b (the rotation b, then a).
inline Quaternion multiply(const Quaternion& a, const Quaternion& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
      a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

/// v rotated by the unit quaternion q (q v q*).
inline void rotate(const Quaternion& q, const double (&v)[3], double (&out)[3]) {
  const Quaternion p{v[0], v[1], v[2], 0.0};
  const Quaternion r = multiply(multiply(q, p), conjugate(q));
  out[0] = r.x;
  out[1] = r.y;
  out[2] = r.z;
}

}  // namespace extractors
}  // namespace sf_config
