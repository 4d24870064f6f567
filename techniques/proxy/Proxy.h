#pragma once
// `proxy`: analytic sphere, box and cylinder stand-ins for soft shadows and colour bleeding, after van der
// Spek, ShadowProxies (OpenGL Insights). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms
// both take: name, effects, the capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Proxy {
    static constexpr const char* kBleed = "bleed";
    static constexpr const char* kBleeding = "bleeding";
    static constexpr const char* kCapacity = "capacity";
    static constexpr const char* kCells = "cells";
    static constexpr const char* kCutoff = "cutoff";
    static constexpr const char* kExponentOn = "exponent_on";
    static constexpr const char* kFalloff = "falloff";
    static constexpr const char* kGrid = "grid";
    static constexpr const char* kModulate = "modulate";
    static constexpr const char* kOffset = "offset";
    static constexpr const char* kPenumbra = "penumbra";
    static constexpr const char* kProxies = "proxies";
    static constexpr const char* kShadow = "shadow";
    static constexpr const char* kStart = "start";

    static TechniqueInfo declaration();
};

} // namespace sb
