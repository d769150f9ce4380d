// The GPU side of the technique seam: a technique's passes before the lighting pass (the sky's
// tables), what they give the lighting pass beyond the technique's block, and a forward pass of
// the objects the technique shades itself (PRT's), drawn after the lighting pass into the same
// tristimulus target. Each technique with
// GPU passes implements one in techniques/<name>/gpu/ (above prism::gpu and prism::scene, below
// the renderer); the renderer makes one per section (makeTechniquePass, over the passes the
// techniques' prism_technique() calls register), runs it each frame and binds it for the
// lighting pass.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string_view>

#include <glm/glm.hpp>

#include "scene/camera_transform.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "scene/scene.h"
#include "techniques/technique_cpu_twin.h"
#include "techniques/technique_section.h"

namespace prism {

// The frame a technique's passes work in: its size, the G-buffer's depth (GL texture name;
// DEPTH_COMPONENT, window depth, 1 where nothing was drawn: for a pass that marches a volume up
// to the scene's surfaces, the nebula's) and its mode, for a technique with baselines of its own:
// RGB (PRT draws RGB-PRT) or the many-wavelength reference (PRT draws its 5 nm reference, the
// nebula marches its double integration); otherwise the section decides.
struct TechniqueFrame {
  int width = 0, height = 0;
  unsigned depthTexture = 0;
  bool rgbMode = false;
  bool referenceMode = false;
  // XYZ → the frame's tristimulus: identity, or a camera observer's inverse matrix (its
  // tristimulus is camera RGB), for a pass that adds a colour it knows as XYZ.
  glm::mat3 fromXyz{1.0f};
};

// What a technique's forward pass draws with. The renderer has bound the accumulation target with
// the G-buffer's depth (in which the technique's objects were drawn, the lighting pass leaving
// their pixels black), depth test LEQUAL without depth writes, additive blending; the pass adds
// (tristimulus, 0) per fragment, alpha 0 so that the lighting pass's frame count stays the mean's
// denominator. Tristimulus is the lighting pass's: XYZ of `observer`, or a camera's RGB when
// `observer` is a camera's curves. Its vertex shader must declare `invariant gl_Position` and
// compute it as gbuffer.vert does (viewProjection × world position) for the depths to be equal.
// What every technique binds for the lighting pass (bindForLighting) is bound again before each
// forward pass, so a pass compiled with the scene's technique defines may read it as the lighting
// pass does (PRT's fragments read the nebula's optical depth).
struct ForwardDrawInput {
  const Scene& scene;
  const CameraTransform& camera;
  const Observer& observer;
  const RgbToSpectrumTable& table;  // the scene's colour space's (albedo upsampling)
  // A pass that composites a volume rather than drawing objects (the nebula's) may turn the depth
  // test off, and turns it back on.
  TechniqueFrame frame;
};

class TechniquePass {
 public:
  virtual ~TechniquePass() = default;
  // This frame's work, from the technique's block, the scene (its lights) and the camera, after
  // the G-buffer pass and before lighting.
  virtual void run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera,
                   const TechniqueFrame& frame) = 0;
  // Binds what the lighting pass reads of it (the bindings its shared GLSL header declares).
  virtual void bindForLighting() const = 0;
  virtual std::size_t gpuMemoryBytes() const = 0;
  // What it holds for the lighting pass, read back for the technique's CPU twin
  // (technique_cpu_twin.h); null when it holds nothing the twin reads. Stalls: for tests.
  virtual std::shared_ptr<const TechniqueTexels> readTexels() const { return nullptr; }
  // Whether it draws objects itself (the scene's meshes whose `technique` is its key): the
  // renderer then calls drawForward after the lighting pass and times that, not run(), under the
  // technique's key.
  virtual bool drawsForward() const { return false; }
  // Draws the technique's objects (see ForwardDrawInput); may prepare on first use (PRT: the
  // transfer from its cache or a bake, the basis and projections) and when its section changed.
  virtual void drawForward(const ForwardDrawInput& /*input*/) {}
};

// The passes of the technique of that key (an OpenGL context must be current; compiles their
// shaders); null for a technique without GPU passes.
std::unique_ptr<TechniquePass> makeTechniquePass(std::string_view key);

// done / total of a precomputation, `what` naming it ("PRT transfer bake"); called from one thread
// at a time, and not at all when the result was cached.
using TechniqueProgress = std::function<void(std::string_view what, std::size_t done, std::size_t total)>;

// The long work a scene's techniques do from the scene alone before their first frame, done ahead
// into their caches, with progress, so that the passes find it there (PRT's transfer bake); no
// OpenGL. A pass class takes part by defining `static void precompute(const Scene&, const
// TechniqueProgress&)`. Errors as the work's own.
void precomputeTechniques(const Scene& scene, const TechniqueProgress& progress);

// With an OpenGL context current, refuses a scene this GPU cannot hold (a limit of its textures)
// before the work of precomputeTechniques, which would otherwise end in the same error at the
// first frame. A pass class takes part by defining `static void requireFits(const Scene&)`.
void requireTechniquesFit(const Scene& scene);

}  // namespace prism
