#include "app/nebula_command_line.h"

#include <filesystem>
#include <memory>
#include <string>

#include "app/nebula_commands.h"
#include "app/option_lists.h"
#include "core/error.h"
#include "core/parallel_for.h"

namespace prism::app {
namespace {

// What the subcommands' options fill, alive as long as the callbacks that read it.
struct NebulaCommandOptions {
  NebulaBasisOptions basis;
  NebulaSweepOptions sweep;
  NebulaRenderOptions render;
  std::string domain;
  std::filesystem::path densityScene, densityOut;
  NebulaBenchOptions bench;
};

}  // namespace

void addNebulaCommands(CLI::App& app) {
  auto o = std::make_shared<NebulaCommandOptions>();
  auto* nebulaCmd = app.add_subcommand("nebula", "spectral nebulae (Barrès 2023): the greedy basis, renders (CPU, or --gpu), the GPU bench");
  nebulaCmd->require_subcommand(1);
  auto* nebBasisCmd = nebulaCmd->add_subcommand("basis", "the greedy exp(-a/λ) basis and its worst projection error per element");
  nebBasisCmd->add_option("--domain", o->domain, "LO,HI µm of λ (default 0.38,0.78; the paper's: 0,1)");
  nebBasisCmd->add_option("--max-depth", o->basis.maxDepthUm, "the family e^(-g/λ): g up to this (µm)")->capture_default_str();
  nebBasisCmd->add_option("--max-exponent", o->basis.maxExponentUm, "candidates a up to this (µm)")->capture_default_str();
  nebBasisCmd->add_option("--spacing", o->basis.spacingUm, "minimum spacing of the exponents (µm; 0: free)")->capture_default_str();
  nebBasisCmd->add_option("--count", o->basis.count, "elements (1..8)")->capture_default_str();
  nebBasisCmd->add_flag("--json", o->basis.json, "JSON output");
  nebBasisCmd->add_option("--plot", o->basis.plotFile, "SVG of the error after each element to write");
  auto* nebSweepCmd = nebulaCmd->add_subcommand("sweep", "projection's error against the basis size (CPU, against the reference)");
  nebSweepCmd->add_option("scene", o->sweep.scene, "nebula scene file")->required();
  nebSweepCmd->add_option("--filters", o->sweep.filters, "hubble or cie1931 (default: the scene's)");
  nebSweepCmd->add_option("--steps", o->sweep.steps, "ray steps (default: the scene's)");
  nebSweepCmd->add_option("--max-basis", o->sweep.maxBasis, "largest basis (1..6)")->capture_default_str();
  nebSweepCmd->add_option("--basis-depth", o->sweep.basisDepthUm,
                          "the optical depth (µm) the basis is fitted up to (within (0, 16], default 2)");
  nebSweepCmd->add_option("--size", o->sweep.size, "the camera's longer side in pixels (default: the scene's)");
  nebSweepCmd->add_flag("--no-lines", o->sweep.noLines, "leave out the emission lines");
  nebSweepCmd->add_flag("--json", o->sweep.json, "JSON output");
  nebSweepCmd->add_option("--plot", o->sweep.plotFile, "SVG of the error against the basis size to write");
  nebSweepCmd->add_option("--threads", o->sweep.threads, "threads (0: all)")->check(CLI::Range(0u, kMaxThreads));
  auto* nebRenderCmd = nebulaCmd->add_subcommand("render", "march a nebula scene (CPU, or --gpu) to an EXR (linear) or PNG");
  nebRenderCmd->add_option("scene", o->render.scene, "nebula scene file (JSON with a 'nebula' section)")->required();
  nebRenderCmd->add_option("-o,--output", o->render.output, "OUT.exr or OUT.png")->required();
  nebRenderCmd->add_option("--method", o->render.method, "reference, analytic, projection, light-density or pre-integration")->capture_default_str();
  nebRenderCmd->add_option("--steps", o->render.steps, "ray steps (default: the scene's)");
  nebRenderCmd->add_option("--size", o->render.size, "the camera's longer side in pixels (default: the scene's)");
  nebRenderCmd->add_option("--filters", o->render.filters, "hubble or cie1931 (default: the scene's)");
  nebRenderCmd->add_option("--basis", o->render.basisSize,
                           "projection, light-density: elements of the exp(-a/λ) basis (1..6, default 4; more: more accurate, a moment more per pixel and star)");
  nebRenderCmd->add_option("--basis-depth", o->render.basisDepthUm,
                           "projection, light-density: the optical depth (µm) the basis is fitted up to (within (0, 16], default 2)");
  nebRenderCmd->add_option("--light-basis", o->render.lightBasisSize, "light-density: elements of the 2D light basis (1..16, default 8)");
  nebRenderCmd->add_option("--reference-intervals", o->render.referenceIntervals,
                           "reference, --compare: Simpson intervals per filter piece (even, default 16)");
  nebRenderCmd->add_option("--uniform-samples", o->render.uniformSamples, "reference: that many λ per channel instead (trapezoid)");
  nebRenderCmd->add_flag("--compare", o->render.compare, "also render the reference; print the max relative error");
  nebRenderCmd->add_flag("--no-lines", o->render.noLines, "leave out the emission lines");
  nebRenderCmd->add_flag("--gpu", o->render.gpu, "march on the GPU (any method; headless EGL)");
  nebRenderCmd->add_option("--threads", o->render.threads, "threads (0: all)")->check(CLI::Range(0u, kMaxThreads));
  auto* nebBenchCmd = nebulaCmd->add_subcommand("bench", "time the GPU marcher against the CPU's, 1, 6 and 32 stars");
  nebBenchCmd->add_option("--repeats", o->bench.repeats, "timed runs per cell (the median is printed)")->capture_default_str();
  nebBenchCmd->add_option("--size", o->bench.size, "pixels a side (a GPU's march needs more than the default to show)")
      ->capture_default_str();
  nebBenchCmd->add_flag_callback("--no-cpu", [o] { o->bench.cpu = false; }, "leave out the CPU's columns");
  auto* nebDensityCmd = nebulaCmd->add_subcommand("density", "write a scene's density grid as a prism-density file");
  nebDensityCmd->add_option("scene", o->densityScene, "nebula scene file, or a renderer scene with a 'nebula' section")->required();
  nebDensityCmd->add_option("-o,--output", o->densityOut, "OUT.density")->required();

  nebBasisCmd->callback([o] {
    if (!o->domain.empty()) {
      auto d = parseNumbers(o->domain, "--domain");
      if (d.size() != 2) throw Error("--domain: expected LO,HI");
      o->basis.lambda0Um = d[0], o->basis.lambda1Um = d[1];
    }
    runNebulaBasis(o->basis);
  });
  nebSweepCmd->callback([o] { runNebulaSweep(o->sweep); });
  nebRenderCmd->callback([o] { runNebulaRender(o->render); });
  nebBenchCmd->callback([o] { runNebulaBench(o->bench); });
  nebDensityCmd->callback([o] { runNebulaDensity(o->densityScene, o->densityOut); });
}

}  // namespace prism::app
