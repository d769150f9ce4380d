#include "techniques/nebula/nebula_section.h"

#include <fmt/format.h>

#include "core/error.h"
#include "core/fnv1a.h"

namespace prism::nebula {

TechniqueBlock NebulaSection::pack(const FramePackInput&) const {
  TechniqueBlock block;
  block.key = kKey;
  return block;
}

std::uint64_t NebulaSection::hashLoadedData(std::uint64_t hash) const {
  const std::int32_t size[3] = {density->nx, density->ny, density->nz};
  hash = fnv1a(size, sizeof size, hash);
  return fnv1a(density->values.data(), density->values.size() * sizeof(float), hash);
}

std::string_view NebulaSection::notTracedBecause() const {
  return "a nebula is its own reference: the paper's double integration (the renderer's reference mode, or "
         "prism nebula render --method reference)";
}

TechniqueBench NebulaSection::bench() const {
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
  return b;
}

NebulaModel NebulaSection::fullModel() const {
  NebulaModel m = model;
  m.density = *density;
  return m;
}

RenderSettings NebulaSection::renderSettings() const {
  RenderSettings s;
  s.method = method;
  s.steps = steps;
  s.basisSize = basis;
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
  std::string key = fmt::format("{}|{}x{}x{}|{}|{}|{}|{},{},{},{}|{}|{}|", source.file.string(), density->nx,
                                density->ny, density->nz, m.extinction, m.scattering, m.emission,
                                m.scatteringSpectrum.coeffs[0], m.scatteringSpectrum.coeffs[1],
                                m.scatteringSpectrum.coeffs[2], m.scatteringSpectrum.coeffs[3],
                                static_cast<int>(m.starModel), basis);
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
  if (source.noise) density = std::make_shared<DensityGrid>(generateFbm(*source.noise));
}

std::unique_ptr<TechniqueSection> NebulaSection::parse(const schema::Node& n, const TechniqueSections&) {
  using schema::Range;
  n.expectObject({"density", "extinction", "scattering", "scattering_spectrum", "emission", "lines", "ionisation", "stars",
                  "star_model", "filters", "passbands", "steps", "box", "method", "basis", "reference_samples", "intensity", "march_every_frame"});
  auto s = std::make_unique<NebulaSection>();
  s->source = readNebulaKeys(n, s->model, s->steps, 0);
  s->density = std::make_shared<DensityGrid>(std::move(s->model.density));
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
    try {
      s->method = methodFromName(m->string());
    } catch (const Error& e) {
      m->fail(e.what());
    }
  }
  if (n.has("basis")) s->basis = n.child("basis").integer(Range::closed(1, 8));
  if (auto r = n.optionalChild("reference_samples")) {
    s->referenceSamples = r->integer(Range::closed(0, 1000));
    if (s->referenceSamples == 1) r->fail("must be 0 (Simpson over each passband piece) or at least 2 wavelengths a channel");
  }
  s->intensity = static_cast<float>(n.number("intensity", s->intensity, Range::atLeast(0.0)));
  s->marchEveryFrame = n.boolean("march_every_frame", s->marchEveryFrame);
  return s;
}

}  // namespace prism::nebula
