// The materials panel: one material at a time, its base colour (edited in sRGB), roughness,
// metalness, conductor and an emitter's luminance, and a plot of its reflectance: measured, or
// upsampled from its colour.
#include <imgui.h>

#include <algorithm>

#include "render/shared_shading.h"
#include "scene/conductors.h"
#include "spectral/rgb_intent.h"
#include "viewer/panel_widgets.h"
#include "viewer/panels.h"

namespace prism::viewer {
namespace {

class MaterialsPanel final : public Panel {
 public:
  const char* title() const override { return "Materials"; }

  void draw(PanelContext& context) override {
    std::vector<Material>& materials = context.scene.materials;
    if (materials.empty()) return;
    mMaterial = std::min(mMaterial, materials.size() - 1);
    if (ImGui::BeginCombo("material", materials[mMaterial].name.c_str())) {
      for (std::size_t i = 0; i < materials.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));  // glTF material names may repeat or be empty
        if (ImGui::Selectable(materials[i].name.c_str(), i == mMaterial)) mMaterial = i;
        ImGui::PopID();
      }
      ImGui::EndCombo();
    }
    Material& m = materials[mMaterial];
    bool& changed = context.changes.scene;
    float srgb[3] = {shared::srgbEncode(m.baseColour.x), shared::srgbEncode(m.baseColour.y),
                     shared::srgbEncode(m.baseColour.z)};
    // A conductor's colour and metalness are its n and k (kept for when it is set back to none).
    ImGui::BeginDisabled(m.conductor.has_value());
    if (ImGui::ColorEdit3("base colour", srgb)) {
      m.baseColour = glm::vec3(shared::srgbDecode(srgb[0]), shared::srgbDecode(srgb[1]), shared::srgbDecode(srgb[2]));
      changed = true;
    }
    ImGui::EndDisabled();
    changed |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f);
    // A lambertian material diffuses all of the light: the loader refuses a metal there, and so
    // does the panel (it rendered black).
    ImGui::BeginDisabled(m.conductor.has_value() || m.lambertian);
    changed |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f);
    ImGui::EndDisabled();
    std::vector<std::string> conductors{"none"};
    for (const std::string& c : listConductors()) conductors.push_back(c);
    std::string conductor = m.conductor ? m.conductor->name : "none";
    // PRT objects are diffuse: the scene loader refuses a conductor on them, and so does the panel.
    const bool onPrt = std::any_of(context.scene.meshes.begin(), context.scene.meshes.end(), [&](const Mesh& mesh) {
      return static_cast<std::size_t>(mesh.material) == mMaterial && mesh.technique == "prt";
    });
    ImGui::BeginDisabled((onPrt || m.lambertian) && !m.conductor);
    if (stringCombo("conductor", conductor, conductors)) {
      if (conductor == "none") m.conductor.reset();
      else m.conductor = conductorIor(conductor);
      changed = true;
    }
    ImGui::EndDisabled();
    if (onPrt && !m.conductor) ImGui::TextDisabled("(PRT objects use it: they are diffuse)");
    else if (m.lambertian) ImGui::TextDisabled("(lambertian: all of the light diffused)");
    if (m.emission || m.emitsRgb()) {  // its luminance, the spectrum's shape kept (the file gives it)
      float& luminance = m.emission ? m.emission->luminance : m.emissiveLuminance;
      float edited = luminance;
      if (ImGui::SliderFloat("emission cd/m2", &edited, 0.01f, 1e5f, "%.3g", ImGuiSliderFlags_Logarithmic) &&
          edited > 0.0f) {
        luminance = edited;
        changed = true;
      }
    }
    reflectancePlot(m, context.table);
  }

 private:
  static void reflectancePlot(const Material& m, const RgbToSpectrumTable& table) {
    const float height = 90.0f;
    ImVec2 origin = ImGui::GetCursorScreenPos();
    float width = std::max(200.0f, ImGui::GetContentRegionAvail().x);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(20, 20, 24, 255));
    Spectrum r = m.reflectance ? *m.reflectance : RgbAlbedoSpectrum(table, m.baseColour).toDense();
    for (int l = 360; l < 830; l += 2) {
      auto at = [&](int lambda) {
        return ImVec2(origin.x + static_cast<float>(lambda - 360) / 470.0f * width,
                      origin.y + height - static_cast<float>(std::clamp(r.at(lambda), 0.0, 1.0)) * (height - 4.0f));
      };
      draw->AddLine(at(l), at(l + 2), IM_COL32(240, 240, 240, 255), 1.5f);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::TextDisabled(m.reflectance ? "measured reflectance" : "upsampled reflectance (Jakob-Hanika), 0-1");
  }

  std::size_t mMaterial = 0;  // the one shown
};

}  // namespace

std::unique_ptr<Panel> makeMaterialsPanel() { return std::make_unique<MaterialsPanel>(); }

}  // namespace prism::viewer
