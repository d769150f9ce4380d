// A scene's "nebula" section: parsed as the scene loader parses it, its keys and defaults; bad
// values refused in one line naming the pointer; copies share the density; the precomputation's
// key follows the model and not the march's settings.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/error_test_support.h"
#include "spectral/sampling.h"
#include "techniques/nebula/nebula_cpu_twin.h"
#include "techniques/nebula/nebula_section.h"

namespace prism::nebula {
namespace {

std::unique_ptr<TechniqueSection> parseSection(const std::string& text) {
  static const schema::Document document{"scene.json", {}};
  nlohmann::json json = schema::parseJson(text, document.name);
  return NebulaSection::parse(schema::Node(json, "/nebula", document), TechniqueSections());
}

const std::string kNoise = R"("density": {"noise": {"resolution": 8}}, "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 9000}])";

TEST(NebulaSection, ReadsTheModelAndWhereItLies) {
  auto parsed = parseSection("{" + kNoise + R"(, "box": {"min": [-2, 0, 1], "size": 4}, "method": "light-density",
                                              "basis": 5, "basis_depth": 6, "reference_samples": 7, "intensity": 250, "steps": 80})");
  const auto& s = dynamic_cast<const NebulaSection&>(*parsed);
  EXPECT_EQ(s.density->size(), glm::ivec3(8));
  EXPECT_EQ(s.model.density.values.size(), 0u);  // the section holds it once, in `density`
  EXPECT_EQ(s.fullModel().density.values, s.density->grid().values);
  ASSERT_EQ(s.model.stars.size(), 1u);
  EXPECT_EQ(s.boxMin, glm::vec3(-2.0f, 0.0f, 1.0f));
  EXPECT_EQ(s.boxSize, 4.0f);
  EXPECT_EQ(s.method, Method::LightDensity);
  EXPECT_EQ(s.renderSettings().basisSize, 5);
  EXPECT_EQ(s.renderSettings().basisMaxDepthUm, 6.0);
  EXPECT_EQ(s.renderSettings().uniformSamples, 7);
  EXPECT_EQ(s.renderSettings().steps, 80);
  EXPECT_EQ(s.intensity, 250.0f);
  EXPECT_FALSE(s.notTracedBecause().empty());

  auto defaults = parseSection("{" + kNoise + "}");
  const auto& d = dynamic_cast<const NebulaSection&>(*defaults);
  EXPECT_EQ(d.method, Method::Projection);
  EXPECT_EQ(d.basis, 4);
  EXPECT_EQ(d.boxMin, glm::vec3(0.0f));
  EXPECT_EQ(d.boxSize, 1.0f);
  EXPECT_EQ(d.referenceSamples, 0);
}

// A split render keyed by the scene must see a density grid change: a file's is not in the scene's
// bytes. Noise is (its parameters), and is not generated for the hash.
TEST(NebulaSection, ItsLoadedDataHashFollowsTheDensity) {
  auto parsed = parseSection("{" + kNoise + "}");
  auto& s = dynamic_cast<NebulaSection&>(*parsed);
  EXPECT_EQ(s.hashLoadedData(7), 7u);
  DensityGrid grid = s.density->grid();
  s.density = std::make_shared<DeferredDensity>(grid);  // as a density file's
  const std::uint64_t hash = s.hashLoadedData(7);
  EXPECT_NE(hash, 7u);
  EXPECT_EQ(hash, s.clone()->hashLoadedData(7));
  grid.values[3] += 1e-4f;
  s.density = std::make_shared<DeferredDensity>(grid);
  EXPECT_NE(hash, s.hashLoadedData(7));
}

// Noise is generated at its first use, once, and shared by the section's copies.
TEST(NebulaSection, NoiseIsGeneratedAtItsFirstUseOnce) {
  auto parsed = parseSection("{" + kNoise + "}");
  const auto& s = dynamic_cast<const NebulaSection&>(*parsed);
  auto copy = s.clone();
  std::size_t reports = 0;
  const DensityGrid& grid = s.density->grid([&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, 8u);
    EXPECT_LE(done, total);
    ++reports;
  });
  EXPECT_EQ(reports, 8u);  // one per z slice
  EXPECT_EQ(grid.values, generateFbm(*s.source.noise).values);
  EXPECT_EQ(&dynamic_cast<const NebulaSection&>(*copy).density->grid([&](std::size_t, std::size_t) { ++reports; }), &grid);
  EXPECT_EQ(reports, 8u);  // made already
}

TEST(NebulaSection, BadValuesNameTheirPlace) {
  auto error = [](const std::string& keys) { return errorOf([&] { parseSection("{" + kNoise + ", " + keys + "}"); }); };
  EXPECT_EQ(error(R"("method": "spline")"),
            "scene.json: /nebula/method: unknown nebula method 'spline' (reference, analytic, projection, "
            "light-density, pre-integration)");
  EXPECT_EQ(error(R"("box": {"size": 0})"), "scene.json: /nebula/box/size: expected a number in (0, 1000000), got 0");
  EXPECT_EQ(error(R"("basis": 7)"), "scene.json: /nebula/basis: expected an integer in [1, 6], got 7");
  EXPECT_EQ(error(R"("basis_depth": 17)"), "scene.json: /nebula/basis_depth: expected a number in (0, 16], got 17");
  EXPECT_EQ(error(R"("reference_samples": 1)"),
            "scene.json: /nebula/reference_samples: must be 0 (Simpson over each passband piece) or at least 2 "
            "wavelengths a channel");
  EXPECT_EQ(error(R"("camera": {})").rfind("scene.json: /nebula/camera: unknown key", 0), 0u);
  EXPECT_EQ(errorOf([] { parseSection(R"({"density": {"noise": {}}, "stars": [{"position": [0, 0, 0], "temperature": 50}]})"); }),
            "scene.json: /nebula/stars/0/temperature: expected a number in [1000, 100000], got 50");
}

TEST(NebulaSection, CopiesShareTheDensityAndTheKeyFollowsTheModel) {
  auto parsed = parseSection("{" + kNoise + "}");
  auto& s = dynamic_cast<NebulaSection&>(*parsed);
  auto copy = s.clone();
  EXPECT_EQ(dynamic_cast<const NebulaSection&>(*copy).density, s.density);
  const std::string key = s.precomputationKey();
  s.method = Method::Reference;
  s.steps = 300;
  s.intensity = 3.0f;
  EXPECT_EQ(s.precomputationKey(), key);  // the march's settings, not the precomputation's
  s.model.stars[0].temperatureK = 9001.0;
  EXPECT_NE(s.precomputationKey(), key);
  s.model.stars[0].temperatureK = 9000.0;
  s.source.noise->seed = 8;
  s.regenerateDensity();
  EXPECT_NE(s.precomputationKey(), key);
  EXPECT_NE(s.density->grid().values, dynamic_cast<const NebulaSection&>(*copy).density->grid().values);
  // Filters and passbands change the precomputation, not the volume (the pass refilters).
  const std::string full = s.precomputationKey(), volume = s.volumeKey();
  s.model.passbands[2].shiftNm = 10.0;
  EXPECT_NE(s.precomputationKey(), full);
  s.model.filters = "cie1931";
  EXPECT_EQ(s.volumeKey(), volume);
  s.model.stars[0].luminosity = 2.0;
  EXPECT_NE(s.volumeKey(), volume);
}

TEST(NebulaSection, TheBenchTimesThePapersBaselineAgainstEachMethodAndTheStarLight) {
  auto parsed = parseSection("{" + kNoise + "}");
  TechniqueBench b = parsed->bench(0);
  ASSERT_EQ(b.configs.size(), 5u);
  const auto& reference = dynamic_cast<const NebulaSection&>(*b.configs[2].section);
  EXPECT_EQ(reference.method, Method::Reference);
  EXPECT_EQ(reference.renderSettings().uniformSamples, 7);  // 21 wavelengths a step
  EXPECT_EQ(reference.steps, 100);
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(dynamic_cast<const NebulaSection&>(*b.configs[static_cast<std::size_t>(i)].section).marchEveryFrame);
  ASSERT_EQ(b.ratios.size(), 3u);
  EXPECT_EQ(b.ratios[0].numerator, b.configs[2].label);
  EXPECT_EQ(b.ratios[0].denominator, b.configs[0].label);
  // The stars' light on surfaces, a still view with and without it.
  const auto& lit = dynamic_cast<const NebulaSection&>(*b.configs[3].section);
  const auto& unlit = dynamic_cast<const NebulaSection&>(*b.configs[4].section);
  EXPECT_TRUE(lit.lightSurfaces && !lit.marchEveryFrame);
  EXPECT_FALSE(unlit.lightSurfaces || unlit.marchEveryFrame);
  EXPECT_EQ(b.ratios[2].numerator, b.configs[3].label);
  EXPECT_EQ(b.ratios[2].denominator, b.configs[4].label);
}

// The lighting pass dims an RGB frame's R, G, B at the wavelengths the rest of Prism stands them for.
TEST(NebulaLighting, TheRgbStandInsAreTheSpectralLibrarys) {
  for (int c = 0; c < 3; ++c) EXPECT_EQ(shared::kNebulaRgbStandInNm[c], kRgbStandInWavelengthsNm[static_cast<std::size_t>(c)]);
  const glm::vec4 t = shared::nebulaTransmittance4(0.5f, glm::vec4(400.0f, 500.0f, 700.0f, 800.0f));
  EXPECT_FLOAT_EQ(t.x, std::exp(-500.0f / 400.0f));
  EXPECT_FLOAT_EQ(t.w, std::exp(-500.0f / 800.0f));
  EXPECT_EQ(shared::nebulaTransmittance4(0.0f, glm::vec4(0.0f)), glm::vec4(1.0f));
}

}  // namespace
}  // namespace prism::nebula
