// EXPECT: QUATERNION_STATES is not supported by PARTICLE_FILTER_SIR yet
// Mistake: a particle filter with a quaternion (its particles and mean are flat vectors)
#define METHOD PARTICLE_FILTER_SIR
#include "valid_quaternions.h"
