// Soccer robot, fusion block (thesis section 4.2.1, Figure 4.2: fusion node 3 fusing the
// estimates of nodes 1 and 2 "by voting or averaging"; the vision/radar paper's weighted
// fusion of the per-sensor estimates, its section 4.3): confidence-weighted averaging of
// the position of one field axis from the vision filter (config/soccer_vision_kf.h) and the
// encoder filter (config/soccer_encoder_kf.h), each weighted by the inverse of the variance
// it publishes with its value (sf_msgs/OutputEntityStamped.variance):
//   p = (p_v / var_v + p_e / var_e) / (1 / var_v + 1 / var_e),  var = 1 / (1/var_v + 1/var_e).
// This is the optimal linear combination of two independent unbiased estimates; the two
// filters see different sensors, so their errors are independent.
//
// Included by soccer_cwa_x.h and soccer_cwa_y.h with SOCCER_CWA_AXIS set to x or y (the
// method has one output value, so each axis is its own node).
//
// Period 1 ms, the per-sensor filters' period. Both inputs are aligned by their header
// stamp (the end of the upstream filter's period), not by arrival: each upstream estimate
// then belongs to exactly one period of this node whatever the phase between the nodes'
// schedules and however the messages are delayed, and a period waits 1.5 ms for them
// (MAX_MEASUREMENT_LAG; offline the schedule starts 1.5 ms before the first estimate, so the
// stamps lie in the middle of its periods and the output refers to 0.5 ms after the
// inputs). An estimate arriving later than that is dropped and counted; the period then
// holds the input's last value (zero-order HOLD) with the variance R of this header: the
// held value is at most one period old, so R is about what the filters report, the vision
// filter's median position variance between frames on soccer_seed1.bag (4.7e-5 m^2) and
// the encoder filter's after some 15 s of drift (1e-2 m^2). The core cannot pass a held
// value's own variance on (doc/fusion_block.md).
#include <sf_msgs/OutputEntityStamped.h>
#include <sf_filter/config/diagonal.hpp>

#ifndef SOCCER_CWA_AXIS
#error "soccer_fusion_cwa.h: define SOCCER_CWA_AXIS (x or y) before including it"
#endif

#define METHOD CONFIDENCE_WEIGHTED_AVERAGING
#define ESTIMATION_PERIOD 1
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((5e-5)(1e-2))
#define TOPICS_IN \
  ((vision_kf/position/SOCCER_CWA_AXIS)(sf_msgs::OutputEntityStamped)(value)(variance)) \
  ((encoder_kf/position/SOCCER_CWA_AXIS)(sf_msgs::OutputEntityStamped)(value)(variance))
#define INPUT_ALIGNMENT ((0)(HOLD)(LAGRANGE)(0))((1)(HOLD)(LAGRANGE)(0))
#define ALIGN_BY_STAMP (0)(1)
#define MAX_MEASUREMENT_LAG 1.5
#define TOPICS_OUT ((fused/position/SOCCER_CWA_AXIS)(0))
