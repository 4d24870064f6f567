#pragma once
#include "bench/lib/harness/Harness.h"
