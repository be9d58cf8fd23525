// Pioneer 3-AT: the inputs of model nav1 (gyroscope, accelerometer) only averaged, for the
// comparison "from averaging to estimation" (thesis section 5.2.2, path "raw" of Fig. 5.6).
// Every period already averages the ~10 samples of each sensor into one value (temporal
// alignment, section 4.3.4); a window of 1 publishes that period average as it is. The path
// is computed offline with the transition eqs. 5.1-5.7 (tools/eval/evaluate.py
// --dead-reckoning a=x1,omega=x0), as the thesis did for "raw".
#define METHOD MOVING_AVERAGE
#include "pioneer/common.h"

#define WINDOW_SIZE 1
#define TOPICS_IN PIONEER_GYRO_INPUT PIONEER_ACCEL_INPUT
#define TOPICS_OUT ((average/angular_velocity)(0))((average/acceleration)(1))
