#pragma once
#include "techniques/TechniqueInfo.h"
