#pragma once
#include "techniques/alpha/Alpha.h"
#include "techniques/gl/Submitter.h"
