#include "techniques/nebula/gpu/nebula_gpu_marcher.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include "core/data_files.h"
#include "core/error.h"
#include "gpu/compute.h"
#include "techniques/nebula/nebula_precomputed.h"

namespace prism::nebula {
namespace {

gpu::Program computeProgram(const char* file, const char* label, std::vector<gpu::ShaderDefine> defines = {}) {
  gpu::ProgramDesc desc;
  desc.compute = shaderDirectory() / "passes" / file;
  desc.includeDirs = {shaderDirectory()};
  desc.defines = std::move(defines);
  desc.label = label;
  return gpu::Program(desc);
}

// A uniform the variant may have compiled away (the light–density march reads no stars).
template <class T>
void setIfActive(const gpu::Program& program, std::string_view name, const T& value) {
  if (program.hasUniform(name)) program.setUniform(name, value);
}

// Error "WHAT need S slabs of NZ texels along z (S·NZ), more than …" unless ⌈width/4⌉ slabs of nz
// texels fit along a 3D texture's z on this GPU.
void requireSlabsFit(int nz, int width, std::string_view what) {
  const int slabs = (width + 3) / 4;
  GLint maxDepth = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxDepth);
  if (static_cast<long>(nz) * slabs > maxDepth)
    throw Error(fmt::format("{} need {} slabs of {} texels along z ({}), more than this GPU's 3D textures hold ({})", what,
                            slabs, nz, static_cast<long>(nz) * slabs, maxDepth));
}

// Per-voxel fields of `width` values as an RGBA32F texture of ⌈width/4⌉ slabs stacked along z
// (nebula_march.comp's uField); a 1×1×1 zero texel for none.
gpu::Texture3D fieldTexture(int nx, int ny, int nz, int width, const std::vector<const VoxelField*>& fields,
                            const char* label) {
  gpu::Texture3DDesc desc;
  desc.internalFormat = GL_RGBA32F;
  desc.format = GL_RGBA;
  desc.label = label;
  std::vector<float> texels;
  if (width == 0) {
    texels.assign(4, 0.0f);
    desc.texels = texels;
    return gpu::Texture3D(desc);
  }
  requireSlabsFit(nz, width, fmt::format("nebula: {} ({} values a voxel)", label, width));
  const int slabs = (width + 3) / 4;
  const std::size_t voxels = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
  texels.assign(voxels * static_cast<std::size_t>(slabs) * 4, 0.0f);
  // Value c of the fields: field c of one each (the stars' depths), or value c of a single one.
  for (int c = 0; c < width; ++c) {
    const VoxelField& f = fields.size() == 1 ? *fields[0] : *fields[static_cast<std::size_t>(c)];
    const int within = fields.size() == 1 ? c : 0;
    const auto slab = static_cast<std::size_t>(c / 4), lane = static_cast<std::size_t>(c % 4);
    for (std::size_t v = 0; v < voxels; ++v)
      texels[(slab * voxels + v) * 4 + lane] =
          f.values[v * static_cast<std::size_t>(f.width) + static_cast<std::size_t>(within)];
  }
  desc.width = nx;
  desc.height = ny;
  desc.depth = nz * slabs;
  desc.texels = texels;
  return gpu::Texture3D(desc);
}

template <class T>
gpu::Buffer bufferOf(std::vector<T> values, const char* label) {
  if (values.empty()) values.resize(1);  // GL buffers are never empty; the counts say what is read
  return gpu::Buffer::fromSpan(std::span<const T>(values), label);
}

}  // namespace

NebulaGpuMarcher::NebulaGpuMarcher(const NebulaRenderer& renderer)
    : mRenderer(&renderer),
      mProjection(computeProgram("nebula_march.comp", "nebula march (projection)")),
      mLightDensity(computeProgram("nebula_march.comp", "nebula march (light-density)", {{"NEBULA_LIGHT_DENSITY", ""}})),
      mReference(computeProgram("nebula_march.comp", "nebula march (reference)", {{"NEBULA_REFERENCE", ""}})),
      mAnalytic(computeProgram("nebula_march.comp", "nebula march (analytic)", {{"NEBULA_ANALYTIC", ""}})),
      mPreIntegration(computeProgram("nebula_march.comp", "nebula march (pre-integration)", {{"NEBULA_PRE_INTEGRATION", ""}})),
      mFinish(computeProgram("nebula_finish.comp", "nebula finish")) {
  if (const std::optional<long> limit = gpu::shaderLoopIterationLimit()) mLoopBudget = *limit * 3 / 4;
  const NebulaPrecomputed& pre = renderer.precomputed();
  const DensityGrid& d = pre.model.density;
  gpu::Texture3DDesc density;
  density.width = d.nx;
  density.height = d.ny;
  density.depth = d.nz;
  density.internalFormat = GL_R32F;
  density.format = GL_RED;
  density.texels = d.values;
  density.label = "nebula density";
  mDensity = gpu::Texture3D(density);

  mLightCoefficients = fieldTexture(d.nx, d.ny, d.nz, pre.lightCount, {&pre.lightCoefficients}, "nebula light coefficients");
  if (pre.lineZones.width > kMaxZones)
    throw Error(fmt::format("nebula: {} ionisation zones, the GPU march holds {}", pre.lineZones.width, kMaxZones));
  mZones = fieldTexture(d.nx, d.ny, d.nz, pre.lineZone.empty() ? 0 : pre.lineZones.width, {&pre.lineZones},
                        "nebula ionisation zones");

  mMomentLo = bufferOf(pre.moments.lo, "nebula moments 0-3");
  mMomentHi = bufferOf(pre.moments.hi, "nebula moments 4-7");
  std::vector<glm::vec4> stars;
  for (const NebulaStar& s : pre.model.stars) stars.emplace_back(glm::vec3(s.position), static_cast<float>(s.luminosity));
  mStars = bufferOf(stars, "nebula stars");
  if (pre.lineLambdaUm.size() > static_cast<std::size_t>(kMaxLines))
    throw Error(fmt::format("nebula: {} emission lines, the GPU march holds {}", pre.lineLambdaUm.size(), kMaxLines));
  std::vector<float> basisM(64, 0.0f);
  for (Eigen::Index k = 0; k < pre.basis.m.rows(); ++k)
    for (Eigen::Index j = 0; j <= k; ++j) basisM[static_cast<std::size_t>(8 * k + j)] = static_cast<float>(pre.basis.m(k, j));
  mBasisMatrix = bufferOf(basisM, "nebula basis matrix");
  uploadFilters();
}

const gpu::Texture3D& NebulaGpuMarcher::starDepth() {
  if (mStarDepth.id() != 0) return mStarDepth;
  const NebulaPrecomputed& pre = mRenderer->precomputed();
  const DensityGrid& d = pre.model.density;
  requireGpuFits(d.nz, pre.starDepth.size());
  std::vector<const VoxelField*> depths;
  for (const VoxelField& f : pre.starDepth) depths.push_back(&f);
  mStarDepth = fieldTexture(d.nx, d.ny, d.nz, static_cast<int>(depths.size()), depths, "nebula star depths");
  return mStarDepth;
}

void NebulaGpuMarcher::uploadFilters() {
  const NebulaPrecomputed& pre = mRenderer->precomputed();
  std::vector<glm::vec4> lines;
  for (std::size_t l = 0; l < pre.lineLambdaUm.size(); ++l)
    lines.emplace_back(static_cast<float>(pre.lineLambdaUm[l]), glm::vec3(pre.lineResponse[l]));
  mLines = bufferOf(lines, "nebula lines");

  // The finish's weights, [(group·3 + channel)·card + j].
  const auto card = pre.basis.a.size();
  std::vector<float>& projection = mProjectionWeightValues;
  std::vector<float>& light = mLightWeightValues;
  projection.clear();
  light.clear();
  for (const auto& perStar : pre.projectionWeights)
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t j = 0; j < card; ++j) projection.push_back(static_cast<float>(perStar[c][j]));
  for (int k = 0; k < pre.lightCount; ++k)
    for (int c = 0; c < 3; ++c)
      for (std::size_t j = 0; j < card; ++j)
        light.push_back(static_cast<float>(pre.lightU[static_cast<std::size_t>((c * pre.lightCount + k) * 8) + j]));
  mProjectionWeights = bufferOf(projection, "nebula projection weights");
  mLightWeights = bufferOf(light, "nebula light-density weights");
}

bool NebulaGpuMarcher::refilter(const NebulaRenderer& renderer) {
  const NebulaPrecomputed &from = mRenderer->precomputed(), &to = renderer.precomputed();
  // The volume's own arrays stay uploaded: the refiltered copy has them bit for bit.
  PRISM_CHECK(to.model.density.values.size() == from.model.density.values.size() &&
              to.model.stars.size() == from.model.stars.size() && to.basis.a.size() == from.basis.a.size() &&
              to.lightCount == from.lightCount && to.lineWeight == from.lineWeight);
  mRenderer = &renderer;
  uploadFilters();
  mAnalyticRanges = {};
  mAnalyticPieces = {};
  mPreIntegrated = {};
  mNodes = {};  // the nodes' weights hold the filters
  return mMarched == Method::Projection || mMarched == Method::LightDensity;
}

void requireGpuFits(int voxelsZ, std::size_t stars) {
  requireSlabsFit(voxelsZ, static_cast<int>(stars), fmt::format("the optical depths of {} stars", stars));
}

void requireMomentsFit(std::size_t count, std::string_view what, int card, std::size_t pixels) {
  // The shaders index the buffer in int (nebula_march.comp, nebula_finish.comp). Not held to
  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE: llvmpipe advertises 128 MiB but binds whole buffers past it
  // (141 MB of moments matched the CPU twin); other drivers' limits were not measured.
  const double floats = static_cast<double>(count) * card * static_cast<double>(pixels);
  constexpr double kLimit = static_cast<double>(std::numeric_limits<std::int32_t>::max()) + 1.0;  // the last index fits
  if (floats > kLimit)
    throw Error(fmt::format("nebula: the march's moments, {} {} × {} elements × {} pixels, are {:.3g} floats, more than "
                            "the shaders index (2³¹): render fewer pixels{}",
                            count, what, card, pixels, floats,
                            what == "stars" ? " or stars, or by light-density, whose moments do not grow with the stars"
                                            : ""));
}

MarchView marchView(const NebulaCamera& cam) {
  // In double, as the CPU marcher builds it, then handed over in float.
  const NebulaViewFrame frame = viewFrame(cam);
  const glm::dvec3 &forward = frame.forward, &right = frame.right, &up = frame.up;
  MarchView v;
  v.position = glm::vec3(cam.position);
  v.forward = glm::vec3(forward);
  v.right = glm::vec3(right);
  v.up = glm::vec3(up);
  v.tanHalf = static_cast<float>(std::tan(cam.fovYDeg * std::numbers::pi / 360.0));
  v.aspect = static_cast<float>(static_cast<double>(cam.width) / cam.height);
  v.width = cam.width;
  v.height = cam.height;
  return v;
}

void NebulaGpuMarcher::uploadReferenceNodes(const RenderSettings& s) {
  const glm::ivec2 key(s.uniformSamples, s.referenceIntervals);
  if (mNodes.chunk != 0 && mNodes.key == key) return;
  // [(star·3 + channel)·stride + node]: (λ, weight), in chunks (nebula_march.comp)
  NebulaRenderer::ReferenceNodes nodes = mRenderer->referenceNodes(s);
  const std::size_t starCount = mRenderer->precomputed().model.stars.size();
  NodeLayout layout;
  layout.key = key;
  std::size_t most = 0;
  for (const auto& channel : nodes.lambdaUm) most = std::max(most, channel.size());
  layout.chunk = most <= static_cast<std::size_t>(kNarrowNodes) ? 4 : 16;
  if (layout.chunk == 4 && !mReferenceNarrow)
    mReferenceNarrow.emplace(computeProgram("nebula_march.comp", "nebula march (reference, narrow)",
                                            {{"NEBULA_REFERENCE", ""}, {"NEBULA_NODE_CHUNK", "4"}}));
  for (int c = 0; c < 3; ++c) {
    const int n = static_cast<int>(nodes.lambdaUm[static_cast<std::size_t>(c)].size());
    layout.count[c] = (n + layout.chunk - 1) / layout.chunk * layout.chunk;
    layout.stride = std::max(layout.stride, layout.count[c]);
  }
  // Padding: weight 0 at 1 µm (a finite e^(−x/λ) times nothing).
  const auto stride = static_cast<std::size_t>(layout.stride);
  std::vector<glm::vec2> packed(starCount * 3 * stride, glm::vec2(1.0f, 0.0f));
  for (std::size_t st = 0; st < starCount; ++st)
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t k = 0; k < nodes.lambdaUm[c].size(); ++k)
        packed[(st * 3 + c) * stride + k] =
            glm::vec2(static_cast<float>(nodes.lambdaUm[c][k]), static_cast<float>(nodes.weights[st][c][k]));
  mReferenceNodes = bufferOf(packed, "nebula reference nodes");
  mNodes = layout;
}

void NebulaGpuMarcher::march(const RenderSettings& s) { march(s, marchView(mRenderer->model().camera)); }

void NebulaGpuMarcher::march(const RenderSettings& s, const MarchView& view) {
  if (s.steps < 1) throw Error("nebula: steps must be ≥ 1");
  const NebulaPrecomputed& pre = mRenderer->precomputed();
  const NebulaModel& m = pre.model;
  mCard = static_cast<int>(pre.basis.a.size());
  if (s.basisSize != mCard)
    throw Error(fmt::format("nebula: the renderer was built for a basis of {} elements, not {}", mCard, s.basisSize));
  mMarched = s.method;
  const bool light = s.method == Method::LightDensity, reference = s.method == Method::Reference;
  const bool analytic = s.method == Method::Analytic, preIntegration = s.method == Method::PreIntegration;
  const bool direct = reference || analytic || preIntegration;  // into the colour, no moments
  mCount = light ? pre.lightCount : direct ? 0 : static_cast<int>(m.stars.size());
  if (analytic && mAnalyticRanges.sizeBytes() == 0) {  // [star·3 + channel]: (first, count, B bits, 0)
    std::vector<glm::ivec4> ranges;
    std::vector<shared::NebulaAnalyticPiece> pieces;
    static_assert(sizeof(shared::NebulaAnalyticPiece) == 6 * 16, "std430: six vec4, no padding");
    for (std::size_t st = 0; st < m.stars.size(); ++st)
      for (std::size_t c = 0; c < 3; ++c) {
        const auto& list = pre.analytic.f32[st][c];
        const auto wienB = static_cast<float>(pre.analytic.wienExponentUm[st]);
        ranges.emplace_back(static_cast<int>(pieces.size()), static_cast<int>(list.size()), std::bit_cast<int>(wienB), 0);
        pieces.insert(pieces.end(), list.begin(), list.end());
      }
    mAnalyticRanges = bufferOf(ranges, "nebula analytic ranges");
    mAnalyticPieces = bufferOf(pieces, "nebula analytic pieces");
  }
  if (preIntegration && mPreIntegrated.sizeBytes() == 0) {  // each star's table, one after another
    mRenderer->preparePreIntegration();
    std::vector<glm::vec4> tables;
    for (const MomentTable& t : pre.preIntegrated) {
      PRISM_CHECK(t.size == pre.moments.size && t.step == pre.moments.step);  // the march reads both with one spacing
      tables.insert(tables.end(), t.lo.begin(), t.lo.end());
    }
    mPreIntegrated = bufferOf(tables, "nebula pre-integration tables");
  }
  if (reference) uploadReferenceNodes(s);
  const std::size_t pixels = static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height);
  requireMomentsFit(static_cast<std::size_t>(mCount), light ? "light functions" : "stars", mCard, pixels);
  const std::size_t momentBytes = std::max<std::size_t>(1, static_cast<std::size_t>(mCount * mCard) * pixels) * sizeof(float);
  if (mMoments.sizeBytes() != momentBytes) mMoments = gpu::Buffer({momentBytes, nullptr, GL_DYNAMIC_STORAGE_BIT, "nebula moments"});
  mLineCount = s.emissionLines && m.emission != 0.0 ? static_cast<int>(pre.lineLambdaUm.size()) : 0;
  const std::size_t marchedBytes = static_cast<std::size_t>(3 + mLineCount) * pixels * sizeof(float);
  if (mMarchedValues.sizeBytes() != marchedBytes)
    mMarchedValues = gpu::Buffer({marchedBytes, nullptr, GL_DYNAMIC_STORAGE_BIT, "nebula marched"});
  if (mColour.sizeBytes() != pixels * sizeof(glm::vec4))
    mColour = gpu::Buffer({pixels * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT, "nebula colour"});
  if (mOpticalDepth.id() == 0 || mOpticalDepth.width() != view.width || mOpticalDepth.height() != view.height) {
    gpu::Texture2DDesc depth;
    depth.width = view.width;
    depth.height = view.height;
    depth.internalFormat = GL_R32F;
    depth.label = "nebula optical depth";
    mOpticalDepth = gpu::Texture2D(depth);
  }
  mSize = {view.width, view.height};

  const gpu::Program& p = light            ? mLightDensity
                          : reference      ? (mNodes.chunk == 4 ? *mReferenceNarrow : mReference)
                          : analytic       ? mAnalytic
                          : preIntegration ? mPreIntegration
                                           : mProjection;
  p.setUniform("uSize", mSize);
  p.setUniform("uCameraPosition", view.position);
  p.setUniform("uForward", view.forward);
  p.setUniform("uRight", view.right);
  p.setUniform("uUp", view.up);
  p.setUniform("uTanHalf", view.tanHalf);
  p.setUniform("uAspect", view.aspect);
  p.setUniform("uHasDepth", view.depthTexture ? 1 : 0);
  p.setUniform("uInverseProjection", view.inverseProjection);
  p.setUniform("uCubePerWorld", view.cubePerWorld);
  if (view.depthTexture) glBindTextureUnit(2, view.depthTexture);
  mOpticalDepth.bindImage(0, GL_READ_WRITE);
  p.setUniform("uSteps", s.steps);
  p.setUniform("uDepthPerDensity", static_cast<float>(kCtUm * m.extinction));
  setIfActive(p, "uScattering", static_cast<float>(m.scattering));
  setIfActive(p, "uEmission", static_cast<float>(m.emission));
  p.setUniform("uCount", direct ? static_cast<int>(m.stars.size()) : mCount);
  setIfActive(p, "uCard", mCard);
  setIfActive(p, "uNodeCount", mNodes.count);
  setIfActive(p, "uNodeStride", mNodes.stride);
  setIfActive(p, "uLineCount", mLineCount);
  setIfActive(p, "uZoneCount", pre.lineZone.empty() ? 0 : pre.lineZones.width);
  if (!pre.lineZone.empty() && p.hasUniform("uLineZone[0]"))  // where the shader reads it, every element
    for (std::size_t l = 0; l < pre.lineZone.size(); ++l) p.setUniform(fmt::format("uLineZone[{}]", l), pre.lineZone[l]);
  setIfActive(p, "uBasisLo", pre.basisLo);
  setIfActive(p, "uBasisHi", pre.basisHi);
  setIfActive(p, "uMomentStep", static_cast<float>(pre.moments.step));
  setIfActive(p, "uMomentSize", pre.moments.size);
  setIfActive(p, "uBandLoUm", static_cast<float>(kBandLoUm));
  setIfActive(p, "uBandHiUm", static_cast<float>(kBandHiUm));
  mDensity.bind(0);
  (light ? mLightCoefficients : starDepth()).bind(1);
  mZones.bind(3);
  mMomentLo.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  mMomentHi.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  mStars.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  mLines.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  mMoments.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
  mMarchedValues.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
  if (analytic) {
    mAnalyticRanges.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
    mAnalyticPieces.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  } else {
    mBasisMatrix.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  }
  if (reference) mReferenceNodes.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  if (preIntegration) mPreIntegrated.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  // In dispatches that each stay within the driver's loop budget (nebula_march_segments.h); the
  // optical depth is an image the next dispatch loads, the lighting pass fetches, tests read back.
  const MarchLoopCost cost = mLoopCost = loopCost(s.method, pre);
  const int lanes = shared::nebulaGroupLanes(mCard);
  const int items = direct ? static_cast<int>(m.stars.size()) : (mCount + lanes - 1) / lanes;
  const std::vector<MarchSegment> segments =
      mLoopBudget ? planMarchSegments(cost, s.steps, items, *mLoopBudget) : std::vector<MarchSegment>{{0, s.steps, 0, items}};
  for (const MarchSegment& segment : segments) {
    p.setUniform("uStepBegin", segment.stepBegin);
    p.setUniform("uStepEnd", segment.stepEnd);
    p.setUniform("uItemBegin", segment.itemBegin);
    p.setUniform("uItemEnd", segment.itemEnd);
    gpu::runCompute(p, {static_cast<GLuint>((view.width + 7) / 8), static_cast<GLuint>((view.height + 7) / 8), 1},
                    gpu::kDefaultComputeBarriers | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  mDispatches = static_cast<int>(segments.size());
}

// Upper bounds of nebula_march.comp's loop iterations (nebula_march_segments.h), loop by loop.
// Per step: the step loop, the zones' slabs (≤ 2) and the lines. Per star of a direct method: its
// slab and lane loops and the channels' (3); the reference's node chunks (the chunk itself
// unrolled); the analytic method's pieces, each its own loop's iteration and at most 2·3 more (the
// closed form's exponential integrals: the continued fraction's three chunks at each bound) or, for a
// Wien star, 4·(1 + 5) (four negative powers, each five chunks of its series); pre-integration
// nothing more. Per group of projection or
// light–density: its slabs (2) and lanes, each lane's coefficients beyond the table (the basis
// matrix's 8 + 36, the raw moments' 4 + 2·4 exponential integrals of ≤ 3 chunks, for both halves).
MarchLoopCost NebulaGpuMarcher::loopCost(Method method, const NebulaPrecomputed& pre) const {
  constexpr long kFixed = 256, kCoefficients = 44 + 2 * (4 + 2 * 4 * 3);
  MarchLoopCost cost{kFixed, 3 + mLineCount, 0, false};
  switch (method) {
    case Method::Reference:
      cost.perItem = 5;
      for (int c = 0; c < 3; ++c) cost.perItem += (mNodes.count[c] + mNodes.chunk - 1) / mNodes.chunk;
      break;
    case Method::Analytic:
      cost.perItem = 5;
      for (std::size_t st = 0; st < pre.analytic.f32.size(); ++st) {
        long star = 5;
        const long perPiece = 1 + (pre.analytic.wienExponentUm[st] > 0.0 ? 4 * (1 + 5) : 2 * 3);
        for (const auto& pieces : pre.analytic.f32[st]) star += static_cast<long>(pieces.size()) * perPiece;
        cost.perItem = std::max(cost.perItem, star);
      }
      break;
    case Method::PreIntegration:
      cost.perItem = 2;
      break;
    case Method::LightDensity:
      cost = {kFixed, 3 + mLineCount + kCoefficients, 2 + 4, true};
      break;
    case Method::Projection:
      cost = {kFixed, 3 + mLineCount, 2 + shared::nebulaGroupLanes(mCard) * (1 + kCoefficients), true};
      break;
  }
  return cost;
}

void NebulaGpuMarcher::finishOnGpu() {
  const int pixels = mSize.x * mSize.y;
  if (pixels == 0) throw Error("nebula: finish() before march()");
  mFinish.setUniform("uWidth", mSize.x);
  mFinish.setUniform("uPixelCount", pixels);
  mFinish.setUniform("uCount", mCount);
  mFinish.setUniform("uCard", mCard);
  mFinish.setUniform("uLineCount", mLineCount);
  mLines.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  mMoments.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
  mMarchedValues.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
  (mMarched == Method::LightDensity ? mLightWeights : mProjectionWeights).bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  mColour.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  gpu::runCompute(mFinish, {static_cast<GLuint>((mSize.x + 7) / 8), static_cast<GLuint>((mSize.y + 7) / 8), 1});
}

NebulaImage NebulaGpuMarcher::finish() {
  finishOnGpu();
  std::vector<glm::vec4> colour = mColour.read<glm::vec4>();
  NebulaImage image{mSize.x, mSize.y, std::vector<glm::vec3>(colour.size())};
  for (std::size_t i = 0; i < colour.size(); ++i) image.pixels[i] = glm::vec3(colour[i]);
  return image;
}

NebulaImage NebulaGpuMarcher::render(const RenderSettings& settings) {
  march(settings);
  return finish();
}

std::vector<float> NebulaGpuMarcher::readMoments() const { return mMoments.read<float>(); }

const std::vector<float>& NebulaGpuMarcher::finishWeights() const {
  return mMarched == Method::LightDensity ? mLightWeightValues : mProjectionWeightValues;
}

std::size_t NebulaGpuMarcher::gpuMemoryBytes() const {
  return mDensity.sizeBytes() + mStarDepth.sizeBytes() + mLightCoefficients.sizeBytes() + mZones.sizeBytes() + mMomentLo.sizeBytes() +
         mMomentHi.sizeBytes() + mBasisMatrix.sizeBytes() + mStars.sizeBytes() + mLines.sizeBytes() + mProjectionWeights.sizeBytes() +
         mLightWeights.sizeBytes() + mMoments.sizeBytes() + mMarchedValues.sizeBytes() + mColour.sizeBytes() +
         mReferenceNodes.sizeBytes() + mOpticalDepth.sizeBytes() + mAnalyticRanges.sizeBytes() + mAnalyticPieces.sizeBytes() +
         mPreIntegrated.sizeBytes();
}

}  // namespace prism::nebula
