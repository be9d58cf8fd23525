// Soccer robot, fusion block: the fused x position (config/soccer_fusion_cwa.h).
#define SOCCER_CWA_AXIS x
#include "soccer_fusion_cwa.h"
