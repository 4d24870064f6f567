#pragma once
#include "techniques/TechniqueInfo.h"
#include "shading/Text.h"
