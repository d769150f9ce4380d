#include "render/frame_data.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/scene_spectra.h"
#include "spectral/colour_space.h"
#include "core/error.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"
#include "spectral/sampling.h"
#include "spectral/sigmoid_fit.h"
#include "techniques/registry.h"

namespace prism::render {
namespace {

glm::vec4 toVec4(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()), 0.0f};
}

// Linear RGB (scene colour space) of a reflectance under the colour space's white (the light the
// upsampling table is fitted under), clamped to [0, 1].
glm::vec4 reflectanceRgb(const Spectrum& reflectance, const RgbColourSpace& space) {
  Eigen::Vector3d xyz =
      reflectanceTristimulus(cie1931Observer(), reflectance, gamutWhiteIlluminant(space));
  Eigen::Vector3d rgb = (space.xyzToRgb * xyz).cwiseMax(0.0).cwiseMin(1.0);
  return toVec4(rgb);
}

// Linear RGB (scene colour space) of a light's spectrum, as RGB mode carries lights: its
// tristimulus at 683 lm/W, unclamped, so that a white surface shows a narrow-band light's colour
// (a 450 nm LED's is far outside sRGB) as it is; what that does to other albedos is
// pixel_shading.glsl's to bound.
glm::vec4 emissionRgb(const Spectrum& spd, const RgbColourSpace& space) {
  return toVec4(space.xyzToRgb * luminousTristimulus(spd));
}

glm::vec4 at4(const Spectrum& s, const glm::vec4& lambdaNm, float scale = 1.0f) {
  glm::vec4 v;
  for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(s.at(lambdaNm[j])) * scale;
  return v;
}

void addBatches(FrameData& frame, const FrameSettings& settings, const FrameContext& context, const Scene& scene,
                std::uint32_t frameIndex) {
  if (settings.mode == RenderMode::Rgb) {
    const Eigen::Matrix3d& m = context.sceneColourSpace->rgbToXyz;
    shared::GpuBatch batch{};
    batch.toX = toVec4(m.row(0).transpose());
    batch.toY = toVec4(m.row(1).transpose());
    batch.toZ = toVec4(m.row(2).transpose());
    frame.batches.push_back(batch);
    return;
  }
  const Observer& obs = *context.observer;
  double scale = absoluteTristimulusScale(obs);
  if (settings.mode == RenderMode::Optimised4) {
    const TechniqueWavelengths set = optimisedWavelengths(scene.techniques);
    shared::GpuBatch batch{};
    for (int j = 0; j < 4; ++j) {
      double lambda = set.lambdaNm[static_cast<std::size_t>(j)];
      Eigen::Vector3d row = obs.at(lambda) * set.weights[static_cast<std::size_t>(j)] * scale;
      batch.lambdaNm[j] = static_cast<float>(lambda);
      batch.toX[j] = static_cast<float>(row.x());
      batch.toY[j] = static_cast<float>(row.y());
      batch.toZ[j] = static_cast<float>(row.z());
    }
    frame.batches.push_back(batch);
    return;
  }
  std::vector<SampledWavelengths> sampled = context.wavelengths->sample(frameIndex);
  std::vector<IntegrationMatrix> matrices = context.wavelengths->matrices(sampled, obs);
  for (std::size_t b = 0; b < sampled.size(); ++b) {
    shared::GpuBatch batch{};
    for (int j = 0; j < 4; ++j) {
      batch.lambdaNm[j] = static_cast<float>(sampled[b].lambdaNm[static_cast<std::size_t>(j)]);
      batch.toX[j] = static_cast<float>(matrices[b](0, j) * scale);
      batch.toY[j] = static_cast<float>(matrices[b](1, j) * scale);
      batch.toZ[j] = static_cast<float>(matrices[b](2, j) * scale);
    }
    frame.batches.push_back(batch);
  }
}

}  // namespace

void requireLightCount(const Scene& scene) {
  if (scene.lights.size() <= static_cast<std::size_t>(shared::kMaxLights)) return;
  std::string added;
  std::size_t own = 0;
  for (const Light& light : scene.lights) {
    if (light.technique.empty()) ++own;
    else added += fmt::format(", and the {}'s {}", light.technique, light.technique == "atmosphere" ? "sun" : "light");
  }
  throw Error(fmt::format("{}: /lights: {} lights{}; the renderer handles at most {}", scene.file.string(), scene.lights.size(),
                          added.empty() ? "" : fmt::format(" ({} in the file{})", own, added), shared::kMaxLights));
}

void requireTechniquesShow(const Scene& scene, const FrameSettings& settings) {
  scene.techniques.requireObserver(observer(settings.observer), settings.mode == RenderMode::Reference);
  if (settings.mode == RenderMode::Optimised4) {
    try {
      optimisedWavelengths(scene.techniques);
    } catch (const Error& e) {
      throw Error(scene.file.string() + ": " + e.what());
    }
  }
}

FrameData buildFrameData(const Scene& scene, const FrameSettings& settings, const FrameContext& context,
                         const RgbToSpectrumTable& table, const std::vector<ShadowView>& shadows,
                         std::uint32_t frameIndex, const CameraTransform& camera) {
  requireLightCount(scene);
  const RgbColourSpace& space = *context.sceneColourSpace;
  const bool rgbMode = settings.mode == RenderMode::Rgb;
  FrameData frame;
  addBatches(frame, settings, context, scene, frameIndex);
  const int batchCount = static_cast<int>(frame.batches.size());

  frame.constants.mode = rgbMode                                   ? shared::kModeRgb
                         : settings.mode == RenderMode::Naive      ? shared::kModeNaive
                                                                   : shared::kModeJakobHanika;
  frame.constants.batchCount = batchCount;
  frame.constants.lightCount = static_cast<int>(scene.lights.size());
  frame.constants.shadowMapSize = settings.shadowMapSize;
  frame.constants.gbufferCoefficients = settings.gbufferAlbedo == GBufferAlbedo::Coefficients ? 1 : 0;
  frame.constants.upsamplingResolution = table.resolution();
  frame.constants.filteredLookup = settings.lookup == UpsamplingLookup::Filtered ? 1 : 0;
  frame.constants.inverseViewProjection = camera.inverseViewProjection;
  frame.constants.cameraPositionW = camera.position;
  frame.constants.viewportSize = glm::vec2(static_cast<float>(settings.width), static_cast<float>(settings.height));

  // Lights and their spectra.
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    shared::GpuLight g{};
    int type = light.type == LightType::Directional ? shared::kLightDirectional
               : light.type == LightType::Point     ? shared::kLightPoint
                                                    : shared::kLightSpot;
    g.positionW = light.position;
    g.type = type;
    g.direction = glm::normalize(light.direction);
    g.intensity = light.intensity;
    g.cosInner = std::cos(glm::radians(light.innerConeDeg));
    g.cosOuter = std::cos(glm::radians(light.outerConeDeg));
    g.shadowLayer = -1;
    g.shadowFromWorld = glm::mat4(1.0f);
    g.shadowCascades[0] = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
    g.shadowCascadeCount = 1;
    for (const ShadowView& view : shadows) {
      if (view.lightIndex != static_cast<int>(i)) continue;
      if (g.shadowLayer >= 0) {  // a directional light's next cascade, or a point light's next face
        if (light.type == LightType::Directional && view.drawn) g.shadowCascades[g.shadowCascadeCount++] = view.cascadeWindow;
        continue;
      }
      g.shadowLayer = view.layer;
      g.shadowFaceScale = view.pointProjection.x;
      g.shadowDepthA = view.pointProjection.y;
      g.shadowDepthB = view.pointProjection.z;
      g.shadowNormalOffsetM = view.normalOffsetM;
      g.shadowDepthBias = view.depthBias;
      g.shadowFromWorld = view.lightFromWorld;
      g.shadowCascades[0] = view.cascadeWindow;
    }
    frame.lights.push_back(g);
    if (rgbMode) {
      frame.lightSpectra.push_back(emissionRgb(light.spd, space));
    } else {
      for (const shared::GpuBatch& batch : frame.batches) {
        frame.lightSpectra.push_back(at4(light.spd, batch.lambdaNm));
      }
    }
  }

  // Background radiance, a light colour of the given luminance.
  if (rgbMode) {
    frame.lightSpectra.push_back(glm::vec4(scene.background * scene.backgroundLuminance, 0.0f));
  } else {
    RgbIlluminantSpectrum background = backgroundRadiance(scene, space, table);
    for (const shared::GpuBatch& batch : frame.batches) {
      glm::vec4 v;
      for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(background.at(batch.lambdaNm[j]));
      frame.lightSpectra.push_back(v);
    }
  }

  // Materials and their spectra. glTF's emission is a light's colour, upsampled per pixel on the
  // colour space's white (RgbIlluminantSpectrum): that white, of luminance 1, is one spectrum that
  // every material emitting so shares.
  int spectraCount = 0;
  int rgbEmissionWhite = shared::kNoEmission;
  if (anyMaterialEmitsRgb(scene)) {
    rgbEmissionWhite = spectraCount++;
    const Spectrum white = scaledWhiteIlluminant(space, 1.0);
    for (const shared::GpuBatch& batch : frame.batches) {
      // RGB mode: (1, 1, 1) itself, so that the colour is shown as it is (the white's spectrum, through
      // its 1 nm table, lands 1e-4 off the space's nominal white).
      frame.materialSpectra.push_back(rgbMode ? glm::vec4(1.0f, 1.0f, 1.0f, 0.0f) : at4(white, batch.lambdaNm));
      frame.materialSpectra.push_back(glm::vec4(0.0f));
    }
  }
  for (const Material& m : scene.materials) {
    shared::GpuMaterial g{};
    g.baseColour = m.baseColour;
    g.metallic = m.metallic;
    g.roughness = m.roughness;
    g.kind = m.conductor     ? shared::kMaterialConductor
             : m.reflectance ? shared::kMaterialMeasured
                             : shared::kMaterialBaseColour;
    g.lambertian = m.lambertian ? 1 : 0;
    g.emission = shared::kNoEmission;
    g.rgbEmissionWhite = m.emitsRgb() ? rgbEmissionWhite : shared::kNoEmission;
    g.rgbEmissionLuminance = m.emitsRgb() ? m.emissiveLuminance : 0.0f;
    if (g.kind != shared::kMaterialBaseColour) {
      g.spectra = spectraCount++;
      for (const shared::GpuBatch& batch : frame.batches) {
        if (rgbMode) {
          const Spectrum& r = m.conductor ? normalIncidenceReflectance(*m.conductor) : *m.reflectance;
          frame.materialSpectra.push_back(reflectanceRgb(r, space));
          frame.materialSpectra.push_back(glm::vec4(0.0f));
        } else if (m.conductor) {
          frame.materialSpectra.push_back(at4(m.conductor->n, batch.lambdaNm));
          frame.materialSpectra.push_back(at4(m.conductor->k, batch.lambdaNm));
        } else {
          frame.materialSpectra.push_back(at4(*m.reflectance, batch.lambdaNm));
          frame.materialSpectra.push_back(glm::vec4(0.0f));
        }
      }
    }
    if (m.emission) {
      g.emission = spectraCount++;
      for (const shared::GpuBatch& batch : frame.batches) {
        frame.materialSpectra.push_back(rgbMode ? emissionRgb(m.emission->spd, space) * m.emission->luminance
                                                : at4(m.emission->spd, batch.lambdaNm, m.emission->luminance));
        frame.materialSpectra.push_back(glm::vec4(0.0f));
      }
    }
    frame.materials.push_back(g);
  }
  if (frame.materials.empty()) {
    shared::GpuMaterial none{};
    none.emission = shared::kNoEmission;
    none.rgbEmissionWhite = shared::kNoEmission;
    frame.materials.push_back(none);
  }
  if (frame.materialSpectra.empty()) frame.materialSpectra.push_back(glm::vec4(0.0f));

  // The environment's light from above, in the lights' units (RGB mode: as a light's colour).
  std::vector<glm::vec4> environmentFromAbove;
  if (const Spectrum* e = context.environmentFromAbove.get()) {
    if (rgbMode) {
      environmentFromAbove.push_back(emissionRgb(*e, space));
    } else {
      for (const shared::GpuBatch& batch : frame.batches) environmentFromAbove.push_back(at4(*e, batch.lambdaNm));
    }
  }

  // The techniques' blocks, each packed by its technique (techniques/technique_section.h).
  for (const auto& section : scene.techniques.all()) {
    FramePackInput input;
    input.batches = frame.batches;
    input.rgbMode = rgbMode;
    input.cameraPositionW = camera.position;
    input.sceneCameraPositionW = scene.camera.position;
    input.lightSpectra = frame.lightSpectra;
    input.environmentFromAbove = environmentFromAbove;
    input.colourSpace = &space;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
      if (scene.lights[i].technique != section->key()) continue;
      input.ownLight = static_cast<int>(i);
      input.ownLightIntensity = scene.lights[i].intensity;
    }
    try {
      frame.techniques.push_back(section->pack(input));
    } catch (const Error& e) {
      throw Error(fmt::format("{}: {}", scene.file.string(), e.what()));
    }
  }
  return frame;
}

}  // namespace prism::render
