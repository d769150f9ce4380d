#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include "core/error.h"

namespace prism::fuzz {
namespace {

struct Scratch {
  std::filesystem::path folder;
  Scratch() {
    folder = std::filesystem::temp_directory_path() / ("prism-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
  }
};

std::size_t rejected = 0;

[[noreturn]] void fail(std::string_view kind, std::string_view what) {
  std::fprintf(stderr, "prism fuzz: %.*s escaped the loader: %.*s\n", static_cast<int>(kind.size()), kind.data(),
               static_cast<int>(what.size()), what.data());
  std::abort();
}

void checkMessage(std::string_view what) {
  if (what.find('\n') != std::string_view::npos) fail("a message of more than one line", what);
  if (what.size() > kMaxMessageLength) fail("a message longer than kMaxMessageLength", what.substr(0, 300));
  if (what.empty()) fail("an empty message", what);
}

}  // namespace

const std::filesystem::path& scratchFolder() {
  static const Scratch scratch;
  return scratch.folder;
}

std::filesystem::path inputFile(std::span<const std::uint8_t> bytes, std::string_view name) {
  std::filesystem::path path = scratchFolder() / std::string(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) fail("a failed write of the input file", path.string());
  return path;
}

std::size_t rejectedLoads() { return rejected; }

void expectOnlyInputErrors(const std::function<void()>& load) {
  try {
    load();
  } catch (const Error& e) {
    checkMessage(e.what());
    ++rejected;
  } catch (const std::filesystem::filesystem_error& e) {
    checkMessage(e.what());
    ++rejected;
  } catch (const std::exception& e) {
    fail("an exception other than prism::Error (the CLI's exit 70)", e.what());
  }
}

}  // namespace prism::fuzz
