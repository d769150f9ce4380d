// What prism adds to CLI11's parsing, whose own words leave the user guessing: the subcommands a
// command takes, an unknown option's nearest, how to give a switch its value, what an integer
// option takes, and decimal numbers only where a number is read (the checks exported for the
// frame settings' options, which CliSettings adds).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace prism::app {

// For the words CLI11 did not expect, the whole message: an option the command does not have
// named with the nearest it has ("unknown option --widht for prism render (did you mean
// --width?)"); on or off right after a switch (`--gizmos on`) with the hint that a switch takes
// its value after '='; other words in the order they were given (CLI11 listed "64 --widht").
std::string unexpectedArgumentsMessage(const CLI::App& app, int argc, char** argv, const std::vector<std::string>& extras);

// For "A subcommand is required": the subcommands of the deepest command given, which CLI11's
// message does not name ("prism atmosphere" takes evaluate or optimise).
std::string subcommandHint(const CLI::App& app);

// For CLI11's "Could not convert: --frames = 1e3": what an integer option takes, which the message
// does not say (a whole number written out, within its type's range); otherwise nothing.
std::string conversionHint(const CLI::App& app, const std::string& message);

// CLI11 checks that a text is a number written in decimal ("6500", "-2.5", "1e-3"; inf and nan
// pass, to the option's own range, which names what it takes), or a whole number so written.
// numberLike: only text that starts as a number does ("0x5"), a word being the option's own to
// refuse or take (--ev scene).
CLI::Validator decimalNumber(bool numberLike = false);
CLI::Validator decimalWholeNumber();

// Gives every number option and positional of `app` and its subcommands (those added so far) a
// check that its text is a number written in decimal ("6500", "-2.5", "1e-3"; whole numbers for
// integers): CLI11 read "0x1964" and "0x1.964p12" as 6500, "0b11" as 3 and "" as 0, where every
// other number Prism reads refuses them. Options that `parsedByPrism` names (text handed to
// Prism's own parser, such as the frame settings, which CliSettings checks itself) are skipped.
void requireDecimalNumbers(CLI::App& app, const std::function<bool(const CLI::Option*)>& parsedByPrism);

}  // namespace prism::app
