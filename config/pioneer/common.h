// What every Pioneer 3-AT header of config/ shares (thesis chapter 5): the sensors and
// controls of Table 5.2, their variances (section 5.1.2), the effective skid-steer radius,
// the estimation period, the known start pose and the particle filter's seed.
//
// Layout: config/<variant>_<method>.h defines METHOD and includes pioneer/<variant>_model.h,
// which writes the variant's equations once for every method; the model header includes
// the state header of its state vector (full_state.h, velocity_state.h) or, for nav3red,
// this file directly. METHOD must come first: it selects the process noise (the particle
// filter has its own Q, section 5.1.2) and, for nav3red, the linear form of the KF.
#pragma once

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float32.h>
#include <sf_filter/config/diagonal.hpp>
#include <sf_filter/config/methods.hpp>

#ifndef METHOD
#error "config/pioneer: #define METHOD before including a Pioneer model header (it selects Q)"
#endif

// The thesis's default period (section 5.2.2). The models use T, so --estimation-period or
// ~estimation_period change it without editing a model.
#define ESTIMATION_PERIOD 100

// Effective radius R [m] of the skid-steer kinematics (section 5.1.2) and the wheel speeds
// it gives (eqs. 5.17-5.18, in mm/s) for the linear velocity v and the angular velocity omega.
#define PIONEER_RADIUS 0.3
#define PIONEER_WHEEL_OBSERVATION(v, omega) \
  (((v) - (omega) * PIONEER_RADIUS) * 1000)(((v) + (omega) * PIONEER_RADIUS) * 1000)

// Eqs. 5.1-5.3 (= 5.8-5.10), the first three rows of every model with a pose: x, y and theta
// advance by delta_s = x[4] along the heading and by omega = x[3] for one period T.
#define PIONEER_POSE_TRANSITION \
  (x[0] + x[4] * cos(x[2])) \
  (x[1] + x[4] * sin(x[2])) \
  (x[2] + x[3] * T)

// Particle filters weigh with every sensor variance times 1000. With the variances of
// section 5.1.2 the likelihood is far narrower than the spread the particle filter's Q gives
// the 700 particles in one period (wheels: 1.4 mm/s against 0.32 m/s; gyroscope: 0.013
// against 0.7 rad/s), so every period a single particle survived (the published variances
// were 1e-30) and a state that the sensors see only one period later (a, through v) was not
// estimated at all: in nav3, without controls to pull a back, the particle filter lost the
// track in 2 of 3 bags (final errors 89 m and 1391 m). Scaled by 1000, all alike as the
// thesis advises for R (5.2.5), the likelihood is as wide as the cloud and several particles
// survive (measured on the shipped bags: 300 to 3000 all keep the track; doc/pioneer.md).
#if METHOD == PARTICLE_FILTER_SIR
#define PIONEER_VARIANCE_SCALE 1000
#else
#define PIONEER_VARIANCE_SCALE 1
#endif

// Measurement inputs (one TOPICS_IN entry each) and their variances, the diagonal of R
// (section 5.1.2): gyroscope IMU-3000 (rad/s), accelerometer KXTF9 whose y axis is the
// robot's x axis (m/s^2), wheel speeds from rosaria (mm/s).
#define PIONEER_GYRO_INPUT ((angular_velocity)(geometry_msgs::Vector3Stamped)(vector.z))
#define PIONEER_GYRO_VARIANCE (0.00017 * PIONEER_VARIANCE_SCALE)
#define PIONEER_ACCEL_INPUT ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))
#define PIONEER_ACCEL_VARIANCE (0.25 * PIONEER_VARIANCE_SCALE)
#define PIONEER_WHEEL_INPUTS \
  ((velocity_wheel_left)(std_msgs::Float32)(data)) \
  ((velocity_wheel_right)(std_msgs::Float32)(data))
#define PIONEER_WHEEL_VARIANCE (2 * PIONEER_VARIANCE_SCALE)
// All four, in the order of the observation model eqs. 5.15-5.18, and their R.
#define PIONEER_ALL_INPUTS PIONEER_GYRO_INPUT PIONEER_ACCEL_INPUT PIONEER_WHEEL_INPUTS
#define PIONEER_ALL_INPUTS_R \
  SF_DIAGONAL((PIONEER_GYRO_VARIANCE)(PIONEER_ACCEL_VARIANCE)(PIONEER_WHEEL_VARIANCE) \
              (PIONEER_WHEEL_VARIANCE))

// Controls of the *ctrl variants: u[0] = cmd_vel.linear.x, u[1] = cmd_vel.angular.z.
#define PIONEER_CMD_VEL_CONTROLS \
  ((cmd_vel)(geometry_msgs::Twist)(linear.x)) \
  ((cmd_vel)(geometry_msgs::Twist)(angular.z))

// Outputs of the states that start with (x, y, theta, omega, delta_s, v): the pose as
// nav_msgs/Odometry and tf, and the velocities.
#define PIONEER_POSE_OUTPUTS \
  ((pose/x)(0))((pose/y)(1))((pose/theta)(2))((velocity/linear)(5))((velocity/angular)(3))
#define PIONEER_POSE_INDICES (0)(1)(2)
// theta (x[2]) is an angle: wrapped to (-pi, pi] after every step, averaged on the circle by
// the UKF and PF (doc/configuration.md, Angles). Every state with a pose declares it.
#define PIONEER_ANGLE_STATES (2)

// Known start pose. The robot starts on a marked position (section 5.1), so the models with
// a pose start at x = y = theta = 0 with a variance of 1e-4 (1 cm, 0.6 deg) on x, y and theta
// and 1 on the other state variables, which the sensors correct within a few periods. The
// default P0 = I would be wrong for the pose: no sensor ever measures x, y or theta, so their
// start variance never shrinks, and with theta at 1 rad^2 the UKF (and the particle filter)
// average cos(theta) over +-1 rad and shorten every step of the path (measured on
// bags/pioneer_seed1.bag: 1.48 m position RMSE for the nav3ctrl UKF, 0.06 m with this P0).
#define PIONEER_POSE_START_VARIANCE 1e-4

// Particle filters: a fixed seed, so that every replay gives the same particles
// (--seed or ~seed choose another).
#if METHOD == PARTICLE_FILTER_SIR
#define RANDOM_SEED 1
#endif
