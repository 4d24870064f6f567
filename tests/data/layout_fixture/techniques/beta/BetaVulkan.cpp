#include "techniques/beta/Beta.h"
#include "techniques/beta/BetaGL.h"
