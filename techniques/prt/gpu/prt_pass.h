// The PRT technique's GPU half: a forward pass drawing the scene's PRT objects (meshes whose
// `technique` is "prt") after the lighting pass, into the same tristimulus target, so that the
// post pass (exposure, adaptation, tone map) finishes them with the rest (technique_pass.h).
//
// Per vertex its 25 SH transfer coefficients (an SSBO indexed by gl_VertexID); the environment's
// m × 25 rows L̃ and each material's R̂ in two more SSBOs (layouts in shaders/shared/prt.glsl).
// The vertex shader computes Ê_j = Σ_k L̃_jk T̃_k (prtVertexIrradiance), the fragment shader
// XYZ = Σ_j Ê_j R̂_j (prtXyz), each program compiled for its basis count m (#define
// PRISM_PRT_BASIS_COUNT: m interpolated varyings, loops of constant length). Spectral PRT and
// RGB-PRT are one draw each; the 5 nm reference six, one per chunk of ≤ 16 wavelengths, summed by
// the blending.
//
// Inside the scene's technique medium (the water: TechniqueSection::medium) or behind its nebula
// the fragment shader dims each projection's sum by the transmittance at the projection's nodes
// (shaders/shared/prt_medium.glsl): the environment through e^(−Kd·depth), the view ray through
// e^(−σt·path) and the nebula's e^(−g/λ) (its optical depth, which the renderer binds for forward
// passes as for lighting), as the lighting pass dims the scene's other surfaces, with each untextured
// material's exact reflectance at the nodes (a fifth buffer); when textured materials are drawn
// the spectral basis also holds the environment as the medium leaves it (attenuatedSpectra),
// which their projected reflectance needs.
//
// Textured materials (a spectral texture, or an RGB base colour texture upsampled per texel) draw
// R̂ from an m-layer RGBA16F array texture instead (prt_texture.h), sampled at the interpolated uv
// with mipmaps; the draws go mesh range by mesh range, untextured neighbours together.
//
// Prepared on first use: the transfer from the cache (prism prt bake's, keyed by the meshes and
// the bake settings) or baked (every PRT object occluding the others); the basis and projections
// again whenever the section, the observer or the objects' materials change.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/vertex_array.h"
#include "gpu/texture.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/prt_medium.h"
#include "techniques/prt/prt_texture.h"
#include "techniques/technique_pass.h"

namespace prism::prt {

// What the pass draws, as the CPU prepared it: the twin's input (readTexels).
struct PrtDrawData final : TechniqueTexels {
  std::vector<std::size_t> meshes;          // indices into Scene::meshes, in the order drawn
  std::vector<glm::vec3> positionsW;        // the scene's world space (y-up), as the G-buffer draws them
  std::vector<std::uint32_t> indices;       // into positionsW, three per triangle
  std::vector<glm::vec2> uvs;               // per vertex, as the meshes give them
  std::vector<int> vertexMaterial;          // into each projection's reflectances
  std::vector<int> materials;               // Scene::materials index of each of those
  std::vector<shared::Sh25> transfer;       // per vertex, PRT's z-up frame
  std::vector<PrtProjection> projections;   // drawn and summed
  // Per material: its reflectance texture, or null (then its R̂ is the projection's reflectance).
  std::vector<std::shared_ptr<const PrtTextureSource>> textures;
  std::vector<Eigen::MatrixXd> reflectanceMaps;  // per projection, its W (prt_texture.h), when a texture is drawn
  int basisCount = 0;                       // spectral: m after clamping to the basis's size
  double capturedEnergy = 0.0;              // spectral: of the m functions
  // The scene's technique medium (the water) the objects are dimmed by, if any, and per
  // projection its nodes (prt_medium.h; their σt and Kd zero without a medium, where a nebula
  // alone may still dim).
  std::optional<PrtMedium> medium;
  std::vector<std::vector<shared::PrtMediumNode>> mediumNodes;
};

class PrtPass final : public TechniquePass {
 public:
  PrtPass();
  // The transfer bake of the scene's PRT objects into the cache (precomputeTechniques).
  static void precompute(const Scene& scene, const TechniqueProgress& progress);
  void run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera,
           const TechniqueFrame& frame) override;
  void bindForLighting() const override {}
  std::size_t gpuMemoryBytes() const override;
  std::shared_ptr<const TechniqueTexels> readTexels() const override { return mData; }
  bool drawsForward() const override { return true; }
  void drawForward(const ForwardDrawInput& input) override;

 private:
  void prepareGeometry(const Scene& scene);
  void prepareProjections(const ForwardDrawInput& input);
  void prepareMediumNodes();
  const gpu::Program& program(int basisCount, const Scene& scene);

  // Indices [first, first + count) of one material, or of untextured materials together.
  struct DrawRange {
    GLint first = 0;
    GLsizei count = 0;
    int material = -1;  // a textured material, or -1
  };

  std::shared_ptr<PrtDrawData> mData;
  std::vector<DrawRange> mRanges;
  bool mGeometryReady = false;
  std::string mProjectionKey;  // what the projections were made from
  gpu::Buffer mVertices, mIndices, mTransfer;
  gpu::VertexArray mVertexArray;
  std::vector<gpu::Buffer> mEnvironments, mMaterials, mNodeReflectances, mMediumNodes;  // one each per projection
  std::vector<std::vector<gpu::Texture2DArray>> mTextures;  // per projection, per material (textured ones)
  std::map<std::string, gpu::Program> mPrograms;       // per basis count and the scene's techniques
};

}  // namespace prism::prt
