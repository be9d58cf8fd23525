// Traits of METHOD PARTICLE_FILTER_SIR (thesis Algorithm 3.4): included once per pass by
// config/methods.hpp, which explains the passes. Its own macros: NUMBER_OF_PARTICLES,
// RANDOM_SEED, RESAMPLING_THRESHOLD, PF_SHARED_DEAD_RECKONING, PF_LINEARISED_PROPOSAL. The model's
// macros are checked for every model-based method by validation.hpp (SF_METHOD_KIND_MODEL).

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE
#if METHOD == PARTICLE_FILTER_SIR
#define SF_CFG_METHOD_NAME "PARTICLE_FILTER_SIR"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_MODEL
#endif
// Defaults of its own macros, for every method: sf_config::Parameters has them all.
#if defined(NUMBER_OF_PARTICLES)
#define SF_CFG_NUMBER_OF_PARTICLES (NUMBER_OF_PARTICLES)
#else
#define SF_CFG_NUMBER_OF_PARTICLES 1000
#endif
#if defined(RANDOM_SEED)
#define SF_CFG_RANDOM_SEED (RANDOM_SEED)
#else
#define SF_CFG_RANDOM_SEED 42
#endif
#if defined(RESAMPLING_THRESHOLD)
#define SF_CFG_RESAMPLING_THRESHOLD (RESAMPLING_THRESHOLD)
#else
#define SF_CFG_RESAMPLING_THRESHOLD 0.5
#endif
// Shared dead reckoning (estimation::ParticleFilterParameters::sharedDeadReckoning): on for a
// state with angles, whose pose is dead-reckoned in every shipped header and is otherwise the
// path of a few resampled ancestors (doc/estimation.md); off otherwise, so flat headers replay
// as before.
#if defined(PF_SHARED_DEAD_RECKONING)
#define SF_CFG_PF_SHARED_DEAD_RECKONING (PF_SHARED_DEAD_RECKONING)
#elif defined(ANGLE_STATES)
#define SF_CFG_PF_SHARED_DEAD_RECKONING 1
#else
#define SF_CFG_PF_SHARED_DEAD_RECKONING 0
#endif
// The linearised proposal (estimation::ParticleProposal::Linearised): off unless asked for.
#if defined(PF_LINEARISED_PROPOSAL)
#define SF_CFG_PF_LINEARISED_PROPOSAL (PF_LINEARISED_PROPOSAL)
#else
#define SF_CFG_PF_LINEARISED_PROPOSAL 0
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_PARAMETERS
// Its run-time parameters: type, name (member of sf_config::Parameters and FilterParameters,
// private ROS parameter ~name, entry of the replay's --params file), default without a
// configuration header, default of the header (SF_CFG_* above).
SF_METHOD_PARAMETER(int, number_of_particles, 1000, SF_CFG_NUMBER_OF_PARTICLES)
SF_METHOD_PARAMETER(unsigned, random_seed, 42, SF_CFG_RANDOM_SEED)
SF_METHOD_PARAMETER(double, resampling_threshold, 0.5, SF_CFG_RESAMPLING_THRESHOLD)
SF_METHOD_PARAMETER(bool, pf_shared_dead_reckoning, false, (SF_CFG_PF_SHARED_DEAD_RECKONING) != 0)
SF_METHOD_PARAMETER(bool, pf_linearised_proposal, false, (SF_CFG_PF_LINEARISED_PROPOSAL) != 0)

#elif SF_METHOD_PART == SF_METHOD_PART_TUNING
// Why the noise identification (tuning/noise_tuning.hpp) refuses it.
SF_METHOD_TUNING(PARTICLE_FILTER_SIR,
                 "the noise identification needs the innovation covariance S of a Kalman filter "
                 "(KF, EKF, UKF); the particle filter's likelihood is a Monte Carlo estimate that "
                 "changes with every draw: identify Q and R with the header's EKF or UKF and use "
                 "them here")

#elif SF_METHOD_PART == SF_METHOD_PART_UNUSED && METHOD != PARTICLE_FILTER_SIR
#if defined(NUMBER_OF_PARTICLES)
#pragma GCC warning "NUMBER_OF_PARTICLES is not used by the chosen METHOD and is ignored"
#endif
#if defined(RANDOM_SEED)
#pragma GCC warning "RANDOM_SEED is not used by the chosen METHOD and is ignored"
#endif
#if defined(RESAMPLING_THRESHOLD)
#pragma GCC warning "RESAMPLING_THRESHOLD is not used by the chosen METHOD and is ignored"
#endif
#if defined(PF_SHARED_DEAD_RECKONING)
#pragma GCC warning "PF_SHARED_DEAD_RECKONING is not used by the chosen METHOD and is ignored"
#endif
#if defined(PF_LINEARISED_PROPOSAL)
#pragma GCC warning "PF_LINEARISED_PROPOSAL is not used by the chosen METHOD and is ignored"
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_CHECKS && METHOD == PARTICLE_FILTER_SIR
#if defined(NUMBER_OF_PARTICLES)
static_assert(std::is_integral<decltype(NUMBER_OF_PARTICLES)>::value && (NUMBER_OF_PARTICLES) >= 1,
              "NUMBER_OF_PARTICLES: expected a positive integer, found '"
              SF_PP_STR(NUMBER_OF_PARTICLES) "'");
#endif
#if defined(RANDOM_SEED)
static_assert(std::is_integral<decltype(RANDOM_SEED)>::value && (RANDOM_SEED) >= 0,
              "RANDOM_SEED: expected a non-negative integer, found '" SF_PP_STR(RANDOM_SEED) "'");
#endif
#if defined(RESAMPLING_THRESHOLD)
static_assert((RESAMPLING_THRESHOLD) >= 0 && (RESAMPLING_THRESHOLD) <= 1,
              "RESAMPLING_THRESHOLD: expected a fraction of NUMBER_OF_PARTICLES between 0 and 1 "
              "(resample when the effective sample size drops below it), found '"
              SF_PP_STR(RESAMPLING_THRESHOLD) "'");
#endif
#if defined(PF_SHARED_DEAD_RECKONING)
static_assert((PF_SHARED_DEAD_RECKONING) == 0 || (PF_SHARED_DEAD_RECKONING) == 1,
              "PF_SHARED_DEAD_RECKONING: expected 1 (the states no measurement weighs carried as "
              "one Gaussian shared by the particles) or 0 (per particle), found '"
              SF_PP_STR(PF_SHARED_DEAD_RECKONING) "'");
#endif
#if defined(PF_LINEARISED_PROPOSAL)
static_assert((PF_LINEARISED_PROPOSAL) == 0 || (PF_LINEARISED_PROPOSAL) == 1,
              "PF_LINEARISED_PROPOSAL: expected 1 (draw each particle from the Kalman posterior "
              "of its prediction) or 0 (from the transition), found '"
              SF_PP_STR(PF_LINEARISED_PROPOSAL) "'");
#endif
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == PARTICLE_FILTER_SIR
#include <sf_estimation/particle_filter.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::ParticleFilterSIR<sf_config::Model>;
// Its step in the node's second unit (filter_binding.hpp).
#define SF_CFG_SECOND_UNIT_INSTANCES(PREFIX) \
  SF_ESTIMATION_PARTICLE_FILTER_STEP(PREFIX, sf_filter::generated::Filter)
template <class = void>  // see filter_binding.hpp
Filter makeFilter(const sf_config::Parameters& p) {
  estimation::ParticleFilterParameters pf;
  pf.particles = p.number_of_particles;
  pf.seed = p.random_seed;
  pf.resamplingThreshold = p.resampling_threshold;
  pf.sharedDeadReckoning = p.pf_shared_dead_reckoning;
  if (p.pf_linearised_proposal) pf.proposal = estimation::ParticleProposal::Linearised;
#if defined(POSE_OUT)
  // A published pose whose heading is an angle: its mean over the particles is taken on SE(2),
  // where poses spread along an arc average to a point of the arc (planar_pose_mean.hpp).
  if (sf_config::kAngleStates[BOOST_PP_SEQ_ELEM(2, POSE_OUT)]) {
    pf.planarPose = estimation::PlanarPoseIndices{BOOST_PP_SEQ_ELEM(0, POSE_OUT),
                                                  BOOST_PP_SEQ_ELEM(1, POSE_OUT),
                                                  BOOST_PP_SEQ_ELEM(2, POSE_OUT)};
  }
#endif
  return makeModelFilter<Filter>(p, pf);
}

}  // namespace generated
}  // namespace sf_filter
#endif
