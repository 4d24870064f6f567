#include "gl/Context.h"
#include "scenes/Scene.h"
