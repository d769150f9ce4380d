// The sky panel (techniques/atmosphere, issue #8): the sun and the atmosphere. Every change
// recomputes the sky's tables next frame; a combination the atmosphere rejects is undone and
// shown as the action's error. Sees only the PanelContext.
#include <imgui.h>

#include "scene/scene_loader.h"
#include "core/error.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/atmosphere/viewer/sky_viewer.h"

namespace prism::viewer {
namespace {

// A slider over a double parameter; true when moved.
bool slider(const char* label, double& value, float lo, float hi, const char* format) {
  float v = static_cast<float>(value);
  if (!ImGui::SliderFloat(label, &v, lo, hi, format)) return false;
  value = v;
  return true;
}

class SkyPanel final : public Panel {
 public:
  const char* title() const override { return "Sky"; }
  bool applies(const Scene& scene) const override {
    return scene.techniques.has(atmosphere::AtmosphereSection::kKey);
  }

  void draw(PanelContext& context) override {
    atmosphere::AtmosphereSection& a = *context.scene.techniques.find<atmosphere::AtmosphereSection>();
    atmosphere::AtmosphereParameters& p = a.parameters;
    bool changed = ImGui::SliderFloat("sun elevation deg", &a.sunElevationDeg, -10.0f, 90.0f, "%.1f");
    changed |= ImGui::SliderFloat("sun azimuth deg", &a.sunAzimuthDeg, -180.0f, 180.0f, "%.0f");
    ImGui::TextUnformatted("strategy: the mode above (rgb = RGB-3, optimised4, jakob-hanika, reference)");
    float groundKm = a.groundAltitudeM * 1e-3f;
    if (ImGui::SliderFloat("ground altitude km", &groundKm, 0.0f, 20.0f, "%.2f")) {
      a.groundAltitudeM = groundKm * 1e3f;
      changed = true;
    }
    atmosphere::AtmosphereParameters before = p;
    double height = p.topRadiusKm - p.bottomRadiusKm;
    changed |= slider("planet radius km", p.bottomRadiusKm, 1000.0f, 20000.0f, "%.0f");
    if (slider("atmosphere height km", height, 20.0f, 200.0f, "%.0f")) changed = true;
    p.topRadiusKm = p.bottomRadiusKm + height;
    changed |= slider("Rayleigh at 1 um /km", p.rayleighScatteringPerKm, 0.0f, 5e-3f, "%.5f");
    changed |= slider("Rayleigh scale height km", p.rayleighScaleHeightKm, 1.0f, 20.0f, "%.1f");
    changed |= ImGui::Checkbox("aerosols", &p.aerosols);
    changed |= slider("turbidity (AOD at 1 um)", p.mieAngstromBeta, 0.0f, 0.5f, "%.4f");
    changed |= slider("Angstrom alpha", p.mieAngstromAlpha, -1.0f, 3.0f, "%.2f");
    changed |= slider("Mie scale height km", p.mieScaleHeightKm, 0.2f, 5.0f, "%.2f");
    changed |= slider("Mie albedo", p.mieSingleScatteringAlbedo, 0.0f, 1.0f, "%.2f");
    changed |= slider("Mie g", p.miePhaseG, -0.95f, 0.95f, "%.2f");
    changed |= slider("ozone DU", p.ozoneColumnDu, 0.0f, 600.0f, "%.0f");
    changed |= slider("ground albedo", p.groundAlbedo, 0.0f, 1.0f, "%.2f");
    changed |= ImGui::Checkbox("multiple scattering", &p.multipleScattering);
    if (!changed) return;
    try {
      atmosphere::validate(p);  // e.g. a scale height above the atmosphere's height
    } catch (const Error& e) {
      p = before;
      context.actionError = e.what();
      return;
    }
    applyTechniqueLights(context.scene);
    context.changes.scene = true;
  }
};

}  // namespace

std::unique_ptr<Panel> makeSkyPanel() { return std::make_unique<SkyPanel>(); }

}  // namespace prism::viewer
