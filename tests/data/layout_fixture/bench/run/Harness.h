#pragma once
#include "bench/output/Rows.h"
#include "gl/backends/Egl.h"
