#include "render/gpu_scene.h"

#include <cstddef>
#include <span>

namespace prism::render {

GpuMesh uploadMesh(const Mesh& mesh) {
  GpuMesh g;
  g.material = mesh.material;
  g.vertices = gpu::Buffer::fromSpan(std::span<const Vertex>(mesh.vertices), mesh.name + " vertices", 0);
  g.indices = gpu::Buffer::fromSpan(std::span<const std::uint32_t>(mesh.indices), mesh.name + " indices", 0);
  gpu::VertexArrayDesc desc;
  desc.attributes = {
      {0, 3, GL_FLOAT, false, false, static_cast<GLuint>(offsetof(Vertex, position))},
      {1, 3, GL_FLOAT, false, false, static_cast<GLuint>(offsetof(Vertex, normal))},
      {2, 2, GL_FLOAT, false, false, static_cast<GLuint>(offsetof(Vertex, uv))},
      {3, 4, GL_FLOAT, false, false, static_cast<GLuint>(offsetof(Vertex, tangent))},
  };
  desc.vertices = &g.vertices;
  desc.strideBytes = sizeof(Vertex);
  desc.indices = &g.indices;
  desc.label = mesh.name;
  g.vertexArray = gpu::VertexArray(desc);
  return g;
}

GpuScene::GpuScene(const Scene& scene) {
  mMeshes.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.indices.empty()) continue;  // nothing to draw, and GL has no empty buffers
    mMeshes.push_back(uploadMesh(mesh));
  }
  mTextures.reserve(scene.textures.size());
  for (const Image& image : scene.textures) {
    gpu::Texture2DDesc desc;
    desc.width = image.width;
    desc.height = image.height;
    desc.internalFormat = image.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    desc.levels = 0;
    desc.sampling.wrap = GL_REPEAT;
    // Scene images are stored top row first; GL's first row is v = 0, which glTF's uv
    // convention (v down) reads as the top: upload as they are.
    desc.data = {GL_RGBA, GL_UNSIGNED_BYTE, std::as_bytes(std::span<const std::uint8_t>(image.rgba))};
    desc.label = image.source;
    gpu::Texture2D texture(desc);
    texture.generateMipmaps();
    mTextures.push_back(std::move(texture));
  }
}

const gpu::Texture2D& GpuScene::texture(int index) const {
  return mTextures.at(static_cast<std::size_t>(index));
}

std::size_t GpuScene::gpuMemoryBytes() const {
  std::size_t bytes = 0;
  for (const GpuMesh& m : mMeshes) bytes += m.vertices.sizeBytes() + m.indices.sizeBytes();
  for (const gpu::Texture2D& t : mTextures) bytes += t.sizeBytes();
  return bytes;
}

}  // namespace prism::render
