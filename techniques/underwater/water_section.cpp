#include "techniques/underwater/water_section.h"

#include <algorithm>

#include "core/error.h"
#include "spectral/sampling.h"
#include "techniques/underwater/jerlov_water.h"
#include "techniques/underwater/underwater_layout.h"

namespace prism::underwater {

void WaterSection::resolve() {
  WaterProperties properties = jerlovWater(type, jerlovDatasetFromName(dataset));
  sigmaA = properties.sigmaA * absorptionScale;
  sigmaS = properties.sigmaS * scatteringScale;
  kd = properties.kd * kdScale;
}

namespace {

glm::vec4 at4(const Spectrum& s, const glm::vec4& lambdaNm) {
  glm::vec4 v;
  for (int j = 0; j < 4; ++j) v[j] = static_cast<float>(s.at(lambdaNm[j]));
  return v;
}

}  // namespace

TechniqueBlock WaterSection::pack(const FramePackInput& input) const {
  TechniqueBlock block;
  block.key = kKey;
  shared::WaterConstants constants{};
  constants.surfaceY = surfaceY(input.sceneCameraPositionW.y);
  constants.depthM = std::max(constants.surfaceY - input.cameraPositionW.y, 0.0f);
  constants.lampScattering = lampScattering ? 1.0f : 0.0f;
  block.constantsBinding = shared::kWaterConstantsBinding;
  block.setConstants(constants);
  block.dataBinding = shared::kWaterSpectraBinding;
  for (std::size_t b = 0; b < input.batches.size(); ++b) {
    glm::vec4 lambdaNm = input.rgbMode ? rgbStandInWavelengths(kRgbStandInWavelengthsNm[1]) : input.batches[b].lambdaNm;
    glm::vec4 s = at4(sigmaS, lambdaNm), a = at4(sigmaA, lambdaNm);
    block.appendData(s);
    block.appendData(a + s);
    block.appendData(at4(kd, lambdaNm));
    block.appendData(b < input.environmentFromAbove.size() ? input.environmentFromAbove[b] : glm::vec4(0.0f));
  }
  return block;
}

TechniqueBench WaterSection::bench(std::size_t pointAndSpotLights) const {
  const std::vector<std::pair<std::string, std::string>> spectral16 = {{"mode", "jakob-hanika"}, {"wavelengths", "16"}};
  TechniqueBench b{{{"rgb dry", {}, true}, {"16 dry", spectral16, true}, {"16 wet", spectral16, false}},
                   {{"rgb_ratio_wet_to_dry", "rgb", "rgb dry"}, {"spectral16_ratio_wet_to_dry", "16 wet", "16 dry"}}};
  if (lampScattering && pointAndSpotLights > 0) {
    auto unscattered = std::make_shared<WaterSection>(*this);
    unscattered->lampScattering = false;
    b.configs.push_back({"16 wet, lamps unscattered", spectral16, false, 0, unscattered});
    b.ratios.push_back({"spectral16_ratio_lamp_scattering", "16 wet", "16 wet, lamps unscattered"});
  }
  return b;
}

std::optional<TechniqueMedium> WaterSection::medium(const glm::vec3& sceneCameraPositionW) const {
  constexpr float kFar = 1e7f;  // the ocean has no sides or bottom
  TechniqueMedium water;
  water.sigmaA = sigmaA;
  water.sigmaS = sigmaS;
  water.regionMin = glm::vec3(-kFar);
  water.regionMax = glm::vec3(kFar, surfaceY(sceneCameraPositionW.y), kFar);
  water.downwellingKd = kd;
  return water;
}

std::unique_ptr<TechniqueSection> WaterSection::parse(const schema::Node& n, const TechniqueSections&) {
  using schema::Range;
  n.expectObject({"type", "dataset", "depth", "scattering_scale", "absorption_scale", "kd_scale", "lamp_scattering"});
  auto w = std::make_unique<WaterSection>();
  if (auto d = n.optionalChild("dataset")) w->dataset = d->string();
  if (auto t = n.optionalChild("type")) w->type = t->string();
  w->depthM = n.numberF("depth", w->depthM, Range::atLeast(0.0));
  w->scatteringScale = n.numberF("scattering_scale", 1.0f, Range::atLeast(0.0));
  w->absorptionScale = n.numberF("absorption_scale", 1.0f, Range::atLeast(0.0));
  w->kdScale = n.numberF("kd_scale", 1.0f, Range::atLeast(0.0));
  w->lampScattering = n.boolean("lamp_scattering", true);
  try {
    jerlovDatasetFromName(w->dataset);
  } catch (const Error& e) {
    n.child("dataset").fail(e.what());
  }
  try {
    w->resolve();
  } catch (const Error& e) {
    (n.has("type") ? n.child("type") : n).fail(e.what());
  }
  return w;
}

}  // namespace prism::underwater
