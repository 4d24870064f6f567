#pragma once
#include "techniques/beta/Beta.h"
#include "techniques/gl/Submitter.h"
