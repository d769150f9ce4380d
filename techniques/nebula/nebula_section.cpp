#include "techniques/nebula/nebula_section.h"

#include <numbers>

#include <fmt/format.h>

#include "core/error.h"
#include "core/fnv1a.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "techniques/nebula/nebula_layout.h"

namespace prism::nebula {

TechniqueBlock NebulaSection::pack(const FramePackInput& input) const {
  TechniqueBlock block;
  block.key = kKey;
  shared::NebulaLightConstants constants{};
  constants.boxMinSize = glm::vec4(boxMin, boxSize);
  constants.starCount = lightSurfaces ? static_cast<int>(model.stars.size()) : 0;
  constants.voxelsZ = density->size().z;
  block.constantsBinding = shared::kNebulaLightConstantsBinding;
  block.setConstants(constants);
  block.dataBinding = shared::kNebulaStarLightsBinding;
  for (int s = 0; s < constants.starCount; ++s) {
    const NebulaStar& star = model.stars[static_cast<std::size_t>(s)];
    block.appendData(glm::vec4(starPositionW(star), 0.0f));
    if (input.rgbMode) {
      PRISM_CHECK(input.colourSpace);
      const Eigen::Vector3d rgb = input.colourSpace->xyzToRgb * luminousTristimulus(starRadiantIntensity(star));
      block.appendData(glm::vec4(static_cast<float>(rgb.x()), static_cast<float>(rgb.y()), static_cast<float>(rgb.z()), 0.0f));
      continue;
    }
    const StarSpectrum shape = starShape(star.temperatureK, model.starModel);
    const double scale = starRadiantScale(star);
    for (const shared::GpuBatch& batch : input.batches) {
      glm::vec4 v;
      for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(scale * shape.shape(batch.lambdaNm[j] * 1e-3));
      block.appendData(v);
    }
  }
  if (block.data.empty()) block.appendData(glm::vec4(0.0f));  // GL buffers are never empty
  return block;
}

Spectrum NebulaSection::starRadiantIntensity(const NebulaStar& star) const {
  const StarSpectrum shape = starShape(star.temperatureK, model.starModel);
  const double scale = starRadiantScale(star);
  Spectrum radiant;
  for (int i = 0; i < kSpectrumSamples; ++i) radiant[i] = scale * shape.shape((kLambdaMinNm + i) * 1e-3);
  return radiant;
}

double NebulaSection::starRadiantScale(const NebulaStar& star) const {
  // The nebula's radiance is intensity/(683·1000) W·m⁻²·sr⁻¹·nm⁻¹ per unit of its model's (ȳ over
  // λ in µm, lengths in the cube's side): a star of luminosity L in the cube's units radiates
  // L·size² of the world's, over 4π sr.
  return intensity * star.luminosity * double(boxSize) * double(boxSize) /
         (4.0 * std::numbers::pi * double(shared::kLumensPerWatt) * 1000.0);
}

glm::vec3 NebulaSection::starPositionW(const NebulaStar& star) const {
  return boxMin + glm::vec3(star.position) * boxSize;
}

std::vector<std::filesystem::path> NebulaSection::inputFiles() const {
  if (source.file.empty()) return {};
  return {source.file};
}

std::uint64_t NebulaSection::hashLoadedData(std::uint64_t hash) const {
  if (density->noise()) return hash;  // its parameters are the scene file's
  const DensityGrid& grid = density->grid();
  const std::int32_t size[3] = {grid.nx, grid.ny, grid.nz};
  hash = fnv1a(size, sizeof size, hash);
  return fnv1a(grid.values.data(), grid.values.size() * sizeof(float), hash);
}

std::string_view NebulaSection::notTracedBecause() const {
  return "a nebula is its own reference: the paper's double integration (the renderer's reference mode, or "
         "prism nebula render --method reference)";
}

TechniqueBench NebulaSection::bench(std::size_t /*pointAndSpotLights*/) const {
  auto projection = std::make_shared<NebulaSection>(*this);
  projection->method = Method::Projection;
  auto light = std::make_shared<NebulaSection>(*this);
  light->method = Method::LightDensity;
  auto reference = std::make_shared<NebulaSection>(*this);
  reference->method = Method::Reference;
  reference->steps = 100;
  reference->referenceSamples = 7;  // 21 wavelengths a step: the paper's baseline
  for (NebulaSection* s : {projection.get(), light.get(), reference.get()}) s->marchEveryFrame = true;
  TechniqueBench b;
  b.configs.push_back({"nebula projection", {}, false, 0, projection});
  b.configs.push_back({"nebula light-density", {}, false, 0, light});
  b.configs.push_back({"nebula reference (paper)", {}, false, 0, reference});
  b.ratios.push_back({"ratio_reference_to_projection", "nebula reference (paper)", "nebula projection"});
  b.ratios.push_back({"ratio_reference_to_light_density", "nebula reference (paper)", "nebula light-density"});
  // What the stars' light on surfaces costs a frame (the lighting pass; the camera held, the march
  // runs once).
  auto lit = std::make_shared<NebulaSection>(*this);
  lit->lightSurfaces = true;
  lit->marchEveryFrame = false;
  auto unlit = std::make_shared<NebulaSection>(*lit);
  unlit->lightSurfaces = false;
  b.configs.push_back({"nebula stars light surfaces", {}, false, 0, lit});
  b.configs.push_back({"nebula stars light nothing", {}, false, 0, unlit});
  b.ratios.push_back({"ratio_star_light_to_none", "nebula stars light surfaces", "nebula stars light nothing"});
  return b;
}

NebulaModel NebulaSection::fullModel() const {
  NebulaModel m = model;
  m.density = density->grid();
  return m;
}

RenderSettings NebulaSection::renderSettings() const {
  RenderSettings s;
  s.method = method;
  s.steps = steps;
  s.basisSize = basis;
  s.basisMaxDepthUm = basisDepthUm;
  s.uniformSamples = referenceSamples;
  return s;
}

std::string NebulaSection::precomputationKey() const {
  std::string key = volumeKey() + model.filters + "|";
  for (const PassbandEdit& e : model.passbands) key += fmt::format("{}×{}|", e.shiftNm, e.widthScale);
  return key;
}

std::string NebulaSection::volumeKey() const {
  const NebulaModel& m = model;
  const glm::ivec3 size = density->size();
  std::string key = fmt::format("{}|{}x{}x{}|{}|{}|{}|{},{},{},{}|{}|{}|{}|", source.file.string(), size.x, size.y,
                                size.z, m.extinction, m.scattering, m.emission,
                                m.scatteringSpectrum.coeffs[0], m.scatteringSpectrum.coeffs[1],
                                m.scatteringSpectrum.coeffs[2], m.scatteringSpectrum.coeffs[3],
                                static_cast<int>(m.starModel), basis, basisDepthUm);
  if (source.noise) {
    const NoiseParameters& p = *source.noise;
    key += fmt::format("noise {} {} {} {} {} {} {}|", p.resolution, p.octaves, p.frequency, p.amplitude, p.gain, p.bias,
                       p.seed);
  }
  for (const LineGroupStrength& l : m.lineGroups) key += fmt::format("{}={}|", l.group, l.strength);
  if (m.ionisation) key += fmt::format("zones {} {}|", m.ionisation->frontRadius, m.ionisation->frontWidth);
  for (const NebulaStar& s : m.stars)
    key += fmt::format("{},{},{},{},{}|", s.position.x, s.position.y, s.position.z, s.temperatureK, s.luminosity);
  return key;
}

void NebulaSection::regenerateDensity() {
  if (source.noise) density = std::make_shared<DeferredDensity>(*source.noise);
}

std::unique_ptr<TechniqueSection> NebulaSection::parse(const schema::Node& n, const TechniqueSections&) {
  using schema::Range;
  n.expectObject({"density", "extinction", "scattering", "scattering_spectrum", "emission", "lines", "ionisation", "stars",
                  "star_model", "filters", "passbands", "steps", "box", "method", "basis", "basis_depth", "reference_samples", "intensity", "march_every_frame",
                  "light_surfaces"});
  auto s = std::make_unique<NebulaSection>();
  s->source = readNebulaKeys(n, s->model, s->steps);
  s->density = s->source.noise ? std::make_shared<DeferredDensity>(*s->source.noise)
                               : std::make_shared<DeferredDensity>(std::move(s->model.density));
  s->model.density = DensityGrid{};
  if (auto box = n.optionalChild("box")) {
    box->expectObject({"min", "size"});
    if (box->has("min")) {
      auto v = box->child("min").numbers(3, Range::closed(-1e6, 1e6));
      s->boxMin = glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    }
    s->boxSize = static_cast<float>(box->number("size", s->boxSize, Range::open(0.0, 1e6)));
  }
  if (auto m = n.optionalChild("method")) {
    const std::string name = m->string();  // its own error names the place: outside the try
    try {
      s->method = methodFromName(name);
    } catch (const Error& e) {
      m->fail(e.what());
    }
  }
  if (n.has("basis")) s->basis = n.child("basis").integer(Range::closed(1, kMaxBasisSize));
  s->basisDepthUm = n.number("basis_depth", s->basisDepthUm, Range{0.0, kMaxBasisDepthUm, true, false});
  if (auto r = n.optionalChild("reference_samples")) {
    s->referenceSamples = r->integer(Range::closed(0, kMaxUniformSamples));
    if (s->referenceSamples == 1) r->fail("must be 0 (Simpson over each passband piece) or at least 2 wavelengths a channel");
  }
  s->intensity = static_cast<float>(n.number("intensity", s->intensity, Range::atLeast(0.0).forFloat()));
  s->marchEveryFrame = n.boolean("march_every_frame", s->marchEveryFrame);
  s->lightSurfaces = n.boolean("light_surfaces", s->lightSurfaces);
  return s;
}

}  // namespace prism::nebula
