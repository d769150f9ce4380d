// The corpus replay: a main for a fuzz target built without libFuzzer (the release and asan
// presets), which feeds it every file of the folders (or files) named on its command line once,
// so that CI runs each saved input — seeds and every crash found, kept as regression inputs —
// through the target under the sanitizers in seconds. An input named regression_* is one that
// Prism once accepted, crashed on or answered wrongly: the replay fails unless the target now
// rejects it (a load throws a one-line input error). Prints how many inputs were accepted and
// rejected.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::size_t accepted = 0, rejected = 0;

void replay(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && in.fail()) {
    std::fprintf(stderr, "fuzz replay: %s: cannot be read\n", file.c_str());
    std::exit(1);
  }
  const std::size_t before = prism::fuzz::rejectedLoads();
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  const bool wasRejected = prism::fuzz::rejectedLoads() > before;
  ++(wasRejected ? rejected : accepted);
  if (!wasRejected && file.filename().string().starts_with("regression_")) {
    std::fprintf(stderr, "fuzz replay: %s: accepted, but regression inputs must be rejected\n", file.c_str());
    std::exit(1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s CORPUS_FOLDER_OR_FILE...\n", argv[0]);
    return 2;
  }
  std::size_t count = 0;
  for (int i = 1; i < argc; ++i) {
    std::filesystem::path root = argv[i];
    if (!std::filesystem::exists(root)) {
      std::fprintf(stderr, "fuzz replay: %s: not found\n", argv[i]);
      return 1;
    }
    if (std::filesystem::is_directory(root)) {
      std::vector<std::filesystem::path> files;
      for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      for (const auto& file : files) replay(file), ++count;
    } else {
      replay(root), ++count;
    }
  }
  std::printf("fuzz replay: %zu inputs, none escaped: %zu accepted, %zu rejected with a one-line error\n", count,
              accepted, rejected);
  if (count == 0) {
    std::fprintf(stderr, "fuzz replay: no inputs\n");
    return 1;
  }
  return 0;
}
