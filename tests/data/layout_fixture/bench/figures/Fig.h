#pragma once
#include "bench/sweep/Sweep.h"
