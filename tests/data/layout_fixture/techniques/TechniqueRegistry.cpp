#include "techniques/Technique.h"
#include "techniques/alpha/Alpha.h"
#include "techniques/beta/Beta.h"
#include "reference/Ref.h"
