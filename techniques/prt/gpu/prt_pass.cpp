#include "techniques/prt/gpu/prt_pass.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <numbers>
#include <span>

#include <fmt/format.h>

#include "core/data_files.h"
#include "core/error.h"
#include "spectral/colour_space.h"
#include "spectral/rgb_intent.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "techniques/prt/gpu/prt_scene_mesh.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/transfer_bake.h"

namespace prism::prt {
namespace {

struct GpuVertex {  // prt.vert's attributes
  glm::vec3 positionW;
  std::uint32_t material;
  glm::vec2 uv;
};
static_assert(sizeof(GpuVertex) == 24);

// An immutable buffer of the values, at least 16 bytes (a zero-sized buffer cannot be bound),
// padded with zeros rather than read past the values' end.
template <class T>
gpu::Buffer bufferOf(std::span<const T> values, const char* label) {
  std::vector<std::byte> bytes(std::max<std::size_t>(values.size_bytes(), 16));
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), values.size_bytes());
  return gpu::Buffer({bytes.size(), bytes.data(), 0, label});
}

const PrtSection& sectionOf(const Scene& scene) {
  const PrtSection* section = scene.techniques.find<PrtSection>();
  PRISM_CHECK(section != nullptr);
  return *section;
}

// The transfer of the scene's PRT objects from the cache, or baked into it.
CachedTransfer sceneTransfer(const Scene& scene, const PrtMesh& mesh, const TechniqueProgress& progress) {
  return cachedTransfer(
      mesh, sceneBakeSettings(scene), cacheDirectory(),
      [&progress](std::size_t done, std::size_t total) { progress("PRT transfer bake", done, total); },
      [](const std::string& note) { fmt::print(stderr, "prism: {}\n", note); });
}

// The medium of the scene's techniques the lighting pass dims surfaces by (the water), as PRT's
// objects take it: σt = σa + σs and Kd (σt where the medium gives none).
std::optional<PrtMedium> sceneMedium(const Scene& scene) {
  std::optional<TechniqueMedium> m = scene.techniques.medium(scene.camera.position);
  if (!m) return std::nullopt;
  Spectrum sigmaT = m->sigmaA + m->sigmaS;
  Spectrum kd = m->downwellingKd ? *m->downwellingKd : sigmaT;
  return PrtMedium{m->regionMin, m->regionMax, std::move(sigmaT), std::move(kd)};
}

}  // namespace

void PrtPass::precompute(const Scene& scene, const TechniqueProgress& progress) {
  PrtSceneMesh bake = prtSceneMesh(scene, PrtMeshes::PrtObjects);
  if (!bake.mesh.indices.empty()) sceneTransfer(scene, bake.mesh, progress);
}

PrtPass::PrtPass() : mData(std::make_shared<PrtDrawData>()) {}

void PrtPass::run(const TechniqueBlock&, const Scene&, const CameraTransform&, const TechniqueFrame&) {}

// Compiled per basis count and per set of the scene's techniques (their shader defines: the
// fragment shader reads what the lighting pass reads of a nebula).
const gpu::Program& PrtPass::program(int basisCount, const Scene& scene) {
  std::vector<gpu::ShaderDefine> defines = {{"PRISM_PRT_BASIS_COUNT", std::to_string(basisCount)}};
  std::string techniques;
  for (const auto& section : scene.techniques.all()) {
    if (section->shaderDefine().empty()) continue;
    defines.push_back({std::string(section->shaderDefine()), "1"});
    techniques += fmt::format(" {}", section->shaderDefine());
  }
  const std::string key = std::to_string(basisCount) + techniques;
  auto it = mPrograms.find(key);
  if (it != mPrograms.end()) return it->second;
  gpu::ProgramDesc desc;
  desc.vertex = shaderDirectory() / "passes" / "prt.vert";
  desc.fragment = shaderDirectory() / "passes" / "prt.frag";
  desc.includeDirs = {shaderDirectory()};
  desc.defines = std::move(defines);
  desc.label = fmt::format("PRT forward pass (m = {}{})", basisCount, techniques);
  return mPrograms.emplace(key, gpu::Program(desc)).first->second;
}

void PrtPass::prepareGeometry(const Scene& scene) {
  PrtDrawData& d = *mData;
  PrtSceneMesh bake = prtSceneMesh(scene, PrtMeshes::PrtObjects);
  std::vector<GpuVertex> vertices;
  d.meshes = bake.meshes;
  d.indices = bake.mesh.indices;
  GLint first = 0;
  for (std::size_t i : d.meshes) {
    const Mesh& mesh = scene.meshes[i];
    auto slot = std::find(d.materials.begin(), d.materials.end(), mesh.material);
    if (slot == d.materials.end()) slot = d.materials.insert(d.materials.end(), mesh.material);
    const int material = static_cast<int>(slot - d.materials.begin());
    for (const Vertex& v : mesh.vertices) {
      d.positionsW.push_back(v.position);
      d.uvs.push_back(v.uv);
      d.vertexMaterial.push_back(material);
      vertices.push_back({v.position, static_cast<std::uint32_t>(material), v.uv});
    }
    // The mesh's indices follow its predecessors' in the bake's order (prt_scene_mesh.h).
    const Material& m = scene.materials.at(static_cast<std::size_t>(mesh.material));
    const int textured = m.spectralTexture || m.baseColourTexture >= 0 ? material : -1;
    const GLsizei count = static_cast<GLsizei>(mesh.indices.size());
    if (!mRanges.empty() && mRanges.back().material == -1 && textured == -1) {
      mRanges.back().count += count;
    } else {
      mRanges.push_back({first, count, textured});
    }
    first += count;
  }
  PRISM_CHECK(static_cast<std::size_t>(first) == d.indices.size());
  if (d.indices.empty()) return;
  // The transfer: from the cache when precompute() or an earlier run baked it; else baked here,
  // with percentages (the commands' progress bars sit above the renderer).
  const auto start = std::chrono::steady_clock::now();
  int lastDecile = -1;
  CachedTransfer cached = sceneTransfer(scene, bake.mesh, [&](std::string_view what, std::size_t done, std::size_t total) {
    int decile = total == 0 ? 10 : static_cast<int>(10 * done / total);
    if (decile != lastDecile) fmt::print(stderr, "\r{} {:3d} %", what, 10 * decile);
    lastDecile = decile;
  });
  if (!cached.fromCache) {
    fmt::print(stderr, "\rPRT transfer bake: {} vertices × {} directions in {:.2f} s → {}\n", bake.mesh.positions.size(),
               sceneBakeSettings(scene).samples,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cached.file.string());
  }
  d.transfer = std::move(cached.transfer);
  mVertices = bufferOf(std::span<const GpuVertex>(vertices), "PRT vertices");
  mIndices = bufferOf(std::span<const std::uint32_t>(d.indices), "PRT indices");
  mTransfer = bufferOf(std::span<const shared::Sh25>(d.transfer), "PRT transfer");
  gpu::VertexArrayDesc vao;
  vao.attributes = {{0, 3, GL_FLOAT, false, false, 0}, {1, 1, GL_UNSIGNED_INT, false, true, 12},
                    {2, 2, GL_FLOAT, false, false, 16}};
  vao.vertices = &mVertices;
  vao.strideBytes = sizeof(GpuVertex);
  vao.indices = &mIndices;
  vao.label = "PRT objects";
  mVertexArray = gpu::VertexArray(vao);
}

void PrtPass::prepareProjections(const ForwardDrawInput& input) {
  const PrtSection& section = sectionOf(input.scene);
  PrtDrawData& d = *mData;
  // What the projections depend on, as text: the section, the observer, the materials.
  // The frame's RGB and reference modes draw PRT's own baselines (technique_pass.h).
  const PrtMode mode = input.frame.rgbMode ? PrtMode::RgbPrt : input.frame.referenceMode ? PrtMode::Reference5nm : section.mode;
  std::string key = fmt::format("{}|{}|{}|{}|{}", environmentKey(section), section.basis, prtModeName(mode),
                                input.observer.name, input.scene.colourSpace);
  for (int m : d.materials) {
    const Material& material = input.scene.materials.at(static_cast<std::size_t>(m));
    double measured = -1.0;  // a fingerprint of a measured reflectance on the grid
    if (material.reflectance) {
      Eigen::VectorXd rho = sampleOnGrid(*material.reflectance);
      measured = rho.dot(Eigen::VectorXd::LinSpaced(rho.size(), 1.0, static_cast<double>(rho.size())));
    }
    key += fmt::format("|{},{},{},{},{},{}", material.baseColour.x, material.baseColour.y, material.baseColour.z, measured,
                       material.baseColourTexture, static_cast<const void*>(material.spectralTexture.get()));
  }
  const bool anyTextured = std::any_of(d.materials.begin(), d.materials.end(), [&](int m) {
    const Material& material = input.scene.materials.at(static_cast<std::size_t>(m));
    return material.spectralTexture || material.baseColourTexture >= 0;
  });
  if (d.medium && mode == PrtMode::Spectral && anyTextured) {  // the basis takes the light as the medium leaves it
    const Eigen::VectorXd ramp = Eigen::VectorXd::LinSpaced(kGridWavelengths, 1.0, kGridWavelengths);
    key += fmt::format("|medium {},{}", sampleOnGrid(d.medium->sigmaT).dot(ramp), sampleOnGrid(d.medium->kd).dot(ramp));
  }
  if (key == mProjectionKey) return;
  std::vector<Spectrum> reflectances;
  std::vector<std::shared_ptr<const PrtTextureSource>> textures;
  for (int m : d.materials) {
    const Material& material = input.scene.materials.at(static_cast<std::size_t>(m));
    std::shared_ptr<const PrtTextureSource> texture;
    if (material.spectralTexture) {
      // The scene's lights (the spectral sky's sun among them) are the lighting pass's, which reads
      // no spectral texture: the loader refuses them, this an edit that adds one.
      if (!input.scene.lights.empty())
        throw Error(fmt::format("{}: /materials/{}: {}", input.scene.file.string(), material.name,
                                kSpectralTextureUnderLights));
      texture = std::make_shared<const PrtTextureSource>(material.spectralTexture);
    } else if (material.baseColourTexture >= 0) {
      const Image& image = input.scene.textures.at(static_cast<std::size_t>(material.baseColourTexture));
      texture = std::make_shared<const PrtTextureSource>(
          PrtRgbTexels{image.width, image.height, image.rgba, image.srgb, material.baseColour}, input.table);
    }
    textures.push_back(texture);
    // A textured material's R̂ comes from its texture; its slot in the projections stays black.
    reflectances.push_back(texture                ? Spectrum::constant(0.0)
                           : material.reflectance ? *material.reflectance
                                                  : RgbAlbedoSpectrum(input.table, material.baseColour).toDense());
  }
  const RgbToSpectrumTable& srgb =
      input.table.gamut() == colourSpace("srgb").name ? input.table : rendererRgbToSpectrumTable("srgb");
  SpectralEnvironment environment = sectionEnvironment(section, srgb);
  // Radiance leaving a Lambertian surface is ρ/π times its irradiance: the 1/π that PRT's sums
  // leave out (prt_evaluation.h's XYZ are irradiance × reflectance), so that Y is luminance.
  const Eigen::MatrixXd grid = environmentOnGrid(environment) / std::numbers::pi;
  std::function<std::vector<PrtProjection>(const std::vector<Spectrum>&)> project;
  int basisCount = 0;
  double energy = 0.0;
  if (mode == PrtMode::Spectral) {
    // The basis of every reflectance of the PRT objects (a texture's: texels on a lattice) and
    // every spectrum of the environment.
    std::vector<Eigen::VectorXd> spectra;
    for (std::size_t i = 0; i < reflectances.size(); ++i) {
      if (!textures[i]) {
        spectra.push_back(sampleOnGrid(reflectances[i]));
      } else {
        for (Eigen::VectorXd& s : textures[i]->representativeSpectra()) spectra.push_back(std::move(s));
      }
    }
    const std::vector<Eigen::VectorXd> light = termSpectra(environment);
    // Textured materials take ρ from R̂'s projection, which needs the light as the medium leaves
    // it in the span; untextured ones take it exact per node and do better without (prt_medium.glsl).
    if (d.medium && anyTextured)
      for (Eigen::VectorXd& s : attenuatedSpectra(light, *d.medium)) spectra.push_back(std::move(s));
    SpectralBasis basis(spectra, {light});
    basisCount = std::min(section.basis, basis.available());
    energy = basis.capturedEnergy(basisCount);
    project = [&grid, &input, phi = basis.leading(basisCount)](const std::vector<Spectrum>& r) {
      return std::vector<PrtProjection>{projectSpectral(r, grid, input.observer, phi)};
    };
  } else if (mode == PrtMode::RgbPrt) {
    basisCount = 3;
    project = [&grid, &input](const std::vector<Spectrum>& r) {
      return std::vector<PrtProjection>{projectRgb(r, grid, input.observer, colourSpace(input.scene.colourSpace))};
    };
  } else {
    project = [&grid, &input](const std::vector<Spectrum>& r) { return projectReference(r, grid, input.observer); };
  }
  std::vector<PrtProjection> projections = project(reflectances);
  std::vector<Eigen::MatrixXd> maps = anyTextured ? gridReflectanceMaps(project) : std::vector<Eigen::MatrixXd>{};
  // Built whole before anything is replaced.
  std::vector<gpu::Buffer> environments, materials, nodeReflectances;
  std::vector<std::vector<gpu::Texture2DArray>> arrays(projections.size());
  for (std::size_t c = 0; c < projections.size(); ++c) {
    const PrtProjection& p = projections[c];
    environments.push_back(bufferOf(std::span<const shared::PrtEnvironment>(&p.environment, 1), "PRT environment"));
    std::vector<shared::PrtGpuMaterial> packed;
    for (const shared::PrtReflectance& r : p.reflectances) packed.push_back(shared::prtGpuMaterial(r));
    materials.push_back(bufferOf(std::span<const shared::PrtGpuMaterial>(packed), "PRT materials"));
    std::vector<glm::vec4> rho;  // material · nodeCount + q
    for (const std::vector<glm::vec3>& perMaterial : p.nodeReflectances)
      for (const glm::vec3& r : perMaterial) rho.emplace_back(r, 0.0f);
    nodeReflectances.push_back(bufferOf(std::span<const glm::vec4>(rho), "PRT node reflectances"));
    arrays[c].resize(textures.size());
    for (std::size_t m = 0; m < textures.size(); ++m) {
      if (!textures[m]) continue;
      const PrtTextureSource& source = *textures[m];
      std::vector<std::uint16_t> layers = PrtTexelProjector(source, maps[c]).layers();
      gpu::Texture2DArrayDesc desc;
      desc.width = source.width();
      desc.height = source.height();
      desc.layers = p.basisCount;
      desc.internalFormat = GL_RGBA16F;
      desc.levels = 0;
      desc.sampling.wrap = GL_REPEAT;
      desc.label = fmt::format("PRT reflectance texture (material {}, projection {})", d.materials[m], c);
      gpu::Texture2DArray& t = arrays[c][m] = gpu::Texture2DArray(desc);
      t.upload({GL_RGBA, GL_HALF_FLOAT, std::as_bytes(std::span<const std::uint16_t>(layers))});
      t.generateMipmaps();
    }
  }
  mEnvironments = std::move(environments);
  mMaterials = std::move(materials);
  mNodeReflectances = std::move(nodeReflectances);
  mTextures = std::move(arrays);
  d.projections = std::move(projections);
  d.textures = std::move(textures);
  d.reflectanceMaps = std::move(maps);
  d.basisCount = basisCount;
  d.capturedEnergy = energy;
  mProjectionKey = std::move(key);
}

// Every frame, since the viewer edits the water: the nodes of each projection (81 at most) are
// cheap to redo, and the buffers are replaced only when they change.
void PrtPass::prepareMediumNodes() {
  PrtDrawData& d = *mData;
  std::vector<std::vector<shared::PrtMediumNode>> nodes;
  for (const PrtProjection& p : d.projections) nodes.push_back(mediumNodes(p, d.medium ? &*d.medium : nullptr));
  const auto same = [](const std::vector<shared::PrtMediumNode>& a, const std::vector<shared::PrtMediumNode>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(shared::PrtMediumNode)) == 0;
  };
  if (nodes.size() == d.mediumNodes.size() && std::equal(nodes.begin(), nodes.end(), d.mediumNodes.begin(), same)) return;
  std::vector<gpu::Buffer> buffers;
  for (const auto& n : nodes) buffers.push_back(bufferOf(std::span<const shared::PrtMediumNode>(n), "PRT medium nodes"));
  mMediumNodes = std::move(buffers);
  d.mediumNodes = std::move(nodes);
}

void PrtPass::drawForward(const ForwardDrawInput& input) {
  if (!mGeometryReady) {
    prepareGeometry(input.scene);
    mGeometryReady = true;
  }
  if (mData->indices.empty()) return;  // no PRT objects
  mData->medium = sceneMedium(input.scene);
  prepareProjections(input);
  prepareMediumNodes();
  const std::optional<PrtMedium>& medium = mData->medium;
  mTransfer.bindBase(GL_SHADER_STORAGE_BUFFER, shared::kPrtTransferBinding);
  for (std::size_t c = 0; c < mData->projections.size(); ++c) {
    const gpu::Program& p = program(mData->projections[c].basisCount, input.scene);
    p.use();
    p.setUniform("uViewProjection", input.camera.viewProjection);
    p.setUniform("uMediumNodeCount", static_cast<GLint>(mData->mediumNodes[c].size()));
    p.setUniform("uMediumBox", GLint{medium ? 1 : 0});
    p.setUniform("uMediumBoxMin", medium ? medium->boxMin : glm::vec3(0.0f));
    p.setUniform("uMediumBoxMax", medium ? medium->boxMax : glm::vec3(0.0f));
    p.setUniform("uCameraPositionW", input.camera.position);
    if (p.hasUniform("uFrameSize"))  // read with a nebula only
      p.setUniform("uFrameSize", glm::vec2(static_cast<float>(input.frame.width), static_cast<float>(input.frame.height)));
    mEnvironments[c].bindBase(GL_SHADER_STORAGE_BUFFER, shared::kPrtEnvironmentBinding);
    mMaterials[c].bindBase(GL_SHADER_STORAGE_BUFFER, shared::kPrtMaterialsBinding);
    mMediumNodes[c].bindBase(GL_SHADER_STORAGE_BUFFER, shared::kPrtMediumNodesBinding);
    mNodeReflectances[c].bindBase(GL_SHADER_STORAGE_BUFFER, shared::kPrtNodeReflectancesBinding);
    for (const DrawRange& range : mRanges) {
      p.setUniform("uTextured", GLint{range.material >= 0 ? 1 : 0});
      if (range.material >= 0) mTextures[c][static_cast<std::size_t>(range.material)].bind(shared::kPrtReflectanceTextureUnit);
      mVertexArray.draw(range.count, range.first);
    }
  }
}

std::size_t PrtPass::gpuMemoryBytes() const {
  std::size_t bytes = mVertices.sizeBytes() + mIndices.sizeBytes() + mTransfer.sizeBytes();
  for (const gpu::Buffer& b : mEnvironments) bytes += b.sizeBytes();
  for (const gpu::Buffer& b : mMaterials) bytes += b.sizeBytes();
  for (const gpu::Buffer& b : mMediumNodes) bytes += b.sizeBytes();
  for (const gpu::Buffer& b : mNodeReflectances) bytes += b.sizeBytes();
  for (const std::vector<gpu::Texture2DArray>& perMaterial : mTextures)
    for (const gpu::Texture2DArray& t : perMaterial) bytes += t.sizeBytes();
  return bytes;
}

}  // namespace prism::prt
