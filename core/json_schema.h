// Checking JSON documents (scene files, glTF files, techniques' scene sections, settings) with
// errors that point into them: the pieces every loader of a JSON document shares.
//
// Every error is a prism::Error of one line, "<document>: <JSON pointer>: <what>", the pointer
// as RFC 6901 writes it ("/lights/0/intensity", "/" for the whole document), so that a user can
// find the place in any editor with a JSON-pointer search (jq, VS Code, …). A malformed file is
// reported as "<document>:<line>:<column>: malformed JSON: <what>" instead, the place being
// all there is to say.
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace prism::schema {

// The reference token of an object key in a JSON pointer (RFC 6901 §3: "~" → "~0", "/" → "~1").
std::string pointerToken(std::string_view key);

// A value as a message quotes it: compact JSON, cut to about 60 characters.
std::string describe(const nlohmann::json& value);

// 1-based line and column (in bytes) of the byte at `offset` in `text`.
struct TextPosition {
  int line = 1;
  int column = 1;
};
TextPosition textPosition(std::string_view text, std::size_t offset);

// Parses a JSON document. Error "<name>:<line>:<column>: malformed JSON: …" when malformed, and
// "<name>: <pointer>: duplicate key" when an object names a key twice (JSON allows it, but the
// second would silently win); "<name>: <pointer>: nested deeper than 64 levels" past kMaxJsonDepth.
nlohmann::json parseJson(std::string_view text, const std::string& name);

// The document errors are reported against.
struct Document {
  std::string name;  // shown first in every message: the file as the user named it
  // Pointers of the values command-line overrides set (`--set`): a message about one of them, or
  // about anything inside one, says so, lest the user search the file for a value it lacks.
  std::set<std::string> setOnCommandLine;
  bool isSetOnCommandLine(const std::string& pointer) const;
};

// Allowed ranges of a number; the message names them ("> 0", "in [0, 1]", "in (0, 90)").
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;
  bool maxExclusive = false;

  static Range any() { return {}; }
  static Range above(double v) { return {v, std::numeric_limits<double>::infinity(), true, false}; }
  static Range atLeast(double v) { return {v, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  bool contains(double v) const;
  std::string text() const;  // "" for any finite number
  // This range within ±kFloatInputLimit.
  Range forFloat() const;
  // This range within int's.
  Range forInt() const;
};

// What a number read as float (numberF, vec2, vec3) may reach in magnitude: a scene's lengths,
// intensities, luminances and colours, which the float pipeline multiplies together (a spectrum
// × an intensity × an exposure) without overflowing float's 3.4e38.
inline constexpr double kFloatInputLimit = 1e12;

// How deeply a JSON document may nest (arrays and objects): deeper is refused while parsing,
// before anything walks the value recursively (Prism's files nest a few levels).
inline constexpr int kMaxJsonDepth = 64;

// A value inside a document with the pointer that leads to it. Cheap to copy; refers to the
// json and the Document, which must outlive it.
class Node {
 public:
  Node(const nlohmann::json& value, std::string pointer, const Document& document);

  const nlohmann::json& json() const { return *mValue; }
  const std::string& pointer() const { return mPointer; }
  const Document& document() const { return *mDocument; }
  // Throws Error("<document>: <pointer>: <what>"), "<pointer> (set on the command line)" where an
  // override set it.
  [[noreturn]] void fail(const std::string& what) const;

  // Objects. `expectObject` checks the type and that every key is one of `allowed`.
  void expectObject(std::initializer_list<std::string_view> allowed) const;
  void expectObject(const std::vector<std::string_view>& allowed) const;
  bool has(std::string_view key) const;
  Node child(std::string_view key) const;  // Error "missing required key 'key'" when absent
  std::optional<Node> optionalChild(std::string_view key) const;
  std::vector<std::string> keys() const;  // in the json's order (sorted)

  // Arrays.
  std::size_t arraySize() const;  // Error unless an array
  Node element(std::size_t index) const;

  // Values. Each checks the type (and range) and names what it expected and what it got.
  double number(const Range& range = Range::any()) const;
  // A number within range.forFloat() that stays within it as a float (1e-300 > 0 is 0 as a float).
  float numberF(const Range& range = Range::any()) const;
  int integer(const Range& range = Range::any()) const;
  bool boolean() const;
  std::string string() const;  // non-empty
  // An array of exactly n numbers, each in range.
  std::vector<double> numbers(std::size_t n, const Range& range = Range::any()) const;
  glm::vec3 vec3(const Range& range = Range::any()) const;
  glm::vec2 vec2(const Range& range = Range::any()) const;

  // Optional keys with a default.
  double number(std::string_view key, double fallback, const Range& range = Range::any()) const;
  float numberF(std::string_view key, float fallback, const Range& range = Range::any()) const;
  bool boolean(std::string_view key, bool fallback) const;
  glm::vec3 vec3(std::string_view key, const glm::vec3& fallback,
                 const Range& range = Range::any()) const;

 private:
  const nlohmann::json* mValue;
  std::string mPointer;
  const Document* mDocument;
};

// A file a document names, which must stay inside `root`: a relative path without "..",
// resolved against `base` (a folder inside root), still inside root once symbolic links are
// resolved (std::filesystem::weakly_canonical on both sides), and an existing regular file that
// this process may read.
// Returns base / relative; Error(what) without a location otherwise (callers add theirs).
std::filesystem::path confinedFile(const std::filesystem::path& root,
                                   const std::filesystem::path& base, std::string_view relative);

// Whether `path`, once symbolic links are resolved, lies inside `root` (itself resolved).
bool isInside(const std::filesystem::path& root, const std::filesystem::path& path);

// A whole file (or pipe) as bytes; Error naming the file when it cannot be read, or is a device or
// a socket.
std::vector<unsigned char> readBinaryFile(const std::filesystem::path& path);

}  // namespace prism::schema
