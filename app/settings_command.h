// `prism settings [--KEY VALUE…]`: the frame settings a command line gives, printed by the key
// table (render/setting_keys.h) as `KEY VALUE` lines, the text `set KEY VALUE` and the viewer's
// settings files take. With --keys, the table itself as Markdown (README's table of keys).
#pragma once

#include "app/render_commands.h"

namespace prism::app {

void printSettings(const SettingsOptions& options, bool keys);

}  // namespace prism::app
