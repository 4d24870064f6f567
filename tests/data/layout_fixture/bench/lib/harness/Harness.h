#pragma once
#include "bench/lib/output/Rows.h"
#include "gl/backends/Egl.h"
#include "registry/Registry.h"
