// EXPECT: OK
// Sensor timeouts on inputs 0 and 3, a plausible range on input 2 (doc/reliability.md).
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT ((0)(500))((3)(1000.5))
#define INPUT_RANGE ((2)(-20)(20.5))((0)(-1e3)(1e3))
