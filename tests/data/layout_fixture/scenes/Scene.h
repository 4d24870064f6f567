#pragma once
#include "core/Base.h"
#include "gl/Context.h"
