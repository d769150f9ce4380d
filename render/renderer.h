// The deferred spectral rasteriser: for each frame, shadow maps for the lights that cast them,
// the G-buffer, the techniques' passes, the spectral lighting pass (accumulating into a
// tristimulus target), the forward passes of objects techniques shade themselves (PRT's) and of
// light gizmos over the G-buffer's copied depth, and the post pass to an 8-bit display image. Settings change between frames without a restart;
// accumulation restarts whenever they (or the camera, or the scene) change. Nothing drawn into the
// shadow maps or the G-buffer changes while frames accumulate (no jitter: pixel centres), so only
// a frame that restarts accumulation draws them; the others draw from the lighting pass on.
//
// The per-frame CPU work is small (wavelengths, integration matrices and spectra at them:
// buildFrameData); everything per pixel runs in shaders/passes over shaders/shared.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "gpu/vertex_array.h"
#include "scene/camera_transform.h"
#include "techniques/technique_pass.h"
#include "render/display_transform.h"
#include "render/frame_context.h"
#include "render/frame_data.h"
#include "render/frame_settings.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"
#include "render/shadow_views.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::render {

class Renderer {
 public:
  // An OpenGL 4.5 context must be current for the renderer's whole life. The table is the
  // Jakob–Hanika table of the scene's colour space; both must outlive the renderer.
  Renderer(const Scene& scene, const RgbToSpectrumTable& table, const FrameSettings& settings);
  Renderer(Scene&&, const RgbToSpectrumTable&, const FrameSettings&) = delete;  // held by reference
  Renderer(const Scene&, RgbToSpectrumTable&&, const FrameSettings&) = delete;

  const FrameSettings& settings() const { return mSettings; }
  const FrameContext& context() const { return mContext; }  // the settings' names, resolved
  // Validated first; on any failure the renderer is left as it was. Accumulation restarts
  // unless only the display transform changed (exposure, tone map, white balance, display).
  void setSettings(const FrameSettings& settings);
  void setCamera(const Camera& camera);  // restarts accumulation
  // The scene held by reference was edited (lights, materials, water: not its meshes or
  // textures): shadow views are planned again, the Lights strategy's pdf follows the lights and
  // accumulation restarts.
  void sceneChanged();
  // Compiles every pass's shaders again from their files (shaderDirectory()); on failure throws
  // gpu::GpuError with the first error as FILE:LINE and keeps the programs it had.
  void reloadShaders();
  const Camera& camera() const { return mCamera; }
  // The next frame starts a new accumulation and draws the G-buffer and every shadow map again,
  // as if every light had moved (a bench's worst case; the other restarts redraw a shadow map
  // only where its view moved).
  void resetAccumulation();

  // Pass boundaries for timing (e.g. gpu timer scopes): called with "shadow", "gbuffer",
  // "atmosphere" (scenes with a sky), "lighting", "prt" (the forward pass of scenes with PRT
  // objects), "nebula" (the nebula's march, then again its composite: a technique that works
  // both before lighting and after it is named twice a frame), "forward", "post" before each pass and with "" after the last.
  using PassHook = std::function<void(std::string_view pass)>;
  void setPassHook(PassHook hook) { mPassHook = std::move(hook); }

  // Renders one frame into the accumulation and display targets (the shadow maps and the
  // G-buffer only when accumulation restarts: "shadow" and "gbuffer" are then not hooked; of the
  // shadow maps, only those whose view moved since they were drawn).
  void renderFrame();
  int accumulatedFrames() const { return mAccumulated; }
  int shadowLayersDrawn() const { return mShadowLayersDrawn; }  // by the last frame

  // Read-backs (they stall; not for a frame loop). Rows top first.
  std::vector<std::uint8_t> readDisplayRgba8() const;
  std::vector<float> readMeanTristimulus() const;  // rgb per pixel, the mean of the frames so far

  // The GPU memory it holds now, in bytes, from the sizes of its textures (render targets,
  // shadow maps, the upsampling table, the scene's images, the sky's tables) and buffers
  // (meshes, per-frame data, the sky's); programs and vertex arrays are not counted. Per-frame
  // buffers only grow: after a switch to fewer wavelengths they keep their largest size.
  std::size_t gpuMemoryBytes() const;

  // What the last frame used, for the CPU twin and tests.
  const FrameData& frameData() const { return mFrame; }
  const CameraTransform& cameraTransform() const { return mCameraTransform; }
  const std::vector<ShadowView>& shadowViews() const { return mShadows.views; }
  const gpu::Texture2D& albedoMetallic() const { return mTargets.albedoMetallic; }
  const gpu::Texture2D& normalRoughness() const { return mTargets.normalRoughness; }
  const gpu::Texture2D& materialId() const { return mTargets.materialId; }
  const gpu::Texture2D& depth() const { return mTargets.depth; }
  const gpu::Texture2D& coefficients() const { return mTargets.coefficients; }  // when the G-buffer has them
  const gpu::Texture2D& emission() const { return mTargets.emission; }  // glTF's emissive colour
  const gpu::Texture2DArray& shadowMaps() const { return mShadows.maps; }
  const gpu::Texture2D& accumulation() const { return mTargets.accumulation; }
  const gpu::Framebuffer& displayFramebuffer() const { return mTargets.displayTarget; }
  // The passes of the technique of that key (the sky's tables) as of the last frame; null when
  // the scene has no such technique or it has no GPU passes.
  const TechniquePass* techniquePass(std::string_view key) const;

 private:
  // Everything sized by the image: built whole, then swapped in.
  struct Targets {
    gpu::Texture2D albedoMetallic, normalRoughness, materialId, depth, emission;
    gpu::Texture2D coefficients;  // GBufferAlbedo::Coefficients only
    gpu::Texture2D accumulation, forwardDepth, display;
    gpu::Framebuffer gbuffer, accumulationTarget, forwardTarget, displayTarget;
  };
  // Everything sized by the shadow-map resolution.
  struct Shadows {
    std::vector<ShadowView> views;
    gpu::Texture2DArray maps;
    std::vector<gpu::Framebuffer> framebuffers;  // one per view
    // Per layer, the view its depths were drawn from (none: not drawn since made or invalidated).
    // The meshes are the renderer's for life, so a layer whose view is unchanged is not drawn again.
    std::vector<std::optional<glm::mat4>> drawnFrom;
  };
  static Targets makeTargets(int width, int height, GBufferAlbedo albedo);
  static ShadowCascading shadowCascading(const FrameSettings& settings, const Camera& camera);
  static Shadows makeShadows(const Scene& scene, int mapSize, const ShadowCascading& cascading);
  // Plans the views again (the lights, the camera), the maps made again only when their number changes.
  void planShadows();
  void hook(std::string_view pass) const;
  void shadowPass();
  void gbufferPass();
  void lightingPass();
  void forwardPass();
  void forwardTechniques();
  void postPass();
  void techniquePasses();
  TechniqueFrame techniqueFrame() const;
  void uploadFrameData();

  const Scene& mScene;
  const RgbToSpectrumTable& mTable;
  FrameSettings mSettings;
  Camera mCamera;
  CameraTransform mCameraTransform;
  Bounds mBounds;
  GpuScene mGpuScene;
  gpu::Texture3D mUpsamplingTable;
  FrameContext mContext;               // mSettings' names, resolved
  DisplayTransform mDisplayTransform;  // of mSettings and the camera's exposure
  FrameData mFrame;
  int mAccumulated = 0;
  int mShadowLayersDrawn = 0;
  float mGizmoSum = 0.0f;  // the light markers' scale summed in the accumulation (forwardPass)
  std::uint32_t mFrameIndex = 0;
  PassHook mPassHook;

  gpu::Program mShadowProgram, mGBufferProgram, mGBufferCoefficientsProgram, mForwardProgram, mPostProgram;
  std::map<std::string, gpu::Program> mLightingPrograms;  // per variant of techniques (#defines)
  gpu::VertexArray mFullScreen;
  GpuMesh mGizmo;  // a unit sphere
  Shadows mShadows;
  Targets mTargets;
  gpu::Buffer mFrameConstants, mBatches, mLights, mMaterials, mLightSpectra, mMaterialSpectra;
  struct TechniqueBuffers {
    gpu::Buffer constants, data;
  };
  std::map<std::string, TechniqueBuffers> mTechniqueBuffers;  // per technique key
  // Per technique key, made for the first frame with its section (null: no GPU passes).
  std::map<std::string, std::unique_ptr<TechniquePass>> mTechniquePasses;
};

}  // namespace prism::render
