// Rauch-Tung-Striebel smoothing of the error-state EKF on a state layout
// (manifold_extended_kalman_filter.hpp): the backward pass of rts_smoother.hpp carried out in
// the tangent space. Per period, from the recorded belief (x_k, P_k) and the control u of the
// next time update, the filter's own prediction is re-derived,
//
//   x(k+1|k) = f(x_k, u, 0),  P(k+1|k) = F P_k F^T + G Q G^T,  C_k = P_k F^T
//
// (F, G the error-state Jacobians at x_k, as the filter took them), and the smoothed belief is
//
//   x_k^s = x_k [+] G_k (x_k+1^s [-] x(k+1|k)),  P_k^s = P_k + G_k (P_k+1^s - P(k+1|k)) G_k^T
//
// with G_k = C_k P(k+1|k)^-1 (rtsGain, rtsCorrect of rts_step.hpp on the tangent error, whose
// origin is the recorded mean). P_k+1^s lives in the tangent space at x_k+1^s and P(k+1|k) at
// x(k+1|k); the pass treats the two as one, as the filter treats the error before and after
// x [+] K nu as one (no reset Jacobian, manifold_extended_kalman_filter.hpp): the two spaces
// differ by the size of the correction. On a flat layout this is exactly the RTS smoother.
#pragma once

#include <utility>
#include <vector>

#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/rts_step.hpp"

namespace estimation {

template <class Model>
class ManifoldRtsSmoother {
  using Filter = ManifoldExtendedKalmanFilter<Model>;
  static constexpr int D = Filter::TangentSize, W = Filter::NoiseSize;
  using Space = typename Filter::StateSpace;

 public:
  using State = typename Filter::State;
  using Covariance = typename Filter::Covariance;
  using Control = typename Filter::Control;

  /// A period of the forward run: the belief after its step and the control of the time
  /// update that led to it; `predicted` false where the belief was set, not predicted.
  struct Period {
    State x;
    Covariance P;
    Control u;
    bool predicted = true;
    /// The belief `filter` holds now after a predict(u) (and its update, if any).
    static Period of(const Filter& filter, const Control& u, bool predicted = true) {
      return Period{filter.state(), filter.covariance(), u, predicted};
    }
  };
  struct Smoothed {
    State x;
    Covariance P;
  };

  ManifoldRtsSmoother(Model model, const typename Filter::ProcessNoise& Q)
      : model_(std::move(model)), Q_(Q) {}
  explicit ManifoldRtsSmoother(const Filter& filter)
      : ManifoldRtsSmoother(filter.model(), filter.processNoise()) {}

  /// Smooths `filtered` (time order) into `smoothed`; the last period and every period
  /// followed by a set belief keep their filtered belief. Throws NumericalError for an
  /// indefinite prediction or a non-finite result.
  void smooth(const std::vector<Period>& filtered, std::vector<Smoothed>& smoothed) const {
    smoothed.resize(filtered.size());
    if (filtered.empty()) return;
    smoothed.back() = Smoothed{filtered.back().x, filtered.back().P};
    for (std::size_t k = filtered.size() - 1; k-- > 0;) {
      const Period& now = filtered[k];
      if (!filtered[k + 1].predicted) {
        smoothed[k] = Smoothed{now.x, now.P};
        continue;
      }
      smoothed[k] = backwardStep(now, filtered[k + 1].u, smoothed[k + 1]);
    }
  }

 private:
  Smoothed backwardStep(const Period& now, const Control& u, const Smoothed& next) const {
    State predicted;
    Matrix<D, D> F;
    Matrix<D, W> G;
    Filter::transitionJacobiansAt(model_, now.x, u, predicted, F, G);
    // The prediction in the tangent space at x_k (origin: the recorded mean).
    OneStepPrediction<D> prediction(D);
    prediction.x.setZero();
    Covariance GQGt;
    GQGt.noalias() = G * Q_ * G.transpose();
    propagateCovariance<D>(F, now.P, GQGt, prediction.P);
    prediction.cross.noalias() = now.P * F.transpose();
    Matrix<D, D> gain;
    rtsGain<D>(prediction, gain);
    const Vector<D> difference = Space::template minus<double>(next.x, predicted);
    Vector<D> step;
    Smoothed out{now.x, now.P};
    rtsCorrect<D>(Vector<D>::Zero(), now.P, prediction, gain, difference, next.P, AngleMask<D>(),
                  step, out.P);
    out.x = Space::template plus<double>(now.x, step);
    return out;
  }

  Model model_;
  typename Filter::ProcessNoise Q_;
};

/// The smoother of an error-state EKF: a copy of its model and Q.
template <class Model>
ManifoldRtsSmoother<Model> smootherFor(const ManifoldExtendedKalmanFilter<Model>& filter) {
  return ManifoldRtsSmoother<Model>(filter);
}

}  // namespace estimation
