// Test fixture: includes another include (and one twice, which expands once).
#include "common/test_colors.glsl"
#include "common/test_colors.glsl"
