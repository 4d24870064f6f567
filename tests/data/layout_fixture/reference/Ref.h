#pragma once
#include "techniques/Technique.h"
