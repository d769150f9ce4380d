// The A/B compositor: the left view and, when split, the right one, each its own renderer of the
// same scene and camera, shown side by side in the window; and the CIEDE2000 heat map of their
// difference (recomputed every 15 frames while shown), which the split panel draws.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "gpu/texture.h"
#include "imaging/image_difference.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "viewer/changes.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {

class Compositor {
 public:
  Compositor(Scene& scene, const RgbToSpectrumTable& table) : mScene(scene), mTable(table) {}

  // Brings each shown view's renderer (made on first use) to its settings, the window size and
  // the changes, and renders it. Errors are not thrown but returned (empty: none): a view that
  // fails keeps its last good settings, the split goes off when the right view cannot be made,
  // the heat map when it cannot be computed.
  std::string render(ViewSettings& view, const Changes& changes, const Camera& camera, int width, int height);
  // Blits the views into the window's framebuffer, the right one over the right half when split.
  void compose(const ViewSettings& view, int width, int height) const;
  // The left view's mean tristimulus as an EXR: XYZ, or camera RGB under a camera's curves.
  void writeLeftExr(const std::filesystem::path& path, const Camera& camera) const;
  void reloadShaders();

  const render::Renderer* left() const { return mLeft.get(); }  // null until the first frame
  // The heat map while shown (a texture with id 0 otherwise) and the statistics it shows.
  const gpu::Texture2D& heatMap() const { return mHeatTexture; }
  const imaging::DifferenceStats& heatMapStats() const { return mHeatStats; }
  // Why the heat map last went off, until one is computed again (empty: it never failed).
  const std::string& heatMapError() const { return mHeatError; }

 private:
  // Changes a view's renderer has yet to take: each view keeps its own, so that one hidden or
  // made later misses nothing.
  struct Pending {
    bool settings = true, camera = true, scene = true;
  };

  void renderView(std::unique_ptr<render::Renderer>& renderer, Pending& pending, render::FrameSettings settings,
                  const Camera& camera, int width, int height);
  void updateHeatMap(const Camera& camera);

  Scene& mScene;
  const RgbToSpectrumTable& mTable;
  // Declared in this order so that they go in the reverse: the heat map, the right view, the left.
  std::unique_ptr<render::Renderer> mLeft, mRight;
  Pending mLeftPending, mRightPending;
  gpu::Texture2D mHeatTexture;
  imaging::DifferenceStats mHeatStats;
  std::string mHeatError;
  int mFramesSinceHeatMap = 1000;
};

}  // namespace prism::viewer
