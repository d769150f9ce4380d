#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "render/display_transform.h"
#include "render/procedural_mesh.h"
#include "spectral/observer.h"
#include "render/upsampling_texture.h"
#include "spectral/data_files.h"

namespace prism::render {
namespace {

gpu::Program passProgram(const char* vertex, const char* fragment, const char* label) {
  gpu::ProgramDesc desc;
  desc.vertex = shaderDirectory() / "passes" / vertex;
  desc.fragment = shaderDirectory() / "passes" / fragment;
  desc.includeDirs = {shaderDirectory()};
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
      mGpuScene(scene),
      mUpsamplingTable(uploadUpsamplingTable(table)),
      mShadowProgram(passProgram("shadow.vert", "shadow.frag", "shadow pass")),
      mGBufferProgram(passProgram("gbuffer.vert", "gbuffer.frag", "g-buffer pass")),
      mLightingProgram(passProgram("fullscreen.vert", "lighting.frag", "lighting pass")),
      mForwardProgram(passProgram("forward.vert", "forward.frag", "forward pass")),
      mPostProgram(passProgram("fullscreen.vert", "post.frag", "post pass")),
      mFullScreen(gpu::VertexArray::attributeless("full-screen triangle")),
      mGizmo(uploadMesh(makeSphere(glm::vec3(0.0f), 1.0f, 16))) {
  validate(mSettings);
  createShadowMaps();
  createTargets();
}

void Renderer::setSettings(const FrameSettings& settings) {
  validate(settings);
  bool resized = settings.width != mSettings.width || settings.height != mSettings.height;
  bool shadowsChanged = settings.shadowMapSize != mSettings.shadowMapSize;
  mSettings = settings;
  if (shadowsChanged) createShadowMaps();
  if (resized) createTargets();
  mAccumulated = 0;
}

void Renderer::setCamera(const Camera& camera) {
  mCamera = camera;
  mAccumulated = 0;
}

void Renderer::createShadowMaps() {
  mShadowViews = planShadowViews(mScene, mSettings.shadowMapSize);
  gpu::Texture2DArrayDesc desc;
  desc.width = desc.height = mSettings.shadowMapSize;
  desc.layers = std::max<GLsizei>(1, static_cast<GLsizei>(mShadowViews.size()));
  desc.internalFormat = GL_DEPTH_COMPONENT32F;
  desc.sampling = {GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE};
  desc.label = "shadow maps";
  mShadowMaps = gpu::Texture2DArray(desc);
  mShadowFramebuffers.clear();
  for (const ShadowView& view : mShadowViews) {
    gpu::FramebufferDesc fb;
    fb.depth.array = &mShadowMaps;
    fb.depth.layer = view.layer;
    fb.label = "shadow map";
    mShadowFramebuffers.emplace_back(fb);
  }
  mAccumulated = 0;
}

void Renderer::createTargets() {
  int w = mSettings.width, h = mSettings.height;
  mAlbedoMetallic = target(w, h, GL_RGBA16F, "g-buffer albedo, metallic");
  mNormalRoughness = target(w, h, GL_RGBA16F, "g-buffer normal, roughness");
  mMaterialId = target(w, h, GL_R32UI, "g-buffer material id");
  mDepth = target(w, h, GL_DEPTH_COMPONENT32F, "g-buffer depth");
  mAccumulation = target(w, h, GL_RGBA32F, "tristimulus accumulation");
  mForwardDepth = target(w, h, GL_DEPTH_COMPONENT32F, "forward depth (copied)");
  mDisplay = target(w, h, GL_RGBA8, "display");
  gpu::FramebufferDesc g;
  g.colour = {{&mAlbedoMetallic, 0}, {&mNormalRoughness, 0}, {&mMaterialId, 0}};
  g.depth.texture = &mDepth;
  g.label = "g-buffer";
  mGBuffer = gpu::Framebuffer(g);
  gpu::FramebufferDesc a;
  a.colour = {{&mAccumulation, 0}};
  a.label = "accumulation";
  mAccumulationTarget = gpu::Framebuffer(a);
  gpu::FramebufferDesc f;
  f.colour = {{&mAccumulation, 0}};
  f.depth.texture = &mForwardDepth;
  f.label = "forward";
  mForwardTarget = gpu::Framebuffer(f);
  gpu::FramebufferDesc d;
  d.colour = {{&mDisplay, 0}};
  d.label = "display";
  mDisplayTarget = gpu::Framebuffer(d);
  mAccumulated = 0;
}

void Renderer::hook(std::string_view pass) const {
  if (mPassHook) mPassHook(pass);
}

void Renderer::renderFrame() {
  mCameraTransform = render::cameraTransform(mCamera, mSettings.width, mSettings.height);
  // A new set of wavelengths every frame (only stochastic strategies differ between frames).
  mFrame = buildFrameData(mScene, mSettings, mTable, mShadowViews, mFrameIndex++);
  uploadFrameData();
  hook("shadow");
  shadowPass();
  hook("gbuffer");
  gbufferPass();
  hook("lighting");
  lightingPass();
  if (mSettings.lightGizmos) {
    hook("forward");
    forwardPass();
  }
  hook("post");
  postPass();
  hook("");
}

void Renderer::uploadFrameData() {
  upload(mBatches, mFrame.batches, "frame batches");
  upload(mLights, mFrame.lights.empty() ? std::vector<shared::GpuLight>(1) : mFrame.lights,
         "frame lights");
  upload(mMaterials, mFrame.materials, "frame materials");
  upload(mLightSpectra, mFrame.lightSpectra, "frame light spectra");
  upload(mMaterialSpectra, mFrame.materialSpectra, "frame material spectra");
}

void Renderer::shadowPass() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // both faces: thin and open meshes must still cast
  mShadowProgram.use();
  for (std::size_t i = 0; i < mShadowViews.size(); ++i) {
    const gpu::Framebuffer& fb = mShadowFramebuffers[i];
    fb.bind();
    fb.clearDepth(1.0f);
    mShadowProgram.setUniform("uLightViewProjection", mShadowViews[i].viewProjection);
    for (const GpuMesh& mesh : mGpuScene.meshes()) mesh.vertexArray.draw();
  }
}

void Renderer::gbufferPass() {
  mGBuffer.bind();
  mGBuffer.clearColour(0, glm::vec4(0.0f));
  mGBuffer.clearColour(1, glm::vec4(0.0f));
  mGBuffer.clearColourUint(2, {0, 0, 0, 0});
  mGBuffer.clearDepth(1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  mGBufferProgram.use();
  mGBufferProgram.setUniform("uViewProjection", mCameraTransform.viewProjection);
  for (const GpuMesh& mesh : mGpuScene.meshes()) {
    const Material& m = mScene.materials.at(static_cast<std::size_t>(mesh.material));
    int textures = 0;
    if (m.baseColourTexture >= 0) {
      mGpuScene.texture(m.baseColourTexture).bind(0);
      textures |= 1;
    }
    if (m.metallicRoughnessTexture >= 0) {
      mGpuScene.texture(m.metallicRoughnessTexture).bind(1);
      textures |= 2;
    }
    if (m.normalTexture >= 0) {
      mGpuScene.texture(m.normalTexture).bind(2);
      textures |= 4;
    }
    mGBufferProgram.setUniform("uBaseColour", m.baseColour);
    mGBufferProgram.setUniform("uMetallic", m.metallic);
    mGBufferProgram.setUniform("uRoughness", m.roughness);
    mGBufferProgram.setUniform("uMaterialId", static_cast<GLuint>(mesh.material + 1));
    mGBufferProgram.setUniform("uTextures", textures);
    mesh.vertexArray.draw();
  }
}

void Renderer::lightingPass() {
  mAccumulationTarget.bind();
  if (mAccumulated == 0) mAccumulationTarget.clearColour(0, glm::vec4(0.0f));
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  mBatches.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  mLights.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  mMaterials.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  mLightSpectra.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  mMaterialSpectra.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
  mAlbedoMetallic.bind(0);
  mNormalRoughness.bind(1);
  mMaterialId.bind(2);
  mDepth.bind(3);
  mShadowMaps.bind(4);
  mUpsamplingTable.bind(5);
  const gpu::Program& p = mLightingProgram;
  p.use();
  p.setUniform("uMode", mFrame.constants.mode);
  p.setUniform("uBatchCount", mFrame.constants.batchCount);
  p.setUniform("uLightCount", mFrame.constants.lightCount);
  p.setUniform("uShadowMapSize", mFrame.constants.shadowMapSize);
  p.setUniform("uUpsamplingResolution", mTable.resolution());
  p.setUniform("uFilteredLookup", mSettings.lookup == UpsamplingLookup::Filtered ? 1 : 0);
  p.setUniform("uInverseViewProjection", mCameraTransform.inverseViewProjection);
  p.setUniform("uCameraPosition", mCameraTransform.position);
  p.setUniform("uViewportSize", glm::vec2(static_cast<float>(mSettings.width),
                                          static_cast<float>(mSettings.height)));
  mFullScreen.draw(3);
  glDisable(GL_BLEND);
  ++mAccumulated;
}

// Each point and spot light as a small sphere glowing in its own colour at twice the exposure's
// white, added over the lit image where nothing in the G-buffer is in front of it.
void Renderer::forwardPass() {
  if (mScene.lights.empty()) return;
  mGBuffer.blitDepthTo(mForwardTarget);
  mForwardTarget.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);  // additive: each pixel of the closed sphere once, its front
  glCullFace(GL_BACK);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  Bounds bounds = sceneBounds(mScene);
  float radius = std::max(0.01f * glm::length(bounds.max - bounds.min), 1e-3f);
  float white = 1.2f * std::exp2(mSettings.ev100.value_or(mCamera.ev100));
  glm::mat3 toXyz = tristimulusToXyz(mSettings);
  glm::mat3 fromXyz = glm::inverse(toXyz);
  const Observer& cie = observer("cie1931");
  mForwardProgram.use();
  mForwardProgram.setUniform("uViewProjection", mCameraTransform.viewProjection);
  for (const Light& light : mScene.lights) {
    if (light.type == LightType::Directional) continue;
    Eigen::Vector3d xyz = cie.integrate(light.spd);
    glm::vec3 colour(static_cast<float>(xyz.x() / xyz.y()), 1.0f, static_cast<float>(xyz.z() / xyz.y()));
    glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), light.position), glm::vec3(radius));
    mForwardProgram.setUniform("uModel", model);
    // In the lighting pass's tristimulus space (XYZ, or camera RGB for a camera observer).
    mForwardProgram.setUniform("uTristimulus", fromXyz * (colour * (2.0f * white)));
    mGizmo.vertexArray.draw();
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
}

void Renderer::postPass() {
  DisplayTransform t = displayTransform(mSettings, mCamera.ev100);
  mDisplayTarget.bind();
  glDisable(GL_DEPTH_TEST);
  mAccumulation.bind(0);
  const gpu::Program& p = mPostProgram;
  p.use();
  p.setUniform("uToDisplay", t.toDisplay);
  p.setUniform("uLuminanceWeights", t.luminanceWeights);
  p.setUniform("uToneMap", static_cast<GLint>(mSettings.toneMap));
  p.setUniform("uTransfer", t.transfer);
  p.setUniform("uDither", mSettings.dither ? 1 : 0);
  p.setUniform("uSeed", static_cast<GLuint>(mFrameIndex * 2654435761u));
  mFullScreen.draw(3);
}

std::vector<std::uint8_t> Renderer::readDisplayRgba8() const {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(mSettings.width * mSettings.height * 4));
  GLint alignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(mDisplay.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()),
                    pixels.data());
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
  return flipRows(pixels, mSettings.width, mSettings.height, 4);
}

std::vector<float> Renderer::readMeanTristimulus() const {
  std::vector<float> rgba = gpu::readTexture2DFloat(mAccumulation, 4);
  std::vector<float> rgb(rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) {
    float a = rgba[i * 4 + 3];
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = a > 0.0f ? rgba[i * 4 + c] / a : 0.0f;
  }
  return flipRows(rgb, mSettings.width, mSettings.height, 3);
}

}  // namespace prism::render
