#include "techniques/alpha/AlphaGL.h"
#include "techniques/gl/Submitter.h"
#include "scenes/Scene.h"
#include "techniques/beta/BetaGL.h"

const char* kLit = "alpha/lit.frag";
const char* kScene = "common/scene.vert";
const char* kBorrowed = "beta/shade.frag";
// Drawn like "beta/shade.frag" (a comment names a shader: not a use)
