// EXPECT: TOPICS_IN: expected a sequence of entries, each entry written as ((topic)(type)(field)) or ((topic)(type)(field)(variance_field)); found ''
// Mistake: TOPICS_IN defined without entries
#include "fake_msgs.h"

#define METHOD MOVING_MEDIAN
#define WINDOW_SIZE 5
#define TOPICS_IN
#define TOPICS_OUT ((median)(0))
