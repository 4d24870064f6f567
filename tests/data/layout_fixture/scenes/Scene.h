#pragma once
#include "core/Clean.h"
