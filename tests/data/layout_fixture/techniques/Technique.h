#pragma once
#include "scenes/Scene.h"
#include "reference/Ref.h"
#include "techniques/submit/Submitter.h"
