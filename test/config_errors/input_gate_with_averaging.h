// EXPECT: INPUT_GATE needs the predicted measurement and innovation covariance of the filter
// Mistake: an averaging method has no innovation covariance
#include "alignment_base_averaging.h"

#define INPUT_GATE ((0)(9))
