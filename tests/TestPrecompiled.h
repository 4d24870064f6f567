// The headers nearly every test file parses, precompiled once per build (tests/CMakeLists.txt): the
// standard library, glm and googletest. Parsing them was about 3 s of each test file's compile at -O1,
// and the suite has about 120 test files in each of CI's two builds. Project headers stay out: a change
// to one of them would otherwise rebuild every test file, and a test of core/ alone would see bench/.
// Each test file still includes what it uses; this header only makes those includes cheap.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
