#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/procedural_mesh.h"
#include "render/upsampling_texture.h"
#include "spectral/colour_space.h"
#include "core/data_files.h"
#include "core/error.h"
#include "spectral/observer.h"

namespace prism::render {
namespace {

gpu::Program passProgram(const char* vertex, const char* fragment, const char* label,
                         std::vector<gpu::ShaderDefine> defines = {}) {
  gpu::ProgramDesc desc;
  desc.vertex = shaderDirectory() / "passes" / vertex;
  desc.fragment = shaderDirectory() / "passes" / fragment;
  desc.includeDirs = {shaderDirectory()};
  desc.defines = std::move(defines);
  desc.label = label;
  return gpu::Program(desc);
}

gpu::Texture2D target(int width, int height, GLenum format, const char* label) {
  gpu::Texture2DDesc desc;
  desc.width = width;
  desc.height = height;
  desc.internalFormat = format;
  desc.sampling = {GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE};
  desc.label = label;
  return gpu::Texture2D(desc);
}

// A buffer holding `values`, replaced only when it must grow.
template <class T>
void upload(gpu::Buffer& buffer, const std::vector<T>& values, const char* label) {
  std::size_t bytes = values.size() * sizeof(T);
  if (buffer.id() == 0 || buffer.sizeBytes() < bytes) {
    buffer = gpu::Buffer({std::max<std::size_t>(bytes, 256), nullptr, GL_DYNAMIC_STORAGE_BIT, label});
  }
  buffer.upload(0, std::as_bytes(std::span<const T>(values)));
}

// The lighting pass's #define variant: the scene's techniques (e.g. "PRISM_TECHNIQUE_WATER") and
// PRISM_RGB_EMISSION where a material emits glTF's way (its upsampling, under llvmpipe's
// masked branches, cost every pixel of every scene up to 23 % of the lighting pass).
std::vector<gpu::ShaderDefine> lightingDefines(const Scene& scene) {
  std::vector<gpu::ShaderDefine> defines;
  for (const auto& section : scene.techniques.all()) defines.push_back({std::string(section->shaderDefine()), ""});
  if (anyMaterialEmitsRgb(scene)) defines.push_back({"PRISM_RGB_EMISSION", ""});
  return defines;
}

std::string lightingVariant(const Scene& scene) {
  std::string key;
  for (const gpu::ShaderDefine& d : lightingDefines(scene)) key += (key.empty() ? "" : " ") + d.name;
  return key;
}

gpu::Program lightingProgram(const Scene& scene) {
  std::string variant = lightingVariant(scene);
  return passProgram("fullscreen.vert", "lighting.frag",
                     variant.empty() ? "lighting pass" : ("lighting pass (" + variant + ")").c_str(),
                     lightingDefines(scene));
}

// Rows top first from GL's bottom-first read-back.
template <class T>
std::vector<T> flipRows(const std::vector<T>& pixels, int width, int height, int channels) {
  std::vector<T> out(pixels.size());
  std::size_t row = static_cast<std::size_t>(width * channels);
  for (int y = 0; y < height; ++y) {
    std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row),
                row, out.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(height - 1 - y) * row));
  }
  return out;
}

}  // namespace

Renderer::Renderer(const Scene& scene, const RgbToSpectrumTable& table,
                   const FrameSettings& settings)
    : mScene(scene),
      mTable(table),
      mSettings(settings),
      mCamera(scene.camera),
      mBounds(sceneBounds(scene)),
      mGpuScene(scene),
      mUpsamplingTable(uploadUpsamplingTable(table)),
      mShadowProgram(passProgram("shadow.vert", "shadow.frag", "shadow pass")),
      mGBufferProgram(passProgram("gbuffer.vert", "gbuffer.frag", "g-buffer pass")),
      mGBufferCoefficientsProgram(passProgram("gbuffer.vert", "gbuffer.frag", "g-buffer pass (coefficients)",
                                              {{"PRISM_GBUFFER_COEFFICIENTS", "1"}})),
      mForwardProgram(passProgram("forward.vert", "forward.frag", "forward pass")),
      mPostProgram(passProgram("fullscreen.vert", "post.frag", "post pass")),
      mFullScreen(gpu::VertexArray::attributeless("full-screen triangle")),
      mGizmo(uploadMesh(makeSphere(glm::vec3(0.0f), 1.0f, 16))) {
  validate(mSettings);
  requireTableForColourSpace(table, scene.colourSpace, scene.file.string());
  requireLightCount(scene);
  requireTechniquesShow(scene, mSettings);
  mLightingPrograms.emplace(lightingVariant(scene), lightingProgram(scene));
  mContext = frameContext(mSettings, mScene, mTable);
  mDisplayTransform = displayTransform(mSettings.display, mContext.display, mCamera.ev100);
  mShadows = makeShadows(mScene, mSettings.shadowMapSize, shadowCascading(mSettings, mCamera));
  mTargets = makeTargets(mSettings.width, mSettings.height, mSettings.gbufferAlbedo);
}

void Renderer::setSettings(const FrameSettings& settings) {
  validate(settings);
  requireTechniquesShow(mScene, settings);
  const bool sameWavelengths =
      effectiveSampling(settings) == effectiveSampling(mSettings) && settings.observer == mSettings.observer;
  FrameContext context = frameContext(settings, mScene, mTable, mContext.environmentFromAbove,
                                      sameWavelengths ? mContext.wavelengths : nullptr);
  DisplayTransform display = displayTransform(settings.display, context.display, mCamera.ev100);
  bool resized = settings.width != mSettings.width || settings.height != mSettings.height ||
                 settings.gbufferAlbedo != mSettings.gbufferAlbedo;
  std::optional<Shadows> shadows;
  if (settings.shadowMapSize != mSettings.shadowMapSize || settings.shadowCascades != mSettings.shadowCascades) {
    shadows = makeShadows(mScene, settings.shadowMapSize, shadowCascading(settings, mCamera));
  }
  std::optional<Targets> targets;
  if (resized) targets = makeTargets(settings.width, settings.height, settings.gbufferAlbedo);
  // Nothing below throws.
  bool lightingChanged = resized || shadows || settings.mode != mSettings.mode ||
                         settings.sampling.count != mSettings.sampling.count ||
                         settings.sampling.minNm != mSettings.sampling.minNm ||
                         settings.sampling.maxNm != mSettings.sampling.maxNm ||
                         settings.sampling.strategy != mSettings.sampling.strategy ||
                         settings.observer != mSettings.observer ||
                         settings.lookup != mSettings.lookup ||
                         settings.lightGizmos != mSettings.lightGizmos;
  if (shadows) mShadows = std::move(*shadows);
  if (targets) mTargets = std::move(*targets);
  mSettings = settings;
  mContext = context;
  mDisplayTransform = display;
  if (lightingChanged) mAccumulated = 0;
}

void Renderer::sceneChanged() {
  requireTechniquesShow(mScene, mSettings);
  // The wavelengths' pdf follows the lights (Lights strategy); made before anything changes.
  FrameContext context = frameContext(mSettings, mScene, mTable);
  planShadows();  // the views follow the lights
  mContext = std::move(context);
  // A camera's matrix is fitted under the lights (resolveDisplay): the display follows them too.
  mDisplayTransform = displayTransform(mSettings.display, mContext.display, mCamera.ev100);
  mAccumulated = 0;
}

void Renderer::reloadShaders() {
  // Built whole before any is replaced: a failure leaves the renderer as it was.
  gpu::Program shadow = passProgram("shadow.vert", "shadow.frag", "shadow pass");
  gpu::Program gbuffer = passProgram("gbuffer.vert", "gbuffer.frag", "g-buffer pass");
  gpu::Program gbufferCoefficients = passProgram("gbuffer.vert", "gbuffer.frag", "g-buffer pass (coefficients)",
                                                 {{"PRISM_GBUFFER_COEFFICIENTS", "1"}});
  gpu::Program lighting = lightingProgram(mScene);
  gpu::Program forward = passProgram("forward.vert", "forward.frag", "forward pass");
  gpu::Program post = passProgram("fullscreen.vert", "post.frag", "post pass");
  // The techniques' passes share shaders/shared with the lighting pass: reloaded together.
  std::map<std::string, std::unique_ptr<TechniquePass>> passes;
  for (const auto& [key, pass] : mTechniquePasses) passes.emplace(key, makeTechniquePass(key));
  mShadowProgram = std::move(shadow);
  mGBufferProgram = std::move(gbuffer);
  mGBufferCoefficientsProgram = std::move(gbufferCoefficients);
  mLightingPrograms.clear();
  mLightingPrograms.emplace(lightingVariant(mScene), std::move(lighting));
  mForwardProgram = std::move(forward);
  mPostProgram = std::move(post);
  mTechniquePasses = std::move(passes);
  resetAccumulation();  // the shadow pass's own shaders may have changed: every map drawn again
}

void Renderer::resetAccumulation() {
  std::fill(mShadows.drawnFrom.begin(), mShadows.drawnFrom.end(), std::nullopt);
  mAccumulated = 0;
}

void Renderer::setCamera(const Camera& camera) {
  mDisplayTransform = displayTransform(mSettings.display, mContext.display, camera.ev100);
  mCamera = camera;
  mAccumulated = 0;
}

ShadowCascading Renderer::shadowCascading(const FrameSettings& settings, const Camera& camera) {
  return {settings.shadowCascades, camera, static_cast<float>(settings.width) / static_cast<float>(settings.height)};
}

void Renderer::planShadows() {
  std::vector<ShadowView> views =
      planShadowViews(mScene, mBounds, mSettings.shadowMapSize, shadowCascading(mSettings, mCamera));
  if (views.size() == mShadows.views.size()) {
    mShadows.views = std::move(views);
  } else {
    mShadows = makeShadows(mScene, mSettings.shadowMapSize, shadowCascading(mSettings, mCamera));
  }
}

Renderer::Shadows Renderer::makeShadows(const Scene& scene, int mapSize, const ShadowCascading& cascading) {
  Shadows s;
  s.views = planShadowViews(scene, mapSize, cascading);
  gpu::Texture2DArrayDesc desc;
  desc.width = desc.height = mapSize;
  desc.layers = std::max<GLsizei>(1, static_cast<GLsizei>(s.views.size()));
  desc.internalFormat = GL_DEPTH_COMPONENT32F;
  desc.sampling = {GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE};
  desc.label = "shadow maps";
  s.maps = gpu::Texture2DArray(desc);
  for (const ShadowView& view : s.views) {
    gpu::FramebufferDesc fb;
    fb.depth.array = &s.maps;
    fb.depth.layer = view.layer;
    fb.label = "shadow map";
    s.framebuffers.emplace_back(fb);
  }
  s.drawnFrom.resize(s.views.size());
  return s;
}

Renderer::Targets Renderer::makeTargets(int w, int h, GBufferAlbedo albedo) {
  Targets t;
  t.albedoMetallic = target(w, h, GL_RGBA16F, "g-buffer albedo, metallic");
  t.normalRoughness = target(w, h, GL_RGBA16F, "g-buffer normal, roughness");
  t.materialId = target(w, h, GL_R32UI, "g-buffer material id");
  t.depth = target(w, h, GL_DEPTH_COMPONENT32F, "g-buffer depth");
  t.accumulation = target(w, h, GL_RGBA32F, "tristimulus accumulation");
  t.forwardDepth = target(w, h, GL_DEPTH_COMPONENT32F, "forward depth (copied)");
  t.display = target(w, h, GL_RGBA8, "display");
  gpu::FramebufferDesc g;
  // glTF's emissive colour (factor × texture, in [0, 1] but for a texture's rounding).
  t.emission = target(w, h, GL_RGBA16F, "g-buffer emission");
  g.colour = {{&t.albedoMetallic, 0}, {&t.normalRoughness, 0}, {&t.materialId, 0}, {&t.emission, 0}};
  if (albedo == GBufferAlbedo::Coefficients) {
    // Coefficients reach ±150 (saturated colours) and cancel each other: 16-bit floats would not do.
    t.coefficients = target(w, h, GL_RGBA32F, "g-buffer Jakob–Hanika coefficients");
    g.colour.push_back({&t.coefficients, 0});
  }
  g.depth.texture = &t.depth;
  g.label = "g-buffer";
  t.gbuffer = gpu::Framebuffer(g);
  gpu::FramebufferDesc a;
  a.colour = {{&t.accumulation, 0}};
  a.label = "accumulation";
  t.accumulationTarget = gpu::Framebuffer(a);
  gpu::FramebufferDesc f;
  f.colour = {{&t.accumulation, 0}};
  f.depth.texture = &t.forwardDepth;
  f.label = "forward";
  t.forwardTarget = gpu::Framebuffer(f);
  gpu::FramebufferDesc d;
  d.colour = {{&t.display, 0}};
  d.label = "display";
  t.displayTarget = gpu::Framebuffer(d);
  return t;
}

void Renderer::hook(std::string_view pass) const {
  if (mPassHook) mPassHook(pass);
}

namespace {

// Write masks are set here rather than assumed: clears and depth writes obey them, and a host
// (a viewer's UI) may have left them off.
void setOpaqueState() {
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // both faces: thin and open meshes must still cast and show
}

}  // namespace

void Renderer::renderFrame() {
  mCameraTransform = prism::cameraTransform(mCamera, mSettings.width, mSettings.height);
  // A directional light's cascades follow the camera: planned with the maps they are drawn into.
  if (mAccumulated == 0) planShadows();
  // A new set of wavelengths every frame (every strategy but Uniform moves between frames).
  mFrame = buildFrameData(mScene, mSettings, mContext, mTable, mShadows.views, mFrameIndex++, mCameraTransform);
  uploadFrameData();
  setOpaqueState();  // every frame, for the passes after these two as well
  mShadowLayersDrawn = 0;
  if (mAccumulated == 0) {  // what the last frames drew there holds while they accumulate
    hook("shadow");
    shadowPass();
    hook("gbuffer");
    gbufferPass();
  }
  techniquePasses();
  hook("lighting");
  lightingPass();
  forwardTechniques();
  if (mSettings.lightGizmos) {
    hook("forward");
    forwardPass();
  }
  hook("post");
  postPass();
  hook("");
}

void Renderer::uploadFrameData() {
  upload(mFrameConstants, std::vector<shared::FrameConstants>{mFrame.constants}, "frame constants");
  upload(mBatches, mFrame.batches, "frame batches");
  upload(mLights, mFrame.lights.empty() ? std::vector<shared::GpuLight>(1) : mFrame.lights,
         "frame lights");
  upload(mMaterials, mFrame.materials, "frame materials");
  upload(mLightSpectra, mFrame.lightSpectra, "frame light spectra");
  upload(mMaterialSpectra, mFrame.materialSpectra, "frame material spectra");
  // Each technique's block, in buffers kept per technique (replaced only when they must grow).
  for (const TechniqueBlock& block : mFrame.techniques) {
    TechniqueBuffers& buffers = mTechniqueBuffers[block.key];
    upload(buffers.constants, block.constants, (block.key + " constants").c_str());
    upload(buffers.data, block.data, (block.key + " data").c_str());
  }
}

void Renderer::shadowPass() {
  setOpaqueState();
  mShadowProgram.use();
  for (std::size_t i = 0; i < mShadows.views.size(); ++i) {
    const ShadowView& view = mShadows.views[i];
    if (!view.drawn || mShadows.drawnFrom[i] == view.viewProjection) continue;
    const gpu::Framebuffer& fb = mShadows.framebuffers[i];
    fb.bind();
    fb.clearDepth(1.0f);
    mShadowProgram.setUniform("uLightViewProjection", view.viewProjection);
    for (const GpuMesh& mesh : mGpuScene.meshes()) mesh.vertexArray.draw();
    mShadows.drawnFrom[i] = view.viewProjection;
    ++mShadowLayersDrawn;
  }
}

void Renderer::gbufferPass() {
  setOpaqueState();
  mTargets.gbuffer.bind();
  mTargets.gbuffer.clearColour(0, glm::vec4(0.0f));
  mTargets.gbuffer.clearColour(1, glm::vec4(0.0f));
  mTargets.gbuffer.clearColourUint(2, {0, 0, 0, 0});
  // glTF's emission: drawn where a material emits so, as the lighting pass then alone reads it.
  mTargets.gbuffer.setColourDrawn(3, anyMaterialEmitsRgb(mScene));
  mTargets.gbuffer.clearColour(3, glm::vec4(0.0f));
  mTargets.gbuffer.clearDepth(1.0f);
  const bool coefficients = mSettings.gbufferAlbedo == GBufferAlbedo::Coefficients;
  const gpu::Program& program = coefficients ? mGBufferCoefficientsProgram : mGBufferProgram;
  program.use();
  program.setUniform("uViewProjection", mCameraTransform.viewProjection);
  if (coefficients) {
    mTargets.gbuffer.clearColour(4, glm::vec4(0.0f));
    mUpsamplingTable.bind(3);
    program.setUniform("uUpsamplingResolution", mTable.resolution());
    program.setUniform("uFilteredLookup", mSettings.lookup == UpsamplingLookup::Filtered ? 1 : 0);
  }
  for (std::size_t i = 0; i < mGpuScene.meshes().size(); ++i) {
    const GpuMesh& mesh = mGpuScene.meshes()[i];
    const Material& m = mScene.materials.at(static_cast<std::size_t>(mesh.material));
    int textures = 0;
    if (m.baseColourTexture >= 0) {
      mGpuScene.texture(m.baseColourTexture).bind(0);
      textures |= shared::kTextureBaseColour;
    }
    if (m.metallicRoughnessTexture >= 0) {
      mGpuScene.texture(m.metallicRoughnessTexture).bind(1);
      textures |= shared::kTextureMetallicRoughness;
    }
    if (m.normalTexture >= 0) {
      mGpuScene.texture(m.normalTexture).bind(2);
      textures |= shared::kTextureNormal;
    }
    if (m.emissiveTexture >= 0) {
      mGpuScene.texture(m.emissiveTexture).bind(4);
      textures |= shared::kTextureEmission;
    }
    program.setUniform("uBaseColour", m.baseColour);
    program.setUniform("uMetallic", m.metallic);
    program.setUniform("uRoughness", m.roughness);
    program.setUniform("uEmissiveFactor", m.emitsRgb() ? m.emissiveFactor : glm::vec3(0.0f));
    // A technique's object is marked: the lighting pass lights it by the scene's lights alone, its
    // technique adds the rest (forwardTechniques).
    program.setUniform("uMaterialId", static_cast<GLuint>(mesh.material + 1) |
                                          (mScene.meshes[i].technique.empty() ? 0u : shared::kTechniqueShadedBit));
    program.setUniform("uTextures", textures);
    mesh.vertexArray.draw();
  }
}

TechniqueFrame Renderer::techniqueFrame() const {
  return {mSettings.width, mSettings.height, mTargets.depth.id(), mSettings.mode == RenderMode::Rgb,
          mSettings.mode == RenderMode::Reference, glm::inverse(mDisplayTransform.toXyz)};
}

// Each technique's GPU work for this frame (the sky's tables, recomputed every frame so that the
// sun and the atmosphere can change live), timed under the technique's key; made on first use.
void Renderer::techniquePasses() {
  for (const TechniqueBlock& block : mFrame.techniques) {
    auto pass = mTechniquePasses.find(block.key);
    if (pass == mTechniquePasses.end()) pass = mTechniquePasses.emplace(block.key, makeTechniquePass(block.key)).first;
    if (!pass->second) continue;
    hook(block.key);  // a pass that also draws forward is timed there again, under the same key
    pass->second->run(block, mScene, mCameraTransform, techniqueFrame());
  }
}

// The objects techniques shade themselves (PRT's), over the G-buffer's depth, added to the
// accumulation where the lighting pass left them black (technique_pass.h, ForwardDrawInput).
void Renderer::forwardTechniques() {
  bool depthCopied = false;
  for (const TechniqueBlock& block : mFrame.techniques) {
    auto pass = mTechniquePasses.find(block.key);
    if (pass == mTechniquePasses.end() || !pass->second || !pass->second->drawsForward()) continue;
    if (!depthCopied) {
      mTargets.gbuffer.blitDepthTo(mTargets.forwardTarget);
      depthCopied = true;
    }
    hook(block.key);
    // What the lighting pass reads of every technique, a forward pass may read too (PRT's
    // fragments read the nebula's optical depth); another forward pass may have rebound it.
    for (const TechniqueBlock& b : mFrame.techniques) {
      if (const TechniquePass* p = techniquePass(b.key)) p->bindForLighting();
    }
    mTargets.forwardTarget.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    pass->second->drawForward({mScene, mCameraTransform, *mContext.tristimulusObserver, mTable, techniqueFrame()});
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
  }
}

void Renderer::lightingPass() {
  mTargets.accumulationTarget.bind();
  if (mAccumulated == 0) mTargets.accumulationTarget.clearColour(0, glm::vec4(0.0f));
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  mFrameConstants.bindBase(GL_UNIFORM_BUFFER, shared::kFrameConstantsBinding);
  mBatches.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  mLights.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  mMaterials.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  mLightSpectra.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  mMaterialSpectra.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
  for (const TechniqueBlock& block : mFrame.techniques) {
    const TechniqueBuffers& buffers = mTechniqueBuffers.at(block.key);
    if (block.constantsBinding >= 0) buffers.constants.bindBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(block.constantsBinding));
    if (block.dataBinding >= 0) buffers.data.bindBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(block.dataBinding));
  }
  mTargets.albedoMetallic.bind(0);
  mTargets.normalRoughness.bind(1);
  mTargets.materialId.bind(2);
  mTargets.depth.bind(3);
  mShadows.maps.bind(4);
  mUpsamplingTable.bind(5);
  if (mSettings.gbufferAlbedo == GBufferAlbedo::Coefficients) mTargets.coefficients.bind(6);
  mTargets.emission.bind(13);  // past the techniques' units (7–12)
  for (const TechniqueBlock& block : mFrame.techniques) {
    if (const TechniquePass* pass = techniquePass(block.key)) pass->bindForLighting();
  }
  // The variant of the scene's techniques, compiled the first time it is needed (an editor may
  // add or remove a technique's section between frames).
  std::string variant = lightingVariant(mScene);
  auto program = mLightingPrograms.find(variant);
  if (program == mLightingPrograms.end()) program = mLightingPrograms.emplace(variant, lightingProgram(mScene)).first;
  program->second.use();
  mFullScreen.draw(3);
  glDisable(GL_BLEND);
  ++mAccumulated;
}

// Each point and spot light as a small sphere glowing in its own colour at twice the exposure's
// white, added over the lit image where nothing in the G-buffer is in front of it.
void Renderer::forwardPass() {
  if (mScene.lights.empty()) return;
  mTargets.gbuffer.blitDepthTo(mTargets.forwardTarget);
  mTargets.forwardTarget.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);  // additive: each pixel of the closed sphere once, its front
  glCullFace(GL_BACK);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  float radius = std::max(0.01f * glm::length(mBounds.max - mBounds.min), 1e-3f);
  float white = 1.2f * std::exp2(mSettings.display.ev100.value_or(mCamera.ev100));
  // The markers' sum in the accumulation is 2·white times its frame count, whatever exposure the
  // earlier frames had (an exposure change does not restart it): this frame adds what brings the
  // sum there, so that the mean shows 2·white of the exposure now.
  const float sum = 2.0f * white * static_cast<float>(mAccumulated);
  const float add = sum - (mAccumulated == 1 ? 0.0f : mGizmoSum);
  mGizmoSum = sum;
  glm::mat3 fromXyz = glm::inverse(mDisplayTransform.toXyz);
  // The colour as the lighting pass's observer sees it (CIE 1931 behind a camera's matrix).
  const Observer& seen = mContext.tristimulusObserver->isCamera ? cie1931Observer() : *mContext.tristimulusObserver;
  mForwardProgram.use();
  mForwardProgram.setUniform("uViewProjection", mCameraTransform.viewProjection);
  for (const Light& light : mScene.lights) {
    if (light.type == LightType::Directional) continue;
    Eigen::Vector3d xyz = seen.integrate(light.spd);
    glm::vec3 colour(static_cast<float>(xyz.x() / xyz.y()), 1.0f, static_cast<float>(xyz.z() / xyz.y()));
    glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), light.position), glm::vec3(radius));
    mForwardProgram.setUniform("uModel", model);
    // In the lighting pass's tristimulus space (XYZ, or camera RGB for a camera observer).
    mForwardProgram.setUniform("uTristimulus", fromXyz * (colour * add));
    mGizmo.vertexArray.draw();
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
}

void Renderer::postPass() {
  const DisplayTransform& t = mDisplayTransform;
  mTargets.displayTarget.bind();
  glDisable(GL_DEPTH_TEST);
  mTargets.accumulation.bind(0);
  const gpu::Program& p = mPostProgram;
  p.use();
  p.setUniform("uToDisplay", t.toDisplay);
  p.setUniform("uDisplayToXyz", t.displayToXyz);
  p.setUniform("uXyzToDisplay", t.xyzToDisplay);
  static_assert(static_cast<int>(ToneMap::None) == shared::kToneMapNone &&
                static_cast<int>(ToneMap::Reinhard) == shared::kToneMapReinhard &&
                static_cast<int>(ToneMap::Aces) == shared::kToneMapAces);
  p.setUniform("uToneMap", static_cast<GLint>(mSettings.display.toneMap));
  p.setUniform("uTransfer", t.transfer);
  p.setUniform("uDither", mSettings.display.dither ? 1 : 0);
  p.setUniform("uSeed", static_cast<GLuint>(mFrameIndex * 2654435761u));
  mFullScreen.draw(3);
}

std::vector<std::uint8_t> Renderer::readDisplayRgba8() const {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(mSettings.width * mSettings.height * 4));
  GLint alignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(mTargets.display.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()),
                    pixels.data());
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
  return flipRows(pixels, mSettings.width, mSettings.height, 4);
}

std::vector<float> Renderer::readMeanTristimulus() const {
  std::vector<float> rgba = gpu::readTexture2DFloat(mTargets.accumulation, 4);
  std::vector<float> rgb(rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) {
    float a = rgba[i * 4 + 3];
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = a > 0.0f ? rgba[i * 4 + c] / a : 0.0f;
  }
  return flipRows(rgb, mSettings.width, mSettings.height, 3);
}

std::size_t Renderer::gpuMemoryBytes() const {
  std::size_t bytes = mGpuScene.gpuMemoryBytes() + mUpsamplingTable.sizeBytes() + mShadows.maps.sizeBytes() +
                      mGizmo.vertices.sizeBytes() + mGizmo.indices.sizeBytes();
  for (const gpu::Texture2D* t : {&mTargets.albedoMetallic, &mTargets.normalRoughness, &mTargets.materialId,
                                  &mTargets.depth, &mTargets.emission, &mTargets.coefficients, &mTargets.accumulation,
                                  &mTargets.forwardDepth, &mTargets.display}) {
    bytes += t->sizeBytes();
  }
  for (const gpu::Buffer* b : {&mFrameConstants, &mBatches, &mLights, &mMaterials, &mLightSpectra,
                               &mMaterialSpectra}) {
    bytes += b->sizeBytes();
  }
  for (const auto& [key, buffers] : mTechniqueBuffers) bytes += buffers.constants.sizeBytes() + buffers.data.sizeBytes();
  for (const auto& [key, pass] : mTechniquePasses) bytes += pass ? pass->gpuMemoryBytes() : 0;
  return bytes;
}

const TechniquePass* Renderer::techniquePass(std::string_view key) const {
  auto pass = mTechniquePasses.find(std::string(key));
  return pass == mTechniquePasses.end() ? nullptr : pass->second.get();
}

}  // namespace prism::render
