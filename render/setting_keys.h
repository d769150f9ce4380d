// The one table of frame-setting keys: for each field of FrameSettings that users set, its name
// (the same text everywhere: `prism render --KEY VALUE`, the viewer script's `set KEY VALUE` and
// `right.KEY`, the viewer's settings files), its type and allowed values, its default, help text,
// and how it is parsed from and printed to text. The CLI's options and --help, the script, the
// settings files and the viewer's choice lists are all made from it, so a key is written once.
//
// parse(print(s)) == s for every key; every parse error is one line,
// `KEY: expected WHAT, got "VALUE"`.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "render/frame_settings.h"

namespace prism::render {

enum class SettingType {
  Integer,  // a whole number within a range
  Number,   // a finite number (ev also takes "scene")
  Range,    // MIN,MAX in nm
  Choice,   // one of `choices`
  Name,     // a name looked up in data/ (observer, illuminant)
  Switch,   // on or off (a flag on the command line: --KEY, or --KEY=off)
};

struct SettingKey {
  std::string name;
  SettingType type = SettingType::Number;
  std::string expects;               // what a value looks like, for errors and --help
  std::vector<std::string> choices;  // every value of a Choice key, in order; empty otherwise
  std::string help;                  // one line, for --help and the viewer's tooltips
  std::string example;               // a valid value other than the default (docs and tests)
  std::function<void(FrameSettings&, std::string_view)> parse;  // Error when the text is bad
  std::function<std::string(const FrameSettings&)> print;
};

// Every key, in the order --help and the settings files list them.
const std::vector<SettingKey>& frameSettingKeys();
// The key called `name`, or null.
const SettingKey* findFrameSettingKey(std::string_view name);

// Sets `key` to `value`; false when `key` is not a frame key. Error (settings unchanged) when the
// value is bad; validate() then checks the combination.
bool applyFrameSetting(FrameSettings& settings, std::string_view key, std::string_view value);
// Every key with its printed value, in table order.
std::vector<std::pair<std::string, std::string>> frameSettingValues(const FrameSettings& settings);

// The text without one leading '+', which from_chars does not read (a sign it reads is '-'): the
// key table's numbers and the command line's decimal checks take "+64" alike.
inline std::string_view withoutPlusSign(std::string_view text) { return text.starts_with('+') ? text.substr(1) : text; }

// The numbers of settings and script commands: a finite number, or a whole one within [min, max];
// Error "WHAT: expected …, got "TEXT"" otherwise.
double parseNumber(std::string_view what, std::string_view text);
long parseInteger(std::string_view what, std::string_view text, long min, long max);
float parseFloat(std::string_view what, std::string_view text);  // parseNumber, as a float
// parseFloat within [min, max]: Error "WHAT: expected a number within MIN–MAX, got "TEXT"" (never
// clamped: a script or settings file says what it means).
float parseFloatWithin(std::string_view what, std::string_view text, float min, float max);

}  // namespace prism::render
