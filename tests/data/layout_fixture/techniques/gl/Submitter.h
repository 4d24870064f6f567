#pragma once
#include "gl/Context.h"
#include "scenes/Scene.h"
#include "techniques/TechniqueInfo.h"
