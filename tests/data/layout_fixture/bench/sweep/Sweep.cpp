#include "bench/lib/harness/Harness.h"
#include "bench/output/Rows.h"
#include "bench/figures/Fig.h"
