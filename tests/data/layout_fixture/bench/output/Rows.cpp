#include "core/Base.h"
#include "bench/run/Harness.h"
