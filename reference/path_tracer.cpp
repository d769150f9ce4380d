#include "reference/path_tracer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "reference/emitter_sampler.h"
#include "reference/environment_sampler.h"
#include "reference/path_medium.h"
#include "reference/path_sampling.h"
#include "reference/surface_brdf.h"
#include "reference/ray_scene.h"
#include "reference/surface_hit.h"
#include "reference/surface_spectra.h"
#include "scene/camera_transform.h"
#include "scene/scene_emission.h"
#include "scene/scene_spectra.h"
#include "shared_cpp.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"

namespace prism::shared {
#include "lights.glsl"
}  // namespace prism::shared

namespace prism::reference {
namespace {

using glm::vec3;
using glm::vec4;

constexpr float kInfinity = std::numeric_limits<float>::infinity();
using shared::kPi;
constexpr int kPassSamples = 8;  // samples per pixel per progressive pass

// A light as lightIncidence() takes it.
struct LightInput {
  int type;
  vec3 position, directionTravel;
  float intensity, cosInner, cosOuter;
  bool castsShadows;
};

// Per material: how its albedo is evaluated at a path's wavelengths.
struct MaterialInput {
  const Material* material;
  vec3 coefficients{0.0f};  // Jakob–Hanika coefficients of the base colour (untextured)
};

// An offset along the geometric normal that clears the surface's own triangles (float
// positions of scenes measured in metres).
vec3 offsetOrigin(const vec3& p, const vec3& geometricNormal) {
  float scale = std::max({1.0f, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return p + geometricNormal * (1e-4f * scale);
}

vec4 exp4(const vec4& v) { return vec4(std::exp(v.x), std::exp(v.y), std::exp(v.z), std::exp(v.w)); }
float mean4(const vec4& v) { return 0.25f * (v.x + v.y + v.z + v.w); }

class PathTracer {
 public:
  PathTracer(const Scene& scene, const RgbToSpectrumTable& table, const ReferenceSettings& settings)
      : mScene(scene),
        mTable(table),
        mSettings(settings),
        mObserver(observer(settings.observer)),
        mScale(absoluteTristimulusScale(mObserver)),
        mSampler(
            sceneWavelengthSampler(settings.wavelengths, mObserver, scene, colourSpace(scene.colourSpace), table)),
        mRays(sceneRays(scene)),
        mBackground(backgroundRadiance(scene, colourSpace(scene.colourSpace), table)),
        mCamera(cameraTransform(scene.camera, settings.width, settings.height)),
        mMedium(effectiveMedium(scene)),
        mEnvironment(scene.techniques.environment(table)),
        mEmissionWhite(scaledWhiteIlluminant(colourSpace(scene.colourSpace), 1.0)),
        mEmitters(scene) {
    if (mEnvironment) {
      EnvironmentSampler sampler(*mEnvironment, mObserver, settings.threads);
      if (!sampler.empty()) mEnvironmentSampler.emplace(std::move(sampler));
    }
    for (const Light& light : scene.lights) {
      int type = light.type == LightType::Directional ? shared::kLightDirectional
                 : light.type == LightType::Point     ? shared::kLightPoint
                                                      : shared::kLightSpot;
      mLights.push_back({type, light.position, glm::normalize(light.direction), light.intensity,
                         std::cos(glm::radians(light.innerConeDeg)),
                         std::cos(glm::radians(light.outerConeDeg)), light.castsShadows});
    }
    for (const Material& m : scene.materials) {
      mMaterials.push_back({&m, RgbAlbedoSpectrum(table, m.baseColour).coefficients()});
    }
  }

  // One path through pixel (x, y) (row 0 at the top): its tristimulus estimate.
  Eigen::Vector3d samplePixel(int x, int y, std::uint32_t sample) const {
    std::uint32_t pixel = static_cast<std::uint32_t>(y * mSettings.width + x);
    PathRandom random(pixel, sample, mSettings.seed);
    // Sample s of N takes part s of every stratum: a pixel's N paths together are a stratified
    // estimate over 4·N strata of the spectrum.
    SampledWavelengths wavelengths =
        mSampler.sample(shared::pcgHash(random.seed() ^ 0x9E3779B9u),  // a stream of its own
                        static_cast<int>(sample % static_cast<std::uint32_t>(mSettings.samplesPerPixel)),
                        mSettings.samplesPerPixel).front();
    vec4 lambdaNm;
    for (int j = 0; j < 4; ++j) lambdaNm[j] = static_cast<float>(wavelengths.lambdaNm[static_cast<std::size_t>(j)]);

    float sx = static_cast<float>(x) + 0.5f, sy = static_cast<float>(y) + 0.5f;
    if (mSettings.filter == PixelFilter::Box) {
      sx = static_cast<float>(x) + random.next();
      sy = static_cast<float>(y) + random.next();
    }
    vec3 direction = cameraDirection(sx / static_cast<float>(mSettings.width),
                                     1.0f - sy / static_cast<float>(mSettings.height));
    MediumAt medium;
    if (mMedium) {
      for (int j = 0; j < 4; ++j) {
        float sigmaA = static_cast<float>(mMedium->sigmaA.at(lambdaNm[j]));
        medium.sigmaS[j] = static_cast<float>(mMedium->sigmaS.at(lambdaNm[j]));
        medium.sigmaT[j] = sigmaA + medium.sigmaS[j];
      }
    }
    vec4 radiance = trace(mCamera.position, direction, lambdaNm, medium, random);

    IntegrationMatrix m = mSampler.matrices({wavelengths}, mObserver).front();
    Eigen::Vector4d l(radiance.x, radiance.y, radiance.z, radiance.w);
    return mScale * (m * l);
  }

 private:
  // The direction through the point uv ∈ [0, 1]² of the image (GL window convention).
  vec3 cameraDirection(float u, float v) const {
    vec4 farPoint = mCamera.inverseViewProjection * vec4(u * 2.0f - 1.0f, v * 2.0f - 1.0f, 1.0f, 1.0f);
    return glm::normalize(vec3(farPoint) / farPoint.w - mCamera.position);
  }

  vec4 backgroundAt(const vec4& lambdaNm) const {
    vec4 v;
    for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(mBackground.at(lambdaNm[j]));
    return v;
  }

  // What a path leaving the scene in `direction` gathers: the camera sees the background; after a
  // bounce, the technique's environment where there is one, else the background.
  vec4 escapedAt(int depth, const vec3& direction, const vec4& lambdaNm) const {
    if (depth == 0 || !mEnvironment) return backgroundAt(lambdaNm);
    vec4 v;
    for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(mEnvironment->radiance(direction, lambdaNm[j]));
    return v;
  }

  // Next-event estimation of the technique's environment from `origin`: a direction drawn from
  // EnvironmentSampler, the environment's radiance through `response` (BRDF·cos, or the phase
  // function; 0 where it takes no light from there) where nothing (no surface, no medium) is in
  // the way, weighted against the chance `density` (per steradian) that the path's own direction
  // takes it (the power heuristic; that direction's share is environmentWeight's).
  template <typename Response, typename Density>
  vec4 aimedEnvironmentLight(const vec3& origin, const vec4& lambdaNm, const MediumAt& medium, PathRandom& random,
                             Response&& response, Density&& density) const {
    const double u0 = random.nextFine();
    const float u1 = random.next(), u2 = random.next();
    const EnvironmentSampler::Direction d = mEnvironmentSampler->sample(u0, u1, u2);
    const vec4 f = response(d.towards);
    if (!(d.pdf > 0.0f) || !(f.x > 0.0f || f.y > 0.0f || f.z > 0.0f || f.w > 0.0f)) return vec4(0.0f);
    if (mRays.occluded(origin, d.towards, 0.0f, kInfinity)) return vec4(0.0f);
    return f * escapedAt(1, d.towards, lambdaNm) * transmittance(origin, d.towards, kInfinity, medium) *
           (powerHeuristic(d.pdf, density(d.towards)) / d.pdf);
  }

  // The share of the environment's light that a direction drawn with density `bouncePdf` (a
  // BRDF's or the phase function's) takes where aimedEnvironmentLight aimed too: 1 where it did
  // not (no environment to aim at, the camera's ray: bouncePdf 0).
  float environmentWeight(const vec3& towards, float bouncePdf) const {
    if (!mEnvironmentSampler || !(bouncePdf > 0.0f)) return 1.0f;
    return powerHeuristic(bouncePdf, mEnvironmentSampler->pdf(towards));
  }

  // What is aimed at from `origin` with `response` and `density` (emitterLight's and
  // aimedEnvironmentLight's): the emitters where `atEmitters` (global transport; direct transport
  // lights nothing with them, as the rasteriser), and the environment.
  template <typename Response, typename Density>
  vec4 aimedLight(const vec3& origin, const vec4& lambdaNm, const MediumAt& medium, PathRandom& random, bool atEmitters,
                  Response&& response, Density&& density) const {
    vec4 sum(0.0f);
    if (atEmitters && !mEmitters.empty()) sum += emitterLight(origin, lambdaNm, medium, random, response, density);
    if (mEnvironmentSampler) sum += aimedEnvironmentLight(origin, lambdaNm, medium, random, response, density);
    return sum;
  }

  // aimedLight at a surface point: BRDF·cos, and the density sampleBrdf draws with.
  vec4 surfaceAimedLight(const SurfaceHit& hit, const vec3& v, const vec4& lambdaNm, const vec4& albedoOrN,
                         const vec4& k, const MediumAt& medium, PathRandom& random, bool atEmitters) const {
    return aimedLight(
        offsetOrigin(hit.positionW, hit.geometricNormalW), lambdaNm, medium, random, atEmitters,
        [&](const vec3& l) { return surfaceResponse(hit, v, l, albedoOrN, k); },
        [&](const vec3& l) { return brdfPdf(hit, v, l); });
  }

  // aimedLight at a scattering point in the medium, the path having travelled along `direction`:
  // the phase function is both the response and the density its next direction is drawn with.
  vec4 mediumAimedLight(const vec3& point, const vec3& direction, const vec4& lambdaNm, const MediumAt& medium,
                        PathRandom& random, bool atEmitters) const {
    auto phase = [&](const vec3& l) { return henyeyGreenstein(glm::dot(l, direction), mMedium->g); };
    return aimedLight(point, lambdaNm, medium, random, atEmitters, [&](const vec3& l) { return vec4(phase(l)); }, phase);
  }

  // Direct transport's light from the environment at a surface point: a direction drawn from the
  // BRDF and one aimed at the environment, weighed, the environment's radiance where nothing (no
  // surface, no medium) is in the way.
  vec4 surfaceEnvironmentLight(const SurfaceHit& hit, const vec3& v, const vec4& lambdaNm, const vec4& albedoOrN,
                               const vec4& k, const MediumAt& medium, PathRandom& random) const {
    const vec3 origin = offsetOrigin(hit.positionW, hit.geometricNormalW);
    vec4 sum(0.0f);
    vec3 l;
    vec4 weight(1.0f);
    float pdf = 0.0f;
    if (sampleBrdf(hit, v, albedoOrN, k, random, l, weight, pdf) && !mRays.occluded(origin, l, 0.0f, kInfinity))
      sum += weight * escapedAt(1, l, lambdaNm) * transmittance(origin, l, kInfinity, medium) * environmentWeight(l, pdf);
    sum += surfaceAimedLight(hit, v, lambdaNm, albedoOrN, k, medium, random, false);
    return sum;
  }

  // Direct transport's light from the environment at a scattering point in the medium, the path
  // having travelled along `direction`: a direction drawn from the phase function (its weight 1)
  // and one aimed at the environment, weighed, the environment's radiance where no surface is in
  // the way, through what is left of the medium (the water's surface, looking up; nothing through
  // an unbounded medium).
  vec4 mediumEnvironmentLight(const vec3& point, const vec3& direction, const vec4& lambdaNm, const MediumAt& medium,
                              PathRandom& random) const {
    const vec3 l = sampleHenyeyGreenstein(direction, mMedium->g, random.next(), random.next());
    vec4 sum(0.0f);
    if (!mRays.occluded(point, l, 0.0f, kInfinity))
      sum += escapedAt(1, l, lambdaNm) * transmittance(point, l, kInfinity, medium) *
             environmentWeight(l, henyeyGreenstein(glm::dot(l, direction), mMedium->g));
    sum += mediumAimedLight(point, direction, lambdaNm, medium, random, false);
    return sum;
  }

  // The spectra of a surface at the path's wavelengths: albedo (or n) and conductor k.
  void surfaceSpectra(const SurfaceHit& hit, const vec4& lambdaNm, vec4& albedoOrN, vec4& k) const {
    const MaterialInput& input = mMaterials[static_cast<std::size_t>(hit.material)];
    const SurfaceSpectra s = reference::surfaceSpectra(hit, *input.material, input.coefficients, mTable, lambdaNm);
    albedoOrN = s.albedoOrN;
    k = s.k;
  }

  // The surface's emitted radiance at the path's wavelengths (0 where its material emits none).
  vec4 emittedAt(const SurfaceHit& hit, const vec4& lambdaNm) const {
    const Material& m = *mMaterials[static_cast<std::size_t>(hit.material)].material;
    return emittedRadiance(hit, m, mTable, mEmissionWhite, lambdaNm);
  }

  // The BRDF of surface_brdf.h at a hit, its material's conductor or not.
  bool conductorAt(const SurfaceHit& hit) const {
    return mMaterials[static_cast<std::size_t>(hit.material)].material->conductor.has_value();
  }
  vec4 surfaceResponse(const SurfaceHit& hit, const vec3& v, const vec3& l, const vec4& albedoOrN, const vec4& k) const {
    return reference::surfaceResponse(hit, conductorAt(hit), v, l, albedoOrN, k);
  }
  float brdfPdf(const SurfaceHit& hit, const vec3& v, const vec3& l) const {
    return reference::brdfPdf(hit, conductorAt(hit), v, l);
  }
  // A direction from the BRDF's lobes (the path's next three numbers); false when the path ends
  // here. throughput is multiplied by BRDF·cos / pdf, and pdf is the direction's density.
  bool sampleBrdf(const SurfaceHit& hit, const vec3& v, const vec4& albedoOrN, const vec4& k, PathRandom& random,
                  vec3& l, vec4& throughput, float& pdf) const {
    const float u1 = random.next(), u2 = random.next(), uLobe = random.next();
    const std::optional<BrdfSample> s = reference::sampleBrdf(hit, conductorAt(hit), v, albedoOrN, k, u1, u2, uLobe);
    if (!s) return false;
    l = s->l;
    throughput *= s->weight;
    pdf = s->pdf;
    return true;
  }

  // Beer–Lambert transmittance of the medium along origin + t·direction, t ∈ [0, tMax].
  vec4 transmittance(const vec3& origin, const vec3& direction, float tMax, const MediumAt& medium) const {
    if (!mMedium) return vec4(1.0f);
    float tEnter, tExit;
    mediumInterval(*mMedium, origin, direction, 0.0f, tMax, tEnter, tExit);
    if (!(tExit > tEnter)) return vec4(1.0f);
    if (std::isinf(tExit)) {
      vec4 none(0.0f);
      for (int j = 0; j < 4; ++j) none[j] = medium.sigmaT[j] > 0.0f ? 0.0f : 1.0f;
      return none;
    }
    return exp4(-medium.sigmaT * (tExit - tEnter));
  }

  // Spectral irradiance from every light at a point (on a surface facing it), times whatever
  // `response` makes of the light's direction: BRDF·cos at a surface, the phase function in a
  // medium. Delta lights, so next-event estimation is exact; shadow rays see surfaces that cast
  // shadows and the medium's transmittance.
  template <typename Response>
  vec4 directLight(const vec3& point, const vec3& rayOrigin, const vec4& lambdaNm, const MediumAt& medium,
                   Response&& response) const {
    vec4 sum(0.0f);
    for (std::size_t i = 0; i < mLights.size(); ++i) {
      const LightInput& light = mLights[i];
      shared::LightIncidence li =
          shared::lightIncidence(light.type, light.position, light.directionTravel, light.intensity,
                                 light.cosInner, light.cosOuter, point);
      if (li.irradiance <= 0.0f) continue;
      vec4 f = response(li.toLight);
      if (!(f.x > 0.0f || f.y > 0.0f || f.z > 0.0f || f.w > 0.0f)) continue;
      float tMax = li.distance > 0.0f ? li.distance * (1.0f - 1e-5f) : kInfinity;
      if (light.castsShadows && mRays.occluded(rayOrigin, li.toLight, 0.0f, tMax)) continue;
      vec4 spd;
      for (int j = 0; j < 4; ++j) spd[j] = static_cast<float>(mScene.lights[i].spd.at(lambdaNm[j]));
      sum += f * spd * li.irradiance * transmittance(rayOrigin, li.toLight, tMax, medium);
    }
    return sum;
  }

  vec4 surfaceDirectLight(const SurfaceHit& hit, const vec3& v, const vec4& lambdaNm, const vec4& albedoOrN,
                          const vec4& k, const MediumAt& medium) const {
    return directLight(hit.positionW, offsetOrigin(hit.positionW, hit.geometricNormalW), lambdaNm, medium,
                       [&](const vec3& toLight) { return surfaceResponse(hit, v, toLight, albedoOrN, k); });
  }

  // Global transport's next-event estimation of the emitting surfaces from `origin`: a point
  // drawn on them (EmitterSampler), its emission through `response` (BRDF·cos at a surface, the
  // phase function in the medium; 0 where it takes no light from that direction) where nothing is
  // in the way, weighted against the chance `density` (per steradian) that the path's own next
  // direction meets it (the power heuristic; a path that meets an emitter so takes the other
  // weight, emissionWeight).
  template <typename Response, typename Density>
  vec4 emitterLight(const vec3& origin, const vec4& lambdaNm, const MediumAt& medium, PathRandom& random,
                    Response&& response, Density&& density) const {
    const double u0 = random.nextFine();
    const float u1 = random.next(), u2 = random.next();
    const EmitterPoint e = mEmitters.sample(u0, u1, u2);
    const vec3 toEmitter = e.position - origin;
    const float distance = glm::length(toEmitter);
    if (!(distance > 0.0f)) return vec4(0.0f);
    const vec3 l = toEmitter / distance;
    const float cosEmitter = std::abs(glm::dot(e.normal, l));
    if (!(cosEmitter > 0.0f)) return vec4(0.0f);
    const vec4 f = response(l);
    if (!(f.x > 0.0f || f.y > 0.0f || f.z > 0.0f || f.w > 0.0f)) return vec4(0.0f);
    if (mRays.occluded(origin, l, 0.0f, distance * (1.0f - 1e-5f))) return vec4(0.0f);  // as the lights' rays
    rays::TriangleHit at = e.at;
    at.distance = distance;
    const vec4 emitted = emittedAt(surfaceHit(mScene, at, origin, l), lambdaNm);
    const float pdfLight = e.pdfArea * distance * distance / cosEmitter;  // per steradian
    return f * emitted * transmittance(origin, l, distance, medium) * (powerHeuristic(pdfLight, density(l)) / pdfLight);
  }

  // The share of an emitter's light met by a direction drawn with density `bouncePdf` (a BRDF's
  // or the phase function's) at `distance` (emitterLight drew the rest): 1 where no emitter was
  // aimed at (the camera's ray, direct transport: bouncePdf 0).
  float emissionWeight(const SurfaceHit& hit, std::uint32_t geometry, float distance, const vec3& direction,
                       float bouncePdf) const {
    if (!(bouncePdf > 0.0f)) return 1.0f;
    const float cosEmitter = std::abs(glm::dot(hit.geometricNormalW, direction));
    if (!(cosEmitter > 0.0f)) return 1.0f;
    return powerHeuristic(bouncePdf, mEmitters.pdfArea(geometry) * distance * distance / cosEmitter);
  }

  // In a medium, with global transport, the distance to the next scattering event is drawn from
  // one of the four wavelengths' scattering coefficient (the hero, chosen at random) and
  // absorption weights the path by Beer–Lambert, so a pure absorber costs no noise; every
  // wavelength is weighted by its own σs·T over the mean of the four heroes' free-flight
  // densities: the one-sample balance heuristic of spectral MIS (Wilkie et al. 2014), unbiased at
  // every wavelength of a chromatic medium. Direct transport (single scattering) forces one
  // scattering event per segment instead, with the same MIS over truncated exponentials.
  vec4 trace(vec3 origin, vec3 direction, const vec4& lambdaNm, const MediumAt& medium,
             PathRandom& random) const {
    const bool global = mSettings.transport == LightTransport::Global;
    vec4 radiance(0.0f), throughput(1.0f);
    float bouncePdf = 0.0f;  // the density of the direction that led here; 0 for the camera's
    for (int depth = 0;; ++depth) {
      std::optional<rays::TriangleHit> found = mRays.intersect(origin, direction, 0.0f, kInfinity);
      const float tSurface = found ? found->distance : kInfinity;
      bool scattered = false;
      if (mMedium) {
        float tEnter, tExit;
        mediumInterval(*mMedium, origin, direction, 0.0f, tSurface, tEnter, tExit);
        if (tExit > tEnter && !global) {
          // Single scattering: every path both scatters once somewhere on the segment (the
          // distance drawn from the hero's extinction, truncated to the segment) and goes on to
          // the surface behind with its exact transmittance: no path is spent missing the medium.
          const float length = tExit - tEnter;
          float sigmaHero = medium.sigmaT[std::min(3, static_cast<int>(random.next() * 4.0f))];
          if (sigmaHero > 0.0f) {
            auto truncatedDensity = [&](const vec4& sigma, float d) {  // per wavelength, at d
              vec4 density;
              for (int j = 0; j < 4; ++j) {
                float kept = std::isinf(length) ? 1.0f : -std::expm1(-sigma[j] * length);
                density[j] = sigma[j] > 0.0f ? sigma[j] * std::exp(-sigma[j] * d) / kept : 0.0f;
              }
              return density;
            };
            float kept = std::isinf(length) ? 1.0f : -std::expm1(-sigmaHero * length);
            float d = -std::log1p(-random.next() * kept) / sigmaHero;
            vec3 point = origin + direction * (tEnter + d);
            vec4 weight = medium.sigmaS * exp4(-medium.sigmaT * d) / mean4(truncatedDensity(medium.sigmaT, d));
            radiance += throughput * weight * directLight(point, point, lambdaNm, medium, [&](const vec3& toLight) {
                          return vec4(henyeyGreenstein(glm::dot(toLight, direction), mMedium->g));
                        });
            if (mEnvironment) radiance += throughput * weight * mediumEnvironmentLight(point, direction, lambdaNm, medium, random);
          }
          vec4 pass(0.0f);
          for (int j = 0; j < 4; ++j) pass[j] = std::isinf(length) ? (medium.sigmaT[j] > 0.0f ? 0.0f : 1.0f)
                                                                   : std::exp(-medium.sigmaT[j] * length);
          throughput *= pass;
        } else if (tExit > tEnter) {
          float sigmaHero = medium.sigmaS[std::min(3, static_cast<int>(random.next() * 4.0f))];
          float u = random.next();
          float t = sigmaHero > 0.0f ? tEnter - std::log1p(-u) / sigmaHero : kInfinity;
          if (t < tExit) {
            float d = t - tEnter;
            throughput *= medium.sigmaS * exp4(-medium.sigmaT * d) / mean4(medium.sigmaS * exp4(-medium.sigmaS * d));
            vec3 point = origin + direction * t;
            radiance += throughput * directLight(point, point, lambdaNm, medium, [&](const vec3& toLight) {
                          return vec4(henyeyGreenstein(glm::dot(toLight, direction), mMedium->g));
                        });
            scattered = true;
            if (!global || depth + 1 >= mSettings.maxDepth) break;
            radiance += throughput * mediumAimedLight(point, direction, lambdaNm, medium, random, true);
            origin = point;
            const vec3 travelled = direction;
            direction = sampleHenyeyGreenstein(direction, mMedium->g, random.next(), random.next());
            bouncePdf = henyeyGreenstein(glm::dot(direction, travelled), mMedium->g);
          } else if (std::isinf(tExit)) {
            // Through an unbounded medium to infinity: only wavelengths the medium neither
            // absorbs nor scatters arrive, and only heroes that do not scatter get there.
            vec4 arrives(0.0f), passes(0.0f);
            for (int j = 0; j < 4; ++j) {
              arrives[j] = medium.sigmaT[j] > 0.0f ? 0.0f : 1.0f;
              passes[j] = medium.sigmaS[j] > 0.0f ? 0.0f : 1.0f;
            }
            throughput *= arrives / mean4(passes);
          } else {
            float d = tExit - tEnter;
            throughput *= exp4(-medium.sigmaT * d) / mean4(exp4(-medium.sigmaS * d));
          }
        }
      }
      if (!scattered) {
        if (!found) {
          // After a bounce, the environment's share this direction takes (aimedEnvironmentLight the rest).
          if (depth == 0 || global)
            radiance += throughput * escapedAt(depth, direction, lambdaNm) * environmentWeight(direction, bouncePdf);
          break;
        }
        SurfaceHit hit = surfaceHit(mScene, *found, origin, direction);
        vec3 v = -direction;
        vec4 albedoOrN, k;
        surfaceSpectra(hit, lambdaNm, albedoOrN, k);
        // What the surface emits, at every hit: direct transport's paths end at their first, what
        // the camera sees (as the rasteriser shows it); global transport's go on, so an emitter
        // lights the scene, met by BRDF samples and aimed at (emitterLight), the two weighed.
        radiance += throughput * emittedAt(hit, lambdaNm) *
                    emissionWeight(hit, found->geometry, found->distance, direction, bouncePdf);
        radiance += throughput * surfaceDirectLight(hit, v, lambdaNm, albedoOrN, k, medium);
        if (!global && mEnvironment) radiance += throughput * surfaceEnvironmentLight(hit, v, lambdaNm, albedoOrN, k, medium, random);
        if (!global || depth + 1 >= mSettings.maxDepth) break;
        radiance += throughput * surfaceAimedLight(hit, v, lambdaNm, albedoOrN, k, medium, random, true);
        vec3 l;
        if (!sampleBrdf(hit, v, albedoOrN, k, random, l, throughput, bouncePdf)) break;
        origin = offsetOrigin(hit.positionW, hit.geometricNormalW);
        direction = l;
      }
      if (depth >= 3) {  // Russian roulette on the largest throughput
        float survive = std::min(1.0f, std::max({throughput.x, throughput.y, throughput.z, throughput.w}));
        if (random.next() >= survive) break;
        throughput /= survive;
      }
    }
    // A NaN or ∞ (a degenerate pdf) must not poison the pixel's mean: such a path counts as 0.
    for (int j = 0; j < 4; ++j) {
      if (!std::isfinite(radiance[j])) return vec4(0.0f);
    }
    return radiance;
  }

  const Scene& mScene;
  const RgbToSpectrumTable& mTable;
  ReferenceSettings mSettings;
  const Observer& mObserver;
  double mScale;
  WavelengthSampler mSampler;
  rays::TriangleBvh mRays;
  RgbIlluminantSpectrum mBackground;
  CameraTransform mCamera;
  std::vector<LightInput> mLights;
  std::vector<MaterialInput> mMaterials;
  std::optional<HomogeneousMedium> mMedium;
  std::shared_ptr<const TechniqueEnvironment> mEnvironment;
  Spectrum mEmissionWhite;  // the colour space's white of luminance 1, glTF's emission's
  EmitterSampler mEmitters;
  std::optional<EnvironmentSampler> mEnvironmentSampler;  // where there is an environment with light
};

}  // namespace

void requireTraceable(const Scene& scene) {
  for (const auto& section : scene.techniques.all()) {
    if (std::string_view why = section->notTracedBecause(); !why.empty())
      throw Error(fmt::format("{}: {}", scene.file.string(), why));
  }
}

ReferenceImage renderReference(const Scene& scene, const RgbToSpectrumTable& table,
                               const ReferenceSettings& settings, const ReferenceProgress& progress) {
  return renderReference(scene, table, settings, ReferenceRegion::whole(settings), progress);
}

ReferenceImage renderReference(const Scene& scene, const RgbToSpectrumTable& table,
                               const ReferenceSettings& settings, const ReferenceRegion& region,
                               const ReferenceProgress& progress) {
  validate(settings);
  validate(region, settings);
  requireTraceable(scene);
  requireTableForColourSpace(table, scene.colourSpace, scene.file.string());
  PathTracer tracer(scene, table, settings);
  const int width = settings.width, rows = region.rows();
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(rows);
  std::vector<Eigen::Vector3d> sum(pixels, Eigen::Vector3d::Zero()), sumSquares = sum;

  const int passes = (region.samples() + kPassSamples - 1) / kPassSamples;
  const std::size_t total = static_cast<std::size_t>(passes) * static_cast<std::size_t>(rows);
  std::size_t done = 0;
  std::mutex progressMutex;
  unsigned threadCount = settings.threads ? settings.threads : allThreads();

  for (int pass = 0; pass < passes; ++pass) {
    const int first = region.sampleBegin + pass * kPassSamples;
    const int last = std::min(region.sampleEnd, first + kPassSamples);
    std::atomic<int> nextRow{0};
    std::exception_ptr failure;
    auto work = [&] {
      try {
        for (int row = nextRow++; row < rows; row = nextRow++) {
          for (int x = 0; x < width; ++x) {
            std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
            for (int s = first; s < last; ++s) {
              Eigen::Vector3d value = tracer.samplePixel(x, region.rowBegin + row, static_cast<std::uint32_t>(s));
              sum[i] += value;
              sumSquares[i] += value.cwiseProduct(value);
            }
          }
          std::lock_guard lock(progressMutex);
          ++done;
          if (progress) progress(done, total);
        }
      } catch (...) {
        std::lock_guard lock(progressMutex);
        if (!failure) failure = std::current_exception();
        nextRow = rows;
      }
    };
    std::vector<std::thread> threads;
    try {
      for (unsigned t = 1; t < threadCount; ++t) threads.emplace_back(work);
    } catch (const std::system_error&) {
      // The system gave fewer threads than asked: the ones started and this one share the rows.
    }
    work();
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
  }

  ReferenceImage image{imaging::FloatImage(width, rows, 3), imaging::FloatImage(width, rows, 3),
                       imaging::FloatImage(width, rows, 3)};
  const double n = region.samples();
  for (std::size_t i = 0; i < pixels; ++i) {
    Eigen::Vector3d mean = sum[i] / n;
    Eigen::Vector3d variance = Eigen::Vector3d::Zero();
    if (n > 1) variance = ((sumSquares[i] - n * mean.cwiseProduct(mean)) / (n - 1)).cwiseMax(0.0);
    for (int c = 0; c < 3; ++c) {
      const std::size_t k = 3 * i + static_cast<std::size_t>(c);
      image.tristimulus.pixels[k] = static_cast<float>(mean[c]);
      image.variance.pixels[k] = static_cast<float>(variance[c] / n);
      image.meanResidual.pixels[k] = static_cast<float>(mean[c] - static_cast<double>(image.tristimulus.pixels[k]));
    }
  }
  return image;
}

}  // namespace prism::reference
