#pragma once
#include <string>
#include <epoxy/gl.h>
#include "gl/Context.h"
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
