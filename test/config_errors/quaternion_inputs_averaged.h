// EXPECT: QUATERNION_INPUTS: an INPUT_ALIGNMENT entry averages or extrapolates a measured quaternion's component
// Mistake: a quaternion component averaged over the period (q and -q would cancel)
#include "valid_quaternion_inputs.h"

#define INPUT_ALIGNMENT ((4)(AVERAGE))
