#include "techniques/alpha/Alpha.h"
#include "techniques/gl/Submitter.h"
#include "techniques/beta/Beta.h"

const char* kLit = "alpha/lit.frag";
const char* kScene = "common/scene.vert";
const char* kBorrowed = "beta/shade.frag";
// Drawn like "beta/shade.frag" (a comment names a shader: not a use)
