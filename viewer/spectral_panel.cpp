// The spectral panel: the left (or only) view's mode, wavelengths and observer, and a plot of the
// observer's curves, each light's SPD, the pdf the wavelengths are drawn from and the frame's
// wavelengths (issue #5, the thesis's Fig. 4.9; issue 16).
#include <imgui.h>

#include <algorithm>
#include <functional>

#include "spectral/observer.h"
#include "viewer/compositor.h"
#include "viewer/panel_widgets.h"
#include "viewer/panels.h"

namespace prism::viewer {
namespace {

class SpectralPanel final : public Panel {
 public:
  const char* title() const override { return "Spectral"; }
  bool openAtStart() const override { return true; }

  void draw(PanelContext& context) override {
    context.changes.settings |= frameSettingsControls(context.view.left, "left", mObservers);
    spectrumPlot(context);
  }

 private:
  static void spectrumPlot(const PanelContext& context) {
    const float height = 150.0f;
    ImVec2 origin = ImGui::GetCursorScreenPos();
    float width = std::max(200.0f, ImGui::GetContentRegionAvail().x);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(20, 20, 24, 255));
    auto at = [&](double lambda, double value) {
      return ImVec2(origin.x + static_cast<float>((lambda - 360.0) / 470.0) * width,
                    origin.y + height - static_cast<float>(std::clamp(value, 0.0, 1.05)) * (height - 6.0f));
    };
    auto curve = [&](const std::function<double(double)>& f, double scale, ImU32 colour) {
      for (int l = 360; l < 830; l += 2) draw->AddLine(at(l, f(l) * scale), at(l + 2, f(l + 2) * scale), colour, 1.5f);
    };
    const render::Renderer* left = context.views.left();
    if (left) {  // the observer the view renders with, resolved when its settings changed
      const Observer& obs = *left->context().observer;
      double peak = 0.0;
      for (int c = 0; c < 3; ++c) peak = std::max(peak, obs.curves[static_cast<std::size_t>(c)].maxValue());
      const ImU32 colours[3] = {IM_COL32(230, 80, 80, 255), IM_COL32(80, 200, 90, 255), IM_COL32(90, 130, 240, 255)};
      for (int c = 0; c < 3; ++c) {
        const Spectrum& s = obs.curves[static_cast<std::size_t>(c)];
        curve([&](double l) { return s.at(l); }, 1.0 / std::max(peak, 1e-12), colours[c]);
      }
    }
    for (const Light& light : context.scene.lights) {
      curve([&](double l) { return light.spd.at(l); }, 1.0 / std::max(light.spd.maxValue(), 1e-12),
            IM_COL32(250, 230, 120, 255));
    }
    if (left && left->settings().mode != render::RenderMode::Rgb) {
      // The pdf the frame's wavelengths are drawn from (importance, lights), scaled to its peak.
      if (const WavelengthPdf* pdf = left->context().wavelengths->pdf()) {
        double peak = 0.0;
        for (int l = 360; l <= 830; ++l) peak = std::max(peak, pdf->density(l));
        curve([&](double l) { return pdf->density(l); }, 1.0 / std::max(peak, 1e-12), IM_COL32(90, 220, 230, 255));
      }
      for (const auto& batch : left->frameData().batches) {
        for (int j = 0; j < 4; ++j) {
          ImVec2 x = at(batch.lambdaNm[j], 0.0);
          draw->AddLine(ImVec2(x.x, origin.y + height), ImVec2(x.x, origin.y + height - 10.0f), IM_COL32(255, 255, 255, 200));
        }
      }
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::TextDisabled(
        "observer curves (r g b), light SPDs (yellow), the wavelengths' pdf (cyan: importance, lights), this "
        "frame's wavelengths (ticks; optimised: the fitted set); 360-830 nm");
  }

  std::vector<std::string> mObservers = observerChoices();
};

}  // namespace

std::unique_ptr<Panel> makeSpectralPanel() { return std::make_unique<SpectralPanel>(); }

}  // namespace prism::viewer
