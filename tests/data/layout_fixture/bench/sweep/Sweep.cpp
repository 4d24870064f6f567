#include "bench/lib/sweep/Plan.h"
#include "bench/lib/output/Rows.h"
#include "bench/figures/Fig.h"
