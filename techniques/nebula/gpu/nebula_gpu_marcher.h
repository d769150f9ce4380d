// The nebula's GPU ray marcher (Barrès 2023): the projection, light–density and reference methods
// of NebulaRenderer::render as compute passes over what a NebulaRenderer precomputed
// (nebula_precomputed.h), uploaded once: the density grid as a 3D texture, each star's optical
// depth per voxel (projection) or the 2D basis's light coefficients per voxel (light–density) as
// a second one, four values a texel; the table of the basis's coefficients, stars and lines as
// buffers; the reference's wavelength nodes and weights per march (they follow its settings).
//   march   shaders/passes/nebula_march.comp: front to back, early termination, per pixel the
//           moments on the basis (per star, or per 2D element) and the emission lines' colour
//   finish  shaders/passes/nebula_finish.comp: the filters' weights times the moments; a filter
//           change re-runs only this
// Per pixel it computes what the CPU marcher computes, in float where the CPU accumulates in
// double (nebula_gpu_test holds the two together). A GL 4.5 context must be current.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

class NebulaGpuMarcher {
 public:
  // Uploads the renderer's grids and tables; the renderer must outlive the marcher. Error when a
  // field's slabs exceed GL_MAX_3D_TEXTURE_SIZE along z (nz·⌈stars/4⌉: 2048 allows 64 stars at 128³).
  explicit NebulaGpuMarcher(const NebulaRenderer& renderer);

  // Whether the GPU marches `method` (projection, light–density and the reference: the paper's
  // double integration, the baseline its speed is measured against).
  static bool supports(Method method);

  // Marches every pixel (settings: method, steps, emission lines; the basis sizes are the
  // renderer's). Error for a method it does not march or a basis size the renderer was not built for.
  void march(const RenderSettings& settings);
  // Turns the last march's moments into the image through the renderer's filter weights.
  NebulaImage finish();
  // march + finish.
  NebulaImage render(const RenderSettings& settings);

  // The last march's moments, [v·pixels + pixel] (nebula_march.comp), and the finish's weights
  // for its method, [(group·3 + channel)·card + j]: what the twin test bounds its rounding by.
  std::vector<float> readMoments() const;
  const std::vector<float>& finishWeights() const;
  int groups() const { return mCount; }
  int card() const { return mCard; }

  std::size_t gpuMemoryBytes() const;

 private:
  const NebulaRenderer& mRenderer;
  gpu::Program mProjection, mLightDensity, mReference, mFinish;
  gpu::Texture3D mDensity, mStarDepth, mLightCoefficients;
  gpu::Buffer mMomentLo, mMomentHi, mBasisMatrix, mStars, mLines;
  std::vector<float> mProjectionWeightValues, mLightWeightValues;
  gpu::Buffer mProjectionWeights, mLightWeights;
  gpu::Buffer mMoments, mLineColour, mColour, mReferenceNodes;
  Method mMarched = Method::Projection;
  int mCount = 0;  // moment groups of the last march: stars, or 2D elements (none for the reference)
  int mCard = 0;
};

}  // namespace prism::nebula
