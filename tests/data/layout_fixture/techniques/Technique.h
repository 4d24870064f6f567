#pragma once
#include "scenes/Scene.h"
#include "reference/Ref.h"
#include "techniques/gl/Submitter.h"
