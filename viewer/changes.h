// What the renderers have yet to take from the viewer's edits: the panels and the script set
// these, and the compositor hands them to each view's renderer once a frame.
#pragma once

namespace prism::viewer {

struct Changes {
  bool settings = false;  // the frame settings of either view
  bool camera = false;
  bool scene = false;  // lights, materials, water, sky: edited in place in the Scene
};

}  // namespace prism::viewer
