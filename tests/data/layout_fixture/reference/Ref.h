#pragma once
#include "techniques/gl/Submitter.h"
#include "registry/Registry.h"
