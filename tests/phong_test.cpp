// Per-vertex Phong (shaders/phong.h) against values computed by hand from docs/DESIGN.md's formula:
// color = ka C A + sum_i S I_i (C o L_i) (kd max(N.l, 0) + ks max(r.V, 0)^n), S = 1/(a + b d + c d^2).
#include "shaders/phong.h"

#include <gtest/gtest.h>

#include <cmath>

namespace phongvk::gpu {
namespace {

MaterialData material() {
  MaterialData m{};
  m.color = vec3(1.0f, 0.5f, 0.25f);
  m.ka = 0.1f;
  m.kd = 0.5f;
  m.ks = 0.3f;
  m.n = 2.0f;
  m.attenuation = vec3(1.0f, 0.5f, 0.25f);
  return m;
}

LightData light(vec3 position, float intensity, vec3 color) {
  LightData l{};
  l.position = position;
  l.intensity = intensity;
  l.color = color;
  return l;
}

void expectColor(vec3 actual, vec3 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-6f);
  EXPECT_NEAR(actual.y, expected.y, 1e-6f);
  EXPECT_NEAR(actual.z, expected.z, 1e-6f);
}

const vec3 P(0.0f, 0.0f, 0.0f);
const vec3 N(0.0f, 0.0f, 1.0f);
const vec3 EYE(0.0f, 0.0f, 5.0f);

TEST(Phong, OneLightStraightAbove) {
  // d = 2, S = 1/(1 + 0.5*2 + 0.25*4) = 1/3; l = N, r = N, r.V = 1: kd + ks = 0.8.
  // 0.1 C + (1/3) * 0.8 C = 0.366667 C.
  const MaterialData m = material();
  const vec3 V = toEye(P, EYE);
  const vec3 c = phongAmbient(m, vec3(1.0f)) + phongLight(P, N, V, m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f)));
  expectColor(c, vec3(0.3666667f, 0.1833333f, 0.0916667f));
}

TEST(Phong, SecondColouredLightAddsItsOwnTerm) {
  // Light 2 at (0,3,4): d = 5, S = 1/(1 + 2.5 + 6.25) = 1/9.75, l = (0,.6,.8), N.l = .8,
  // r = (0,-.6,.8), r.V = .8, spec = .64; kd .8 + ks .64 = .592; green light, intensity 2:
  // green channel 2/9.75 * 0.5 * 0.592 = 0.0607179.
  const MaterialData m = material();
  const vec3 V = toEye(P, EYE);
  const vec3 c = phongAmbient(m, vec3(1.0f)) + phongLight(P, N, V, m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f))) +
                 phongLight(P, N, V, m, light(vec3(0, 3, 4), 2.0f, vec3(0, 1, 0)));
  expectColor(c, vec3(0.3666667f, 0.1833333f + 0.0607179f, 0.0916667f));
}

TEST(Phong, DirectionalLightHasOneDirectionAndNoFallOff) {
  // l = (0, .6, .8) everywhere, S = 1 whatever the attenuation: N.l = .8, r = (0, -.6, .8), with the
  // eye straight above r.V = .8, spec .8^2 = .64: kd .5 * .8 + ks .3 * .64 = 0.592 per unit colour.
  const MaterialData m = material();
  LightData sun = light(vec3(0.0f, 0.6f, 0.8f), 1.0f, vec3(1.0f));
  sun.directional = 1.0f;
  for (const vec3& at : {P, vec3(100.0f, -40.0f, 0.0f)}) {
    const vec3 V = toEye(at, at + vec3(0.0f, 0.0f, 5.0f));
    expectColor(phongLight(at, N, V, m, sun), vec3(0.592f, 0.296f, 0.148f));
  }
  sun.position = vec3(0.0f, 0.6f, -0.8f);  // from below: nothing
  expectColor(phongLight(P, N, toEye(P, EYE), m, sun), vec3(0.0f));
}

// A spot light at (0, 0, 2) pointing straight down, full within 20 degrees, dark beyond 40: its
// constants as the host computes them (prepare/scene_data.cpp), glTF's fall-off.
LightData spotDown() {
  LightData l = light(vec3(0, 0, 2), 1.0f, vec3(1.0f));
  const double cosInner = std::cos(20 * M_PI / 180), cosOuter = std::cos(40 * M_PI / 180);
  const double scale = 1 / (cosInner - cosOuter);
  l.flags = LIGHT_SPOT;
  l.spotAxis = vec3(0, 0, -1);
  l.spotScale = float(scale);
  l.spotOffset = float(-cosOuter * scale);
  return l;
}

TEST(Phong, SpotLightIsAPointLightWithinItsInnerCone) {
  const MaterialData m = material();
  const vec3 V = toEye(P, EYE);
  const vec3 point = phongLight(P, N, V, m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f)));
  EXPECT_EQ(phongLight(P, N, V, m, spotDown()), point);  // on the axis: the cone is exactly 1
  // 15 degrees off the axis, still inside the inner cone.
  const vec3 at(float(2 * std::tan(15 * M_PI / 180)), 0.0f, 0.0f);
  EXPECT_EQ(phongLight(at, N, toEye(at, at + EYE), m, spotDown()),
            phongLight(at, N, toEye(at, at + EYE), m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f))));
}

TEST(Phong, SpotLightFallsOffBetweenItsConesAndIsDarkBeyond) {
  const MaterialData m = material();
  // 30 degrees off the axis: t = (cos 30 - cos 40) / (cos 20 - cos 40) = 0.575768, cone t^2 = 0.331509.
  const vec3 at(float(2 * std::tan(30 * M_PI / 180)), 0.0f, 0.0f);
  const vec3 V = toEye(at, at + EYE);
  const vec3 point = phongLight(at, N, V, m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f)));
  expectColor(phongLight(at, N, V, m, spotDown()), point * 0.331509f);
  // 45 degrees off the axis: nothing, though the point light there lights it.
  const vec3 beyond(2.0f, 0.0f, 0.0f);
  EXPECT_GT(phongLight(beyond, N, toEye(beyond, beyond + EYE), m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f))).x, 0.0f);
  expectColor(phongLight(beyond, N, toEye(beyond, beyond + EYE), m, spotDown()), vec3(0.0f));
}

TEST(Phong, AttenuationOnlyQuadratic) {
  // a = b = 0, c = 1: S = 1/d^2 = 1/4 at d = 2; (kd + ks) * S = 0.2.
  MaterialData m = material();
  m.attenuation = vec3(0.0f, 0.0f, 1.0f);
  const vec3 c = phongLight(P, N, toEye(P, EYE), m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f)));
  expectColor(c, vec3(0.2f, 0.1f, 0.05f));
}

TEST(Phong, LightBehindTheSurfaceAddsNothing) {
  const MaterialData m = material();
  const vec3 c = phongLight(P, N, toEye(P, EYE), m, light(vec3(0, 0, -2), 1.0f, vec3(1.0f)));
  expectColor(c, vec3(0.0f));
}

TEST(Phong, LightAtTheVertexAddsNothing) {
  const MaterialData m = material();
  const vec3 c = phongLight(P, N, toEye(P, EYE), m, light(P, 1.0f, vec3(1.0f)));
  expectColor(c, vec3(0.0f));
}

TEST(Phong, ShininessZeroGivesFullSpecularWhereLit) {
  // Light at (0,3,4), eye along +y: r = (0,-.6,.8), r.V = -.6 < 0. With n = 0 the specular
  // factor is still 1 (N.l > 0); with n = 2 it is 0.
  MaterialData m = material();
  const vec3 V = toEye(P, vec3(0.0f, 5.0f, 0.0f));
  const LightData l = light(vec3(0, 3, 4), 1.0f, vec3(1.0f));
  m.n = 0.0f;
  const float S = 1.0f / 9.75f;
  expectColor(phongLight(P, N, V, m, l), vec3(1.0f, 0.5f, 0.25f) * (S * (0.5f * 0.8f + 0.3f)));
  m.n = 2.0f;
  expectColor(phongLight(P, N, V, m, l), vec3(1.0f, 0.5f, 0.25f) * (S * (0.5f * 0.8f)));
}

TEST(Phong, EyeAtTheVertexIsNotNaN) {
  const MaterialData m = material();
  const vec3 c = phongLight(P, N, toEye(P, P), m, light(vec3(0, 0, 2), 1.0f, vec3(1.0f)));
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
  expectColor(c, vec3(1.0f, 0.5f, 0.25f) * (0.5f / 3.0f));  // diffuse only: V = 0 -> r.V = 0
}

TEST(Phong, AmbientUsesSceneAmbientColour) {
  const MaterialData m = material();
  expectColor(phongAmbient(m, vec3(1.0f, 0.0f, 0.5f)), vec3(0.1f, 0.0f, 0.0125f));
}

}  // namespace
}  // namespace phongvk::gpu

namespace phongvk::gpu {
namespace {

TEST(Phong, SharedPowerMatchesTheLibraryToSevenDigits) {
  // powPositive is built from +, *, / and exponent bits so every device gets the same bits; it
  // must still be pow to float precision over the range specular highlights use. The bound grows
  // with |n log2 x| because one float ulp of that exponent is already that much of the result
  // (the same holds for GLSL's pow).
  for (float n : {0.5f, 1.0f, 2.0f, 10.0f, 37.5f, 1000.0f}) {
    for (float x = 1e-6f; x <= 1.0f; x *= 1.37f) {
      const double want = std::pow(double(x), double(n));
      const float got = powPositive(x, n);
      if (want < 1e-30) {
        EXPECT_LT(got, 1e-29f) << x << "^" << n;
      } else {
        const double exponent = std::abs(double(n) * std::log2(double(x)));
        EXPECT_NEAR(got / want, 1.0, 2e-7 * (4.0 + exponent)) << x << "^" << n;
      }
    }
    EXPECT_EQ(powPositive(1.0f, n), 1.0f);
  }
  EXPECT_EQ(powPositive(0.5f, 1000.0f), 0.0f);  // 2^-1000 underflows to exactly 0, never subnormal
}

}  // namespace
}  // namespace phongvk::gpu
