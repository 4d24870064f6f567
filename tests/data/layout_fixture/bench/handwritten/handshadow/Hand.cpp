#include "scenes/Scene.h"
#include "gl/Context.h"
