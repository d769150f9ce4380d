// `prism bench` without a scene: Prism's Google Benchmark suite (bench/), its flags passed through.
#pragma once

#include <string>
#include <vector>

namespace prism::app {

// `args`: the command line's flags for Google Benchmark; 2 when one is not its, else 0.
int runBenchmarks(std::vector<std::string> args);

}  // namespace prism::app
