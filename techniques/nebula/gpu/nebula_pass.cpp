#include "techniques/nebula/gpu/nebula_pass.h"

#include <chrono>
#include <mutex>

#include <fmt/format.h>

#include "core/data_files.h"
#include "core/error.h"
#include "spectral/colour_space.h"
#include "techniques/nebula/nebula_basis_coverage.h"
#include "techniques/nebula/nebula_cpu_twin.h"
#include "techniques/nebula/nebula_light_warnings.h"

namespace prism::nebula {
namespace {

const NebulaSection& sectionOf(const Scene& scene) {
  const auto* s = scene.techniques.find<NebulaSection>();
  PRISM_CHECK(s != nullptr);
  return *s;
}

// Whether the GPU reads the stars' optical depths (NebulaGpuMarcher::starDepth): every march but
// light-density's (the renderer's reference mode marches the reference), and the lighting pass
// where the stars light surfaces.
bool readsStarDepths(const NebulaSection& section, bool referenceMode) {
  if (section.model.stars.empty()) return false;
  return referenceMode || section.renderSettings().method != Method::LightDensity || section.lightSurfaces;
}

void requireStarDepthsFit(const Scene& scene, bool referenceMode) {
  const NebulaSection& section = sectionOf(scene);
  if (!readsStarDepths(section, referenceMode)) return;
  try {
    requireGpuFits(section.density->size().z, section.model.stars.size());
  } catch (const Error& e) {
    // What reads them, and how none would be read.
    const char* remedy = referenceMode ? "; the reference mode's march reads them"
                         : section.renderSettings().method == Method::LightDensity
                             ? "; the stars light surfaces, which reads them (\"light_surfaces\": false reads none)"
                             : "; \"method\": \"light-density\" with \"light_surfaces\": false reads none of them";
    throw Error(fmt::format("{}: /nebula/stars: {}{}", scene.file.string(), e.what(), remedy));
  }
}

// The last section's precomputation, shared by precompute() and the passes (a viewer's second
// view, the bench's configurations): building it is the slow part (each star's optical depth per
// voxel).
std::shared_ptr<const NebulaRenderer> precomputation(const NebulaSection& section, const TechniqueProgress& progress) {
  static std::mutex mutex;
  static std::string memoKey, memoVolumeKey;
  static std::shared_ptr<const NebulaRenderer> memo;
  const std::string key = section.precomputationKey(), volumeKey = section.volumeKey();
  std::lock_guard lock(mutex);
  if (memo && memoKey == key) return memo;
  if (memo && memoVolumeKey == volumeKey) {  // other filters or passbands through the same volume
    memo = std::make_shared<const NebulaRenderer>(*memo, section.model.filters, section.model.passbands);
    memoKey = key;
    return memo;
  }
  RenderSettings basis;
  basis.basisSize = section.basis;
  basis.basisMaxDepthUm = section.basisDepthUm;
  const auto start = std::chrono::steady_clock::now();
  section.density->grid([&](std::size_t done, std::size_t total) {
    if (progress) progress("nebula density", done, total);
  });
  auto renderer = std::make_shared<const NebulaRenderer>(section.fullModel(), basis, [&](std::size_t done, std::size_t total) {
    if (progress) progress("nebula precomputation", done, total);
  });
  if (!progress)
    fmt::print(stderr, "nebula precomputation: {}×{}×{} voxels, {} star(s) in {:.2f} s\n", section.density->size().x,
               section.density->size().y, section.density->size().z, section.model.stars.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  memo = renderer;
  memoKey = key;
  memoVolumeKey = volumeKey;
  return renderer;
}

gpu::Program compositeProgram() {
  gpu::ProgramDesc desc;
  desc.vertex = shaderDirectory() / "passes" / "fullscreen.vert";
  desc.fragment = shaderDirectory() / "passes" / "nebula_composite.frag";
  desc.includeDirs = {shaderDirectory()};
  desc.label = "nebula composite";
  return gpu::Program(desc);
}

// The view of the renderer's camera in the section's cube (MarchView, without the depth).
MarchView marchView(const NebulaSection& section, const CameraTransform& camera, int width, int height) {
  // View space's axes in the world are the view matrix's rows; a uniform scale and a translation
  // take the world to the cube, so directions stay.
  const glm::mat4& v = camera.view;
  MarchView view;
  view.right = glm::normalize(glm::vec3(v[0][0], v[1][0], v[2][0]));
  view.up = glm::normalize(glm::vec3(v[0][1], v[1][1], v[2][1]));
  view.forward = -glm::normalize(glm::vec3(v[0][2], v[1][2], v[2][2]));
  view.tanHalf = 1.0f / camera.projection[1][1];
  view.aspect = camera.projection[1][1] / camera.projection[0][0];
  view.position = (camera.position - section.boxMin) / section.boxSize;
  view.width = width;
  view.height = height;
  view.inverseProjection = glm::inverse(camera.projection);
  view.cubePerWorld = 1.0f / section.boxSize;
  return view;
}

// The 3×3 matrix from the section's channels to XYZ, intensity included.
glm::mat3 channelsToXyz(const NebulaSection& section) {
  glm::mat3 m(1.0f);
  if (section.model.filters == "hubble") {  // the palette's R, G, B as linear sRGB
    const Eigen::Matrix3d& rgbToXyz = colourSpace("srgb").rgbToXyz;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[c][r] = static_cast<float>(rgbToXyz(r, c));
  }
  return m * section.intensity;
}

}  // namespace

NebulaPass::NebulaPass() : mComposite(compositeProgram()), mEmpty(gpu::VertexArray::attributeless()) {}

void NebulaPass::precompute(const Scene& scene, const TechniqueProgress& progress) {
  const NebulaSection& section = sectionOf(scene);
  std::shared_ptr<const NebulaRenderer> renderer = precomputation(section, progress);
  // What the scene's camera sees of light beyond the projection basis, and how thick the march's
  // steps are (its view as it starts: a square of 32 × 32 rays in the cube, at the camera's
  // vertical field of view).
  NebulaCamera camera;
  camera.position = glm::dvec3((scene.camera.position - section.boxMin) / section.boxSize);
  camera.target = glm::dvec3((scene.camera.target - section.boxMin) / section.boxSize);
  camera.fovYDeg = scene.camera.verticalFovDeg;
  camera.width = camera.height = 32;
  const RenderSettings settings = section.renderSettings();
  const BasisCoverage coverage = basisCoverage(*renderer, settings, camera);
  for (const std::string& warning : {coarseGridWarning(renderer->model().density),
                                     emptyGridWarning(renderer->model().density), unlitLinesWarning(renderer->model()),
                                     darkNebulaWarning(*renderer),
                                     stepThicknessWarning(coverage, settings, "\"steps\": {:.0f}"),
                                     basisCoverageWarning(coverage, settings, "\"basis_depth\": {:.0f} and \"basis\": 6")})
    if (!warning.empty()) fmt::print(stderr, "prism: warning: {}: /nebula: {}\n", scene.file.string(), warning);
}

void NebulaPass::requireFits(const Scene& scene) { requireStarDepthsFit(scene, false); }

void NebulaPass::run(const TechniqueBlock&, const Scene& scene, const CameraTransform& camera,
                     const TechniqueFrame& frame) {
  const NebulaSection& section = sectionOf(scene);
  const std::string key = section.precomputationKey();
  bool refiltered = false;
  // Every frame, before a precomputation made here: the method and the stars' light on surfaces
  // change without one.
  requireStarDepthsFit(scene, frame.referenceMode);
  if (!mRenderer || key != mPrecomputationKey) {
    std::shared_ptr<const NebulaRenderer> renderer = precomputation(section, {});
    const std::string volumeKey = section.volumeKey();
    if (mMarcher && volumeKey == mVolumeKey) {  // other filters or passbands: the same volume uploaded
      if (!mMarcher->refilter(*renderer)) mMarchKey.clear();
      refiltered = true;
    } else {
      auto marcher = std::make_unique<NebulaGpuMarcher>(*renderer);  // before anything is replaced
      mMarcher = std::move(marcher);
      mMarchKey.clear();
    }
    mRenderer = std::move(renderer);
    mPrecomputationKey = key;
    mVolumeKey = volumeKey;
  }
  mStarsLightSurfaces = section.lightSurfaces && !section.model.stars.empty();
  if (mStarsLightSurfaces) mMarcher->starDepth();  // uploaded ahead of the lighting pass, which binds it
  RenderSettings settings = section.renderSettings();
  if (frame.referenceMode) {  // the renderer's ground truth: the nebula's own
    settings.method = Method::Reference;
    settings.uniformSamples = 0;
  }
  MarchView view = marchView(section, camera, frame.width, frame.height);
  view.depthTexture = frame.depthTexture;
  // The view and the settings; not the depth: a renderer's meshes never change.
  const glm::mat4& p = camera.projection;
  const std::string marchKey =
      fmt::format("{}|{}|{}|{}|{},{},{}|{},{},{}|{},{},{}|{},{}|{}x{}|{},{},{},{}", methodName(settings.method),
                  settings.steps, settings.basisSize, settings.uniformSamples, view.position.x, view.position.y,
                  view.position.z, view.forward.x, view.forward.y, view.forward.z, view.up.x, view.up.y, view.up.z,
                  view.tanHalf, view.aspect, view.width, view.height, p[2][2], p[3][2], p[2][0], p[2][1]);
  if (marchKey != mMarchKey || section.marchEveryFrame) {
    mMarcher->march(settings, view);
    mMarcher->finishOnGpu();
    mMarchKey = marchKey;
    mView = view;
    mSettings = settings;
    ++mMarches;
  } else if (refiltered) {  // the moments stand: only the filters' weights changed
    mMarcher->finishOnGpu();
  }
}

void NebulaPass::bindForLighting() const {
  if (!mMarcher) return;
  mMarcher->opticalDepth().bind(static_cast<GLuint>(shared::kNebulaOpticalDepthUnit));
  // Unbound where the stars light no surface: the lighting pass then reads no star's depth.
  if (mStarsLightSurfaces) mMarcher->starDepth().bind(static_cast<GLuint>(shared::kNebulaStarDepthUnit));
  else glBindTextureUnit(static_cast<GLuint>(shared::kNebulaStarDepthUnit), 0);
}

std::shared_ptr<const TechniqueTexels> NebulaPass::readTexels() const {
  if (!mMarcher) return nullptr;
  auto texels = std::make_shared<NebulaTexels>();
  texels->width = mView.width;
  texels->height = mView.height;
  texels->opticalDepthUm = gpu::readTexture2DFloat(mMarcher->opticalDepth(), 1);
  texels->precomputation = mRenderer;
  return texels;
}

void NebulaPass::drawForward(const ForwardDrawInput& input) {
  if (!mMarcher) return;
  const NebulaSection& section = sectionOf(input.scene);
  glDisable(GL_DEPTH_TEST);  // the march stopped at the surfaces already
  mComposite.use();
  mComposite.setUniform("uSize", glm::ivec2(mView.width, mView.height));
  mComposite.setUniform("uToTristimulus", input.frame.fromXyz * channelsToXyz(section));
  mMarcher->colour().bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  mEmpty.draw(3);
  glEnable(GL_DEPTH_TEST);
}

std::size_t NebulaPass::gpuMemoryBytes() const { return mMarcher ? mMarcher->gpuMemoryBytes() : 0; }

}  // namespace prism::nebula
