// Dead-reckoned states of a model: the states that no measurement reads and that no state a
// measurement depends on reads in its transition, such as a planar pose integrated from
// measured velocities. They carry no weight in a particle filter: its particles' values of them
// are integrals of each particle's own history, and after a few resamplings all particles share
// the history of a few ancestors, so the particles' mean of a dead-reckoned pose is the pose of a
// few random walkers (doc/estimation.md, "Shared dead reckoning").
//
// Found from the model's functions alone: each state is perturbed at a few points spread around
// the start and a state whose change moves no bit of an output at any of them is taken as not
// read by it. An output that is not a number at a point counts as read (the safe side: the state
// stays with the particles).
#pragma once

#include <cmath>
#include <random>

#include "sf_estimation/types.hpp"

namespace estimation {

namespace detail {

/// reads(r, c): output r of `evaluate` changed when state c was perturbed at any point.
template <int Outputs, int N, class Evaluate>
void markReads(Evaluate&& evaluate, const Vector<N>& x, Index outputs,
               Eigen::Matrix<bool, Outputs, N>& reads) {
  Vector<Outputs> base(outputs), moved(outputs);
  evaluate(x, base);
  Vector<N> perturbed = x;
  for (Index c = 0; c < x.size(); ++c) {
    perturbed(c) = x(c) + 0.37 + 0.1 * std::abs(x(c));
    evaluate(perturbed, moved);
    perturbed(c) = x(c);
    for (Index r = 0; r < outputs; ++r) {
      if (!(moved(r) == base(r))) reads(r, c) = true;
    }
  }
}

}  // namespace detail

/// Mask of the dead-reckoned states of `model` (see above), probed at four points x0 + s z
/// (z standard normal per entry, s = 0.5, 1, 2, 4 times max(1, |x0|)) with controls drawn the
/// same way. A deterministic seed: the same model always gives the same mask.
template <class Model>
Mask<Model::StateSize> deadReckonedStates(const Model& model, const Vector<Model::StateSize>& x0,
                                          Index controlSize) {
  constexpr int N = Model::StateSize, M = Model::MeasurementSize, L = Model::ControlSize;
  const Index n = x0.size(), m = model.measurementSize();
  Eigen::Matrix<bool, M, N> observed = Eigen::Matrix<bool, M, N>::Constant(m, n, false);
  Eigen::Matrix<bool, N, N> transitions = Eigen::Matrix<bool, N, N>::Constant(n, n, false);
  std::mt19937_64 engine(20261206);
  std::normal_distribution<double> normal;
  Vector<N> x(n);
  Vector<L> u(controlSize);
  for (const double scale : {0.5, 1.0, 2.0, 4.0}) {
    for (Index i = 0; i < n; ++i)
      x(i) = x0(i) + scale * std::max(1.0, std::abs(x0(i))) * normal(engine);
    for (Index i = 0; i < controlSize; ++i) u(i) = scale * normal(engine);
    detail::markReads<M, N>([&](const Vector<N>& s, Vector<M>& out) { model.observation(s, out); },
                            x, m, observed);
    detail::markReads<N, N>(
        [&](const Vector<N>& s, Vector<N>& out) { model.transition(s, u, out); }, x, n,
        transitions);
  }
  // Weighed: read by a measurement, or read by the transition of a weighed state.
  Mask<N> weighed = observed.colwise().any().transpose();
  for (bool grew = true; grew;) {
    grew = false;
    for (Index r = 0; r < n; ++r) {
      if (!weighed(r)) continue;
      for (Index c = 0; c < n; ++c) {
        if (transitions(r, c) && !weighed(c)) weighed(c) = grew = true;
      }
    }
  }
  return (!weighed.array()).matrix();
}

}  // namespace estimation
