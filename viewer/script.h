// The script runner: `prism view --script FILE` (the language is in viewer.h). Reads the whole
// file first, renders a first frame, then runs each command against the viewer in order; the
// first that fails prints "prism: error: FILE:LINE: what" and ends the run.
#pragma once

#include <filesystem>

#include "viewer/viewer_loop.h"

namespace prism::viewer {

// The exit code: 0, or 1 after a failing command. Error when the file cannot be read.
int runScript(Viewer& viewer, const std::filesystem::path& path);

}  // namespace prism::viewer
