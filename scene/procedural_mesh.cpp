#include "scene/procedural_mesh.h"

#include <algorithm>
#include <cmath>

#include "shared_cpp.h"
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "random.glsl"
}  // namespace prism::shared

namespace prism {

namespace {

using shared::kPi;

// The horizontal tangent of a plane facing n (unit): +y × n, or +x for a vertical normal.
glm::vec3 planeTangent(const glm::vec3& n) {
  glm::vec3 t = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), n);
  float len = glm::length(t);
  // sin 0.5° : below it the cross product is too short to trust its direction.
  if (len < 0.0087f) return {1.0f, 0.0f, 0.0f};
  return t / len;
}

// A w × h rectangle centred at c in the plane spanned by t (width, +u) and b = n × t
// (height, toward the image's top), two counter-clockwise triangles seen from n.
void appendQuad(Mesh& mesh, const glm::vec3& c, const glm::vec3& n, const glm::vec3& t, float w,
                float h) {
  glm::vec3 b = glm::cross(n, t);
  auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  const float corners[4][2] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  for (const auto& corner : corners) {
    Vertex v;
    v.position = c + corner[0] * w * t + corner[1] * h * b;
    v.normal = n;
    v.uv = {corner[0] + 0.5f, 0.5f - corner[1]};
    v.tangent = glm::vec4(t, 1.0f);  // b points toward −v: w = +1 (procedural_mesh.h)
    mesh.vertices.push_back(v);
  }
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

// Any unit vector orthogonal to the unit vector n (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited", JCGT 6(1), Listing 3).
glm::vec3 anyOrthogonal(const glm::vec3& n) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float b = n.x * n.y * a;
  return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

}  // namespace

Mesh makeSphere(const glm::vec3& centreW, float radiusM, int segments) {
  PRISM_CHECK(segments >= 3 && radiusM > 0.0f);
  int stacks = std::max(2, segments / 2);
  Mesh mesh;
  mesh.name = "sphere";
  // p(φ, θ) = centre + r (sin θ sin φ, cos θ, sin θ cos φ), u = φ / 2π, v = θ / π: ∂p/∂φ is
  // along (cos φ, 0, −sin φ), the tangent, and −∂p/∂θ is toward the north pole, i.e. −v.
  for (int i = 0; i <= stacks; ++i) {
    float v = static_cast<float>(i) / static_cast<float>(stacks);
    float theta = v * kPi;
    for (int j = 0; j <= segments; ++j) {
      float u = static_cast<float>(j) / static_cast<float>(segments);
      float phi = u * 2.0f * kPi;
      Vertex vertex;
      vertex.normal = {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
      if (i == 0) vertex.normal = {0.0f, 1.0f, 0.0f};  // exact poles
      if (i == stacks) vertex.normal = {0.0f, -1.0f, 0.0f};
      vertex.position = centreW + radiusM * vertex.normal;
      vertex.uv = {u, v};
      vertex.tangent = {std::cos(phi), 0.0f, -std::sin(phi), 1.0f};
      mesh.vertices.push_back(vertex);
    }
  }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (segments + 1) + j); };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < segments; ++j) {
      // a (north-west), b (south-west), c (south-east), d (north-east): a b c and a c d are
      // counter-clockwise seen from outside; the pole rows would each give one empty triangle.
      std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {a, b, c});
      if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});
    }
  }
  return mesh;
}

Mesh makePlane(const glm::vec3& centreW, const glm::vec3& normalW, const glm::vec2& sizeM) {
  PRISM_CHECK(glm::length(normalW) > 0.0f);
  glm::vec3 n = glm::normalize(normalW);
  Mesh mesh;
  mesh.name = "plane";
  appendQuad(mesh, centreW, n, planeTangent(n), sizeM.x, sizeM.y);
  return mesh;
}

namespace {

// Value noise in [−1, 1]: hashed lattice values blended with smoothstep weights.
float valueNoise(float x, float z, std::uint32_t seed) {
  float fx = std::floor(x), fz = std::floor(z);
  auto lattice = [&](float i, float k) {
    auto ui = static_cast<std::uint32_t>(static_cast<std::int32_t>(i));
    auto uk = static_cast<std::uint32_t>(static_cast<std::int32_t>(k));
    std::uint32_t h = shared::pcgHash(ui ^ shared::pcgHash(uk ^ shared::pcgHash(seed)));
    return shared::uintToUnitFloat(h) * 2.0f - 1.0f;
  };
  auto smooth = [](float t) { return t * t * (3.0f - 2.0f * t); };
  float tx = smooth(x - fx), tz = smooth(z - fz);
  float a = glm::mix(lattice(fx, fz), lattice(fx + 1.0f, fz), tx);
  float b = glm::mix(lattice(fx, fz + 1.0f), lattice(fx + 1.0f, fz + 1.0f), tx);
  return glm::mix(a, b, tz);
}

}  // namespace

Mesh makeHeightField(const glm::vec3& centreW, const glm::vec2& sizeM, int resolution, float amplitudeM,
                     float featureM, std::uint32_t seed, float tileM) {
  PRISM_CHECK(resolution >= 1 && sizeM.x > 0.0f && sizeM.y > 0.0f && featureM > 0.0f && tileM > 0.0f);
  Mesh mesh;
  mesh.name = "heightfield";
  const int n = resolution;
  for (int i = 0; i <= n; ++i) {      // rows along +z
    for (int j = 0; j <= n; ++j) {    // columns along +x
      float x = centreW.x + sizeM.x * (static_cast<float>(j) / static_cast<float>(n) - 0.5f);
      float z = centreW.z + sizeM.y * (static_cast<float>(i) / static_cast<float>(n) - 0.5f);
      float height = 0.0f, scale = 1.0f, weight = 0.0f;
      for (int octave = 0; octave < 3; ++octave) {
        height += scale * valueNoise(x / (featureM * scale), z / (featureM * scale), seed + static_cast<std::uint32_t>(octave));
        weight += scale;
        scale *= 0.5f;
      }
      Vertex v;
      v.position = {x, centreW.y + amplitudeM * height / weight, z};
      v.uv = {x / tileM, z / tileM};
      mesh.vertices.push_back(v);
    }
  }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      // Seen from above (+y) with x to the right and z towards the viewer, a (i, j) → b (i+1, j)
      // → c (i+1, j+1) runs counter-clockwise.
      std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
  computeNormals(mesh);
  computeTangents(mesh);
  return mesh;
}

Mesh makeBox(const glm::vec3& centreW, const glm::vec3& sizeM, const glm::vec3& rotationDeg) {
  Mesh mesh;
  mesh.name = "box";
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = sign;
      glm::vec3 t = planeTangent(n);
      glm::vec3 b = glm::cross(n, t);
      float w = std::abs(glm::dot(t, sizeM)), h = std::abs(glm::dot(b, sizeM));
      appendQuad(mesh, 0.5f * sizeM[axis] * n, n, t, w, h);
    }
  }
  transformMesh(mesh, trsMatrix(centreW, rotationDeg, glm::vec3(1.0f)));
  return mesh;
}

glm::mat3 eulerRotation(const glm::vec3& degrees) {
  glm::mat4 r(1.0f);
  r = glm::rotate(r, glm::radians(degrees.z), glm::vec3(0.0f, 0.0f, 1.0f));
  r = glm::rotate(r, glm::radians(degrees.y), glm::vec3(0.0f, 1.0f, 0.0f));
  r = glm::rotate(r, glm::radians(degrees.x), glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::mat3(r);
}

glm::mat4 trsMatrix(const glm::vec3& translation, const glm::vec3& rotationDeg,
                    const glm::vec3& scale) {
  glm::mat4 m = glm::mat4(eulerRotation(rotationDeg)) * glm::scale(glm::mat4(1.0f), scale);
  m[3] = glm::vec4(translation, 1.0f);
  return m;
}

void transformMesh(Mesh& mesh, const glm::mat4& m) {
  glm::mat3 linear(m);
  glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
  bool mirrored = glm::determinant(linear) < 0.0f;
  for (Vertex& v : mesh.vertices) {
    v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
    glm::vec3 n = normalMatrix * v.normal;
    if (glm::length(n) > 0.0f) v.normal = glm::normalize(n);
    glm::vec3 t = linear * glm::vec3(v.tangent);
    t -= v.normal * glm::dot(v.normal, t);  // a non-uniform scale tilts t off the surface
    glm::vec3 tangent = glm::length(t) > 1e-12f ? glm::normalize(t) : anyOrthogonal(v.normal);
    v.tangent = glm::vec4(tangent, mirrored ? -v.tangent.w : v.tangent.w);
  }
  if (mirrored)
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

namespace {

// The smooth normals of computeNormals, written to the vertices `which` picks.
template <typename Which>
void smoothNormals(Mesh& mesh, Which which) {
  std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    glm::vec3 face = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                mesh.vertices[c].position - mesh.vertices[a].position);
    sums[a] += face;
    sums[b] += face;
    sums[c] += face;
  }
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (!which(mesh.vertices[i])) continue;
    float len = glm::length(sums[i]);
    mesh.vertices[i].normal = len > 0.0f ? sums[i] / len : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

}  // namespace

void computeNormals(Mesh& mesh) {
  smoothNormals(mesh, [](const Vertex&) { return true; });
}

void computeZeroNormals(Mesh& mesh) {
  smoothNormals(mesh, [](const Vertex& v) { return v.normal == glm::vec3(0.0f); });
}

void computeTangents(Mesh& mesh) {
  std::vector<glm::vec3> dpdu(mesh.vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> dpdv(mesh.vertices.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    const Vertex &va = mesh.vertices[a], &vb = mesh.vertices[b], &vc = mesh.vertices[c];
    glm::vec3 e1 = vb.position - va.position, e2 = vc.position - va.position;
    glm::vec2 d1 = vb.uv - va.uv, d2 = vc.uv - va.uv;
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f)) continue;  // degenerate uvs: this triangle says nothing
    // Solve [e1 e2] = [∂p/∂u ∂p/∂v] [d1 d2] (Lengyel 2001, Eq. 4).
    glm::vec3 u = (e1 * d2.y - e2 * d1.y) / det;
    glm::vec3 v = (e2 * d1.x - e1 * d2.x) / det;
    for (std::uint32_t k : {a, b, c}) {
      dpdu[k] += u;
      dpdv[k] += v;
    }
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    Vertex& v = mesh.vertices[i];
    glm::vec3 t = dpdu[i] - v.normal * glm::dot(v.normal, dpdu[i]);
    if (!(glm::length(t) > 1e-12f)) {
      v.tangent = glm::vec4(anyOrthogonal(v.normal), 1.0f);
      continue;
    }
    t = glm::normalize(t);
    // The bitangent cross(n, t)·w must point along −∂p/∂v.
    float w = glm::dot(glm::cross(v.normal, t), dpdv[i]) > 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(t, w);
  }
}

}  // namespace prism
