// A bake split by vertex ranges (prism prt bake --part): each part's transfer is that of the
// whole bake, bit for bit; parts merge only when they are of one bake and cover it exactly once.
#include "techniques/prt/transfer_part.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/transfer_bake.h"

namespace prism::prt {
namespace {

std::filesystem::path partFolder() {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "prt_part_test";
  std::filesystem::create_directories(dir);
  return dir;
}

// Task `index` of `count`'s part of the ColorChecker height field's bake (self-shadowing).
std::filesystem::path bakePart(const PrtMesh& mesh, const BakeSettings& settings, TaskIndex task) {
  const int vertices = static_cast<int>(mesh.positions.size());
  TransferPart part{transferKey(mesh, settings), settings.samples, vertices, shareOf(task, vertices), {}};
  part.transfer = bakeTransfer(mesh, settings, part.vertices, {}, 1);
  std::filesystem::path file = partFolder() / ("part-" + std::to_string(task.index) + "-of-" +
                                               std::to_string(task.count) + "-" + std::to_string(settings.samples));
  saveTransferPart(file, part);
  return file;
}

std::string mergeError(const std::vector<std::filesystem::path>& files) {
  try {
    mergeTransferParts(files);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TransferPart, ThreePartsMergeToTheWholeBakeBitForBit) {
  const PrtMesh mesh = makeColourCheckerObject(4).mesh;
  const BakeSettings settings{64, true};
  const std::vector<shared::Sh25> whole = bakeTransfer(mesh, settings, {}, 2);
  std::vector<std::filesystem::path> files;
  for (int i : {2, 0, 1}) files.push_back(bakePart(mesh, settings, {i, 3}));
  ASSERT_TRUE(isTransferPart(files[0]));
  TransferPart merged = mergeTransferParts(files);
  EXPECT_EQ(merged.key, transferKey(mesh, settings));
  EXPECT_EQ(merged.samples, 64);
  ASSERT_EQ(merged.transfer.size(), whole.size());
  for (std::size_t v = 0; v < whole.size(); ++v)
    for (int k = 0; k < 25; ++k) ASSERT_EQ(merged.transfer[v].c[k], whole[v].c[k]) << "vertex " << v;
}

TEST(TransferPart, RefusesGapsOverlapsOtherBakesAndDamage) {
  const PrtMesh mesh = makeColourCheckerObject(4).mesh;
  const int n = static_cast<int>(mesh.positions.size());
  const std::filesystem::path a = bakePart(mesh, {16, true}, {0, 3}), b = bakePart(mesh, {16, true}, {1, 3}),
                              c = bakePart(mesh, {16, true}, {2, 3});
  const IndexRange middle = shareOf({1, 3}, n), last = shareOf({2, 3}, n);
  EXPECT_EQ(mergeError({a, c}), "merge: vertices " + std::to_string(middle.begin) + ":" + std::to_string(middle.end) +
                                    " are missing");
  EXPECT_EQ(mergeError({a, b}), "merge: vertices " + std::to_string(last.begin) + ":" + std::to_string(n) + " are missing");
  EXPECT_NE(mergeError({a, b, b, c}).find("are in both"), std::string::npos);
  const std::filesystem::path other = bakePart(mesh, {32, true}, {1, 3});
  EXPECT_NE(mergeError({a, other, c}).find("is a part of another PRT bake"), std::string::npos);
  EXPECT_FALSE(isTransferPart(partFolder()));

  const std::filesystem::path damaged = partFolder() / "damaged";
  std::filesystem::copy_file(b, damaged, std::filesystem::copy_options::overwrite_existing);
  {
    std::fstream f(damaged, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(60);
    f.put('\x7f');
  }
  EXPECT_NE(mergeError({a, damaged, c}).find("checksum"), std::string::npos);
  std::filesystem::resize_file(damaged, 100);
  EXPECT_NE(mergeError({a, damaged, c}).find("truncated"), std::string::npos);
  EXPECT_THROW(bakeTransfer(mesh, {16, true}, IndexRange{n - 1, n + 1}), Error);
}

}  // namespace
}  // namespace prism::prt
