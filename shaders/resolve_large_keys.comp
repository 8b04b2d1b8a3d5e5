// resolve_large.comp's keys build: every winner's key kept in the key buffer for the second resolve
// pass instead of its colour, no owned tiles, and each bin's list taken LIST_CHUNK entries a round
// when that is set. For frames whose lists are too long for lavapipe's loop budget, and frames lit
// per pixel (flat and Phong shading), which the second pass lights from the keys.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#define RESOLVE_LARGE_KEYS
#include "resolve_large.glsl"
