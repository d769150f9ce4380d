// What prism adds to three of CLI11's parse errors, whose own words leave the user guessing: the
// subcommands a command takes, how to give a switch its value, and what an integer option takes.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace prism::app {

// For a word CLI11 did not expect: when it is on or off right after a switch (`--gizmos on`),
// the hint that a switch takes its value after '='; otherwise nothing.
std::string switchValueHint(int argc, char** argv, const std::vector<std::string>& extras);

// For "A subcommand is required": the subcommands of the deepest command given, which CLI11's
// message does not name ("prism atmosphere" takes evaluate or optimise).
std::string subcommandHint(const CLI::App& app);

// For CLI11's "Could not convert: --frames = 1e3": what an integer option takes, which the message
// does not say (a whole number written out, within its type's range); otherwise nothing.
std::string conversionHint(const CLI::App& app, const std::string& message);

}  // namespace prism::app
