// The primitive functions of Armesto et al.'s multi-rate holds (Table 1): from the newest
// n + 1 samples u(t_j), ..., u(t_{j-n}) (times not necessarily uniform) they extrapolate the
// signal to a time t > t_j.
//
//   Lagrange  u(t) = sum_l [ prod_{q != l} (t - t_{j-q}) / (t_{j-l} - t_{j-q}) ] u(t_{j-l})
//             the polynomial of degree n through the samples: reproduces any polynomial of
//             degree <= n exactly.
//   Bezier    u(t) = sum_l C(n, l) w1^(n-l) w2^l u(t_{j-l}),
//             w1 = 1 + s, w2 = -s, s = (t - t_j) / (t_j - t_{j-n})
//             the samples are the control points. The sign of w2 is Wang et al.'s eq. (10):
//             with it the weights sum to (w1 + w2)^n = 1, so a constant is held and a ramp
//             sampled uniformly is extrapolated exactly; Table 1 as extracted prints w2 = +s,
//             whose weights sum to (1 + 2s)^n and would amplify a constant.
//   Taylor    u(t) = sum_l (t - t_j)^l / l! u^(l)(t_j), the derivatives from backward
//             differences (eq. 2): u^(l)(t_j) = (u^(l-1)(t_j) - u^(l-1)(t_{j-1})) / (t_j -
//             t_{j-1}).
//
// Order 0 is the zero-order hold (u(t) = u(t_j)) and order 1 the first-order hold (the line
// through the two newest samples) for all three. With fewer than n + 1 samples stored the
// order drops to what the history allows (one sample: zero-order hold).
#pragma once

#include <array>
#include <iterator>
#include <string_view>

#include "sf_filter/core/alignment/sample_history.hpp"

namespace sf_filter {

enum class HoldPrimitive { Lagrange, Bezier, Taylor };

inline const char* toString(HoldPrimitive p) {
  static constexpr const char* kNames[] = {"LAGRANGE", "BEZIER", "TAYLOR"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(HoldPrimitive::Taylor) + 1,
                "one name per value");
  const auto i = static_cast<std::size_t>(p);
  return i < std::size(kNames) ? kNames[i] : "?";
}

/// The highest hold order the history can hold (kCapacity samples).
constexpr int kMaxHoldOrder = SampleHistory::kCapacity - 1;

/// sum_l C(n, l) w1^(n-l) w2^l P_l with P_l = point(l), l = 0..n (Wang et al., eq. 8).
template <class ControlPoint>
double bernsteinCombination(int n, double w1, double w2, ControlPoint point) {
  std::array<double, SampleHistory::kCapacity + 1> w1Power{}, w2Power{};
  w1Power[0] = w2Power[0] = 1.0;
  for (int l = 1; l <= n; ++l) {
    w1Power[static_cast<std::size_t>(l)] = w1Power[static_cast<std::size_t>(l - 1)] * w1;
    w2Power[static_cast<std::size_t>(l)] = w2Power[static_cast<std::size_t>(l - 1)] * w2;
  }
  double binomial = 1.0;  // C(n, l)
  double sum = 0.0;
  for (int l = 0; l <= n; ++l) {
    sum += binomial * w1Power[static_cast<std::size_t>(n - l)] *
           w2Power[static_cast<std::size_t>(l)] * point(l);
    binomial = binomial * (n - l) / (l + 1);
  }
  return sum;
}

namespace hold_detail {
/// The order actually used: `order`, limited by the samples stored. Requires !h.empty().
inline int usableOrder(const SampleHistory& h, int order) {
  return order < h.size() - 1 ? order : h.size() - 1;
}
}  // namespace hold_detail

/// Lagrange interpolation polynomial through the newest order + 1 samples, evaluated at t.
inline double lagrangeHold(const SampleHistory& h, int order, double t) {
  const int n = hold_detail::usableOrder(h, order);
  double sum = 0.0;
  for (int l = 0; l <= n; ++l) {
    double basis = 1.0;
    for (int q = 0; q <= n; ++q) {
      if (q != l) basis *= (t - h[q].time) / (h[l].time - h[q].time);
    }
    sum += basis * h[l].value;
  }
  return sum;
}

/// Bezier curve with the newest order + 1 samples as control points, evaluated at t.
inline double bezierHold(const SampleHistory& h, int order, double t) {
  const int n = hold_detail::usableOrder(h, order);
  if (n == 0) return h[0].value;
  const double s = (t - h[0].time) / (h[0].time - h[n].time);
  return bernsteinCombination(n, 1.0 + s, -s, [&h](int l) { return h[l].value; });
}

/// Taylor polynomial of degree `order` at the newest sample, derivatives by backward
/// differences, evaluated at t.
inline double taylorHold(const SampleHistory& h, int order, double t) {
  const int n = hold_detail::usableOrder(h, order);
  // difference[m] holds u^(l)(t_{j-m}) for m = 0..n-l while l runs up.
  std::array<double, SampleHistory::kCapacity> difference{};
  for (int m = 0; m <= n; ++m) difference[static_cast<std::size_t>(m)] = h[m].value;
  const double dt = t - h[0].time;
  double term = 1.0;  // (t - t_j)^l / l!
  double sum = difference[0];
  for (int l = 1; l <= n; ++l) {
    for (int m = 0; m <= n - l; ++m) {
      const auto k = static_cast<std::size_t>(m);
      difference[k] = (difference[k] - difference[k + 1]) / (h[m].time - h[m + 1].time);
    }
    term *= dt / l;
    sum += term * difference[0];
  }
  return sum;
}

/// The hold's value at t from the history (Algorithm 1, lines 7-10). Requires !h.empty().
inline double holdValue(HoldPrimitive primitive, const SampleHistory& h, int order, double t) {
  switch (primitive) {
    case HoldPrimitive::Lagrange:
      return lagrangeHold(h, order, t);
    case HoldPrimitive::Bezier:
      return bezierHold(h, order, t);
    case HoldPrimitive::Taylor:
      return taylorHold(h, order, t);
  }
  return h[0].value;
}

}  // namespace sf_filter
