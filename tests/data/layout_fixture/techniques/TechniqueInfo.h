#pragma once
#include "scenes/Scene.h"
#include "shading/Text.h"
