// EXPECT: OK
// Every policy, gates, stamps and a lag on a model-based filter
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT \
  ((0)(FILL)(0.001)(5)(0.1)) ((1)(HOLD)(TAYLOR)(2)) ((2)(LAST)) ((3)(SAMPLED))
#define INPUT_GATE ((0)(9.0))((3)(6.63))
#define ALIGN_BY_STAMP (0)(2)
#define MAX_MEASUREMENT_LAG 50
