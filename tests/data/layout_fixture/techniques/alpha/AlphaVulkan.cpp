#include "techniques/alpha/Alpha.h"
#include "techniques/vulkan/Pipeline.h"
#include "scenes/Scene.h"
