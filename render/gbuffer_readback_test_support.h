// A rendered frame's G-buffer, shadow maps and accumulation read back from the GPU, for tests that
// hold the lighting pass to its CPU twin (render/cpu_shading.h) pixel by pixel; and that twin's
// value at a pixel (LightingTwin), for tests of passes that draw on top of the lighting pass.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/texture.h"
#include "render/cpu_shading.h"
#include "render/renderer.h"

namespace prism::render {

struct GBufferReadback {
  explicit GBufferReadback(const Renderer& renderer, bool coefficients = false)
      : albedo(gpu::readTexture2DFloat(renderer.albedoMetallic(), 4)),
        normal(gpu::readTexture2DFloat(renderer.normalRoughness(), 4)),
        ids(gpu::readTexture2DUint(renderer.materialId(), 1)),
        depth(gpu::readTexture2DFloat(renderer.depth(), 1)),
        emission(gpu::readTexture2DFloat(renderer.emission(), 4)),
        stored(coefficients ? gpu::readTexture2DFloat(renderer.coefficients(), 4) : std::vector<float>()),
        lit(gpu::readTexture2DFloat(renderer.accumulation(), 4)) {
    for (const ShadowView& view : renderer.shadowViews())
      shadowLayers.push_back(gpu::readTextureLayerFloat(renderer.shadowMaps(), view.layer));
  }

  // Pixel i's texel (i = y·width + x, GL rows).
  GBufferTexel texel(std::size_t i) const {
    GBufferTexel t;
    t.albedoMetallic = glm::vec4(albedo[4 * i], albedo[4 * i + 1], albedo[4 * i + 2], albedo[4 * i + 3]);
    t.normalRoughness = glm::vec4(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2], normal[4 * i + 3]);
    t.materialId = ids[i];
    t.depth = depth[i];
    t.emission = glm::vec3(emission[4 * i], emission[4 * i + 1], emission[4 * i + 2]);
    if (!stored.empty()) t.coefficients = glm::vec3(stored[4 * i], stored[4 * i + 1], stored[4 * i + 2]);
    return t;
  }
  // Pixel i's accumulated tristimulus.
  glm::vec3 accumulated(std::size_t i) const { return {lit[4 * i], lit[4 * i + 1], lit[4 * i + 2]}; }
  // Pixel (x, y)'s point in the world (GL rows), from its depth through the frame's inverse
  // view-projection.
  glm::vec3 worldPosition(int x, int y, int width, int height, const glm::mat4& inverseViewProjection) const {
    const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                       (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
    const float d = depth[static_cast<std::size_t>(y * width + x)];
    const glm::vec4 h = inverseViewProjection * glm::vec4(2.0f * uv - 1.0f, 2.0f * d - 1.0f, 1.0f);
    return glm::vec3(h) / h.w;
  }

  std::vector<float> albedo, normal;
  std::vector<std::uint32_t> ids;
  std::vector<float> depth, emission, stored, lit;
  std::vector<std::vector<float>> shadowLayers;
};

// What the lighting pass left at each pixel, by its CPU twin: for PRT objects, whose forward pass
// adds its sums on top, the scene's lights and, under water, the in-scattering along the view ray.
class LightingTwin {
 public:
  LightingTwin(const Renderer& renderer, const RgbToSpectrumTable& table)
      : mReadback(renderer), mShading(renderer.frameData(), table, mReadback.shadowLayers),
        mCamera(renderer.cameraTransform()), mWidth(renderer.settings().width), mHeight(renderer.settings().height) {}
  glm::dvec3 at(int x, int y) {
    const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(mWidth),
                       (static_cast<float>(y) + 0.5f) / static_cast<float>(mHeight));
    return glm::dvec3(mShading.shade(mReadback.texel(static_cast<std::size_t>(y * mWidth + x)), uv, mCamera));
  }

 private:
  GBufferReadback mReadback;
  CpuShading mShading;
  CameraTransform mCamera;
  int mWidth, mHeight;
};

}  // namespace prism::render
