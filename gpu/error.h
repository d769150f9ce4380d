// The one exception type of the GPU layer (STYLE.md §10: user and environment errors, as opposed
// to programmer errors). what() is a single line a CLI can print as is: "FILE:LINE:COL: error:
// …" for shader errors (mapped back to the original #included file), or a sentence naming what
// to install for ContextUnavailable. id() is the stable diagnostic tests assert on; log() holds
// the full driver log, every line mapped to original files, where there is one.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "gpu/diagnostics.h"

namespace prism::gpu {

class GpuError : public std::runtime_error {
 public:
  GpuError(Diagnostic id, const std::string& message, std::string log = {})
      : std::runtime_error(message), mId(id), mLog(std::move(log)) {}

  Diagnostic id() const { return mId; }
  const std::string& log() const { return mLog; }

 private:
  Diagnostic mId;
  std::string mLog;
};

}  // namespace prism::gpu
