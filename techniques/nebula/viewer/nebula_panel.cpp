// The nebula panel (techniques/nebula): method, basis size, steps, filters and their passbands
// (moved and resized), intensity, the medium, the ionisation zones, the density's noise, the stars
// and whether they light the surfaces. Sees only the PanelContext. Edits that make the pass
// precompute again (anything of the model: about half a second at 64³) or march again reach the
// scene when a control is released, not while it is dragged; the intensity and the star light are live.
#include <imgui.h>

#include <map>

#include <fmt/format.h>

#include "core/error.h"

#include "techniques/nebula/nebula_section.h"
#include "techniques/nebula/viewer/nebula_viewer.h"
#include "viewer/panel_widgets.h"

namespace prism::viewer {
namespace {

// Controls that edit a value only once released: the scene is the renderer's, and most of the
// section's values make the pass precompute again, which must not happen on every frame of a drag.
// The value being dragged lives here meanwhile (one control is active at a time).
class ReleasedEdits {
 public:
  bool slider(const char* label, double& value, float lo, float hi, const char* format, bool logarithmic = false) {
    glm::vec3 v(static_cast<float>(value));
    const bool done = control(label, v, [&](float* p) {
      // Clamped: a value typed in (ctrl-click) stays within the bounds the scene loader holds too.
      return ImGui::SliderFloat(label, p, lo, hi, format,
                                ImGuiSliderFlags_AlwaysClamp | (logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
    });
    if (done) value = v.x;
    return done;
  }
  bool slider(const char* label, int& value, int lo, int hi) {
    glm::vec3 v(static_cast<float>(value));
    const bool done = control(label, v, [&](float* p) {
      int i = static_cast<int>(*p);
      const bool edited = ImGui::SliderInt(label, &i, lo, hi);
      *p = static_cast<float>(i);
      return edited;
    });
    if (done) value = static_cast<int>(v.x);
    return done;
  }
  bool drag3(const char* label, glm::dvec3& value, float lo, float hi) {
    glm::vec3 v(value);
    const bool done = control(label, v, [&](float* p) { return ImGui::DragFloat3(label, p, 0.01f, lo, hi, "%.2f"); });
    if (done) value = glm::dvec3(v);
    return done;
  }

 private:
  // Draws `widget` (whose id is `label`'s) over the pending value while it is active; true once
  // an edit is released, with `v` the released value.
  template <class Widget>
  bool control(const char* label, glm::vec3& v, Widget widget) {
    const ImGuiID id = ImGui::GetID(label);
    if (mActive == id) v = mPending;
    widget(&v.x);
    if (ImGui::IsItemActive()) {
      mActive = id;
      mPending = v;
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      mActive = 0;
      return true;
    }
    if (!ImGui::IsItemActive() && mActive == id) mActive = 0;
    return false;
  }

  ImGuiID mActive = 0;
  glm::vec3 mPending{0.0f};
};

bool noiseControls(ReleasedEdits& edits, nebula::NoiseParameters& p) {
  bool changed = false;
  changed |= edits.slider("resolution", p.resolution, 8, 256);
  changed |= edits.slider("octaves", p.octaves, 1, 8);
  changed |= edits.slider("frequency", p.frequency, 0.5f, 12.0f, "%.2f");
  changed |= edits.slider("amplitude", p.amplitude, 0.0f, 4.0f, "%.2f");
  changed |= edits.slider("gain", p.gain, 0.0f, 1.0f, "%.2f");
  changed |= edits.slider("bias", p.bias, -1.0f, 1.0f, "%.2f");
  int seed = static_cast<int>(p.seed);
  if (ImGui::InputInt("seed", &seed, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) && seed >= 0) {
    p.seed = static_cast<std::uint64_t>(seed);
    changed = true;
  }
  return changed;
}

bool starControls(ReleasedEdits& edits, std::vector<nebula::NebulaStar>& stars) {
  bool changed = false;
  for (std::size_t i = 0; i < stars.size(); ++i) {
    nebula::NebulaStar& s = stars[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::TextUnformatted(fmt::format("star {}", i).c_str());
    changed |= edits.drag3("position", s.position, -2.0f, 3.0f);
    changed |= edits.slider("temperature K", s.temperatureK, static_cast<float>(nebula::kMinStarTemperatureK),
                            static_cast<float>(nebula::kMaxStarTemperatureK), "%.0f", true);
    changed |= edits.slider("luminosity", s.luminosity, 0.0f, 10.0f, "%.2f");
    bool remove = ImGui::Button("remove");
    ImGui::PopID();
    if (remove) {
      stars.erase(stars.begin() + static_cast<std::ptrdiff_t>(i));
      return true;
    }
  }
  if (ImGui::Button("add star")) {
    stars.push_back({glm::dvec3(0.5), 10000.0, 1.0});
    changed = true;
  }
  return changed;
}

// Each channel's passband: moved (nm) and resized (× its width), or reset. An edit that would
// leave no passband in the band is refused here, with its message, rather than by the pass.
bool passbandControls(ReleasedEdits& edits, nebula::NebulaModel& model, const nebula::FilterSet& fitted, std::string& error) {
  bool changed = false;
  for (std::size_t c = 0; c < 3; ++c) {
    ImGui::PushID(static_cast<int>(c));
    ImGui::TextUnformatted(fitted.channels[c].name.c_str());
    nebula::PassbandEdit e = model.passbands[c];
    bool edited = edits.slider("shift", e.shiftNm, static_cast<float>(-nebula::kMaxPassbandShiftNm),
                               static_cast<float>(nebula::kMaxPassbandShiftNm), "%+.0f nm");
    edited |= edits.slider("width", e.widthScale, static_cast<float>(nebula::kMinPassbandWidthScale),
                           static_cast<float>(nebula::kMaxPassbandWidthScale), "× %.2f", true);
    if (ImGui::Button("reset")) {
      e = {};
      edited = true;
    }
    ImGui::PopID();
    if (!edited) continue;
    try {
      nebula::editedPassband(fitted.channels[c], e);
      model.passbands[c] = e;
      error.clear();
      changed = true;
    } catch (const Error& x) {
      error = x.what();
    }
  }
  if (!error.empty()) ImGui::TextWrapped("%s", error.c_str());
  return changed;
}

class NebulaPanel final : public Panel {
 public:
  const char* title() const override { return "Nebula"; }
  bool applies(const Scene& scene) const override { return scene.techniques.has(nebula::NebulaSection::kKey); }

  void draw(PanelContext& context) override {
    nebula::NebulaSection& s = *context.scene.techniques.find<nebula::NebulaSection>();
    bool changed = false;
    std::string method = nebula::methodName(s.method);
    if (stringCombo("method", method, {"projection", "light-density", "analytic", "pre-integration", "reference"})) {
      s.method = nebula::methodFromName(method);
      changed = true;
    }
    changed |= mEdits.slider("basis size", s.basis, 1, nebula::kMaxBasisSize);
    changed |= mEdits.slider("basis depth (µm)", s.basisDepthUm, 0.5f, static_cast<float>(nebula::kMaxBasisDepthUm), "%.1f");
    changed |= mEdits.slider("steps", s.steps, 10, 400);
    changed |= stringCombo("filters", s.model.filters, {"hubble", "cie1931"});
    if (ImGui::TreeNode("passbands")) {
      auto fitted = mFilterSets.find(s.model.filters);
      if (fitted == mFilterSets.end()) fitted = mFilterSets.emplace(s.model.filters, nebula::filterSet(s.model.filters)).first;
      changed |= passbandControls(mEdits, s.model, fitted->second, mPassbandError);
      ImGui::TreePop();
    }
    // Live: the composite alone reads it.
    changed |= ImGui::SliderFloat("intensity", &s.intensity, 1e-3f, 1e4f, "%.3g", ImGuiSliderFlags_Logarithmic);
    changed |= mEdits.slider("extinction", s.model.extinction, 0.0f, 20.0f, "%.2f");
    changed |= mEdits.slider("scattering", s.model.scattering, 0.0f, 10.0f, "%.2f");
    changed |= mEdits.slider("emission", s.model.emission, 0.0f, 0.02f, "%.4f");
    bool zoned = s.model.ionisation.has_value();
    if (ImGui::Checkbox("ionisation zones", &zoned)) {
      s.model.ionisation = zoned ? std::optional<nebula::IonisationModel>(nebula::IonisationModel{}) : std::nullopt;
      changed = true;
    }
    if (s.model.ionisation) {
      changed |= mEdits.slider("front radius", s.model.ionisation->frontRadius, 0.01f,
                               static_cast<float>(nebula::kMaxFrontRadius), "%.3f", true);
      changed |= mEdits.slider("front width", s.model.ionisation->frontWidth, 0.01f,
                               static_cast<float>(nebula::kMaxFrontWidth), "%.2f");
    }
    if (s.source.noise && ImGui::TreeNode("density (noise)")) {
      if (noiseControls(mEdits, *s.source.noise)) {
        s.regenerateDensity();
        changed = true;
      }
      ImGui::TreePop();
    }
    if (ImGui::TreeNode("stars")) {
      changed |= ImGui::Checkbox("light the surfaces", &s.lightSurfaces);  // live: the lighting pass reads it
      changed |= starControls(mEdits, s.model.stars);
      ImGui::TreePop();
    }
    if (changed) context.changes.scene = true;
  }

 private:
  ReleasedEdits mEdits;
  std::map<std::string, nebula::FilterSet> mFilterSets;  // as fitted, by name: the passbands' names and checks
  std::string mPassbandError;
};

}  // namespace

std::unique_ptr<Panel> makeNebulaPanel() { return std::make_unique<NebulaPanel>(); }

}  // namespace prism::viewer
