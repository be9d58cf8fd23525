// config/nav1_ekf.h with ACCEL_OUT (doc/filter_node.md, "Published topics"): the Pioneer's full
// state holds the forward acceleration a = x[6], published on accel/filtered. Nothing else
// changes, so the replay's CSV is sf_nav1_ekf's to the byte (test/robots/test_accel_output.py).
#include "../../config/nav1_ekf.h"

#define ACCEL_OUT (6)
