// `prism view`: the interactive viewer. A GLFW window (GL 4.5 core) with a Dear ImGui interface
// (Debian's libimgui-dev) over the renderer: camera controls, every spectral setting live, the
// observer's curves and the lights' SPDs with the frame's wavelengths marked, lights, materials
// and water edited in place, an A/B split of two modes with a CIEDE2000 heat map, screenshots,
// settings files, and hot reload of the shaders (errors shown, never a crash).
//
// A script (`--script FILE`) drives the same viewer without a person, one command a line:
//   set KEY VALUE        a frame key of viewer_settings.h for the left (or only) view,
//                        right.KEY for the right one, or: split on|off, heat-map on|off, fov DEG,
//                        light.N.spd NAME, light.N.intensity X, light.N.direction X,Y,Z,
//                        light.N.position X,Y,Z (point, spot), light.N.shadows on|off,
//                        material.NAME.base-colour R,G,B, material.NAME.roughness X,
//                        material.NAME.metallic X, water.type T, water.depth M, sky.*,
//                        prt.mode M, prt.basis N, prt.illuminant NAME, prt.rotation DEG, nebula.*
//   frames N             render N frames (the window shows them)
//   resize W H           resize the window
//   orbit YAW PITCH      degrees
//   screenshot FILE      .png: the window as shown (UI included); .exr: the left view's tristimulus
//   save-settings FILE / load-settings FILE
//   reload-shaders
//   soak N [MB]          N frames that change settings every 10 frames, resize every 100 and
//                        toggle the split every 250, then print the live GL objects, the heap in
//                        use and resident memory (allocator trimmed) before and after; fails when
//                        a kind of GL object is not back to its count, or the heap or anonymous
//                        resident memory grew by more than MB
//   heat-map-stats       print the split view's CIEDE2000 mean, p95 and max (heat map on)
// `#` starts a comment; "…" keeps spaces in one word (set light.0.spd "nist:Cool White FL"). The
// whole script is checked first (commands, argument counts, counts and angles); a bad command is
// one line "FILE:LINE: what" and exit 1, before any frame when the check finds it.
#pragma once

#include <filesystem>
#include <optional>

#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "viewer/script.h"

namespace prism::viewer {

// A window's side in pixels, at start (--width, --height) and in a script's `resize`.
inline constexpr int kMinWindowSide = 16;
inline constexpr int kMaxWindowSide = 8192;

struct ViewerOptions {
  int width = 1280;  // kMinWindowSide..kMaxWindowSide
  int height = 720;
  std::optional<Script> script;  // run it, then close (loaded and checked before the window opens)
};

// The scene is edited in place; the table is the scene colour space's. Returns the exit code.
int runViewer(Scene& scene, const RgbToSpectrumTable& table, const render::FrameSettings& initial,
              const ViewerOptions& options);

}  // namespace prism::viewer
