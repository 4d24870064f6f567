#pragma once
#include <string>
#include <glm/glm.hpp>
