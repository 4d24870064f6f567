#include "core/Base.h"
#include "bench/lib/harness/Harness.h"
