// The deferred spectral rasteriser: for each frame, shadow maps for the lights that cast them,
// the G-buffer, the spectral lighting pass (accumulating into a tristimulus target), a forward
// pass over the G-buffer's copied depth (light gizmos) and the post pass to an 8-bit display
// image. Settings change between frames without a restart;
// accumulation restarts whenever they (or the camera) change.
//
// The per-frame CPU work is small (wavelengths, integration matrices and spectra at them:
// buildFrameData); everything per pixel runs in shaders/passes over shaders/shared.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "gpu/vertex_array.h"
#include "render/camera_transform.h"
#include "render/frame_data.h"
#include "render/frame_settings.h"
#include "render/gpu_scene.h"
#include "render/scene.h"
#include "render/shadow_views.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::render {

class Renderer {
 public:
  // An OpenGL 4.5 context must be current for the renderer's whole life. The table is the
  // Jakob–Hanika table of the scene's colour space; both must outlive the renderer.
  Renderer(const Scene& scene, const RgbToSpectrumTable& table, const FrameSettings& settings);

  const FrameSettings& settings() const { return mSettings; }
  void setSettings(const FrameSettings& settings);
  void setCamera(const Camera& camera);  // restarts accumulation
  const Camera& camera() const { return mCamera; }
  void resetAccumulation() { mAccumulated = 0; }

  // Pass boundaries for timing (e.g. gpu timer scopes): called with "shadow", "gbuffer",
  // "lighting", "forward", "post" before each pass and with "" after the last.
  using PassHook = std::function<void(std::string_view pass)>;
  void setPassHook(PassHook hook) { mPassHook = std::move(hook); }

  // Renders one frame into the accumulation and display targets.
  void renderFrame();
  int accumulatedFrames() const { return mAccumulated; }

  // Read-backs (they stall; not for a frame loop). Rows top first.
  std::vector<std::uint8_t> readDisplayRgba8() const;
  std::vector<float> readMeanTristimulus() const;  // rgb per pixel, the mean of the frames so far

  // What the last frame used, for the CPU twin and tests.
  const FrameData& frameData() const { return mFrame; }
  const CameraTransform& cameraTransform() const { return mCameraTransform; }
  const std::vector<ShadowView>& shadowViews() const { return mShadowViews; }
  const gpu::Texture2D& albedoMetallic() const { return mAlbedoMetallic; }
  const gpu::Texture2D& normalRoughness() const { return mNormalRoughness; }
  const gpu::Texture2D& materialId() const { return mMaterialId; }
  const gpu::Texture2D& depth() const { return mDepth; }
  const gpu::Texture2DArray& shadowMaps() const { return mShadowMaps; }
  const gpu::Texture2D& accumulation() const { return mAccumulation; }

 private:
  void createTargets();
  void createShadowMaps();
  void hook(std::string_view pass) const;
  void shadowPass();
  void gbufferPass();
  void lightingPass();
  void forwardPass();
  void postPass();
  void uploadFrameData();

  const Scene& mScene;
  const RgbToSpectrumTable& mTable;
  FrameSettings mSettings;
  Camera mCamera;
  CameraTransform mCameraTransform;
  GpuScene mGpuScene;
  gpu::Texture3D mUpsamplingTable;
  std::vector<ShadowView> mShadowViews;
  FrameData mFrame;
  int mAccumulated = 0;
  std::uint32_t mFrameIndex = 0;
  PassHook mPassHook;

  gpu::Program mShadowProgram, mGBufferProgram, mLightingProgram, mForwardProgram, mPostProgram;
  gpu::VertexArray mFullScreen;
  GpuMesh mGizmo;  // a unit sphere
  gpu::Texture2DArray mShadowMaps;
  std::vector<gpu::Framebuffer> mShadowFramebuffers;
  gpu::Texture2D mAlbedoMetallic, mNormalRoughness, mMaterialId, mDepth;
  gpu::Texture2D mAccumulation, mForwardDepth, mDisplay;
  gpu::Framebuffer mGBuffer, mAccumulationTarget, mForwardTarget, mDisplayTarget;
  gpu::Buffer mBatches, mLights, mMaterials, mLightSpectra, mMaterialSpectra;
};

}  // namespace prism::render
