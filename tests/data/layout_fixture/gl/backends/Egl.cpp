#include "gl/Context.h"
#include "core/Base.h"
#include "shading/Text.h"
