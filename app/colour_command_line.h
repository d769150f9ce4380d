// `prism colour …` on the command line: its subcommands and their options on CLI11, each run by
// its subcommand's callback once the line is parsed (colour_commands.h does the work; errors
// reach main's handlers as any command's do).
#pragma once

#include <CLI/CLI.hpp>

namespace prism::app {

void addColourCommands(CLI::App& app);

}  // namespace prism::app
