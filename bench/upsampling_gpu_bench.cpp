// GPU cost per pixel of the two upsampling lookups (shaders/common_upsampling.glsl) on the
// 64³ sRGB table: 1920×1080 lookups per dispatch, timed with GL_TIME_ELAPSED queries on a GPU
// and with the wall clock around a finished dispatch on llvmpipe (whose timer queries do not
// measure its worker threads' execution).
// A fixed count of dispatches keeps a slow software rasteriser bounded. Skipped with a message
// where no OpenGL 4.5 context can be made.
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

#include "gpu/buffer.h"
#include "gpu/compute.h"
#include "gpu/error.h"
#include "gpu/headless_context.h"
#include "gpu/program.h"
#include "render/upsampling_texture.h"
#include "core/data_files.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism {
namespace {

constexpr GLuint kPixels = 1920 * 1080;

template <bool kFiltered>
void upsamplingGpuLookup(benchmark::State& state) {
  // Any setup failure (no context, shaders not found, …) skips this benchmark, not prism bench.
  std::unique_ptr<gpu::HeadlessContext> context;
  std::unique_ptr<gpu::Texture3D> texture;
  std::unique_ptr<gpu::Program> program;
  std::unique_ptr<gpu::Buffer> sink;
  try {
    gpu::ContextDesc contextDesc;
    contextDesc.debugContext = false;  // time what a release build runs, without validation
    context = std::make_unique<gpu::HeadlessContext>(contextDesc);
    texture = std::make_unique<gpu::Texture3D>(render::uploadUpsamplingTable(rendererRgbToSpectrumTable("srgb")));
    gpu::ProgramDesc desc;
    desc.compute = shaderDirectory() / "bench" / "upsampling_cost.comp";
    desc.includeDirs = {shaderDirectory() / "shared", shaderDirectory()};
    if (kFiltered) desc.defines = {{"UPSAMPLING_FILTERED", ""}};
    program = std::make_unique<gpu::Program>(desc);
    sink = std::make_unique<gpu::Buffer>(
        gpu::BufferDesc{kPixels * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT, "sink"});
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  sink->bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  texture->bind(0);
  program->use();
  program->setUniform("resolution", GLint{64});
  program->setUniform("count", kPixels);
  gpu::runCompute1D(*program, kPixels);  // warm-up: llvmpipe compiles at first dispatch
  glFinish();
  const bool software = context->renderer().find("llvmpipe") != std::string::npos;
  GLuint query = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &query);
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query);
    gpu::runCompute1D(*program, kPixels);
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
    glFinish();
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(software ? wall : static_cast<double>(ns) * 1e-9);
  }
  glDeleteQueries(1, &query);
  state.SetItemsProcessed(state.iterations() * kPixels);
  state.SetLabel(context->renderer());
}
void upsamplingGpuManual(benchmark::State& state) { upsamplingGpuLookup<false>(state); }
void upsamplingGpuFiltered(benchmark::State& state) { upsamplingGpuLookup<true>(state); }
BENCHMARK(upsamplingGpuManual)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);
BENCHMARK(upsamplingGpuFiltered)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace
}  // namespace prism
