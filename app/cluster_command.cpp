#include "app/cluster_command.h"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/option_error.h"
#include "batch/slurm_script.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "reference/path_tracer.h"
#include "render/frame_settings.h"
#include "scene/scene_loader.h"
#include "spectral/colour_space.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

namespace prism::app {
namespace {

using batch::shellQuote;

constexpr std::int64_t kMiB = 1024 * 1024;

// What the estimates below add up, measured with /usr/bin/time on `prism reference` (Release):
// 33 MiB resident for a 64×48 image of spheres_d65, 116 MiB at 1024×1024, i.e. ~85 bytes a pixel
// (sums and squares in double, three float images); a part copies its nine planes once more to
// write them (36 bytes) and the EXR encoder holds about as much again. The merge keeps the whole
// image's running means and M2 in double (48 bytes), its three float images (36) and one part.
constexpr std::int64_t kProcessBytes = 64 * kMiB;  // code, tables (a 64³ table is 9 MiB), Embree
constexpr std::int64_t kTaskBytesPerPixel = 160;
constexpr std::int64_t kMergeBytesPerPixel = 200;

// Slurm's --mem: 1.5 × the estimate (allocator slack, OpenEXR's buffers), in whole 64 MiB, at
// least 256 MiB: a task over --mem is killed, one under it wastes only a reservation.
std::int64_t requestMiB(std::int64_t bytes) {
  const std::int64_t withSlack = bytes + bytes / 2;
  return std::max<std::int64_t>(256, (withSlack + 64 * kMiB - 1) / (64 * kMiB) * 64);
}

// A scene's bytes as the path tracer holds them: the mesh twice (Prism's and Embree's with its
// BVH, about the same again) and the textures' texels.
std::int64_t sceneBytes(const Scene& scene) {
  std::int64_t bytes = 0;
  for (const Mesh& mesh : scene.meshes) {
    bytes += 3 * static_cast<std::int64_t>(mesh.vertices.size() * sizeof(Vertex) + mesh.indices.size() * 4);
  }
  for (const Image& texture : scene.textures) bytes += static_cast<std::int64_t>(texture.rgba.size());
  return bytes;
}

std::string prismExecutable() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("prism") : self.string();
}

batch::SlurmScript scriptBase(const ClusterOptions& o, const std::string& name) {
  if (o.tasks < 1) throw Error(fmt::format("--tasks must be at least 1, got {}", o.tasks));
  if (o.cpusPerTask < 1 || o.cpusPerTask > 1024) throw Error(fmt::format("--cpus must be within 1–1024, got {}", o.cpusPerTask));
  batch::checkSlurmTime(o.time, "--time");
  batch::SlurmScript s;
  s.tasks = o.tasks;
  s.sbatchOptions = o.sbatchOptions;
  s.array.name = name;
  s.array.cpusPerTask = o.cpusPerTask;
  s.array.time = o.time;
  s.finish.cpusPerTask = 1;
  s.finish.time = "00:30:00";  // reading parts and writing one image or report: disk speed, not CPU
  return s;
}

// The script of `s`, its folder of parts and logs checked first: the jobs would fail on it after the
// queue (a file where it belongs, no permission).
void printScript(const batch::SlurmScript& s) {
  requireWritableFolder(s.logs);
  fmt::print("{}", batch::slurmScriptText(s));
}

std::string joined(const std::vector<double>& values) {
  std::string text;
  for (double v : values) text += fmt::format("{}{}", text.empty() ? "" : ",", v);
  return text;
}

}  // namespace

void printReferenceClusterScript(const ClusterOptions& o) {
  const ReferenceOptions& r = o.reference;
  checkReferenceOutputs(r.output, r.variance);
  referenceDisplay(r.display, r.output);  // the merge job's, checked here
  if (o.split != "rows" && o.split != "samples") throw Error(fmt::format("--split: expected rows or samples, got \"{}\"", excerpt(o.split)));
  const bool rows = o.split == "rows";
  if (r.ev100) fromOption("--ev", [&] { render::validateEv100(*r.ev100); });
  if (r.threads != 0) throw Error("--threads: each task runs as many threads as its --cpus (SLURM_CPUS_PER_TASK)");
  const Scene scene = loadScene(r.scene, r.sets);  // refused here, not in a hundred tasks
  reference::requireTraceable(scene);
  // The merge job writes them without reading the scene: checked here, as prism reference does.
  requireWritable(r.output);
  requireNotSceneInput(r.output, scene);
  if (!r.variance.empty()) {
    requireWritable(r.variance);
    requireNotSceneInput(r.variance, scene);
  }
  const reference::ReferenceSettings settings = referenceSettings(r);
  const int most = rows ? settings.height : settings.samplesPerPixel;
  if (o.tasks > most) {
    throw Error(fmt::format("--tasks {}: {} {} make at most {} tasks", o.tasks, most,
                            rows ? "rows" : "paths per pixel", most));
  }
  batch::SlurmScript s = scriptBase(o, "prism-reference");
  const std::filesystem::path output = std::filesystem::absolute(r.output);
  s.logs = o.parts.empty() ? std::filesystem::path(output.string() + ".parts") : std::filesystem::absolute(o.parts);
  s.summary = fmt::format("prism reference {} ({}x{}, {} paths per pixel) as {} tasks by {}, then prism merge into {}",
                          r.scene.string(), settings.width, settings.height, settings.samplesPerPixel, o.tasks,
                          o.split, output.string());

  std::string command = shellQuote(prismExecutable()) + " reference " + shellQuote(std::filesystem::absolute(r.scene).string());
  auto add = [&](const std::string& option, const std::string& value) { command += " " + option + " " + shellQuote(value); };
  add("--width", std::to_string(r.width));
  add("--height", std::to_string(r.height));
  add("--spp", std::to_string(r.samplesPerPixel));
  add("--transport", r.transport);
  if (r.maxDepth) add("--max-depth", std::to_string(*r.maxDepth));
  add("--filter", r.filter);
  if (r.camera.empty()) add("--observer", r.observer);
  else add("--camera", r.camera);
  if (!r.range.empty()) add("--range", joined(r.range));
  add("--strategy", r.strategy);
  add("--seed", std::to_string(r.seed));
  if (r.ev100) add("--ev", fmt::format("{}", *r.ev100));
  for (const std::string& set : r.sets) add("--set", set);
  command += " --threads \"$SLURM_CPUS_PER_TASK\"";
  if (rows) {
    command += fmt::format(" --tile \"$SLURM_ARRAY_TASK_ID/{}\"", o.tasks);
  } else {  // task I's share of the paths, ⌊I·spp/N⌋ to ⌊(I+1)·spp/N⌋, as core/task_split.h computes it
    command += fmt::format(" --samples \"$((SLURM_ARRAY_TASK_ID * {0} / {1})):$(((SLURM_ARRAY_TASK_ID + 1) * {0} / {1}))\"",
                           settings.samplesPerPixel, o.tasks);
  }
  const std::string partName = fmt::format("part-{}-of-{}.exr", "$SLURM_ARRAY_TASK_ID", o.tasks);
  command += " -o " + shellQuote(s.logs.string()) + "/\"" + partName + "\"";
  s.array.command = command;

  const std::int64_t pixels = static_cast<std::int64_t>(settings.width) * settings.height;
  const std::int64_t taskPixels = rows ? pixels / o.tasks + settings.width : pixels;  // the tallest band
  s.array.memoryMiB = requestMiB(kProcessBytes + sceneBytes(scene) + taskPixels * kTaskBytesPerPixel);

  s.finish.name = "prism-merge";
  s.finish.memoryMiB = requestMiB(kProcessBytes + pixels * kMergeBytesPerPixel);
  s.finish.command = shellQuote(prismExecutable()) + " merge " + shellQuote(s.logs.string()) +
                     fmt::format("/part-*-of-{}.exr", o.tasks) + " -o " + shellQuote(output.string());
  if (!r.variance.empty()) s.finish.command += " --variance " + shellQuote(std::filesystem::absolute(r.variance).string());
  // As --KEY=VALUE (a value may start with '-'); a lamp's .csv by its absolute path, as every
  // other file here: the merge job runs wherever the script is submitted from.
  for (const auto& [key, value] : r.display.values) {
    const bool file = key == "white-balance" && std::filesystem::is_regular_file(value);
    s.finish.command += " " + shellQuote("--" + key + "=" + (file ? std::filesystem::absolute(value).string() : value));
  }
  printScript(s);
}

void printValidateClusterScript(const ClusterOptions& o) {
  const harness::ValidateOptions& v = o.validate;
  const int experiments = harness::validateExperimentCount(v.only);
  if (o.tasks > experiments) throw Error(fmt::format("--tasks {}: at most {} tasks, one per experiment", o.tasks, experiments));
  if (!v.scenes.empty() && !std::filesystem::is_directory(v.scenes))
    throw Error(fmt::format("--scenes {}: no such folder", v.scenes.string()));
  requireWritableFolder(v.output);
  batch::SlurmScript s = scriptBase(o, "prism-validate");
  const std::filesystem::path output = std::filesystem::absolute(v.output);
  s.logs = output / "parts";
  s.summary = fmt::format("prism validate{}{} as {} tasks, then prism validate --collect into {}", v.quick ? " --quick" : "",
                          v.only.empty() ? "" : fmt::format(" --only {}", fmt::join(v.only, ",")), o.tasks, output.string());
  std::string common = v.quick ? " --quick" : "";
  common += " -o " + shellQuote(output.string());
  if (!v.scenes.empty()) common += " --scenes " + shellQuote(std::filesystem::absolute(v.scenes).string());
  if (!v.only.empty()) common += " --only " + shellQuote(fmt::format("{}", fmt::join(v.only, ",")));
  // The rasteriser runs on the GPU (EGL; Mesa's llvmpipe on a node without one, whose threads
  // follow the CPUs Slurm gives: LP_NUM_THREADS), the path tracer and the bakes on --threads.
  s.array.command = "env LP_NUM_THREADS=\"$SLURM_CPUS_PER_TASK\" " + shellQuote(prismExecutable()) +
                    fmt::format(" validate --task \"$SLURM_ARRAY_TASK_ID/{}\" --threads \"$SLURM_CPUS_PER_TASK\"", o.tasks) +
                    common;
  // Measured peaks (/usr/bin/time): 183 MiB for a --quick task of two experiments, 185 and 189 MiB
  // for full-size tasks of one sphere scene and one reef depth: the renderer's, not the images'.
  s.array.memoryMiB = 512;
  s.finish.name = "prism-validate-collect";
  s.finish.memoryMiB = 256;
  // Its own split's parts: an earlier sweep into the same folder with another task count left its.
  s.finish.command = shellQuote(prismExecutable()) + fmt::format(" validate --collect --tasks {}", o.tasks) + common;
  printScript(s);
}

void printLutClusterScript(const ClusterOptions& o) {
  const LutOptions& l = o.lut;
  const std::string gamut = colourSpace(l.gamut).name;
  fromOption("--res", [&] { requireBuildableResolution(l.resolution); });
  if (o.tasks > tableColumns(l.resolution)) {
    throw Error(fmt::format("--tasks {}: the {}³ table has {} columns, at most {} tasks", o.tasks, l.resolution,
                            tableColumns(l.resolution), tableColumns(l.resolution)));
  }
  if (l.output.empty()) throw Error("lut: give the output file with -o");
  refuseImageExtension(l.output, "-o", "upsampling table");  // as prism lut and prism merge refuse it
  requireWritable(l.output);
  batch::SlurmScript s = scriptBase(o, "prism-lut");
  const std::filesystem::path output = std::filesystem::absolute(l.output);
  s.logs = output.string() + ".parts";
  s.summary = fmt::format("prism lut --gamut {} --res {} as {} tasks by columns, then prism merge into {}", gamut,
                          l.resolution, o.tasks, output.string());
  s.array.command = shellQuote(prismExecutable()) +
                    fmt::format(" lut --gamut {} --res {} --part \"$SLURM_ARRAY_TASK_ID/{}\" --threads \"$SLURM_CPUS_PER_TASK\"",
                                shellQuote(gamut), l.resolution, o.tasks) +
                    " -o " + shellQuote(s.logs.string()) + fmt::format("/\"part-$SLURM_ARRAY_TASK_ID-of-{}.prismlut\"", o.tasks);
  // A task holds the whole table (n³ × 9 floats) and its part; the merge the parts and the table.
  const std::int64_t tableBytes = std::int64_t{l.resolution} * l.resolution * l.resolution * 9 * 4;
  s.array.memoryMiB = requestMiB(kProcessBytes + 2 * tableBytes);
  s.finish.name = "prism-lut-merge";
  s.finish.memoryMiB = requestMiB(kProcessBytes + 3 * tableBytes);
  s.finish.command = shellQuote(prismExecutable()) + " merge " + shellQuote(s.logs.string()) +
                     fmt::format("/part-*-of-{}.prismlut", o.tasks) + " -o " + shellQuote(output.string());
  printScript(s);
}

void printPrtClusterScript(const ClusterOptions& o) {
  const PrtBakeOptions& p = o.prt;
  const PrtBakeTarget target = prtBakeTarget(p);  // the model is read here, not in a hundred tasks
  const auto vertices = static_cast<std::int64_t>(target.mesh.positions.size());
  if (o.tasks > vertices) throw Error(fmt::format("--tasks {}: {} has {} vertices, at most {} tasks", o.tasks, p.input, vertices, vertices));
  batch::SlurmScript s = scriptBase(o, "prism-prt-bake");
  const std::filesystem::path cacheFile = std::filesystem::absolute(target.cacheFile);
  requireWritableFolder(cacheFile.parent_path());  // --cache, or the default cache's folder
  s.logs = cacheFile.string() + ".parts";
  s.summary = fmt::format("prism prt bake {} ({} vertices, {} directions each{}) as {} tasks by vertices, then prism "
                          "merge into {}",
                          p.input, vertices, target.settings.samples, target.settings.shadows ? "" : ", unshadowed",
                          o.tasks, cacheFile.string());
  s.array.command = shellQuote(prismExecutable()) + " prt bake " +
                    shellQuote(std::filesystem::absolute(p.input).string()) +
                    fmt::format(" --samples {}", target.settings.samples) + (target.settings.shadows ? "" : " --no-shadows") +
                    fmt::format(" --part \"$SLURM_ARRAY_TASK_ID/{}\" --threads \"$SLURM_CPUS_PER_TASK\"", o.tasks) +
                    " -o " + shellQuote(s.logs.string()) + fmt::format("/\"part-$SLURM_ARRAY_TASK_ID-of-{}.prtpart\"", o.tasks);
  // A task holds the scene as loaded, the mesh (positions, normals, indices) and Embree's copy
  // with its BVH (about three times the triangles' bytes), and its share of the transfer (100
  // bytes a vertex); the merge every part and the whole transfer.
  const auto meshBytes = static_cast<std::int64_t>(target.mesh.positions.size() * 24 + target.mesh.indices.size() * 4);
  s.array.memoryMiB = requestMiB(kProcessBytes + 4 * meshBytes + vertices * 100 / o.tasks + 100);
  s.finish.name = "prism-prt-merge";
  s.finish.memoryMiB = requestMiB(kProcessBytes + 3 * vertices * 100);
  s.finish.command = shellQuote(prismExecutable()) + " merge " + shellQuote(s.logs.string()) +
                     fmt::format("/part-*-of-{}.prtpart", o.tasks) + " -o " + shellQuote(cacheFile.string());
  printScript(s);
}

}  // namespace prism::app
