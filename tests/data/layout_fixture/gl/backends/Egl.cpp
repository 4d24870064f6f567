#include "gl/Context.h"
#include "core/Base.h"
