// The technique seam: each technique (techniques/<name>/) owns a section of the scene file — its
// data, parsed and validated by the technique — and the scene holds it as a TechniqueSection
// without including the technique's headers. The scene loader reads the sections of the
// techniques listed in techniques/registry.h, the one place a new technique is registered. Per
// frame the renderer asks each section for its block (pack: its constants and its per-batch
// data, laid out by the technique's shared GLSL header), uploads and binds it where that header
// says, and compiles the lighting pass with each section's shader define.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/error.h"
#include "core/json_schema.h"
#include "frame_layout.h"
#include "spectral/spectrum.h"

namespace prism {

class RgbToSpectrumTable;
struct RgbColourSpace;
struct Observer;

// A directional light a technique puts into the scene (the sky's sun). The scene loader adds it
// to the scene's lights like any other, normalised photometrically (spd is absolute, W/m²/nm;
// its luminous integral becomes the light's intensity in lux), and tags it with the technique's
// key; the technique keeps its direction in step when the section changes (applyTechniqueLights).
struct TechniqueLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // of travel, unit
  Spectrum spd;
  std::string spdLabel;
  bool castsShadows = true;
  // On a surface facing it, lux; < 0: the spd's own (683 lm/W · ∫ spd ȳ dλ). 0 with a non-zero
  // spd: a light that is out (a sun below the horizon).
  double illuminanceLux = -1.0;
  // Whether its spectrum and illuminance follow the section on every edit (applyTechniqueLights),
  // not only its direction: a sun whose colour the section computes (PRT's spectral sky), rather
  // than one the user may edit as a light (the atmosphere's).
  bool followsSection = false;
};

// A homogeneous medium a technique fills part of the scene with, as the reference path tracer
// (reference/path_tracer.h) traces it: absorption σa and scattering σs per wavelength in 1/m, a
// Henyey–Greenstein asymmetry g, inside the box [regionMin, regionMax] (world space, m).
struct TechniqueMedium {
  Spectrum sigmaA;
  Spectrum sigmaS;
  float g = 0.0f;
  glm::vec3 regionMin{0.0f};
  glm::vec3 regionMax{0.0f};
  // The diffuse attenuation (1/m) of light from above reaching depth z below the region's top,
  // e^(−Kd·z), which the rasteriser's passes apply to distant light (PRT's environment under
  // water); none: σa + σs.
  std::optional<Spectrum> downwellingKd;
};

// The distant light a technique surrounds the scene with (PRT's environment), as the reference
// path tracer traces it: spectral radiance arriving from a direction, W·m⁻²·sr⁻¹·nm⁻¹ as the
// scene's lights are (683 lm/W · ∫ L ȳ dλ is its luminance in cd/m²), everywhere beyond the scene. The path
// tracer lights the scene with it where the rasteriser's technique does: paths that leave the
// scene after a bounce gather it (camera rays still see the scene's background, as the
// rasteriser draws it), and with direct transport each surface point and each scattering point in
// a medium samples it once (the rasteriser's water in-scatters it: scalarIrradianceFromAbove). A sun is
// not part of it: a technique adds that as a light (TechniqueSection::light), which every
// renderer samples directly.
class TechniqueEnvironment {
 public:
  virtual ~TechniqueEnvironment() = default;
  // `directionW`: unit, world space, towards where the light comes from.
  virtual double radiance(const glm::vec3& directionW, double lambdaNm) const = 0;
  // Its radiance over the sky's hemisphere (world y > 0), ∫ L dω without the cosine, W·m⁻²·nm⁻¹:
  // the scalar irradiance it sends down through a horizontal plane, which a medium below scatters
  // per unit of its phase function (the water's in-scattering, shaders/shared/underwater.glsl).
  // By default a midpoint rule over 32 × 64 cells of equal solid angle (cos θ and azimuth) at
  // every 5 nm, linear between, for smooth environments; one made of texels or of closed forms
  // overrides it with its exact sum (a map's sun, a texel, would fall between the cells).
  virtual Spectrum scalarIrradianceFromAbove() const;
};

// What a technique's block is packed from: the frame's wavelength batches (in RGB mode one batch
// whose channels are R, G, B), where the frame is seen from and where the scene file put the
// camera (which anchors e.g. the water's surface), and the light the technique added (its
// index among the frame's lights and its intensity, −1 and 0 when it added none) with the
// frame's light spectra (frame_layout.glsl's lightSpectrumIndex).
struct FramePackInput {
  std::span<const shared::GpuBatch> batches;
  bool rgbMode = false;
  glm::vec3 cameraPositionW{0.0f};
  glm::vec3 sceneCameraPositionW{0.0f};
  std::span<const glm::vec4> lightSpectra;
  int ownLight = -1;
  float ownLightIntensity = 0.0f;
  // Per batch, the scene's distant environment's scalarIrradianceFromAbove in the lights'
  // units (at the batch's wavelengths; in RGB mode its linear RGB, as lightSpectra's); empty when
  // the scene has no environment or nothing takes it (FrameContext::environmentFromAbove).
  std::span<const glm::vec4> environmentFromAbove;
  // The scene's colour space: in RGB mode a light a technique adds itself is its linear RGB there
  // (xyzToRgb of luminousTristimulus, as the frame's lights).
  const RgbColourSpace* colourSpace = nullptr;
};

// A technique's part of one frame, as the GPU reads it: `constants` for a std140 uniform block at
// constantsBinding, `data` for a std430 storage buffer at dataBinding (bindings and layouts from
// the technique's shared GLSL header). The CPU twin reads the same bytes.
struct TechniqueBlock {
  std::string key;
  int constantsBinding = -1;
  std::vector<std::byte> constants;
  int dataBinding = -1;
  std::vector<std::byte> data;

  template <class T>
  void setConstants(const T& value) {
    constants.resize(sizeof(T));
    std::memcpy(constants.data(), &value, sizeof(T));
  }
  template <class T>
  void appendData(const T& value) {
    std::size_t at = data.size();
    data.resize(at + sizeof(T));
    std::memcpy(data.data() + at, &value, sizeof(T));
  }
  template <class T>
  T constantsAs() const {
    PRISM_CHECK(constants.size() == sizeof(T));
    T value{};
    std::memcpy(&value, constants.data(), sizeof(T));
    return value;
  }
  template <class T>
  T dataAt(std::size_t index) const {
    PRISM_CHECK((index + 1) * sizeof(T) <= data.size());
    T value{};
    std::memcpy(&value, data.data() + index * sizeof(T), sizeof(T));
    return value;
  }
  template <class T>
  std::size_t dataCount() const { return data.size() / sizeof(T); }
};

class TechniqueSection;

// A configuration the scene bench (harness/scene_bench.h) times for a technique, interleaved round
// by round with its own: frame settings by their keys (render/setting_keys.h, e.g. "mode" →
// "optimised4") over the run's, on the scene as it is or with the technique's section taken out.
struct TechniqueBenchConfig {
  std::string label;  // unique in the run, e.g. "16 dry"
  std::vector<std::pair<std::string, std::string>> settings;
  bool withoutTechnique = false;
  int framesPerRound = 0;  // 0: the run's; else that many (and at most one warm-up frame)
  // Non-null: on a copy of the scene whose section is this one instead (PRT's RGB-PRT baseline
  // against its spectral basis: the same objects, another mode of the technique).
  std::shared_ptr<const TechniqueSection> section = nullptr;
};
// A ratio the bench reports for a technique: the frame time of configuration `numerator` over
// that of `denominator` (labels of its configurations, or "rgb", the run's RGB frames).
struct TechniqueBenchRatio {
  std::string name;  // its key in the JSON report, e.g. "ratio_optimised4_to_rgb3"
  std::string numerator, denominator;
};
struct TechniqueBench {
  std::vector<TechniqueBenchConfig> configs;
  std::vector<TechniqueBenchRatio> ratios;
};

// Four wavelengths and their weights fitted for a technique (García Liñán's, for the sky): what
// the optimised4 mode renders its scenes with; weights in nm (the batch's row c is c̄(λᵢ)·wᵢ).
struct TechniqueWavelengths {
  std::array<double, 4> lambdaNm{};
  std::array<double, 4> weights{};
};

class TechniqueSection {
 public:
  virtual ~TechniqueSection() = default;
  // The section's key in a scene file ("water", "atmosphere"), and the technique's name.
  virtual std::string_view key() const = 0;
  // The #define that specialises the lighting pass for it (PRISM_TECHNIQUE_<NAME>, see
  // shaders/shared/pixel_shading.glsl).
  virtual std::string_view shaderDefine() const = 0;
  virtual std::unique_ptr<TechniqueSection> clone() const = 0;
  // The light the technique adds to the scene, if any.
  virtual std::optional<TechniqueLight> light() const { return std::nullopt; }
  // Its block for one frame.
  virtual TechniqueBlock pack(const FramePackInput& input) const = 0;
  // The medium the reference traces for it, for a scene whose file puts the camera at
  // sceneCameraPositionW; none when the technique adds no medium.
  virtual std::optional<TechniqueMedium> medium(const glm::vec3& /*sceneCameraPositionW*/) const {
    return std::nullopt;
  }
  // Its distant light for the reference and for the water's in-scattering, if it has one; `table`
  // is the scene's colour space's
  // upsampling table (what its RGB content is upsampled by). The scene's objects it shades
  // itself (shadesObjects) are traced as Lambertian surfaces of their material's albedo.
  virtual std::shared_ptr<const TechniqueEnvironment> environment(const RgbToSpectrumTable& /*table*/) const {
    return nullptr;
  }
  // Why the reference path tracer cannot trace the technique, naming the technique's own
  // references (it refuses such scenes with this); empty when it traces it.
  virtual std::string_view notTracedBecause() const { return {}; }
  // `hash` (core/fnv1a.h) chained with what the section loaded from files other than the scene
  // file (an environment map's texels, a density grid), so that what is keyed by a scene's
  // identity (the parts of a split reference render, batch/reference_part.h) sees such a file
  // change; `hash` itself when it reads none. The scene file's bytes cover the section's keys.
  virtual std::uint64_t hashLoadedData(std::uint64_t hash) const { return hash; }
  // The files besides the scene file it read (an environment map), so that a command's output is
  // never one of them (requireNotSceneInput, scene/scene.h).
  virtual std::vector<std::filesystem::path> inputFiles() const { return {}; }
  // What the scene bench measures of its cost besides the run's own configurations, in a scene
  // with that many point and spot lights (water's lamp in-scattering is measured only with some).
  virtual TechniqueBench bench(std::size_t /*pointAndSpotLights*/) const { return {}; }
  // Its own optimised wavelengths, if it has them (scenes with such a technique are compared in
  // optimised4 mode against the reference in the gallery).
  virtual std::optional<TechniqueWavelengths> optimisedWavelengths() const { return std::nullopt; }
  // Whether scene objects may name it as their `technique`: it then shades them itself, in a
  // forward pass of its own after the lighting pass (TechniquePass::drawForward; PRT objects),
  // and the deferred pipeline only keeps their depth. The scene loader refuses an object naming a
  // technique that is absent from the scene or does not shade objects.
  virtual bool shadesObjects() const { return false; }
  // Error when it cannot show a frame through `observer` (PRT's rgb-prt mode, colours defined on
  // CIE 1931, under a camera's curves), in the many-wavelength reference mode or another:
  // checked before a frame's work, not at its draw.
  virtual void requireObserver(const Observer& /*observer*/, bool /*referenceMode*/) const {}
};

// A scene's sections, at most one per technique, in registration order; copied deeply (a scene
// is a value: an editor changes its copy).
class TechniqueSections {
 public:
  TechniqueSections() = default;
  TechniqueSections(const TechniqueSections& other);
  TechniqueSections& operator=(const TechniqueSections& other);
  TechniqueSections(TechniqueSections&&) noexcept = default;
  TechniqueSections& operator=(TechniqueSections&&) noexcept = default;

  void add(std::unique_ptr<TechniqueSection> section);  // replaces a section of the same key
  void remove(std::string_view key);
  bool has(std::string_view key) const { return find(key) != nullptr; }
  const TechniqueSection* find(std::string_view key) const;
  TechniqueSection* find(std::string_view key);
  template <class T>
  const T* find() const {
    for (const auto& s : mSections)
      if (auto* t = dynamic_cast<const T*>(s.get())) return t;
    return nullptr;
  }
  template <class T>
  T* find() {
    for (auto& s : mSections)
      if (auto* t = dynamic_cast<T*>(s.get())) return t;
    return nullptr;
  }
  const std::vector<std::unique_ptr<TechniqueSection>>& all() const { return mSections; }
  // The first technique medium (the water), for a scene whose file puts the camera at
  // sceneCameraPositionW: the one the path tracer traces and PRT's objects are dimmed by.
  std::optional<TechniqueMedium> medium(const glm::vec3& sceneCameraPositionW) const {
    for (const auto& s : mSections)
      if (std::optional<TechniqueMedium> m = s->medium(sceneCameraPositionW)) return m;
    return std::nullopt;
  }
  // The first distant light (PRT's environment), if any: what the path tracer traces and the
  // water in-scatters.
  std::shared_ptr<const TechniqueEnvironment> environment(const RgbToSpectrumTable& table) const {
    for (const auto& s : mSections)
      if (std::shared_ptr<const TechniqueEnvironment> e = s->environment(table)) return e;
    return nullptr;
  }
  void requireObserver(const Observer& observer, bool referenceMode) const {
    for (const auto& s : mSections) s->requireObserver(observer, referenceMode);
  }

 private:
  std::vector<std::unique_ptr<TechniqueSection>> mSections;
};

// How the scene loader reads one technique's section: `parse` checks the node (errors through
// schema::Node::fail, so that they name the scene file and the JSON pointer) and may refuse
// sections parsed before it (`earlier`), as the sky refuses water.
struct TechniqueSectionParser {
  std::string_view key;
  std::unique_ptr<TechniqueSection> (*parse)(const schema::Node& node, const TechniqueSections& earlier);
};

}  // namespace prism
