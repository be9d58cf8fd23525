// Soccer robot, fusion block: the fused y position (config/soccer_fusion_cwa.h).
#define SOCCER_CWA_AXIS y
#include "soccer_fusion_cwa.h"
