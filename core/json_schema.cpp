#include "core/json_schema.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"

namespace prism::schema {

using nlohmann::json;

std::string pointerToken(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string describe(const json& value) {
  return excerpt(value.dump(-1, ' ', false, json::error_handler_t::replace), 60);
}

TextPosition textPosition(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  TextPosition p;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      lineStart = i + 1;
    }
  }
  p.column = static_cast<int>(offset - lineStart) + 1;
  return p;
}

namespace {

// %g: "0", "90", "0.5", "1e-06": what a user would have typed.
// Whole numbers below 1e10 in full (a range [1, 1048576], not [1, 1.04858e+06]; int's limits), others as %g.
std::string formatNumber(double v) {
  char buffer[32];
  if (v == std::trunc(v) && std::abs(v) < 1e10) std::snprintf(buffer, sizeof buffer, "%.0f", v);
  else std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// Tracks where the parser is, to name the place of a duplicate key or of too deep a nesting.
class StructureCheck {
 public:
  explicit StructureCheck(const std::string& name) : mName(name) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (depth >= kMaxJsonDepth)
          throw Error(mName + ": " + excerpt(pointer()) + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                      " levels");
        mFrames.push_back({event == json::parse_event_t::object_start, childToken(), {}, {}, 0});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        mFrames.pop_back();
        break;
      case json::parse_event_t::key: {
        Frame& frame = mFrames.back();
        frame.key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.key).second)
          throw Error(mName + ": " + excerpt(pointer() + "/" + pointerToken(frame.key), 160) + ": duplicate key");
        break;
      }
      case json::parse_event_t::value:
        childToken();  // counts array elements
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool isObject = false;
    std::string token;  // this container's reference token in its parent
    std::set<std::string> keys;
    std::string key;    // the key being read (objects)
    std::size_t index;  // the next element (arrays)
  };

  // The token of the value that starts now, in the innermost container.
  std::string childToken() {
    if (mFrames.empty()) return {};
    Frame& frame = mFrames.back();
    if (frame.isObject) return pointerToken(frame.key);
    return std::to_string(frame.index++);
  }

  std::string pointer() const {
    std::string p;
    for (std::size_t i = 1; i < mFrames.size(); ++i) p += "/" + mFrames[i].token;
    return p;
  }

  const std::string& mName;
  std::vector<Frame> mFrames;
};

}  // namespace

json parseJson(std::string_view text, const std::string& name) {
  try {
    StructureCheck check(name);
    return json::parse(text.begin(), text.end(), std::ref(check));
  } catch (const json::parse_error& e) {
    // nlohmann's message is "[json.exception.parse_error.N] parse error at line L, column C:
    // what"; its `byte` is the 1-based index of the last byte read, the one that failed.
    std::string what = e.what();
    std::size_t bracket = what.find("] ");
    std::size_t colon = what.find(": ", bracket == std::string::npos ? 0 : bracket);
    if (colon != std::string::npos) what = what.substr(colon + 2);
    TextPosition p = textPosition(text, e.byte == 0 ? 0 : e.byte - 1);
    // nlohmann quotes the token it failed in ("last read: '…'") whole: a string of megabytes.
    throw Error(name + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) +
                ": malformed JSON: " + excerpt(what, 200));
  } catch (const json::out_of_range& e) {
    // A number beyond double's range ("number overflow parsing '1e999'"): nlohmann gives no
    // position, so find the token it quotes.
    std::string what = e.what();
    std::size_t bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    std::size_t open = what.find('\''), close = what.rfind('\'');
    std::string where = name;
    if (open != std::string::npos && close > open) {
      std::size_t at = text.find(what.substr(open + 1, close - open - 1));
      if (at != std::string_view::npos) {
        TextPosition p = textPosition(text, at);
        where += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
      }
    }
    throw Error(where + ": malformed JSON: " + excerpt(what, 200));
  }
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (minExclusive ? !(v > min) : !(v >= min)) return false;
  if (maxExclusive ? !(v < max) : !(v <= max)) return false;
  return true;
}

Range Range::forFloat() const {
  Range r = *this;
  if (!(r.min > -kFloatInputLimit)) r = {-kFloatInputLimit, r.max, false, r.maxExclusive};
  if (!(r.max < kFloatInputLimit)) r = {r.min, kFloatInputLimit, r.minExclusive, false};
  return r;
}

Range Range::forInt() const {
  constexpr double kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
  Range r = *this;
  if (!(r.min > kMin)) r = {kMin, r.max, false, r.maxExclusive};
  if (!(r.max < kMax)) r = {r.min, kMax, r.minExclusive, false};
  return r;
}

std::string Range::text() const {
  bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
  if (hasMin && hasMax)
    return std::string(" in ") + (minExclusive ? "(" : "[") + formatNumber(min) + ", " +
           formatNumber(max) + (maxExclusive ? ")" : "]");
  if (hasMin) return std::string(minExclusive ? " > " : " >= ") + formatNumber(min);
  if (hasMax) return std::string(maxExclusive ? " < " : " <= ") + formatNumber(max);
  return "";
}

Node::Node(const nlohmann::json& value, std::string pointer, const Document& document)
    : mValue(&value), mPointer(std::move(pointer)), mDocument(&document) {}

bool Document::isSetOnCommandLine(const std::string& pointer) const {
  for (const std::string& set : setOnCommandLine)
    if (pointer == set || (pointer.starts_with(set) && pointer[set.size()] == '/')) return true;
  return false;
}

void Node::fail(const std::string& what) const {
  // A pointer quotes the document's keys, which may be megabytes long.
  throw Error(mDocument->name + ": " + (mPointer.empty() ? "/" : excerpt(mPointer, 160)) +
              (mDocument->isSetOnCommandLine(mPointer) ? " (set on the command line)" : "") + ": " + what);
}

void Node::expectObject(std::initializer_list<std::string_view> allowed) const {
  expectObject(std::vector<std::string_view>(allowed));
}

void Node::expectObject(const std::vector<std::string_view>& allowed) const {
  if (!mValue->is_object()) fail("expected an object, got " + describe(*mValue));
  for (const auto& [key, value] : mValue->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    Node(value, mPointer + "/" + pointerToken(key), *mDocument).fail("unknown key (allowed: " + list + ")");
  }
}

bool Node::has(std::string_view key) const {
  return mValue->is_object() && mValue->contains(key);
}

Node Node::child(std::string_view key) const {
  if (!mValue->is_object()) fail("expected an object, got " + describe(*mValue));
  auto it = mValue->find(key);
  if (it == mValue->end()) fail("missing required key '" + std::string(key) + "'");
  return Node(*it, mPointer + "/" + pointerToken(key), *mDocument);
}

std::optional<Node> Node::optionalChild(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return child(key);
}

std::vector<std::string> Node::keys() const {
  if (!mValue->is_object()) fail("expected an object, got " + describe(*mValue));
  std::vector<std::string> out;
  for (const auto& item : mValue->items()) out.push_back(item.key());
  return out;
}

std::size_t Node::arraySize() const {
  if (!mValue->is_array()) fail("expected an array, got " + describe(*mValue));
  return mValue->size();
}

Node Node::element(std::size_t index) const {
  if (!mValue->is_array() || index >= mValue->size())
    fail("no element " + std::to_string(index));
  return Node((*mValue)[index], mPointer + "/" + std::to_string(index), *mDocument);
}

double Node::number(const Range& range) const {
  // NaN and infinities cannot be written in JSON, but a number too large for a double parses
  // as infinity: "finite" is part of every expectation.
  if (!mValue->is_number() || !range.contains(mValue->get<double>()))
    fail("expected a" + std::string(range.text().empty() ? " finite" : "") + " number" +
         range.text() + ", got " + describe(*mValue));
  return mValue->get<double>();
}

int Node::integer(const Range& range) const {
  // Within int's range too, said in the message (2147483648 read "expected an integer >= 0").
  const Range r = range.forInt();
  bool ok = mValue->is_number_integer() && r.contains(mValue->get<double>());
  if (!ok) fail("expected an integer" + r.text() + ", got " + describe(*mValue));
  return mValue->get<int>();
}

bool Node::boolean() const {
  if (!mValue->is_boolean()) fail("expected true or false, got " + describe(*mValue));
  return mValue->get<bool>();
}

std::string Node::string() const {
  if (!mValue->is_string() || mValue->get_ref<const std::string&>().empty())
    fail("expected a non-empty string, got " + describe(*mValue));
  return mValue->get<std::string>();
}

std::vector<double> Node::numbers(std::size_t n, const Range& range) const {
  if (!mValue->is_array() || mValue->size() != n)
    fail("expected an array of " + std::to_string(n) + " numbers, got " + describe(*mValue));
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(element(i).number(range));
  return out;
}

float Node::numberF(const Range& range) const {
  const Range r = range.forFloat();
  const double v = number(r);
  const auto f = static_cast<float>(v);
  // Against the bounds as floats too: 0.7 ≥ 0.7 holds once both are rounded, not as float(0.7) ≥ 0.7.
  Range asFloat = r;
  asFloat.min = static_cast<float>(r.min);
  asFloat.max = static_cast<float>(r.max);
  if (!asFloat.contains(f))
    fail("expected a number" + r.text() + ", got " + describe(*mValue) + " (" + formatNumber(f) +
         " as a float, the renderer's precision)");
  return f;
}

glm::vec3 Node::vec3(const Range& range) const {
  numbers(3, range.forFloat());  // the array's shape, in one message
  return {element(0).numberF(range), element(1).numberF(range), element(2).numberF(range)};
}

glm::vec2 Node::vec2(const Range& range) const {
  numbers(2, range.forFloat());
  return {element(0).numberF(range), element(1).numberF(range)};
}

double Node::number(std::string_view key, double fallback, const Range& range) const {
  auto c = optionalChild(key);
  return c ? c->number(range) : fallback;
}

float Node::numberF(std::string_view key, float fallback, const Range& range) const {
  auto c = optionalChild(key);
  return c ? c->numberF(range) : fallback;
}

bool Node::boolean(std::string_view key, bool fallback) const {
  auto c = optionalChild(key);
  return c ? c->boolean() : fallback;
}

glm::vec3 Node::vec3(std::string_view key, const glm::vec3& fallback, const Range& range) const {
  auto c = optionalChild(key);
  return c ? c->vec3(range) : fallback;
}

bool isInside(const std::filesystem::path& root, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::path r = std::filesystem::weakly_canonical(root, ec);
  if (ec) return false;
  std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
  if (ec) return false;
  auto [rootEnd, pathIt] = std::mismatch(r.begin(), r.end(), p.begin(), p.end());
  // A trailing empty element ("dir/") in root matches anything.
  return rootEnd == r.end() || (std::next(rootEnd) == r.end() && rootEnd->empty());
}

std::filesystem::path confinedFile(const std::filesystem::path& root,
                                   const std::filesystem::path& base, std::string_view relative) {
  std::filesystem::path rel(relative);
  if (relative.empty()) throw Error("empty file name");
  if (rel.is_absolute() || rel.has_root_name() || rel.has_root_directory() ||
      relative.front() == '/' || relative.front() == '\\')
    throw Error("absolute path '" + std::string(relative) + "' is not allowed (files must be inside " +
                root.string() + ")");
  for (const auto& part : rel) {
    if (part == "..")
      throw Error("'..' is not allowed in '" + std::string(relative) + "' (files must be inside " +
                  root.string() + ")");
  }
  std::filesystem::path full = base / rel;
  if (!isInside(root, full)) {
    // Both resolved: a relative root read "outside ." for a scene in the working folder.
    std::error_code ec;
    throw Error("'" + std::string(relative) + "' resolves to " + std::filesystem::weakly_canonical(full, ec).string() +
                ", outside " + std::filesystem::weakly_canonical(root, ec).string());
  }
  std::error_code ec;
  if (!std::filesystem::exists(full, ec)) throw Error("file not found: " + full.string());
  if (!std::filesystem::is_regular_file(full, ec)) throw Error("not a file: " + full.string());
  // Here rather than where the file is read: a glTF's image is read by tinygltf, which said only
  // that it "could not be loaded".
  if (::access(full.c_str(), R_OK) != 0) throw Error("cannot read " + full.string() + ": " + std::strerror(errno));
  return full;
}

std::vector<unsigned char> readBinaryFile(const std::filesystem::path& path) {
  requireInputFile(path, "a file");  // a pipe (a script from `<(…)`) is the user's own stream
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open file");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(path.string() + ": read error");
  return bytes;
}

}  // namespace prism::schema
