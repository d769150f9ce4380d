// The transfer bake: against Ramamoorthi & Hanrahan's closed form on a convex object, its
// self-shadowing, its determinism, and its cache.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/worst_of.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/sh_tools.h"
#include "techniques/prt/transfer_bake.h"

namespace prism::prt {
namespace {

// A unit icosphere (icosahedron subdivided `levels` times): convex, vertex normals radial.
PrtMesh icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::vec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::vec3& v : p) v = glm::normalize(v);
  std::vector<std::uint32_t> f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                                  11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                                  3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(glm::normalize(p[a] + p[b]));
      return mid[key] = static_cast<std::uint32_t>(p.size() - 1);
    };
    std::vector<std::uint32_t> g;
    for (std::size_t i = 0; i < f.size(); i += 3) {
      std::uint32_t a = f[i], b = f[i + 1], c = f[i + 2], ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = g;
  }
  return {p, p, f};
}

double legendre(int l, double x) {
  switch (l) {
    case 0: return 1.0;
    case 1: return x;
    case 2: return 0.5 * (3 * x * x - 1);
    case 3: return 0.5 * (5 * x * x * x - 3 * x);
    default: return (35 * x * x * x * x - 30 * x * x + 3) / 8.0;
  }
}

TEST(TransferBake, ConvexObjectMatchesRamamoorthiHanrahanWithinOnePercent) {
  // L(ω) = Σ_l a_l P_l(ω·d): by Funk–Hecke the irradiance at normal n is Σ_l Â_l a_l P_l(n·d),
  // Â = π, 2π/3, π/4, 0, −π/24 — typed here from the paper, not from the shared header. The
  // environment is projected on SH-5 (exact: degree ≤ 4), the transfer baked with Embree rays on
  // a convex icosphere (no ray may hit it) and 1024 directions; bound 1 % (the issue's).
  const double a[5] = {1.0, 0.5, 0.3, 0.2, 0.2};
  const double hat[5] = {std::numbers::pi, 2 * std::numbers::pi / 3, std::numbers::pi / 4, 0.0, -std::numbers::pi / 24};
  glm::dvec3 d = glm::normalize(glm::dvec3(0.3, 0.4, 0.85));
  ShVector env = projectOnSh([&](const glm::dvec3& w) {
    double s = 0.0;
    for (int l = 0; l < 5; ++l) s += a[l] * legendre(l, glm::dot(w, d));
    return s;
  }, 12, 24);
  PrtMesh mesh = icosphere(3);
  std::vector<shared::Sh25> shadowed = bakeTransfer(mesh, {1024, true});
  std::vector<shared::Sh25> open = bakeTransfer(mesh, {1024, false});
  shared::Sh25 l = toSh25(env);
  double worst = 0.0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    double x = glm::dot(glm::dvec3(mesh.normals[v]), d), exact = 0.0;
    for (int b = 0; b < 5; ++b) exact += hat[b] * a[b] * legendre(b, x);
    double baked = shared::shDot(l, shadowed[v]);
    worst = worstOf(worst, std::abs(baked / exact - 1.0));
    for (int k = 0; k < 25; ++k) ASSERT_EQ(shadowed[v].c[k], open[v].c[k]) << "a ray hit the convex object";
  }
  std::printf("convex icosphere, %zu vertices, 1024 directions: worst relative irradiance error %.3g %%\n",
              mesh.positions.size(), 100 * worst);
  EXPECT_LT(worst, 0.01);
}

TEST(TransferBake, SelfShadowingOnlyRemovesLight) {
  // V ≤ 1 and Y_00 > 0: the shadowed DC term is at most the unshadowed one, and strictly less at
  // the feet of the colour checker's bumps.
  PrtObject object = makeColourCheckerObject(6);
  auto shadowed = bakeTransfer(object.mesh, {256, true});
  auto open = bakeTransfer(object.mesh, {256, false});
  int darker = 0;
  for (std::size_t v = 0; v < shadowed.size(); ++v) {
    EXPECT_LE(shadowed[v].c[0], open[v].c[0] + 1e-6f);
    if (shadowed[v].c[0] < 0.95f * open[v].c[0]) ++darker;
  }
  EXPECT_GT(darker, static_cast<int>(shadowed.size() / 10));
}

TEST(TransferBake, IsIndependentOfTheThreadCount) {
  PrtObject object = makeColourCheckerObject(4);
  auto one = bakeTransfer(object.mesh, {64, true}, {}, 1);
  auto two = bakeTransfer(object.mesh, {64, true}, {}, 2);
  for (std::size_t v = 0; v < one.size(); ++v)
    for (int k = 0; k < 25; ++k) ASSERT_EQ(one[v].c[k], two[v].c[k]);
}

TEST(TransferBake, RefusesBadMeshesAndSettings) {
  PrtMesh mesh = icosphere(0);
  EXPECT_THROW(bakeTransfer(mesh, {0, true}), Error);
  PrtMesh broken = mesh;
  broken.indices[4] = 99;
  EXPECT_THROW(bakeTransfer(broken, {16, true}), Error);
  broken = mesh;
  broken.normals.pop_back();
  EXPECT_THROW(bakeTransfer(broken, {16, true}), Error);
}

TEST(TransferCache, RoundTripsAndRebuildsADamagedFile) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "prt_cache_test";
  std::filesystem::remove_all(dir);
  PrtMesh mesh = icosphere(1);
  BakeSettings settings{32, true};
  std::vector<std::string> notes;
  auto note = [&notes](const std::string& s) { notes.push_back(s); };
  CachedTransfer first = cachedTransfer(mesh, settings, dir, {}, note);
  EXPECT_FALSE(first.fromCache);
  CachedTransfer second = cachedTransfer(mesh, settings, dir, {}, note);
  EXPECT_TRUE(second.fromCache);
  EXPECT_TRUE(notes.empty());
  for (std::size_t v = 0; v < first.transfer.size(); ++v)
    for (int k = 0; k < 25; ++k) ASSERT_EQ(first.transfer[v].c[k], second.transfer[v].c[k]);

  {  // flip one coefficient's byte
    std::fstream f(first.file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('\x7f');
  }
  EXPECT_THROW(
      {
        try {
          readTransferFile(first.file, transferKey(mesh, settings));
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
          throw;
        }
      },
      Error);
  CachedTransfer third = cachedTransfer(mesh, settings, dir, {}, note);
  EXPECT_FALSE(third.fromCache);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("rebuilding"), std::string::npos) << notes[0];
  EXPECT_NO_THROW(readTransferFile(first.file, transferKey(mesh, settings)));
  // Another mesh's key, a truncated file: refused.
  EXPECT_THROW(readTransferFile(first.file, transferKey(mesh, {64, true})), Error);
  std::filesystem::resize_file(first.file, 40);
  EXPECT_THROW(readTransferFile(first.file, transferKey(mesh, settings)), Error);
}

// A cache that cannot be written is said before the bake (it used to fail once the bake was done).
TEST(TransferCache, AnUnwritableCacheIsRefusedBeforeTheBake) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "prt_cache_unwritable";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "prt") << "a file where the cache's folder goes";
  bool baked = false;
  EXPECT_THROW(cachedTransfer(icosphere(1), {8, true}, dir, [&baked](std::size_t, std::size_t) { baked = true; }), Error);
  EXPECT_FALSE(baked);
  // A folder where the entry goes is said once, before the bake: it was noted "rebuilding", then
  // refused as "is a folder" when the bake was done.
  std::filesystem::remove(dir / "prt");
  std::filesystem::create_directories(transferCacheFile(dir, transferKey(icosphere(1), {8, true})));
  std::vector<std::string> notes;
  try {
    cachedTransfer(icosphere(1), {8, true}, dir, [&baked](std::size_t, std::size_t) { baked = true; },
                   [&notes](const std::string& s) { notes.push_back(s); });
    ADD_FAILURE() << "a folder at the entry was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(": is a folder where the cache keeps a PRT transfer; remove it"),
              std::string::npos) << e.what();
  }
  EXPECT_FALSE(baked);
  EXPECT_TRUE(notes.empty());
}

// Bakes of edited meshes piled up in the cache for good: it keeps the newest within its bound, and
// nothing of the user's in a folder of their choosing (--cache DIR).
TEST(TransferCache, TheCacheKeepsItsNewestEntries) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "prt_cache_bounded";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "prt");
  const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  auto entry = [&](int i) {
    std::ostringstream name;
    name << "transfer-" << std::hex << std::setw(16) << std::setfill('0') << i << ".bin";
    return dir / "prt" / name.str();
  };
  for (int i = 0; i < 300; ++i) {
    std::ofstream(entry(i)) << "an old entry";
    std::filesystem::last_write_time(entry(i), old + std::chrono::seconds(i));
  }
  std::ofstream(dir / "prt" / "mine.bin") << "the user's";
  std::filesystem::last_write_time(dir / "prt" / "mine.bin", old);
  const CachedTransfer made = cachedTransfer(icosphere(1), {8, true}, dir);
  std::size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "prt")) entries += e.path().extension() == ".bin";
  EXPECT_EQ(entries, 257u);  // 256 and the user's
  EXPECT_TRUE(std::filesystem::exists(made.file));
  EXPECT_TRUE(std::filesystem::exists(dir / "prt" / "mine.bin"));
  EXPECT_FALSE(std::filesystem::exists(entry(44)));  // the oldest went
  EXPECT_TRUE(std::filesystem::exists(entry(45)));
}

}  // namespace
}  // namespace prism::prt
