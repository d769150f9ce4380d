// The PRT forward pass's CPU twin for the render tests (prt_pass_test.cpp,
// prt_texture_pass_test.cpp): the pixel's triangle found by a ray through its centre, the
// vertices' Ê interpolated with the hit's barycentrics (perspective-correct interpolation is
// interpolation on the triangle in space), R̂ the material's or its texture's at the hit's uv, and
// prtXyz summed over the very data the pass uploaded (PrtPass::readTexels), through the medium's
// nodes when the scene has one.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "render/frame_settings.h"

#include "scene/camera_transform.h"
#include "techniques/prt/gpu/prt_pass.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/prt_shared.h"

namespace prism::render {

// The modes the twin tests run: spectral PRT and the 5 nm reference in a spectral frame, and an
// RGB frame (which draws RGB-PRT whatever the section says).
struct PrtModeCase {
  prt::PrtMode mode;
  RenderMode frameMode;
};

inline auto prtModeCases() {
  return testing::Values(PrtModeCase{prt::PrtMode::Spectral, RenderMode::JakobHanika},
                         PrtModeCase{prt::PrtMode::Reference5nm, RenderMode::JakobHanika},
                         PrtModeCase{prt::PrtMode::Spectral, RenderMode::Rgb});
}

// The twin tests' frame: the case's frame mode, small shadow maps, no dither.
inline FrameSettings prtTwinSettings(const PrtModeCase& c, int width, int height) {
  FrameSettings settings;
  settings.width = width;
  settings.height = height;
  settings.mode = c.frameMode;
  settings.shadowMapSize = 256;
  settings.display.dither = false;
  return settings;
}

inline std::string prtModeCaseName(const testing::TestParamInfo<PrtModeCase>& param) {
  std::string name = std::string(prt::prtModeName(param.param.mode)) + "_frame_" +
                     std::string(renderModeName(param.param.frameMode));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

struct Hit {
  std::size_t triangle = 0;
  glm::dvec3 barycentric{0.0};
  double distance = 0.0;
};

// The nearest triangle along the ray (Möller & Trumbore 1997), in double.
inline std::optional<Hit> intersect(const prt::PrtDrawData& d, const glm::dvec3& origin, const glm::dvec3& dir) {
  std::optional<Hit> best;
  for (std::size_t t = 0; t + 2 < d.indices.size(); t += 3) {
    glm::dvec3 a(d.positionsW[d.indices[t]]), b(d.positionsW[d.indices[t + 1]]), c(d.positionsW[d.indices[t + 2]]);
    glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) continue;
    glm::dvec3 s = origin - a;
    double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    glm::dvec3 q = glm::cross(s, e1);
    double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    double distance = glm::dot(e2, q) / det;
    if (distance <= 0.0 || (best && distance >= best->distance)) continue;
    best = Hit{t, glm::dvec3(1.0 - u - v, u, v), distance};
  }
  return best;
}

// The ray through window position (x, y) (GL's: y up, pixel centres at +0.5).
inline std::pair<glm::dvec3, glm::dvec3> pixelRay(const CameraTransform& camera, double x, double y, int w, int h) {
  glm::dvec2 ndc(2.0 * x / w - 1.0, 2.0 * y / h - 1.0);
  glm::dmat4 inverse(camera.inverseViewProjection);
  glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0), farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
  glm::dvec3 n = glm::dvec3(nearPoint) / nearPoint.w, f = glm::dvec3(farPoint) / farPoint.w;
  return {n, glm::normalize(f - n)};
}

// The hit through pixel (x, y)'s centre when the pixel lies inside one object (rays half a pixel
// away hit the same material): a silhouette's pixels may take another triangle's colour.
inline std::optional<Hit> interiorHit(const prt::PrtDrawData& d, const CameraTransform& camera, int x, int y, int w, int h) {
  auto [origin, dir] = pixelRay(camera, x + 0.5, y + 0.5, w, h);
  std::optional<Hit> hit = intersect(d, origin, dir);
  if (!hit) return std::nullopt;
  for (glm::dvec2 o : {glm::dvec2(-0.5, 0.0), glm::dvec2(0.5, 0.0), glm::dvec2(0.0, -0.5), glm::dvec2(0.0, 0.5)}) {
    auto [o2, d2] = pixelRay(camera, x + 0.5 + o.x, y + 0.5 + o.y, w, h);
    std::optional<Hit> h2 = intersect(d, o2, d2);
    if (!h2 || d.vertexMaterial[d.indices[h2->triangle]] != d.vertexMaterial[d.indices[hit->triangle]]) return std::nullopt;
  }
  return hit;
}

// The hit's interpolated texture coordinates.
inline glm::dvec2 hitUv(const prt::PrtDrawData& d, const Hit& hit) {
  glm::dvec2 uv(0.0);
  for (int k = 0; k < 3; ++k) uv += hit.barycentric[k] * glm::dvec2(d.uvs[d.indices[hit.triangle + static_cast<std::size_t>(k)]]);
  return uv;
}

// A textured material's R̂ at uv as GL_LINEAR samples the base level with GL_REPEAT: the
// projector's half-rounded texels (what the pass uploaded), mixed bilinearly.
inline shared::PrtReflectance sampledReflectance(const prt::PrtTextureSource& source, const prt::PrtTexelProjector& projector,
                                                 const glm::dvec2& uv) {
  const int w = source.width(), h = source.height();
  const double x = (uv.x - std::floor(uv.x)) * w - 0.5, y = (uv.y - std::floor(uv.y)) * h - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
  auto texel = [&](int dx, int dy) {
    const int ix = static_cast<int>(x0) + dx, iy = static_cast<int>(y0) + dy;
    return projector.texel(((ix % w) + w) % w, ((iy % h) + h) % h);
  };
  const shared::PrtReflectance a = texel(0, 0), b = texel(1, 0), c = texel(0, 1), e = texel(1, 1);
  shared::PrtReflectance r{};
  for (int j = 0; j < projector.basisCount(); ++j) {
    const glm::dvec3 top = glm::mix(glm::dvec3(a.r[j]), glm::dvec3(b.r[j]), fx);
    const glm::dvec3 bottom = glm::mix(glm::dvec3(c.r[j]), glm::dvec3(e.r[j]), fx);
    r.r[j] = glm::vec3(glm::mix(top, bottom, fy));
  }
  return r;
}

// Calls f(x, y, hit) at every interior pixel (interiorHit; y a GL row); returns how many.
template <class F>
int forInteriorPixels(const prt::PrtDrawData& d, const CameraTransform& camera, int w, int h, F&& f) {
  int visited = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (std::optional<Hit> hit = interiorHit(d, camera, x, y, w, h)) {
        f(x, y, *hit);
        ++visited;
      }
  return visited;
}

// Calls f(x, y, hit) at the interior pixels (interiorHit; y a GL row) among `samples` random ones
// drawn from `seed`; returns how many.
template <class F>
int forRandomInteriorPixels(const prt::PrtDrawData& d, const CameraTransform& camera, int w, int h, unsigned seed,
                            int samples, F&& f) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1);
  int visited = 0;
  for (int n = 0; n < samples; ++n) {
    const int x = px(rng), y = py(rng);
    if (std::optional<Hit> hit = interiorHit(d, camera, x, y, w, h)) {
      f(x, y, *hit);
      ++visited;
    }
  }
  return visited;
}

// The fragment shader's sum on the CPU: Ê interpolated with the hit's barycentrics, then prtXyz,
// for every projection (the 5 nm reference has six); a textured material's R̂ sampled at the hit.
// Inside the scene's medium or behind `nebulaDepthUm` of its nebula (the nebula pass's optical
// depth at the pixel), the sum over the projection's nodes dimmed by them, with an untextured
// material's exact reflectance per node (prt_medium.h).
inline glm::dvec3 cpuTristimulus(const prt::PrtDrawData& d, const Hit& hit, const glm::vec3& cameraPositionW,
                                  float nebulaDepthUm = 0.0f) {
  glm::dvec3 point(0.0);
  for (int k = 0; k < 3; ++k)
    point += hit.barycentric[k] * glm::dvec3(d.positionsW[d.indices[hit.triangle + static_cast<std::size_t>(k)]]);
  glm::dvec3 sum(0.0);
  const int material = d.vertexMaterial[d.indices[hit.triangle]];
  const prt::PrtTextureSource* texture = d.textures.empty() ? nullptr : d.textures[static_cast<std::size_t>(material)].get();
  for (std::size_t c = 0; c < d.projections.size(); ++c) {
    const prt::PrtProjection& p = d.projections[c];
    shared::PrtBasisIrradiance e{};
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = d.indices[hit.triangle + static_cast<std::size_t>(k)];
      shared::PrtBasisIrradiance ev = shared::prtVertexIrradiance(p.environment, d.transfer[v], p.basisCount);
      for (int j = 0; j < p.basisCount; ++j) e.e[j] += static_cast<float>(hit.barycentric[k]) * ev.e[j];
    }
    const shared::PrtReflectance r =
        texture ? sampledReflectance(*texture, prt::PrtTexelProjector(*texture, d.reflectanceMaps[c]), hitUv(d, hit))
                : p.reflectances[static_cast<std::size_t>(material)];
    sum += glm::dvec3(prt::prtXyzThroughMedium(e, r, p.basisCount, d.mediumNodes[c],
                                               texture ? nullptr : &p.nodeReflectances[static_cast<std::size_t>(material)],
                                               d.medium ? &*d.medium : nullptr, cameraPositionW, glm::vec3(point),
                                               nebulaDepthUm));
  }
  return sum;
}

}  // namespace prism::render
