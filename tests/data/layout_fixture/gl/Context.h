#pragma once
#include "core/Base.h"
#include "shading/Text.h"
