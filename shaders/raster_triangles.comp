// Triangle pass: one invocation per triangle. Cull and snap (triangle_setup.h); a small one (32-bit edge
// functions suffice) is rasterized right here; one that crosses the near plane or the guard band,
// or is not small, goes to the clip list, and the clip pass (clip_triangles.comp) draws it or hands
// it to resolve. lavapipe runs both sides of every branch (masked; only loops really branch), so
// any code here costs every triangle: the large-triangle path, which few triangles take, lives in
// the clip pass (docs/PERFORMANCE.md, "Raster"). Built with SPEC_POINT_PASS it is the point pass,
// one invocation per point quad (drawPoint), and the triangle pass leaves those records to it.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "triangle_setup.h"
#include "small_triangles.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = SETUP_GROUP_SIZE) in;

// A small unclipped triangle, with 32-bit edges. True where it drew a fragment that may still win
// a pixel (offerKey).
bool rasterizeSmallTriangle(TriangleSetup t) {
  EdgeSetup small;
  if (!setupSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2], t.frontFacing != 0u, frame.width, frame.height, small)) {
    return false;
  }
  if (!IDS_PASS) markBins(small.bbox);
  return rasterizeSmall(t, small);
}

// Lists records first .. first + count - 1 for the clip pass (a triangle, or a point's two halves),
// with its indirect dispatch grown to reach them.
void listForClipPass(uint first, uint count) {
  uint k = atomicAdd(clipList.count, count);
  for (uint i = 0u; i < count; ++i) clipIds[k + i] = first + i;
  atomicMax(clipList.groupsX, min((k + count - 1u) / CLIP_GROUP_SIZE + 1u, control.groupCap));
}

// Triangle `id`: set up, then drawn here if small and unclipped, else listed for the clip pass. On
// the 32-bit key path's depth pass, kept (raster_loops.glsl keepTriangle) where it may win a pixel.
void drawTriangle(uint id) {
  vec3 h0, h1, h2;
  bool cullBack;
  loadForSetup(id, h0, h1, h2, cullBack);
  TriangleSetup t;
  if (!setupPlane(h0, h1, h2, cullBack, id, frame, t)) return;
  bool inside = insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection);
  if (inside && !setupUnclipped(h0, h1, h2, frame, t)) return;
  if (inside && fitsSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2])) {
    bool mayWin = rasterizeSmallTriangle(t);
#ifdef PHONGVK_KEYS32
    if (!IDS_PASS && mayWin) keepTriangle(id);
#endif
  } else if (!IDS_PASS) {
    listForClipPass(id, 1u);
  }
}

// The point pass: this shader built to draw the point quads (control.pointBase to pointEnd), a
// quad an invocation (drawPoint), while the triangle pass draws the records before and after them.
// A pass of its own because lavapipe runs every branch of a pass for every record (masked).
layout(constant_id = SPEC_POINT_PASS) const bool POINT_PASS = false;

// Point quad `id` (its first half; `id + 1` its second, screen_quads.h), with the keys, bins,
// clip-list entries and kept bits the triangle pass gives its halves drawn as triangles, in one
// invocation and with one set-up for both (docs/DESIGN.md "Points and lines" says why they agree):
// the halves share their corners' coordinates, so they are culled, clipped and kept small alike and
// share a box and a facing; each pixel's depth is the point's (the depth range of a half is that
// one value, and depthKey holds a depth to its range); a pixel either half covers takes the lower
// id among those that cover it, as the smaller key would.
void drawPoint(uint id) {
  uvec4 record = TEXEL(triangleTexels, id);
  vec3 h = floats(TEXEL(shadedTexels, record.x)).xyz;
  vec3 h0, h1, h2;  // the first half's corners: (-, -), (+, -), (+, +)
  quadCorners(h, h, record.z, frame, h0, h1, h2);
  TriangleSetup t;
  if (!setupPlane(h0, h1, h2, false, id, frame, t)) return;
  bool inside = insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection);
  if (inside && !setupUnclipped(h0, h1, h2, frame, t)) return;
  if (!inside || !fitsSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2])) {  // both halves to the clip pass
    listForClipPass(id, 2u);
    return;
  }
  ivec2 a = t.snapped[0], c = t.snapped[2];  // the second half's corners: (-, -), (+, +), (-, +)
  bool front = t.frontFacing != 0u;
  EdgeSetup first, second;
  bool drawsFirst = setupSmallEdges(a, t.snapped[1], c, front, frame.width, frame.height, first);
  bool drawsSecond = setupSmallEdges(a, c, ivec2(a.x, c.y), front, frame.width, frame.height, second);
  if (!drawsFirst && !drawsSecond) return;
  ivec4 box = drawsFirst ? first.bbox : second.bbox;  // the same box where both are set up
  if (!IDS_PASS) markBins(box);
  VisibilityKey key = depthKey(t.zMin, t.zMin, t.zMax, frame.farPlane, id);  // zMin = zMax: the point's depth
  VisibilityKey keySecond = depthKey(t.zMin, t.zMin, t.zMax, frame.farPlane, id + 1u);
  bool mayWinFirst = false, mayWinSecond = false;
  for (int y = box.y; y <= box.w; ++y) {
    for (int x = box.x; x <= box.z; ++x) {
      bool inFirst = drawsFirst && coversSmall(first, x, y);
      bool inSecond = drawsSecond && coversSmall(second, x, y);
      if (inFirst || inSecond) {
        bool mayWin = offerKey(uint(y) * frame.width + uint(x), inFirst ? key : keySecond);
        mayWinFirst = mayWinFirst || (mayWin && inFirst);
        mayWinSecond = mayWinSecond || (mayWin && inSecond);
      }
    }
  }
#ifdef PHONGVK_KEYS32
  if (!IDS_PASS && mayWinFirst) keepTriangle(id);
  if (!IDS_PASS && mayWinSecond) keepTriangle(id + 1u);
#endif
}

void main() {
  loadUniforms();
#ifdef PHONGVK_KEYS32
  if (IDS_PASS && KEPT_LIST) {  // the kept triangles only, from their list, one an invocation
    for (uint k = gl_GlobalInvocationID.x; k < clipList.keptListed; k += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
      drawTriangle(clipIds[keptListIndex(k)]);
    }
    checkLoopBudget();
    return;
  }
  if (IDS_PASS) {  // the kept triangles only, a chunk of their bits an invocation
    uint span = keptSpan(control.triangleCount);
    uint chunks = keptChunks(control.triangleCount);
    for (uint c = gl_GlobalInvocationID.x; c < chunks; c += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
      for (uint bits = keptChunkBits(c, span); bits != 0u; bits &= bits - 1u) drawTriangle(c * span + uint(findLSB(bits)));
    }
    checkLoopBudget();
    return;
  }
#endif
  // Grid-stride: the host caps the group count at control.groupCap.
  uint stride = gl_NumWorkGroups.x * SETUP_GROUP_SIZE;
  uint pointRecords = control.pointEnd - control.pointBase;
  if (POINT_PASS) {
    for (uint q = gl_GlobalInvocationID.x; q < pointRecords / 2u; q += stride) drawPoint(control.pointBase + 2u * q);
  } else {  // every record but the point quads'
    for (uint i = gl_GlobalInvocationID.x; i < control.triangleCount - pointRecords; i += stride) {
      drawTriangle(i < control.pointBase ? i : i + pointRecords);
    }
  }
  checkLoopBudget();
}
