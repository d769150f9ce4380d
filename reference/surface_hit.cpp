#include "reference/surface_hit.h"

#include <cmath>

#include "shared_cpp.h"

namespace prism::shared {
#include "transfer.glsl"
#include "surface_inputs.glsl"
}  // namespace prism::shared

namespace prism::reference {
namespace {

glm::vec4 texel(const Image& image, int x, int y) {
  x = ((x % image.width) + image.width) % image.width;
  y = ((y % image.height) + image.height) % image.height;
  const std::uint8_t* p =
      &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                   static_cast<std::size_t>(x)) * 4];
  glm::vec4 v(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f);
  if (image.srgb) {
    v = glm::vec4(shared::srgbDecode(v.x), shared::srgbDecode(v.y), shared::srgbDecode(v.z), v.w);
  }
  return v;
}

}  // namespace

glm::vec4 sampleTexture(const Image& image, const glm::vec2& uv) {
  // Wrapped to [0, 1) first (repeat), so that no coordinate is too large for an int.
  auto wrap = [](float t) { return std::isfinite(t) ? t - std::floor(t) : 0.0f; };
  float x = wrap(uv.x) * static_cast<float>(image.width) - 0.5f;
  float y = wrap(uv.y) * static_cast<float>(image.height) - 0.5f;
  float x0 = std::floor(x), y0 = std::floor(y);
  float fx = x - x0, fy = y - y0;
  int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  glm::vec4 top = glm::mix(texel(image, ix, iy), texel(image, ix + 1, iy), fx);
  glm::vec4 bottom = glm::mix(texel(image, ix, iy + 1), texel(image, ix + 1, iy + 1), fx);
  return glm::mix(top, bottom, fy);
}

SurfaceHit surfaceHit(const Scene& scene, const rays::TriangleHit& hit, const glm::vec3& origin,
                      const glm::vec3& direction) {
  const Mesh& mesh = scene.meshes[hit.geometry];
  const Material& material = scene.materials[static_cast<std::size_t>(mesh.material)];
  const Vertex& a = mesh.vertices[mesh.indices[3 * hit.triangle]];
  const Vertex& b = mesh.vertices[mesh.indices[3 * hit.triangle + 1]];
  const Vertex& c = mesh.vertices[mesh.indices[3 * hit.triangle + 2]];
  const float w = 1.0f - hit.u - hit.v;

  SurfaceHit s;
  s.material = mesh.material;
  s.lambertian = material.lambertian || !mesh.technique.empty();
  s.positionW = origin + direction * hit.distance;
  glm::vec3 winding = glm::cross(b.position - a.position, c.position - a.position);
  bool frontFacing = glm::dot(winding, direction) < 0.0f;
  float windingLength = glm::length(winding);
  s.geometricNormalW = windingLength > 0.0f ? winding / windingLength : -direction;
  if (!frontFacing) s.geometricNormalW = -s.geometricNormalW;

  glm::vec3 n = a.normal * w + b.normal * hit.u + c.normal * hit.v;
  n = glm::dot(n, n) > 1e-20f ? glm::normalize(n) : (frontFacing ? 1.0f : -1.0f) * s.geometricNormalW;
  if (!frontFacing) n = -n;
  glm::vec2 uv = a.uv * w + b.uv * hit.u + c.uv * hit.v;
  s.uv = uv;
  glm::vec4 tangent = a.tangent * w + b.tangent * hit.u + c.tangent * hit.v;

  int textures = 0;
  glm::vec3 baseColourTexel(1.0f);
  glm::vec4 metallicRoughnessTexel(1.0f);
  glm::vec3 normalTexel(0.5f, 0.5f, 1.0f);
  auto image = [&](int index) -> const Image& { return scene.textures[static_cast<std::size_t>(index)]; };
  if (material.baseColourTexture >= 0) {
    textures |= shared::kTextureBaseColour;
    baseColourTexel = glm::vec3(sampleTexture(image(material.baseColourTexture), uv));
  }
  if (material.metallicRoughnessTexture >= 0) {
    textures |= shared::kTextureMetallicRoughness;
    metallicRoughnessTexel = sampleTexture(image(material.metallicRoughnessTexture), uv);
  }
  if (material.normalTexture >= 0) {
    textures |= shared::kTextureNormal;
    normalTexel = glm::vec3(sampleTexture(image(material.normalTexture), uv));
  }
  glm::vec3 emissiveTexel(1.0f);
  if (material.emissiveTexture >= 0) {
    textures |= shared::kTextureEmission;
    emissiveTexel = glm::vec3(sampleTexture(image(material.emissiveTexture), uv));
  }
  shared::SurfaceInputs inputs =
      shared::surfaceInputs(material.baseColour, material.metallic, material.roughness, n, tangent, textures,
                            baseColourTexel, metallicRoughnessTexel, normalTexel, material.emissiveFactor, emissiveTexel);
  s.albedo = inputs.albedo;
  s.metallic = inputs.metallic;
  s.roughness = inputs.roughness;
  s.normalW = inputs.normal;
  s.emission = inputs.emission;
  return s;
}

}  // namespace prism::reference
