// The PRT panel (techniques/prt): mode, basis size m, the environment's illuminant, shape,
// luminance and rotation, or the spectral sky's sun. Sees only the PanelContext.
#include <imgui.h>

#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/viewer/prt_viewer.h"
#include "viewer/panel_widgets.h"

namespace prism::viewer {
namespace {

// Whether a PRT object's material has a spectral texture.
bool hasSpectralTexture(const Scene& scene) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.technique == prt::PrtSection::kKey && scene.materials.at(static_cast<std::size_t>(mesh.material)).spectralTexture)
      return true;
  return false;
}

class PrtPanel final : public Panel {
 public:
  const char* title() const override { return "PRT"; }
  bool applies(const Scene& scene) const override { return scene.techniques.has(prt::PrtSection::kKey); }

  void draw(PanelContext& context) override {
    prt::PrtSection& s = *context.scene.techniques.find<prt::PrtSection>();
    if (mIlluminants.empty()) {  // read once, not every frame
      for (const IlluminantInfo& i : listIlluminants()) mIlluminants.push_back(i.name);
    }
    std::string mode(prt::prtModeName(s.mode));
    bool changed = false;
    if (stringCombo("mode", mode, {"spectral", "rgb-prt", "reference-5nm"})) {
      for (prt::PrtMode m : {prt::PrtMode::Spectral, prt::PrtMode::RgbPrt, prt::PrtMode::Reference5nm})
        if (mode == prt::prtModeName(m)) s.mode = m;
      changed = true;
    }
    changed |= ImGui::SliderInt("basis m", &s.basis, 1, shared::kPrtMaxBasis);
    if (s.map) {
      ImGui::TextUnformatted(("map: " + s.map->file.filename().string()).c_str());
    } else if (s.sky) {
      // Released, not dragged: each new sun tabulates the sky again (about 0.6 s).
      ImGui::TextUnformatted("Prism's spectral sky");
      ImGui::SliderFloat("sun elevation deg", &s.sky->atmosphere.sunElevationDeg, -10.0f, 90.0f, "%.1f");
      changed |= ImGui::IsItemDeactivatedAfterEdit();
      ImGui::SliderFloat("sun azimuth deg", &s.sky->atmosphere.sunAzimuthDeg, -180.0f, 180.0f, "%.1f");
      changed |= ImGui::IsItemDeactivatedAfterEdit();
      // The sun is the deferred pipeline's light, which reads no spectral texture: the pass
      // refuses the two together, so the disc stays off while a PRT material has one — and while
      // the atmosphere section's sun lights the scene (the loader refuses two suns).
      ImGui::BeginDisabled(!s.sky->sunDisc && (hasSpectralTexture(context.scene) || context.scene.techniques.has("atmosphere")));
      changed |= ImGui::Checkbox("sun disc", &s.sky->sunDisc);
      ImGui::EndDisabled();
    } else {
      changed |= stringCombo("illuminant", s.illuminant, mIlluminants);
      changed |= stringCombo("shape", s.shape, {"sky", "uniform"});
    }
    if (!s.sky)
      changed |= ImGui::SliderFloat("luminance cd/m2", &s.luminanceCdM2, 1.0f, 1e5f, "%.0f", ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::SliderFloat("rotation deg", &s.rotationDeg, -180.0f, 180.0f, "%.1f");
    if (changed) {
      applyTechniqueLights(context.scene);  // the spectral sky's sun light follows its sun and rotation
      context.changes.scene = true;
    }
  }

 private:
  std::vector<std::string> mIlluminants;
};

}  // namespace

std::unique_ptr<Panel> makePrtPanel() { return std::make_unique<PrtPanel>(); }

}  // namespace prism::viewer
