// Second resolve pass (resolve.glsl, resolve_keys.glsl) for Gouraud shading: the tiles small
// triangles touched (every tile of the touched bins where resolve_large left every winner's key:
// KEYS_ONLY), a lane per pixel; per pixel whose key is still set, the winning key's triangle ->
// Gouraud colour -> packed RGBA8. Kept apart from resolve_large.comp because on lavapipe the mere
// presence of that pass's code makes this simple path several times slower; flat and Phong
// shading have a pass of their own (resolve_lit.comp) for the same reason.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "gouraud.h"
#include "bindings.glsl"
#include "resolve.glsl"

uint pixelColor(uint id, int x, int y) { return shadePixel(loadGouraud(id), x, y, frame, INTERPOLATION); }

#include "resolve_keys.glsl"
