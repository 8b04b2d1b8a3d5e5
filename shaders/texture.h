// texture.h — sampling a base-colour texture, the same bits on every device (docs/DESIGN.md
// "Textures"): the texture coordinate interpolated with the raster's own barycentrics, wrapped in
// float by operations that are exact (floor, subtraction of an integer part, halving), turned into
// a fixed-point texel position with 8 fractional bits, and the four texels blended with integer
// weights. Each renderer fetches the texels its own way (resolve_lit.comp from the texel pool,
// the reference from its vector); the indices and the blend are these. See glsl_cpp.h for the
// dialect rules.
#ifndef PHONGVK_TEXTURE_H
#define PHONGVK_TEXTURE_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "phong.h"

SHARED_BEGIN

// The four texels a lookup blends (indices into the texel pool, row-major per texture), and the
// position's fractions toward the second column and row, 0..255.
struct TextureTaps {
  uint i00;
  uint i10;
  uint i01;
  uint i11;
  uint fx;
  uint fy;
};

// x0 + b1 (x1 - x0) + b2 (x2 - x0) for texture coordinates, as Gouraud interpolates colours.
FN vec2 interpolateUv(vec2 x0, vec2 x1, vec2 x2, vec2 b) {
  PRECISE vec2 x = x0 + b.x * (x1 - x0) + b.y * (x2 - x0);
  return x;
}

// Coordinate u wrapped into [0, 1] by `mode` (TEXTURE_WRAP_*); NaN and infinities give 0. Every
// step is exact in float: u - floor(u) is u's fractional bits, u * 0.5 a halving. A float of
// magnitude 2^23 or more is an integer (so repeats to 0); 2^24 or more is even (mirrors to 0).
FN float wrapUnit(float u, uint mode) {
  float v = (u >= 0.0f || u < 0.0f) ? u : 0.0f;
  if (mode == TEXTURE_WRAP_CLAMP) return v >= 0.0f ? (v <= 1.0f ? v : 1.0f) : 0.0f;
  if (mode == TEXTURE_WRAP_MIRROR) {
    v = abs(v) < 16777216.0f ? v : 0.0f;
    PRECISE float m = v - 2.0f * floor(v * 0.5f);  // [0, 2]
    return m <= 1.0f ? m : 2.0f - m;
  }
  v = abs(v) < 8388608.0f ? v : 0.0f;
  PRECISE float r = v - floor(v);
  return r;
}

// Texel index i of a side of n texels, i in [-1, n] (one past either end, where bilinear taps
// reach), wrapped by `mode`: repeat wraps around, clamp and mirror take the edge texel.
FN uint wrapIndex(int i, uint n, uint mode) {
  if (mode == TEXTURE_WRAP_REPEAT) return uint(i < 0 ? int(n) - 1 : (i >= int(n) ? i - int(n) : i));
  return uint(clamp(i, 0, int(n) - 1));
}

// Texture t's position at wrapped coordinate w (in [0, 1]) along a side of n texels in 1/256 of a
// texel, less half a texel for bilinear filtering (texel centres sit at k + 0.5): the first tap's
// index (floor) and the fraction toward the next (0 for nearest filtering). n * 256 <= 2^22 is a
// float exactly, and the product is correctly rounded on every device.
FN ivec2 tapOf(float w, uint n, uint filtering) {
  int p = int(floor(w * float(n * 256u)));
  if (filtering == TEXTURE_FILTER_BILINEAR) p -= 128;
  return ivec2(p >> 8, filtering == TEXTURE_FILTER_BILINEAR ? (p & 255) : 0);
}

// The taps of texture t at coordinate uv with `filtering` (TEXTURE_FILTER_*).
FN TextureTaps textureTaps(TextureData t, vec2 uv, uint filtering) {
  ivec2 x = tapOf(wrapUnit(uv.x, t.wrap & 255u), t.width, filtering);
  ivec2 y = tapOf(wrapUnit(uv.y, (t.wrap >> 8u) & 255u), t.height, filtering);
  uint x0 = wrapIndex(x.x, t.width, t.wrap & 255u), x1 = wrapIndex(x.x + 1, t.width, t.wrap & 255u);
  uint y0 = wrapIndex(y.x, t.height, (t.wrap >> 8u) & 255u), y1 = wrapIndex(y.x + 1, t.height, (t.wrap >> 8u) & 255u);
  TextureTaps taps;
  taps.i00 = t.offset + y0 * t.width + x0;
  taps.i10 = t.offset + y0 * t.width + x1;
  taps.i01 = t.offset + y1 * t.width + x0;
  taps.i11 = t.offset + y1 * t.width + x1;
  taps.fx = uint(x.y);
  taps.fy = uint(y.y);
  return taps;
}

// Channel `shift` of the four texels, blended with weights (256 - fx or fx) * (256 - fy or fy),
// which sum to 2^16, rounded to the nearest: integers, exact on every device.
FN uint blendChannel(uint c00, uint c10, uint c01, uint c11, uint fx, uint fy, uint shift) {
  uint sum = ((c00 >> shift) & 255u) * ((256u - fx) * (256u - fy)) + ((c10 >> shift) & 255u) * (fx * (256u - fy)) +
             ((c01 >> shift) & 255u) * ((256u - fx) * fy) + ((c11 >> shift) & 255u) * (fx * fy);
  return ((sum + 32768u) >> 16u) << shift;
}

// The RGBA8 colour of the taps' texels c00..c11 (nearest filtering: fx = fy = 0, c00 itself).
FN uint blendTaps(uint c00, uint c10, uint c01, uint c11, TextureTaps taps) {
  return blendChannel(c00, c10, c01, c11, taps.fx, taps.fy, 0u) | blendChannel(c00, c10, c01, c11, taps.fx, taps.fy, 8u) |
         blendChannel(c00, c10, c01, c11, taps.fx, taps.fy, 16u) | (255u << 24u);
}

// The texture a pixel of a triangle samples: its material's when it has one, else its mesh's (the
// same at the triangle's three vertices; TEXTURE_NONE for none).
FN uint textureOf(MaterialData m, VertexUv a) { return m.texture != TEXTURE_NONE ? m.texture : a.texture; }

// A colour (Gouraud's interpolated one, or the material's C before lighting) times a texel's.
FN vec3 texturedColor(vec3 color, uint texel) {
  PRECISE vec3 c = color * unitColor(texel);
  return c;
}

SHARED_END

#endif  // PHONGVK_TEXTURE_H
