// The nebula's GPU ray marcher (Barrès 2023): every method of NebulaRenderer::render (reference,
// analytic, projection, light–density, pre-integration) as compute passes over what a
// NebulaRenderer precomputed
// (nebula_precomputed.h), uploaded once: the density grid as a 3D texture, each star's optical
// depth per voxel (projection) or the 2D basis's light coefficients per voxel (light–density) as
// a second one, four values a texel, and the ionisation zones (if any) as a third; the table of the basis's coefficients, stars and lines as
// buffers; the reference's wavelength nodes and weights when its settings change; the
// analytic method's passband pieces and pre-integration's tables when first marched.
//   march   shaders/passes/nebula_march.comp: front to back, early termination, per pixel the
//           moments on the basis (per star, or per 2D element) and each emission line's light
//   finish  shaders/passes/nebula_finish.comp: the filters' weights times the moments, and their
//           responses at the lines times the lines' light; after projection or light–density a
//           filter change (refilter) re-runs only this
// Per pixel it computes what the CPU marcher computes, in float where the CPU accumulates in
// double (nebula_gpu_test holds the two together). A GL 4.5 context must be current.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "techniques/nebula/gpu/nebula_march_segments.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

// Where a march looks from, in the unit cube's coordinates: a pinhole camera and its image
// (the ray through pixel (x, y), row 0 at the top, is forward + u·right + v·up, u and v spanning
// ±tanHalf·aspect and ±tanHalf), and optionally the scene in front of the nebula: a depth texture
// of the image's size (GL window depth, row 0 at the bottom; 1: nothing there), turned into a
// distance along each ray by `inverseProjection` (window depth → view space, world units) times
// `cubePerWorld`: each ray stops there.
struct MarchView {
  glm::vec3 position{0.5f, 0.5f, -1.0f};
  glm::vec3 forward{0.0f, 0.0f, 1.0f}, right{-1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
  float tanHalf = 0.414f, aspect = 1.0f;
  int width = 128, height = 128;
  GLuint depthTexture = 0;  // none
  glm::mat4 inverseProjection{1.0f};
  float cubePerWorld = 1.0f;
};
// The view of a nebula scene's own camera, as the CPU marcher builds its rays.
MarchView marchView(const NebulaCamera& camera);

// Error, before any precomputation (or the density's generation), when the optical depths of
// `stars` stars would not fit this GPU (a current context's) over a density of `voxelsZ` along z:
// they stack ⌈stars/4⌉ copies of the grid along a 3D texture's z. Only where they are read:
// every method but light-density, and the lighting of surfaces by the stars.
void requireGpuFits(int voxelsZ, std::size_t stars);
// Error when the march's per-pixel moments (`count` stars for projection, light functions for
// light-density, each `card` elements, over `pixels`) outgrow what the shaders index: 2³¹ floats
// (8 stars × 4 elements at 8192²). Checked by every march; the command line checks it before any
// work too.
void requireMomentsFit(std::size_t count, std::string_view what, int card, std::size_t pixels);

class NebulaGpuMarcher {
 public:
  // Uploads the renderer's grids and tables; the renderer must outlive the marcher. Error when a
  // field's slabs exceed GL_MAX_3D_TEXTURE_SIZE along z (nz·⌈stars/4⌉: 2048 allows 64 stars at 128³),
  // or for more than kMaxLines emission lines (those of the model's groups) or kMaxZones zones.
  explicit NebulaGpuMarcher(const NebulaRenderer& renderer);
  static constexpr int kMaxLines = 16;  // nebula_march.comp's kMaxNebulaLines
  static constexpr int kMaxZones = 8;   // its two slabs of uZones

  // The same volume through other filters or passbands: `renderer` is the refiltered copy of this
  // marcher's (NebulaRenderer's refiltering constructor) and replaces it (it must outlive the
  // marcher). Uploads what the filters change: the lines' responses, the finish's weights; the
  // analytic pieces and pre-integration tables are made again at their next march. True when the
  // last march still holds, so that finish() shows the new filters without marching: after
  // projection or light–density (the paper's point); false after the direct methods.
  bool refilter(const NebulaRenderer& renderer);

  // Marches every pixel (settings: method, steps, emission lines; the basis sizes are the
  // renderer's). Error for a basis size the renderer was not built for.
  void march(const RenderSettings& settings);
  // The same from another view (the renderer's camera, nebula_pass.h).
  void march(const RenderSettings& settings, const MarchView& view);
  // Turns the last march's moments into the image through the renderer's filter weights.
  NebulaImage finish();
  // The same, left on the GPU: colour() holds the image, a vec4 a pixel (alpha 0), row 0 at the top.
  void finishOnGpu();
  const gpu::Buffer& colour() const { return mColour; }
  // The last march's optical depth g (µm) from the camera to where each ray stopped, R32F, the
  // image's size, row 0 at the bottom (shared/nebula_lighting.glsl).
  const gpu::Texture2D& opticalDepth() const { return mOpticalDepth; }
  // Each star's optical depth g_s (µm) per voxel, RGBA32F, star s in lane s % 4 of the z-slab s / 4
  // (nebula_march.comp's uField for every method but light-density, and the lighting pass's where
  // the stars light surfaces; a 1×1×1 zero texel without stars). Uploaded when first asked for, so
  // that light-density, which reads none, marches any number of stars; Error (requireGpuFits)
  // when they do not fit this GPU.
  const gpu::Texture3D& starDepth();
  // march + finish.
  NebulaImage render(const RenderSettings& settings);

  // The last march's moments, [v·pixels + pixel] (nebula_march.comp), and the finish's weights
  // for its method, [(group·3 + channel)·card + j]: what the twin test bounds its rounding by.
  std::vector<float> readMoments() const;
  const std::vector<float>& finishWeights() const;
  int groups() const { return mCount; }
  int card() const { return mCard; }
  int lines() const { return mLineCount; }  // lines the last march wrote

  std::size_t gpuMemoryBytes() const;

  // The loop iterations each dispatch of a march may run (nebula_march_segments.h): by default
  // three quarters of the driver's limit (gpu::shaderLoopIterationLimit, a margin for loops the
  // bound takes as unrolled), none without one. Tests set less to split any march.
  void setLoopBudget(std::optional<long> budget) { mLoopBudget = budget; }
  int dispatches() const { return mDispatches; }  // the last march's
  const MarchLoopCost& loopCost() const { return mLoopCost; }  // what the last march was split by

 private:
  void uploadFilters();  // the lines' responses and the finish's weights
  // The reference's nodes and weights for these settings, unless the last upload was for them.
  void uploadReferenceNodes(const RenderSettings& settings);
  MarchLoopCost loopCost(Method method, const NebulaPrecomputed& pre) const;

  const NebulaRenderer* mRenderer;
  gpu::Program mProjection, mLightDensity, mReference, mAnalytic, mPreIntegration, mFinish;
  // The reference for at most kNarrowNodes nodes a channel (the paper's baseline, 7): its node loop
  // in chunks of 4, not 16, so that it evaluates 8 nodes a channel and not 16 — and runs at most
  // twice the loop iterations, which llvmpipe caps (nebula_march.comp). Compiled at its first march.
  static constexpr int kNarrowNodes = 8;
  std::optional<gpu::Program> mReferenceNarrow;
  // How mReferenceNodes is laid out, and for which settings (uniform samples, Simpson intervals):
  // per channel, its nodes padded to a multiple of the chunk; chunk 0: none uploaded.
  struct NodeLayout {
    glm::ivec2 key{0};
    glm::ivec3 count{0};
    int stride = 0, chunk = 0;
  };
  NodeLayout mNodes;
  gpu::Texture3D mDensity, mStarDepth, mLightCoefficients, mZones;
  gpu::Buffer mMomentLo, mMomentHi, mBasisMatrix, mStars, mLines;
  std::vector<float> mProjectionWeightValues, mLightWeightValues;
  gpu::Buffer mProjectionWeights, mLightWeights;
  gpu::Buffer mMoments, mMarchedValues, mColour, mReferenceNodes;  // mMarchedValues: nebula_march.comp's Marched
  gpu::Texture2D mOpticalDepth;
  gpu::Buffer mAnalyticRanges, mAnalyticPieces, mPreIntegrated;  // made when first marched
  Method mMarched = Method::Projection;
  glm::ivec2 mSize{0};  // of the last march's image
  int mCount = 0;  // moment groups of the last march: stars, or 2D elements (none for the direct methods)
  int mCard = 0;
  int mLineCount = 0;
  std::optional<long> mLoopBudget;
  int mDispatches = 0;
  MarchLoopCost mLoopCost;
};

}  // namespace prism::nebula
