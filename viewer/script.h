// The script runner: `prism view --script FILE` (the language is in viewer.h). The whole file is
// read and checked before anything renders, so that a typo on the last line does not cost the
// work before it; then each command runs against the viewer in order, and the first that fails
// prints "prism: error: FILE:LINE: what" and ends the run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "viewer/camera_controller.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {

class Viewer;

struct ScriptLine {
  int line = 0;
  std::vector<std::string> words;  // the command, then its arguments
};

struct Script {
  std::filesystem::path path;
  std::vector<ScriptLine> lines;
};

// Reads and checks a script: Error "FILE: …" when it cannot be read (a folder, a missing file, a
// device), "FILE:LINE: …" for an unknown command, a wrong number of arguments, a count or angle
// that is not a number in its range, a screenshot that is not .png or .exr, `set width` (the window
// has the views' size: `resize`), or an unterminated quote. Words are separated by spaces; "…" keeps
// spaces inside one (set light.0.spd "nist:Cool White FL"); # outside quotes starts a comment.
Script loadScript(const std::filesystem::path& path);

// The script run on copies of the viewer's state, before anything renders, so that a bad line
// fails before the lines above it have written their files: every `set`, `orbit` and
// `load-settings` (keys, values, the scene's lights and materials, settings files; one the script
// saved is taken as saved; a pipe is left to the run), and every file it writes (writable, and
// none the script or a file the scene reads). Not rehearsed: what rendering finds (`frames`'
// errors, `heat-map-stats` without a heat map). Error "FILE:LINE: what" for the first line that
// would fail.
void rehearseScript(const Script& script, ViewSettings view, CameraController camera, Scene scene);

// The exit code: 0, or 1 after a failing command (the rehearsal's included).
int runScript(Viewer& viewer, const Script& script);

}  // namespace prism::viewer
