#include "viewer/viewer.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "gpu/error.h"
#include "gpu/object_counter.h"
#include "gpu/texture.h"
#include "gpu/window_context.h"
#include "imaging/exr_file.h"
#include "imaging/heatmap.h"
#include "imaging/image_difference.h"
#include "imaging/png_file.h"
#include "render/display_transform.h"
#include "render/renderer.h"
#include "render/shared_shading.h"
#include "scene/conductors.h"
#include "scene/scene_loader.h"
#include "spectral/csv.h"
#include "spectral/error.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "techniques/underwater/jerlov_water.h"
#include "viewer/camera_controller.h"
#include "viewer/compositor.h"
#include "viewer/light_spectrum.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {
namespace {

struct ScriptLine {
  int line = 0;
  std::vector<std::string> words;
};

std::vector<ScriptLine> readScript(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(fmt::format("{}: cannot read the script", path.string()));
  std::vector<ScriptLine> lines;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (std::size_t hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    ScriptLine line{n, {}};
    for (std::string w; words >> w;) line.words.push_back(w);
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

// The process's memory in MB once the allocator has given its free pages back (malloc_trim).
// Untrimmed, resident memory also counts the freed memory glibc keeps for reuse (47 MB after a
// 1 000-frame soak round), which varies from run to run, leak or not.
struct MemoryUse {
  double heap = 0.0;       // handed out by malloc and not freed, over every arena (mallinfo2)
  double anonymous = 0.0;  // resident anonymous pages: the heap, thread stacks, compiled shaders
  double files = 0.0;      // resident pages of mapped files: the code of the libraries run so far
};

MemoryUse memoryUse() {
  malloc_trim(0);
  MemoryUse m;
  struct mallinfo2 info = mallinfo2();
  m.heap = static_cast<double>(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    std::istringstream words(line);
    std::string key;
    double kilobytes = 0.0;
    words >> key >> kilobytes;
    if (key == "RssAnon:") m.anonymous = kilobytes / 1024.0;
    if (key == "RssFile:") m.files = kilobytes / 1024.0;
  }
  return m;
}

glm::vec3 parseVec3(const std::string& what, const std::string& text) {
  glm::vec3 v;
  std::stringstream in(text);
  std::string part;
  for (int i = 0; i < 3; ++i) {
    if (!std::getline(in, part, ',')) throw Error(fmt::format("{}: expected X,Y,Z, got \"{}\"", what, text));
    v[i] = parseFloat(what, part);
  }
  return v;
}

// Dear ImGui over the window, from construction to destruction.
class ImGuiSession {
 public:
  explicit ImGuiSession(gpu::WindowContext& window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window.window(), true);
    ImGui_ImplOpenGL3_Init("#version 450");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

class Viewer {
 public:
  Viewer(gpu::WindowContext& window, Scene& scene, const RgbToSpectrumTable& table,
         const render::FrameSettings& initial)
      : mWindow(window), mScene(scene), mTable(table), mCamera(scene.camera) {
    mView.left = initial;
    mView.right = initial;
    mView.right.mode = render::RenderMode::Rgb;
    for (const IlluminantInfo& info : listIlluminants()) {
      // Parametric families ("blackbody:<K>") have their own controls.
      if (info.name.find('<') == std::string::npos) mIlluminants.push_back(info.name);
    }
    mObservers = {"cie1931", "cie1964"};
    for (const std::string& c : listCameras()) mObservers.push_back(c);
    Bounds b = sceneBounds(scene);
    mFlySpeed = std::max(0.5f, 0.25f * glm::length(b.max - b.min));
    auto fill = [](std::array<char, 512>& buffer, const char* text) {
      std::snprintf(buffer.data(), buffer.size(), "%s", text);
    };
    fill(mScreenshotPath, "prism_screenshot.png");
    fill(mSettingsPath, "prism_view_settings.json");
  }

  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  int interactive() {
    while (!mWindow.shouldClose()) frame();  // errors are shown in the window, not thrown
    return 0;
  }

  int scripted(const std::filesystem::path& path) {
    std::vector<ScriptLine> lines = readScript(path);
    frame();
    for (const ScriptLine& line : lines) {
      try {
        execute(line.words);
      } catch (const std::exception& e) {
        fmt::print(stderr, "prism: error: {}:{}: {}\n", path.string(), line.line, e.what());
        return 1;
      }
    }
    return 0;
  }

 private:
  // One frame: input, both views, the window, the interface, the swap.
  void frame() {
    auto now = std::chrono::steady_clock::now();
    float seconds = std::chrono::duration<float>(now - mLastFrame).count();
    mLastFrame = now;
    mFrameMs[mFrameCursor++ % mFrameMs.size()] = seconds * 1000.0f;

    mWindow.pollEvents();
    gpu::WindowSize size = mWindow.framebufferSize();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (size.width > 0 && size.height > 0) {  // minimised: nothing to draw into
      handleInput(std::min(seconds, 0.1f));
      mRenderError = mCompositor.render(mView, {mSettingsChanged, mCameraChanged, mSceneChanged}, mCamera.camera(),
                                        size.width, size.height);
      mSettingsChanged = mCameraChanged = mSceneChanged = false;
      mCompositor.compose(mView, size.width, size.height);
    }
    interface();
    ImGui::Render();
    if (size.width > 0 && size.height > 0) {
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (!mPendingScreenshot.empty()) {
        writeScreenshot(mPendingScreenshot, size.width, size.height);
        mPendingScreenshot.clear();
      }
    }
    mWindow.swapBuffers();
  }

  void handleInput(float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* w = mWindow.window();
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(w, &x, &y);
    float dx = static_cast<float>(x - mCursorX), dy = static_cast<float>(y - mCursorY);
    mCursorX = x;
    mCursorY = y;
    if (!io.WantCaptureMouse) {
      if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
        mCamera.orbit(-dx * 0.005f, dy * 0.005f);
        mCameraChanged = true;
      }
      if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
        mCamera.look(-dx * 0.003f, -dy * 0.003f);
        mCameraChanged = true;
      }
      if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
        mCamera.pan(-dx * 0.002f, dy * 0.002f);
        mCameraChanged = true;
      }
      if (io.MouseWheel != 0.0f) {
        mCamera.dolly(0.1f * io.MouseWheel);
        mCameraChanged = true;
      }
    }
    if (!io.WantCaptureKeyboard) {
      glm::vec3 move(0.0f);
      auto key = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS ? 1.0f : 0.0f; };
      move.x = key(GLFW_KEY_D) - key(GLFW_KEY_A);
      move.y = key(GLFW_KEY_E) - key(GLFW_KEY_Q);
      move.z = key(GLFW_KEY_W) - key(GLFW_KEY_S);
      if (move != glm::vec3(0.0f)) {
        mCamera.fly(move * mFlySpeed * seconds);
        mCameraChanged = true;
      }
      if (key(GLFW_KEY_R) > 0.0f) {
        mCamera.reset();
        mCameraChanged = true;
      }
    }
  }

  void writeScreenshot(const std::filesystem::path& path, int w, int h) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    imaging::PngImage image(w, h, {});
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::uint8_t* p = &rgba[(static_cast<std::size_t>(h - 1 - y) * static_cast<std::size_t>(w) +
                                       static_cast<std::size_t>(x)) * 4];
        image.setPixel(x, y, {p[0], p[1], p[2]});
      }
    }
    image.write(path);
  }

  // renderNow: take it in a frame of its own (the script); from the interface, in this frame.
  void screenshot(const std::filesystem::path& path, bool renderNow) {
    if (path.extension() == ".exr") return mCompositor.writeLeftExr(path, mCamera.camera());
    if (path.extension() != ".png") throw Error(fmt::format("{}: a screenshot is a .png or an .exr", path.string()));
    mPendingScreenshot = path;  // written after the interface is drawn, before the swap
    if (renderNow) {
      frame();
      if (!mPendingScreenshot.empty()) throw Error("the window is minimised: nothing to take");
    }
  }

  // ---- the interface -------------------------------------------------------------------------

  template <typename T>
  bool combo(const char* label, T& value, const std::vector<std::pair<T, std::string>>& choices) {
    std::string current;
    for (const auto& [v, name] : choices) if (v == value) current = name;
    bool changed = false;
    if (ImGui::BeginCombo(label, current.c_str())) {
      for (const auto& [v, name] : choices) {
        if (ImGui::Selectable(name.c_str(), v == value)) {
          value = v;
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
    return changed;
  }

  bool stringCombo(const char* label, std::string& value, const std::vector<std::string>& choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
      for (const std::string& c : choices) {
        if (ImGui::Selectable(c.c_str(), c == value)) {
          value = c;
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
    return changed;
  }

  bool frameSettingsControls(render::FrameSettings& s, const char* id) {
    ImGui::PushID(id);
    bool changed = combo<render::RenderMode>("mode", s.mode,
                                             {{render::RenderMode::Rgb, "rgb"},
                                              {render::RenderMode::Naive, "naive"},
                                              {render::RenderMode::JakobHanika, "jakob-hanika"},
                                              {render::RenderMode::Reference, "reference (472 wavelengths)"},
                                              {render::RenderMode::Optimised4, "optimised4 (sky's 4 wavelengths)"}});
    int count = s.sampling.count;
    if (ImGui::SliderInt("wavelengths", &count, 4, 256)) {
      s.sampling.count = std::max(4, count / 4 * 4);
      changed = true;
    }
    float range[2] = {static_cast<float>(s.sampling.minNm), static_cast<float>(s.sampling.maxNm)};
    if (ImGui::SliderFloat2("range nm", range, 360.0f, 830.0f, "%.0f")) {
      s.sampling.minNm = std::clamp<double>(range[0], 360.0, 829.0);
      s.sampling.maxNm = std::clamp<double>(range[1], s.sampling.minNm + 1.0, 830.0);
      changed = true;
    }
    changed |= combo<SamplingStrategy>("strategy", s.sampling.strategy,
                                       {{SamplingStrategy::Uniform, "uniform"},
                                        {SamplingStrategy::Stratified, "stratified"},
                                        {SamplingStrategy::Rotated, "rotated"},
                                        {SamplingStrategy::Importance, "importance"}});
    changed |= stringCombo("observer", s.observer, mObservers);
    ImGui::PopID();
    return changed;
  }

  // Observer curves, each light's SPD and the frame's wavelengths (issue #5, the thesis's Fig. 4.9).
  void spectrumPlot() {
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
    const Observer& obs = observer(mView.left.observer);
    double peak = 0.0;
    for (int c = 0; c < 3; ++c) peak = std::max(peak, obs.curves[static_cast<std::size_t>(c)].maxValue());
    const ImU32 colours[3] = {IM_COL32(230, 80, 80, 255), IM_COL32(80, 200, 90, 255), IM_COL32(90, 130, 240, 255)};
    for (int c = 0; c < 3; ++c) {
      const Spectrum& s = obs.curves[static_cast<std::size_t>(c)];
      curve([&](double l) { return s.at(l); }, 1.0 / std::max(peak, 1e-12), colours[c]);
    }
    for (const Light& light : mScene.lights) {
      curve([&](double l) { return light.spd.at(l); }, 1.0 / std::max(light.spd.maxValue(), 1e-12),
            IM_COL32(250, 230, 120, 255));
    }
    const render::Renderer* left = mCompositor.left();
    if (left && left->settings().mode != render::RenderMode::Rgb) {
      for (const auto& batch : left->frameData().batches) {
        for (int j = 0; j < 4; ++j) {
          ImVec2 x = at(batch.lambdaNm[j], 0.0);
          draw->AddLine(ImVec2(x.x, origin.y + height), ImVec2(x.x, origin.y + height - 10.0f), IM_COL32(255, 255, 255, 200));
        }
      }
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::TextDisabled("observer curves (r g b), light SPDs (yellow), this frame's wavelengths (ticks); 360-830 nm");
  }

  void reflectancePlot(const Material& m) {
    const float height = 90.0f;
    ImVec2 origin = ImGui::GetCursorScreenPos();
    float width = std::max(200.0f, ImGui::GetContentRegionAvail().x);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(20, 20, 24, 255));
    Spectrum r = m.reflectance ? *m.reflectance : upsampledReflectanceSpectrum(mTable.lookup(m.baseColour));
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

  void interface() {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(430, std::max(200.0f, ImGui::GetIO().DisplaySize.y - 20.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("Prism");
    float mean = 0.0f;
    for (float ms : mFrameMs) mean += ms;
    mean /= static_cast<float>(mFrameMs.size());
    ImGui::Text("%.1f ms  %.0f FPS   %s", mean, mean > 0.0f ? 1000.0f / mean : 0.0f, mWindow.renderer().c_str());
    ImGui::PlotLines("##frame", mFrameMs.data(), static_cast<int>(mFrameMs.size()),
                     static_cast<int>(mFrameCursor % mFrameMs.size()), "frame ms", 0.0f, 2.0f * mean + 1.0f,
                     ImVec2(0, 40));
    for (const std::string* error : {&mRenderError, &mActionError}) {
      if (!error->empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error->c_str());
    }
    if (!mActionError.empty() && ImGui::SmallButton("dismiss")) mActionError.clear();

    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
      float fov = mCamera.camera().verticalFovDeg;
      if (ImGui::SliderFloat("field of view", &fov, 5.0f, 150.0f, "%.0f°")) {
        mCamera.setFieldOfView(fov);
        mCameraChanged = true;
      }
      if (ImGui::Button("reset (R)")) {
        mCamera.reset();
        mCameraChanged = true;
      }
      ImGui::SameLine();
      ImGui::TextDisabled("drag: orbit, right: look, middle: pan, wheel: dolly, WASD QE: fly");
    }
    if (ImGui::CollapsingHeader("Spectral", ImGuiTreeNodeFlags_DefaultOpen)) {
      mSettingsChanged |= frameSettingsControls(mView.left, "left");
      spectrumPlot();
    }
    if (ImGui::CollapsingHeader("A/B split", ImGuiTreeNodeFlags_DefaultOpen)) {
      mSettingsChanged |= ImGui::Checkbox("split: left | right", &mView.split);
      if (mView.split) {
        mSettingsChanged |= frameSettingsControls(mView.right, "right");
        ImGui::Checkbox("CIEDE2000 heat map", &mView.heatMap);
        if (mView.heatMap && mCompositor.heatMap().id() != 0) {
          ImGui::Text("dE00 mean %.2f  p95 %.2f  max %.1f", mCompositor.heatMapStats().meanDeltaE, mCompositor.heatMapStats().p95DeltaE,
                      mCompositor.heatMapStats().maxDeltaE);
          float w = ImGui::GetContentRegionAvail().x;
          const gpu::Texture2D& heat = mCompositor.heatMap();
          float h = w * static_cast<float>(heat.height()) / static_cast<float>(heat.width());
          ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(heat.id())), ImVec2(w, h));
        }
      }
    }
    if (ImGui::CollapsingHeader("Lights")) lightsPanel();
    if (ImGui::CollapsingHeader("Materials")) materialsPanel();
    if (mScene.water && ImGui::CollapsingHeader("Water")) waterPanel();
    if (mScene.atmosphere && ImGui::CollapsingHeader("Sky")) skyPanel();
    if (ImGui::CollapsingHeader("Display")) displayPanel();
    if (ImGui::CollapsingHeader("Files")) filesPanel();
    ImGui::End();
  }

  void lightsPanel() {
    for (std::size_t i = 0; i < mScene.lights.size(); ++i) {
      Light& light = mScene.lights[i];
      ImGui::PushID(static_cast<int>(i));
      ImGui::Text("light %zu (%s): %s", i,
                  light.type == LightType::Directional ? "directional" : light.type == LightType::Point ? "point" : "spot",
                  light.spdLabel.c_str());
      std::string choice = light.spdLabel;
      if (stringCombo("SPD", choice, mIlluminants)) {
        runAction([&] {
          setLightSpd(light, choice);
          mSceneChanged = true;
        });
      }
      if (ImGui::SliderFloat("blackbody K", &mBlackbodyK, 1000.0f, 12000.0f, "%.0f K")) {
        runAction([&] {
          setLightSpd(light, fmt::format("blackbody:{:.0f}", mBlackbodyK));
          mSceneChanged = true;
        });
      }
      float led[2] = {mLedPeakNm, mLedWidthNm};
      if (ImGui::SliderFloat2("LED peak, width nm", led, 380.0f, 700.0f, "%.0f")) {
        mLedPeakNm = led[0];
        mLedWidthNm = std::clamp(led[1], 5.0f, 100.0f);
        runAction([&] {
          setLightSpd(light, fmt::format("led:{:.0f}:{:.0f}", mLedPeakNm, mLedWidthNm));
          mSceneChanged = true;
        });
      }
      ImGui::InputText("CSV file", mCsvPath.data(), mCsvPath.size());
      ImGui::SameLine();
      if (ImGui::Button("load")) {
        runAction([&] {
          std::string path = mCsvPath.data();
          setLightSpectrum(light, readSpectrumCsv(path, Extrapolation::Zero, 0.0).toDense(), "csv:" + path);
          mSceneChanged = true;
        });
      }
      if (ImGui::SliderFloat("intensity", &light.intensity, 1.0f, 200000.0f, "%.0f", ImGuiSliderFlags_Logarithmic)) {
        mSceneChanged = true;
      }
      if (light.type != LightType::Point) {
        glm::vec3 d = glm::normalize(light.direction);
        float azimuth = std::atan2(d.x, d.z) / kDegrees, elevation = std::asin(-d.y) / kDegrees;
        bool turned = ImGui::SliderFloat("azimuth", &azimuth, -180.0f, 180.0f, "%.0f°");
        turned |= ImGui::SliderFloat("elevation", &elevation, -89.0f, 89.0f, "%.0f°");
        if (turned) {
          float a = azimuth * kDegrees, e = elevation * kDegrees;
          light.direction = glm::vec3(std::cos(e) * std::sin(a), -std::sin(e), std::cos(e) * std::cos(a));
          mSceneChanged = true;
        }
      }
      ImGui::Separator();
      ImGui::PopID();
    }
  }

  void materialsPanel() {
    if (mScene.materials.empty()) return;
    mMaterial = std::min(mMaterial, mScene.materials.size() - 1);
    if (ImGui::BeginCombo("material", mScene.materials[mMaterial].name.c_str())) {
      for (std::size_t i = 0; i < mScene.materials.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));  // glTF material names may repeat or be empty
        if (ImGui::Selectable(mScene.materials[i].name.c_str(), i == mMaterial)) mMaterial = i;
        ImGui::PopID();
      }
      ImGui::EndCombo();
    }
    Material& m = mScene.materials[mMaterial];
    float srgb[3] = {shared::srgbEncode(m.baseColour.x), shared::srgbEncode(m.baseColour.y),
                     shared::srgbEncode(m.baseColour.z)};
    if (ImGui::ColorEdit3("base colour", srgb)) {
      m.baseColour = glm::vec3(shared::srgbDecode(srgb[0]), shared::srgbDecode(srgb[1]), shared::srgbDecode(srgb[2]));
      mSceneChanged = true;
    }
    mSceneChanged |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f);
    mSceneChanged |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f);
    std::vector<std::string> conductors{"none"};
    for (const std::string& c : listConductors()) conductors.push_back(c);
    std::string conductor = m.conductor ? m.conductor->name : "none";
    if (stringCombo("conductor", conductor, conductors)) {
      if (conductor == "none") m.conductor.reset();
      else m.conductor = conductorIor(conductor);
      mSceneChanged = true;
    }
    reflectancePlot(m);
  }

  void waterPanel() {
    Water& w = *mScene.water;
    if (mWaterTypesOf != w.dataset) {  // read from data/ when the data set changes, not every frame
      mWaterTypes = underwater::listJerlovTypes(underwater::jerlovDatasetFromName(w.dataset));
      mWaterTypesOf = w.dataset;
    }
    bool changed = stringCombo("type", w.type, mWaterTypes);
    changed |= stringCombo("data set", w.dataset, {"jerlov", "williamson2022"});
    changed |= ImGui::SliderFloat("camera depth m", &w.depthM, 0.0f, 60.0f, "%.1f");
    changed |= ImGui::SliderFloat("scattering x", &w.scatteringScale, 0.0f, 4.0f);
    changed |= ImGui::SliderFloat("absorption x", &w.absorptionScale, 0.0f, 4.0f);
    changed |= ImGui::SliderFloat("Kd x", &w.kdScale, 0.0f, 4.0f);
    if (changed) applyWater();
  }

  // The sun and the atmosphere (issue #8): every change recomputes the sky's tables next frame.
  void skyPanel() {
    Atmosphere& a = *mScene.atmosphere;
    atmosphere::AtmosphereParameters& p = a.parameters;
    bool changed = ImGui::SliderFloat("sun elevation deg", &a.sunElevationDeg, -10.0f, 90.0f, "%.1f");
    changed |= ImGui::SliderFloat("sun azimuth deg", &a.sunAzimuthDeg, -180.0f, 180.0f, "%.0f");
    ImGui::TextUnformatted("strategy: the mode above (rgb = RGB-3, optimised4, jakob-hanika, reference)");
    float groundKm = a.groundAltitudeM * 1e-3f;
    if (ImGui::SliderFloat("ground altitude km", &groundKm, 0.0f, 20.0f, "%.2f")) {
      a.groundAltitudeM = groundKm * 1e3f;
      changed = true;
    }
    auto slider = [&](const char* label, double& value, float lo, float hi, const char* format) {
      float v = static_cast<float>(value);
      if (!ImGui::SliderFloat(label, &v, lo, hi, format)) return false;
      value = v;
      return true;
    };
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
      mActionError = e.what();
      return;
    }
    applySky();
  }

  void applySky() {
    applySun(mScene);
    mSceneChanged = true;
  }

  void applyWater() {
    Water& w = *mScene.water;
    try {
      resolveWater(w);
    } catch (const Error& e) {  // a type the other data set lacks: back to its first
      w.type = underwater::listJerlovTypes(underwater::jerlovDatasetFromName(w.dataset)).front();
      resolveWater(w);
      mActionError = e.what();
    }
    mSceneChanged = true;
  }

  void displayPanel() {
    render::FrameSettings& s = mView.left;
    mSettingsChanged |= combo<render::ToneMap>("tone map", s.toneMap, {{render::ToneMap::None, "none"},
                                                                    {render::ToneMap::Reinhard, "reinhard"},
                                                                    {render::ToneMap::Aces, "aces"}});
    bool sceneEv = !s.ev100.has_value();
    if (ImGui::Checkbox("the scene camera's exposure", &sceneEv)) {
      s.ev100 = sceneEv ? std::nullopt : std::optional<float>(mCamera.camera().ev100);
      mSettingsChanged = true;
    }
    if (s.ev100) mSettingsChanged |= ImGui::SliderFloat("EV100", &*s.ev100, -5.0f, 20.0f, "%.1f");
    std::vector<std::string> balances{"none"};
    balances.insert(balances.end(), mIlluminants.begin(), mIlluminants.end());
    mSettingsChanged |= stringCombo("white balance", s.whiteBalance, balances);
    mSettingsChanged |= stringCombo("display", s.display, {"srgb", "display-p3", "rec2020"});
    if (mSettingsChanged) {  // one display for both halves of the split
      mView.right.toneMap = s.toneMap;
      mView.right.ev100 = s.ev100;
      mView.right.whiteBalance = s.whiteBalance;
      mView.right.display = s.display;
    }
  }

  void filesPanel() {
    ImGui::InputText("screenshot", mScreenshotPath.data(), mScreenshotPath.size());
    ImGui::SameLine();
    if (ImGui::Button("save##shot")) runAction([&] { screenshot(mScreenshotPath.data(), false); });
    ImGui::InputText("settings", mSettingsPath.data(), mSettingsPath.size());
    if (ImGui::Button("save settings")) runAction([&] { saveViewSettings(mSettingsPath.data(), mView, mCamera.camera()); });
    ImGui::SameLine();
    if (ImGui::Button("load settings")) runAction([&] { loadSettings(mSettingsPath.data()); });
    if (ImGui::Button("reload shaders")) runAction([&] { reloadShaders(); });
  }

  // An action from the interface: its error stays on screen until the next action or dismissed.
  template <typename F>
  void runAction(F&& action) {
    try {
      action();
      mActionError.clear();
    } catch (const std::exception& e) {
      mActionError = e.what();
    }
  }

  void loadSettings(const std::filesystem::path& path) {
    Camera camera = mCamera.camera();
    loadViewSettings(path, mView, camera);
    mCamera = CameraController(camera);
    mSettingsChanged = mCameraChanged = true;
  }

  void reloadShaders() { mCompositor.reloadShaders(); }

  // ---- the script -----------------------------------------------------------------------------

  void execute(const std::vector<std::string>& w) {
    auto need = [&](std::size_t n) {
      if (w.size() != n + 1) throw Error(fmt::format("{} takes {} argument{}", w[0], n, n == 1 ? "" : "s"));
    };
    const std::string& verb = w[0];
    if (verb == "set") {
      need(2);
      set(w[1], w[2]);
      if (mSettingsChanged) {  // a bad value should fail here, at its line
        render::validate(mView.left);
        render::validate(mView.right);
      }
    } else if (verb == "frames") {
      need(1);
      long n = parseInteger("frames", w[1], 0, 1000000);
      for (long i = 0; i < n; ++i) frame();
      if (!mRenderError.empty()) throw Error(mRenderError);
    } else if (verb == "resize") {
      need(2);
      resize(static_cast<int>(parseInteger("width", w[1], 16, 8192)),
             static_cast<int>(parseInteger("height", w[2], 16, 8192)));
    } else if (verb == "orbit") {
      need(2);
      mCamera.orbit(parseFloat("yaw", w[1]) * kDegrees, parseFloat("pitch", w[2]) * kDegrees);
      mCameraChanged = true;
    } else if (verb == "screenshot") {
      need(1);
      screenshot(w[1], true);
    } else if (verb == "save-settings") {
      need(1);
      saveViewSettings(w[1], mView, mCamera.camera());
    } else if (verb == "load-settings") {
      need(1);
      loadSettings(w[1]);
    } else if (verb == "heat-map-stats") {
      need(0);
      if (!(mView.split && mView.heatMap) || mCompositor.heatMap().id() == 0) throw Error("no heat map yet (set split on, heat-map on, frames N)");
      fmt::print("heat map: mean {:.3f} p95 {:.3f} max {:.3f}\n", mCompositor.heatMapStats().meanDeltaE, mCompositor.heatMapStats().p95DeltaE,
                 mCompositor.heatMapStats().maxDeltaE);
      std::fflush(stdout);
    } else if (verb == "reload-shaders") {
      need(0);
      reloadShaders();
    } else if (verb == "soak") {
      if (w.size() != 2 && w.size() != 3) throw Error("soak takes FRAMES and optionally MAX-GROWTH-MB");
      soak(static_cast<int>(parseInteger("soak", w[1], 1, 1000000)),
           w.size() == 3 ? std::optional<double>(parseFloat("soak's memory bound", w[2])) : std::nullopt);
    } else {
      throw Error(fmt::format("unknown command \"{}\" (set, frames, resize, orbit, screenshot, save-settings, "
                              "load-settings, reload-shaders, soak, heat-map-stats)", verb));
    }
  }

  void resize(int width, int height) {
    glfwSetWindowSize(mWindow.window(), width, height);
    // The window system answers asynchronously: wait (briefly) until the framebuffer follows.
    for (int i = 0; i < 200; ++i) {
      mWindow.pollEvents();
      gpu::WindowSize s = mWindow.framebufferSize();
      if (s.width == width && s.height == height) break;
      glfwWaitEventsTimeout(0.01);
    }
  }

  void set(const std::string& key, const std::string& value) {
    if (key.rfind("right.", 0) == 0) {
      if (!applyFrameSetting(mView.right, key.substr(6), value)) throw Error(fmt::format("unknown setting \"{}\"", key));
      mSettingsChanged = true;
      return;
    }
    if (applyFrameSetting(mView.left, key, value)) {
      mSettingsChanged = true;
      return;
    }
    auto onOff = [&](bool& flag) {
      if (value != "on" && value != "off") throw Error(fmt::format("{}: expected on or off, got \"{}\"", key, value));
      flag = value == "on";
      mSettingsChanged = true;
    };
    if (key == "split") return onOff(mView.split);
    if (key == "heat-map") return onOff(mView.heatMap);
    if (key == "fov") {
      mCamera.setFieldOfView(parseFloat(key, value));
      mCameraChanged = true;
      return;
    }
    if (key == "water.type" || key == "water.depth") {
      if (!mScene.water) throw Error("the scene has no water");
      if (key == "water.type") mScene.water->type = value;
      else mScene.water->depthM = std::max(0.0f, parseFloat(key, value));
      resolveWater(*mScene.water);
      mSceneChanged = true;
      return;
    }
    if (key.rfind("sky.", 0) == 0) {
      if (!mScene.atmosphere) throw Error("the scene has no atmosphere");
      Atmosphere& a = *mScene.atmosphere;
      atmosphere::AtmosphereParameters p = a.parameters;
      std::string_view k = std::string_view(key).substr(4);
      if (k == "elevation") a.sunElevationDeg = std::clamp(parseFloat(key, value), -90.0f, 90.0f);
      else if (k == "azimuth") a.sunAzimuthDeg = parseFloat(key, value);
      else if (k == "turbidity") p.mieAngstromBeta = parseFloat(key, value);
      else if (k == "ozone") p.ozoneColumnDu = parseFloat(key, value);
      else if (k == "aerosols" || k == "multiple-scattering") {
        if (value != "on" && value != "off") throw Error(fmt::format("{}: expected on or off, got \"{}\"", key, value));
        (k == "aerosols" ? p.aerosols : p.multipleScattering) = value == "on";
      }
      else throw Error(fmt::format("unknown setting \"{}\" (sky.elevation, azimuth, turbidity, ozone, aerosols, "
                                   "multiple-scattering)", key));
      atmosphere::validate(p);  // nothing changes on an error
      a.parameters = p;
      applySky();
      return;
    }
    std::vector<std::string> parts;
    std::stringstream in(key);
    for (std::string p; std::getline(in, p, '.');) parts.push_back(p);
    if (parts.size() == 3 && parts[0] == "light") {
      if (mScene.lights.empty()) throw Error(fmt::format("{}: the scene has no lights", key));
      auto i = static_cast<std::size_t>(
          parseInteger("light index", parts[1], 0, static_cast<long>(mScene.lights.size()) - 1));
      Light& light = mScene.lights[i];
      if (parts[2] == "spd") setLightSpd(light, value);
      else if (parts[2] == "intensity") light.intensity = std::max(0.0f, parseFloat(key, value));
      else if (parts[2] == "direction") {
        glm::vec3 d = parseVec3(key, value);
        if (!(glm::length(d) > 0.0f)) throw Error(fmt::format("{}: expected a non-zero direction", key));
        light.direction = glm::normalize(d);
      } else {
        throw Error(fmt::format("unknown setting \"{}\" (light.N.spd, intensity, direction)", key));
      }
      mSceneChanged = true;
      return;
    }
    if (parts.size() == 3 && parts[0] == "material") {
      auto it = std::find_if(mScene.materials.begin(), mScene.materials.end(),
                             [&](const Material& m) { return m.name == parts[1]; });
      if (it == mScene.materials.end()) throw Error(fmt::format("{}: no material \"{}\"", key, parts[1]));
      if (parts[2] == "base-colour") it->baseColour = glm::clamp(parseVec3(key, value), glm::vec3(0.0f), glm::vec3(1.0f));
      else if (parts[2] == "roughness") it->roughness = std::clamp(parseFloat(key, value), 0.0f, 1.0f);
      else if (parts[2] == "metallic") it->metallic = std::clamp(parseFloat(key, value), 0.0f, 1.0f);
      else throw Error(fmt::format("unknown setting \"{}\" (material.NAME.base-colour, roughness, metallic)", key));
      mSceneChanged = true;
      return;
    }
    throw Error(fmt::format("unknown setting \"{}\" (frame keys of viewer_settings.h, right.KEY, split, heat-map, "
                            "fov, light.N.*, material.NAME.*, water.type, water.depth, sky.*)", key));
  }

  // Parameter changes every 10 frames, a resize every 100, the split toggled every 250; counts
  // taken in the same state before and after. Error when any kind of GL object is not back to
  // its count, or when the heap in use or anonymous resident memory (allocator trimmed) grew by
  // more than maxGrowthMb (when given).
  void soak(int frames, std::optional<double> maxGrowthMb) {
    const ViewSettings start = mView;
    const float startIntensity = mScene.lights.empty() ? 0.0f : mScene.lights[0].intensity;
    const gpu::WindowSize startSize = mWindow.framebufferSize();
    // Both views made before the first count, so that the counts compare like with like.
    mView.split = true;
    mSettingsChanged = true;
    frame();
    mView = start;
    mSettingsChanged = true;
    for (int i = 0; i < 20; ++i) frame();
    gpu::GlObjectCounts objectsBefore = gpu::liveGlObjects();
    const MemoryUse memoryBefore = memoryUse();
    const render::RenderMode modes[] = {render::RenderMode::JakobHanika, render::RenderMode::Rgb,
                                        render::RenderMode::Naive};
    const int counts[] = {4, 8, 16, 12};
    const SamplingStrategy strategies[] = {SamplingStrategy::Uniform, SamplingStrategy::Rotated,
                                           SamplingStrategy::Stratified};
    for (int i = 1; i <= frames; ++i) {
      if (i % 10 == 0) {
        int k = i / 10;
        mView.left.mode = modes[k % 3];
        mView.left.sampling.count = counts[k % 4];
        mView.left.sampling.strategy = strategies[k % 3];
        mView.left.gbufferAlbedo = k % 7 == 0 ? render::GBufferAlbedo::Coefficients : render::GBufferAlbedo::Rgb;
        if (!mScene.lights.empty()) {
          mScene.lights[0].intensity *= k % 2 ? 1.25f : 0.8f;
          mSceneChanged = true;
        }
        mSettingsChanged = true;
      }
      if (i % 100 == 0) resize((i / 100) % 2 ? startSize.width * 3 / 4 : startSize.width, (i / 100) % 2 ? startSize.height * 3 / 4 : startSize.height);
      if (i % 250 == 0) {
        mView.split = !mView.split;
        mView.heatMap = mView.split;
        mSettingsChanged = true;
      }
      frame();
    }
    mView = start;
    if (!mScene.lights.empty()) mScene.lights[0].intensity = startIntensity;
    mSettingsChanged = mSceneChanged = true;
    resize(startSize.width, startSize.height);
    for (int i = 0; i < 20; ++i) frame();
    gpu::GlObjectCounts objectsAfter = gpu::liveGlObjects();
    const MemoryUse memoryAfter = memoryUse();
    fmt::print("soak: {} frames with setting changes every 10, resizes every 100, split toggled every 250\n", frames);
    fmt::print("soak: GL objects {} -> {} ({} -> {})\n", objectsBefore.total(), objectsAfter.total(),
               gpu::describeGlObjects(objectsBefore), gpu::describeGlObjects(objectsAfter));
    fmt::print("soak: heap in use {:.1f} MB -> {:.1f} MB; resident, allocator trimmed: anonymous {:.1f} MB -> "
               "{:.1f} MB, mapped files {:.1f} MB -> {:.1f} MB\n",
               memoryBefore.heap, memoryAfter.heap, memoryBefore.anonymous, memoryAfter.anonymous, memoryBefore.files,
               memoryAfter.files);
    std::fflush(stdout);
    if (!(objectsAfter == objectsBefore)) throw Error("soak: GL objects were left behind (or lost)");
    if (!maxGrowthMb) return;
    if (!(memoryAfter.heap - memoryBefore.heap <= *maxGrowthMb)) {
      throw Error(fmt::format("soak: the heap in use grew by {:.1f} MB (bound {:g} MB)",
                              memoryAfter.heap - memoryBefore.heap, *maxGrowthMb));
    }
    if (!(memoryAfter.anonymous - memoryBefore.anonymous <= *maxGrowthMb)) {
      throw Error(fmt::format("soak: anonymous resident memory grew by {:.1f} MB (bound {:g} MB)",
                              memoryAfter.anonymous - memoryBefore.anonymous, *maxGrowthMb));
    }
  }

  gpu::WindowContext& mWindow;
  Scene& mScene;
  const RgbToSpectrumTable& mTable;
  CameraController mCamera;
  ViewSettings mView;
  ImGuiSession mImGui{mWindow};
  Compositor mCompositor{mScene, mTable};  // goes before ImGui, as the window's GL objects did
  bool mSettingsChanged = false, mCameraChanged = false, mSceneChanged = false;
  std::string mRenderError;  // from the last frame's rendering, shown in red
  std::string mActionError;  // from the last action in the interface, shown until dismissed
  std::vector<std::string> mIlluminants, mObservers;
  float mFlySpeed = 1.0f;
  double mCursorX = 0.0, mCursorY = 0.0;
  std::chrono::steady_clock::time_point mLastFrame = std::chrono::steady_clock::now();
  std::array<float, 120> mFrameMs{};
  std::size_t mFrameCursor = 0;
  std::filesystem::path mPendingScreenshot;
  float mBlackbodyK = 3000.0f, mLedPeakNm = 450.0f, mLedWidthNm = 20.0f;
  std::size_t mMaterial = 0;
  std::vector<std::string> mWaterTypes;  // of the data set mWaterTypesOf
  std::string mWaterTypesOf;
  std::array<char, 512> mCsvPath{}, mScreenshotPath{}, mSettingsPath{};
};

}  // namespace

int runViewer(Scene& scene, const RgbToSpectrumTable& table, const render::FrameSettings& initial,
              const ViewerOptions& options) {
  gpu::WindowDesc desc;
  desc.width = options.width;
  desc.height = options.height;
  desc.title = "Prism — " + scene.file.filename().string();
  desc.vsync = options.script.empty();
  gpu::WindowContext window(desc);
  Viewer viewer(window, scene, table, initial);
  return options.script.empty() ? viewer.interactive() : viewer.scripted(options.script);
}

}  // namespace prism::viewer
