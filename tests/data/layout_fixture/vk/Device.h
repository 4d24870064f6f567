#pragma once
#include "shading/Text.h"
#include "gl/Context.h"
