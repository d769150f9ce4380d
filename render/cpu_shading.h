// The CPU twin of the lighting pass: shaders/shared/pixel_shading.glsl compiled as C++, with
// accessors over the same FrameData the GPU reads, the CPU upsampling lookup, shadow maps read
// back from the GPU and each technique's twin (techniques/technique_cpu_twin.h), once per
// combination of techniques. Tests hold the GPU's lighting pass to it pixel by pixel.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera_transform.h"
#include "render/frame_data.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "techniques/technique_cpu_twin.h"

namespace prism::render {

// One G-buffer texel as the lighting pass reads it.
struct GBufferTexel {
  glm::vec4 albedoMetallic{0.0f};
  glm::vec4 normalRoughness{0.0f};
  std::uint32_t materialId = 0;  // material index + 1; 0 where no geometry is
  float depth = 1.0f;
  glm::vec3 coefficients{0.0f};  // Jakob–Hanika coefficients, when the G-buffer holds them
  glm::vec3 emission{0.0f};      // glTF's emissive colour
};

class CpuShading {
 public:
  // shadowLayers: each layer's depths, size × size, row 0 at the bottom (GL order); texels: what
  // the techniques' passes hold for the lighting pass, read back (TechniquePass::readTexels), by
  // technique key. The table is looked up with the manual (reference) path and must outlive
  // this; the frame is copied.
  CpuShading(const FrameData& frame, const RgbToSpectrumTable& table,
             std::vector<std::vector<float>> shadowLayers, TechniqueTexelsByKey texels = {});
  ~CpuShading();
  CpuShading(const CpuShading&) = delete;
  CpuShading& operator=(const CpuShading&) = delete;

  // Tristimulus of the pixel whose centre is at uv ∈ [0, 1]² (GL window convention). Not
  // thread-safe: the kernel keeps the texel being shaded.
  glm::vec3 shade(const GBufferTexel& texel, const glm::vec2& uv, const CameraTransform& camera);

 private:
  struct Kernel;
  std::unique_ptr<Kernel> mKernel;
};

}  // namespace prism::render
