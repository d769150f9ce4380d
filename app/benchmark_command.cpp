#include "app/benchmark_command.h"

#include <benchmark/benchmark.h>

namespace prism::app {

int runBenchmarks(std::vector<std::string> args) {
  std::vector<char*> argv{const_cast<char*>("prism bench")};
  for (std::string& a : args) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace prism::app
