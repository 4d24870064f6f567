#pragma once
#include "bench/lib/sweep/Plan.h"
