// What every configuration header's translation unit includes that does not depend on the
// header: Eigen, ROS serialization, the common message types, the filters and the fusion
// core. sf_add_filter() precompiles this file once per package and force-includes it in each
// node's unit (doc/build_cost.md, "Precompiled prelude"), so that a rebuild after editing a
// header parses only the header and the code generated from it.
//
// Nothing here may read a configuration macro (METHOD, TOPICS_IN, ...): the prelude is
// included before the configuration header. The configuration layer (sf_filter/config/) is
// left out for that reason; the filters it chooses among come from the same list
// (sf_estimation/filters.hpp).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <std_msgs/Float32.h>
#include <std_msgs/Float64.h>

#include <sf_estimation/filters.hpp>

#include "sf_filter/core/fusion_engine_of.hpp"
#include "sf_filter/definition/input_state.hpp"
#include "sf_filter/definition/node_definition.hpp"
