#version 450
#include "common/frame.glsl"
#include "beta/x.glsl"
#include "alpha/own.glsl"
