// The GPU side of the technique seam: a technique's passes before the lighting pass (the sky's
// tables) and what they give the lighting pass beyond the technique's block. Each technique with
// GPU passes implements one in techniques/<name>/gpu/ (above prism::gpu and prism::scene, below
// the renderer); the renderer makes one per section (makeTechniquePass, over the passes the
// techniques' prism_technique() calls register), runs it each frame and binds it for the
// lighting pass.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "scene/camera_transform.h"
#include "scene/scene.h"
#include "techniques/technique_cpu_twin.h"
#include "techniques/technique_section.h"

namespace prism {

class TechniquePass {
 public:
  virtual ~TechniquePass() = default;
  // This frame's work, from the technique's block, the scene (its lights) and the camera.
  virtual void run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera) = 0;
  // Binds what the lighting pass reads of it (the bindings its shared GLSL header declares).
  virtual void bindForLighting() const = 0;
  virtual std::size_t gpuMemoryBytes() const = 0;
  // What it holds for the lighting pass, read back for the technique's CPU twin
  // (technique_cpu_twin.h); null when it holds nothing the twin reads. Stalls: for tests.
  virtual std::shared_ptr<const TechniqueTexels> readTexels() const { return nullptr; }
};

// The passes of the technique of that key (an OpenGL context must be current; compiles their
// shaders); null for a technique without GPU passes.
std::unique_ptr<TechniquePass> makeTechniquePass(std::string_view key);

}  // namespace prism
