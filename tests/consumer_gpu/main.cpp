// Runs pcgHash(0) from the installed shaders through an installed prism::gpu and prints it.
#include <cstdio>

#include "gpu/buffer.h"
#include "gpu/compute.h"
#include "gpu/error.h"
#include "gpu/headless_context.h"
#include "gpu/program.h"

int main() {
  try {
    prism::gpu::HeadlessContext context;
    prism::gpu::Program program(
        {.compute = KERNEL, .includeDirs = {std::filesystem::path(SHADER_DIR) / "shared"}});
    prism::gpu::Buffer result({.sizeBytes = 4});
    result.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    prism::gpu::runCompute(program, {});
    std::printf("pcgHash(0) = %u\n", result.read<GLuint>()[0]);
    return 0;
  } catch (const prism::gpu::GpuError& e) {
    std::fprintf(stderr, "gpu_consumer: %s\n", e.what());
    return 1;
  }
}
