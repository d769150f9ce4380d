// A scene's meshes and textures on the GPU: one interleaved vertex buffer and index buffer per
// mesh (render/scene.h's Vertex layout), and one texture per image, sRGB-format for colour
// images so that sampling decodes them with the sRGB transfer function, with mipmaps.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/texture.h"
#include "gpu/vertex_array.h"
#include "scene/scene.h"

namespace prism::render {

struct GpuMesh {
  gpu::Buffer vertices;
  gpu::Buffer indices;
  gpu::VertexArray vertexArray;
  int material = 0;
};

// One mesh on the GPU (its vertex array reads its own two buffers).
GpuMesh uploadMesh(const Mesh& mesh);

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);  // an OpenGL 4.5 context must be current

  const std::vector<GpuMesh>& meshes() const { return mMeshes; }
  const gpu::Texture2D& texture(int index) const;
  // Bytes of its vertex, index and texture storage (mip chains included).
  std::size_t gpuMemoryBytes() const;

 private:
  std::vector<GpuMesh> mMeshes;
  std::vector<gpu::Texture2D> mTextures;
};

}  // namespace prism::render
