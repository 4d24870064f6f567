#include "core/Base.h"
