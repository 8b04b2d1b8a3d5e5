#include "reference/raycast.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace phongvk {

// Everything here is double on purpose: this is the exact picture the float renderers are measured
// against, so it shares none of their maths (shaders/phong.h, triangle_setup.h, gouraud.h) and keeps its own
// rounding error far below one 8-bit step.

namespace {

const Object& theSphere(const SceneSpec& scene) {
  if (scene.objects.size() != 1 ||
      (scene.objects[0].shape != Shape::Sphere && scene.objects[0].shape != Shape::Icosphere)) {
    throw ArgumentError(scene.path + ": the analytic ground truth needs a scene of exactly one sphere or icosphere");
  }
  return scene.objects[0];
}

// The ray through the centre of pixel (x, y), its direction scaled so its forward component is 1:
// the ray parameter is then the view-space depth the renderers clip with. Pixel centres sit at
// (x + 0.5, y + 0.5) about the view's principal point, y grows downwards. A perspective camera's
// rays leave the eye; an orthographic camera's leave the plane through the eye, all forward.
struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;
};

Ray pixelRay(const View& view, int x, int y) {
  const double a = (x + 0.5 - view.principal.x) / view.focal.x;
  const double b = (view.principal.y - (y + 0.5)) / view.focal.y;
  const glm::dvec3 offset = a * view.right + b * view.up;
  if (view.orthographic) return {view.eye + offset, view.forward};
  return {view.eye, view.forward + offset};
}

// Depth of the nearer intersection of eye + t d with the sphere, or -1 when the ray misses.
// The quadratic is solved in the cancellation-free form (q = -(B + sign(B) sqrt(disc)) / 2).
double nearerHit(const glm::dvec3& eye, const glm::dvec3& d, const glm::dvec3& center, double radius) {
  const glm::dvec3 o = eye - center;
  const double A = glm::dot(d, d);
  const double B = 2 * glm::dot(o, d);
  const double C = glm::dot(o, o) - radius * radius;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return -1;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  if (q == 0) return -1;  // only when the eye sits on the sphere looking along its tangent
  const double t0 = q / A, t1 = C / q;
  return std::min(t0, t1);
}

// A spot light's cone at the unit direction l toward it, in closed form (docs/DESIGN.md "Lights").
double spotCone(const LightSpec& light, const glm::dvec3& l) {
  const double cosInner = std::cos(glm::radians(light.innerCone)), cosOuter = std::cos(glm::radians(light.outerCone));
  const double cd = -glm::dot(glm::normalize(light.direction), l);
  const double t = std::clamp((cd - cosOuter) / std::max(cosInner - cosOuter, 0.001), 0.0, 1.0);
  return t * t;
}

// docs/DESIGN.md "Phong": ka C A + sum_i S I_i (C o L_i) (kd max(N.l, 0) + ks max(r.V, 0)^n), the
// specular term only where N.l > 0, a light exactly at P adding nothing.
// V is the unit vector toward the viewer.
glm::dvec3 phong(const glm::dvec3& P, const glm::dvec3& N, const glm::dvec3& V, const SceneSpec& scene,
                 const MaterialSpec& m) {
  const glm::dvec3 C(m.color);
  glm::dvec3 color = double(m.ka) * C * glm::dvec3(scene.ambient);
  for (const LightSpec& light : scene.lights) {
    const glm::dvec3 toLight = light.directional ? -glm::normalize(light.direction) : light.position - P;
    const double d = light.directional ? 1 : glm::length(toLight);
    if (d == 0) continue;
    const glm::dvec3 l = toLight / d;
    const double NdotL = glm::dot(N, l);
    if (NdotL <= 0) continue;
    double S = light.directional ? 1 : 1 / (m.attenuation.x + m.attenuation.y * d + m.attenuation.z * d * d);
    if (light.inverseSquare) {
      const double window = light.range > 0 ? std::clamp(1 - std::pow(d / light.range, 4), 0.0, 1.0) : 1.0;
      S = window * window / (d * d);
    }
    if (light.spot) S *= spotCone(light, l);
    const glm::dvec3 r = 2 * NdotL * N - l;
    const double rV = std::max(glm::dot(r, V), 0.0);
    const double specular = m.n == 0 ? 1 : std::pow(rV, double(m.n));
    color += S * light.intensity * (C * glm::dvec3(light.color)) * (m.kd * NdotL + m.ks * specular);
  }
  return color;
}

// Clamp to [0, 1], round(c * 255), as the renderers write colours.
void writeColor(uint8_t* rgb, const glm::dvec3& c) {
  for (int i = 0; i < 3; ++i) rgb[i] = static_cast<uint8_t>(std::floor(std::clamp(c[i], 0.0, 1.0) * 255 + 0.5));
}

}  // namespace

Image raycastSphere(const SceneSpec& scene, const View& view) {
  const Object& sphere = theSphere(scene);
  const MaterialSpec& material = scene.materials.empty() ? MaterialSpec{} : scene.materials.at(sphere.material);
  Image image(view.width, view.height);
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      const Ray ray = pixelRay(view, x, y);
      const double t = nearerHit(ray.origin, ray.direction, sphere.center, sphere.radius);
      // The renderers clip the nearer surface at the near plane and cull the far (back-facing)
      // one, so a nearer hit outside [near, far] shows the background, not the far side.
      if (t < view.nearPlane || t > view.farPlane) {
        writeColor(image.pixel(x, y), glm::dvec3(scene.background));
        continue;
      }
      const glm::dvec3 P = ray.origin + t * ray.direction;
      const glm::dvec3 V = view.orthographic ? -view.forward : glm::normalize(view.eye - P);
      writeColor(image.pixel(x, y), phong(P, (P - sphere.center) / sphere.radius, V, scene, material));
    }
  }
  return image;
}

}  // namespace phongvk
