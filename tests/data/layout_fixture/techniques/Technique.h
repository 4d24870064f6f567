#pragma once
#include "techniques/TechniqueInfo.h"
#include "reference/Ref.h"
#include "techniques/gl/Submitter.h"
