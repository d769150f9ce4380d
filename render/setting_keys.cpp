#include "render/setting_keys.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "core/json_schema.h"
#include "scene/scene.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::render {
namespace {

template <typename T>
using Field = T& (*)(FrameSettings&);

// The accessors are written once for both directions; print only reads through them.
template <typename T>
const T& read(Field<T> field, const FrameSettings& s) {
  return field(const_cast<FrameSettings&>(s));
}

[[noreturn]] void fail(const SettingKey& key, std::string_view value) {
  throw Error(fmt::format("{}: expected {}, got \"{}\"", key.name, key.expects, excerpt(value)));
}

// "a, b or c".
std::string listOf(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return text;
}

// Every key's parse and print read and write its field through `field`, so the key's text is
// the only thing a builder below is given besides it.
SettingKey integerKey(std::string name, std::string help, std::string example, long min, long max,
                      Field<int> field, long multipleOf = 1) {
  SettingKey k{std::move(name), SettingType::Integer,
               multipleOf == 1 ? fmt::format("a whole number within {}–{}", min, max)
                               : fmt::format("a multiple of {} within {}–{}", multipleOf, min, max),
               {}, std::move(help), std::move(example), {}, {}};
  k.parse = [key = k, min, max, field, multipleOf](FrameSettings& s, std::string_view v) {
    long value = 0;
    try {
      value = parseInteger(key.name, v, min, max);
    } catch (const Error&) {
      fail(key, v);  // in the key's words: "a multiple of 4 within …" where it has a step
    }
    if (value % multipleOf != 0) fail(key, v);
    field(s) = static_cast<int>(value);
  };
  k.print = [field](const FrameSettings& s) { return std::to_string(read(field, s)); };
  return k;
}

template <typename E>
SettingKey choiceKey(std::string name, std::string help, std::string example, std::vector<E> values,
                     std::string_view (*nameOf)(E), Field<E> field) {
  SettingKey k{std::move(name), SettingType::Choice, {}, {}, std::move(help), std::move(example), {}, {}};
  for (E e : values) k.choices.emplace_back(nameOf(e));
  k.expects = listOf(k.choices);
  k.parse = [k, values, nameOf, field](FrameSettings& s, std::string_view v) {
    for (E e : values) {
      if (nameOf(e) == v) {
        field(s) = e;
        return;
      }
    }
    fail(k, v);
  };
  k.print = [nameOf, field](const FrameSettings& s) { return std::string(nameOf(read(field, s))); };
  return k;
}

// A string field with a fixed set of values (the display's colour space).
SettingKey textChoiceKey(std::string name, std::string help, std::string example, std::vector<std::string> choices,
                         Field<std::string> field) {
  SettingKey k{std::move(name), SettingType::Choice, listOf(choices), std::move(choices), std::move(help),
               std::move(example), {}, {}};
  k.parse = [k, field](FrameSettings& s, std::string_view v) {
    for (const std::string& c : k.choices) {
      if (c == v) {
        field(s) = c;
        return;
      }
    }
    fail(k, v);
  };
  k.print = [field](const FrameSettings& s) { return read(field, s); };
  return k;
}

// A name looked up in data/ by `check` (which throws when it does not know it).
SettingKey nameKey(std::string name, std::string help, std::string example, std::string expects,
                   void (*check)(std::string_view), Field<std::string> field) {
  SettingKey k{std::move(name), SettingType::Name, std::move(expects), {}, std::move(help), std::move(example), {}, {}};
  k.parse = [k, check, field](FrameSettings& s, std::string_view v) {
    try {
      check(v);
    } catch (const Error& e) {  // its own words: "blackbody: temperature must be within …", "did you mean 'D65'?"
      throw Error(fmt::format("{}: {}", k.name, e.what()));
    }
    field(s) = std::string(v);
  };
  k.print = [field](const FrameSettings& s) { return read(field, s); };
  return k;
}

SettingKey switchKey(std::string name, std::string help, std::string example, Field<bool> field) {
  SettingKey k{std::move(name), SettingType::Switch, "on or off", {"on", "off"}, std::move(help),
               std::move(example), {}, {}};
  k.parse = [k, field](FrameSettings& s, std::string_view v) {
    if (v != "on" && v != "off") fail(k, v);
    field(s) = v == "on";
  };
  k.print = [field](const FrameSettings& s) { return std::string(read(field, s) ? "on" : "off"); };
  return k;
}

SettingKey rangeKey() {
  SettingKey k{"range", SettingType::Range, "MIN,MAX in nm", {}, "the sampled wavelengths' range (within 360–830 nm)",
               "380,720", {}, {}};
  k.parse = [k](FrameSettings& s, std::string_view v) {
    std::size_t comma = v.find(',');
    if (comma == std::string_view::npos) fail(k, v);
    try {
      double minNm = parseNumber(k.name, v.substr(0, comma));
      s.sampling.maxNm = parseNumber(k.name, v.substr(comma + 1));
      s.sampling.minNm = minNm;
    } catch (const Error&) {
      fail(k, v);
    }
    try {  // here, where the key is known: the frame's check said no option
      validateWavelengthRange(s.sampling.minNm, s.sampling.maxNm);
    } catch (const Error& e) {
      throw Error(k.name + ": " + e.what());
    }
  };
  k.print = [](const FrameSettings& s) { return fmt::format("{},{}", s.sampling.minNm, s.sampling.maxNm); };
  return k;
}

SettingKey exposureKey() {
  SettingKey k{"ev", SettingType::Number, fmt::format("an EV100 within ±{:g} or scene", kEv100Limit), {},
               "exposure EV100 (scene: the scene camera's)", "9.5", {}, {}};
  k.parse = [k](FrameSettings& s, std::string_view v) {
    if (v == "scene") {
      s.display.ev100.reset();
      return;
    }
    float ev100 = 0.0f;
    try {
      ev100 = parseFloat(k.name, v);
    } catch (const Error&) {
      fail(k, v);
    }
    if (!(std::abs(ev100) <= kEv100Limit)) fail(k, v);  // said as the option, not as validate's sentence
    s.display.ev100 = ev100;
  };
  k.print = [](const FrameSettings& s) {
    return s.display.ev100 ? fmt::format("{}", *s.display.ev100) : std::string("scene");
  };
  return k;
}

std::vector<SettingKey> makeKeys() {
  using S = FrameSettings&;
  std::vector<SettingKey> keys;
  keys.push_back(integerKey("width", "image width", "640", 1, 16384, [](S s) -> int& { return s.width; }));
  keys.push_back(integerKey("height", "image height", "360", 1, 16384, [](S s) -> int& { return s.height; }));
  keys.push_back(choiceKey<RenderMode>(
      "mode", "how colour is rendered (reference: 472 wavelengths; optimised4: the sky's four, with an atmosphere)",
      "naive",
      {RenderMode::Rgb, RenderMode::Naive, RenderMode::JakobHanika, RenderMode::Reference, RenderMode::Optimised4},
      renderModeName, [](S s) -> RenderMode& { return s.mode; }));
  keys.push_back(integerKey("wavelengths", "wavelengths per pixel (4–64 under the optimised strategy, the default)", "32", 4, 1000,
                            [](S s) -> int& { return s.sampling.count; }, 4));
  keys.push_back(rangeKey());
  keys.push_back(choiceKey<SamplingStrategy>(
      "strategy", "how the wavelengths are drawn", "rotated",
      {SamplingStrategy::Uniform, SamplingStrategy::Stratified, SamplingStrategy::Rotated, SamplingStrategy::Importance,
       SamplingStrategy::Lights, SamplingStrategy::Optimised},
      samplingStrategyName, [](S s) -> SamplingStrategy& { return s.sampling.strategy; }));
  keys.push_back(nameKey("observer", "the colour matching functions, or a camera's curves (raw camera RGB)", "cie1964",
                         "cie1931, cie1964 or a camera (see `prism colour list cameras`)",
                         [](std::string_view n) { observer(n); }, [](S s) -> std::string& { return s.observer; }));
  keys.push_back(choiceKey<UpsamplingLookup>("lookup", "upsampling table lookup", "manual",
                                             {UpsamplingLookup::Filtered, UpsamplingLookup::Manual},
                                             upsamplingLookupName,
                                             [](S s) -> UpsamplingLookup& { return s.lookup; }));
  keys.push_back(choiceKey<GBufferAlbedo>("gbuffer", "what the G-buffer keeps of a base colour", "coefficients",
                                          {GBufferAlbedo::Rgb, GBufferAlbedo::Coefficients}, gbufferAlbedoName,
                                          [](S s) -> GBufferAlbedo& { return s.gbufferAlbedo; }));
  keys.push_back(integerKey("shadow-map-size", "shadow map texels per side", "1024", 16, 8192,
                            [](S s) -> int& { return s.shadowMapSize; }));
  keys.push_back(integerKey("shadow-cascades",
                            "a directional light's shadow maps: 1 covers the whole scene, more are fitted to the "
                            "camera's view, finest near it",
                            "2", 1, kShadowCascadesMax, [](S s) -> int& { return s.shadowCascades; }));
  keys.push_back(switchKey("gizmos", "draw point and spot lights as glowing markers (forward pass)", "on",
                           [](S s) -> bool& { return s.lightGizmos; }));
  keys.push_back(exposureKey());
  keys.push_back(nameKey("white-balance", "adapt this illuminant's white to the display white", "A",
                         "none, an illuminant (see `prism colour list illuminants`) or a lamp's .csv",
                         [](std::string_view n) {
                           if (n != "none") lampSpectrum(std::string(n));
                         },
                         [](S s) -> std::string& { return s.display.whiteBalance; }));
  keys.push_back(choiceKey<Adaptation>("adaptation", "the white balance's chromatic adaptation", "cat02",
                                       {Adaptation::Bradford, Adaptation::Cat02, Adaptation::VonKries}, adaptationName,
                                       [](S s) -> Adaptation& { return s.display.adaptation; }));
  keys.push_back(choiceKey<ToneMap>("tonemap", "the tone map", "reinhard",
                                    {ToneMap::None, ToneMap::Reinhard, ToneMap::Aces}, toneMapName,
                                    [](S s) -> ToneMap& { return s.display.toneMap; }));
  keys.push_back(textChoiceKey("display", "the display's colour space and transfer", "rec2020",
                               {"srgb", "display-p3", "rec2020"},
                               [](S s) -> std::string& { return s.display.colourSpace; }));
  keys.push_back(switchKey("dither", "dither before 8-bit quantisation", "off",
                           [](S s) -> bool& { return s.display.dither; }));
  return keys;
}

}  // namespace

const std::vector<SettingKey>& frameSettingKeys() {
  static const std::vector<SettingKey> keys = makeKeys();
  return keys;
}

const SettingKey* findFrameSettingKey(std::string_view name) {
  for (const SettingKey& k : frameSettingKeys()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

bool applyFrameSetting(FrameSettings& settings, std::string_view key, std::string_view value) {
  const SettingKey* k = findFrameSettingKey(key);
  if (!k) return false;
  k->parse(settings, value);
  return true;
}

std::vector<std::pair<std::string, std::string>> frameSettingValues(const FrameSettings& settings) {
  std::vector<std::pair<std::string, std::string>> values;
  for (const SettingKey& k : frameSettingKeys()) values.emplace_back(k.name, k.print(settings));
  return values;
}

double parseNumber(std::string_view what, std::string_view text) {
  double v = 0.0;
  const std::string_view digits = withoutPlusSign(text);
  auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size() || !std::isfinite(v)) {
    throw Error(fmt::format("{}: expected a number, got \"{}\"", what, excerpt(text)));
  }
  return v;
}

long parseInteger(std::string_view what, std::string_view text, long min, long max) {
  long v = 0;
  const std::string_view digits = withoutPlusSign(text);
  auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size() || v < min || v > max) {
    throw Error(fmt::format("{}: expected a whole number within {}–{}, got \"{}\"", what, min, max, excerpt(text)));
  }
  return v;
}

float parseFloat(std::string_view what, std::string_view text) {
  const double v = parseNumber(what, text);
  if (!(std::abs(v) <= schema::kFloatInputLimit)) {
    throw Error(fmt::format("{}: expected a number within ±{:g} (what floats carry through a frame), got \"{}\"", what,
                            schema::kFloatInputLimit, excerpt(text)));
  }
  return static_cast<float>(v);
}

float parseFloatWithin(std::string_view what, std::string_view text, float min, float max) {
  const float v = parseFloat(what, text);
  if (!(v >= min && v <= max))
    throw Error(fmt::format("{}: expected a number within {:g}–{:g}, got \"{}\"", what, min, max, excerpt(text)));
  return v;
}

}  // namespace prism::render
