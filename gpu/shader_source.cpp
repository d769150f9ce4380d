#include "gpu/shader_source.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "gpu/error.h"

namespace prism::gpu {
namespace {

namespace fs = std::filesystem;

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string_view trimLeft(std::string_view s) {
  std::size_t i = s.find_first_not_of(" \t");
  return i == std::string_view::npos ? std::string_view() : s.substr(i);
}

// The rest of `line` after `# name` (whitespace allowed around '#'), if it is that directive.
std::optional<std::string_view> directive(std::string_view line, std::string_view name) {
  line = trimLeft(line);
  if (line.empty() || line.front() != '#') return std::nullopt;
  line = trimLeft(line.substr(1));
  if (!line.starts_with(name)) return std::nullopt;
  line.remove_prefix(name.size());
  if (!line.empty() && isIdentifierChar(line.front())) return std::nullopt;
  return line;
}

// `"name"` optionally followed by a // comment; nullopt if malformed.
std::optional<std::string> quotedName(std::string_view rest) {
  rest = trimLeft(rest);
  if (rest.empty() || rest.front() != '"') return std::nullopt;
  std::size_t close = rest.find('"', 1);
  if (close == std::string_view::npos || close == 1) return std::nullopt;
  std::string name(rest.substr(1, close - 1));
  std::string_view after = trimLeft(rest.substr(close + 1));
  if (!after.empty() && !after.starts_with("//")) return std::nullopt;
  return name;
}

bool isGoogleIncludeExtension(std::string_view line) {
  std::optional<std::string_view> rest = directive(line, "extension");
  if (!rest) return false;
  std::string_view name = trimLeft(*rest);
  constexpr std::string_view google = "GL_GOOGLE_include_directive";
  return name.starts_with(google) &&
         (name.size() == google.size() || !isIdentifierChar(name[google.size()]));
}

// A tiny left-to-right matcher for the driver log formats.
struct Cursor {
  std::string_view text;
  bool literal(std::string_view s) {
    if (!text.starts_with(s)) return false;
    text.remove_prefix(s.size());
    return true;
  }
  bool number(std::string& out) {
    std::size_t n = 0;
    while (n < text.size() && std::isdigit(static_cast<unsigned char>(text[n]))) ++n;
    if (n == 0 || n > 9) return false;
    out = std::string(text.substr(0, n));
    text.remove_prefix(n);
    return true;
  }
};

std::vector<std::string> readLines(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || fs::is_directory(file))
    throw GpuError(Diagnostic::ShaderFileNotFound,
                   file.string() + ": error: cannot read shader file");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

std::string where(const fs::path& file, std::size_t lineNumber) {
  return file.string() + ":" + std::to_string(lineNumber) + ": error: ";
}

class Assembler {
 public:
  explicit Assembler(std::span<const fs::path> includeDirs) : mIncludeDirs(includeDirs) {}

  ShaderSource run(const fs::path& root, std::span<const ShaderDefine> defines) {
    fs::path display = root.lexically_normal();
    numberOf(display);
    std::vector<std::string> lines = readLines(display);
    auto versionLine = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
      return directive(l, "version").has_value();
    });
    if (versionLine == lines.end())
      throw GpuError(Diagnostic::MissingVersion,
                     where(display, 1) + "no #version directive (a shader's root file needs one)");
    auto afterVersion = static_cast<std::size_t>(versionLine - lines.begin()) + 1;
    for (std::size_t i = 0; i < afterVersion; ++i) mText += lines[i] + '\n';
    for (const ShaderDefine& d : defines)
      mText += "#define " + d.name + (d.value.empty() ? "" : " " + d.value) + '\n';
    if (!defines.empty()) lineDirective(afterVersion + 1, 0);
    emit(display, 0, lines, afterVersion);
    return {std::move(mText), std::move(mFiles)};
  }

 private:
  int numberOf(const fs::path& display) {
    std::error_code ec;
    fs::path key = fs::weakly_canonical(display, ec);
    if (ec) key = display;
    auto [it, inserted] = mNumbers.try_emplace(key.string(), static_cast<int>(mFiles.size()));
    if (inserted) mFiles.push_back(display);
    return it->second;
  }

  void lineDirective(std::size_t nextLine, int sourceNumber) {
    // GLSL ≥ 3.30: the line after `#line L S` is line L of source string S.
    mText += "#line " + std::to_string(nextLine) + ' ' + std::to_string(sourceNumber) + '\n';
  }

  fs::path resolve(const fs::path& includer, std::size_t lineNumber, const std::string& name) {
    std::vector<fs::path> searched{includer.parent_path()};
    searched.insert(searched.end(), mIncludeDirs.begin(), mIncludeDirs.end());
    for (const fs::path& dir : searched) {
      fs::path candidate = (dir / name).lexically_normal();
      if (fs::is_regular_file(candidate)) return candidate;
    }
    std::string list;
    for (const fs::path& dir : searched)
      list += (list.empty() ? "" : ", ") + (dir.empty() ? std::string(".") : dir.string());
    throw GpuError(Diagnostic::IncludeNotFound, where(includer, lineNumber) + "#include \"" + name +
                                                    "\" not found (searched " + list + ")");
  }

  void emit(const fs::path& file, int sourceNumber, const std::vector<std::string>& lines,
            std::size_t first) {
    mOpen.push_back(file);
    for (std::size_t i = first; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      std::size_t lineNumber = i + 1;
      if (isGoogleIncludeExtension(line)) {
        mText += '\n';
        continue;
      }
      std::optional<std::string_view> rest = directive(line, "include");
      if (!rest) {
        mText += line + '\n';
        continue;
      }
      std::optional<std::string> name = quotedName(*rest);
      if (!name)
        throw GpuError(Diagnostic::IncludeMalformed,
                       where(file, lineNumber) + "expected #include \"name\", got '" + line + "'");
      fs::path target = resolve(file, lineNumber, *name);
      checkCycle(file, lineNumber, target);
      int targetNumber = numberOf(target);
      lineDirective(1, targetNumber);
      emit(target, targetNumber, readLines(target), 0);
      lineDirective(lineNumber + 1, sourceNumber);
    }
    mOpen.pop_back();
  }

  void checkCycle(const fs::path& includer, std::size_t lineNumber, const fs::path& target) {
    auto same = [&](const fs::path& open) {
      std::error_code ec;
      return fs::equivalent(open, target, ec);
    };
    auto it = std::find_if(mOpen.begin(), mOpen.end(), same);
    if (it == mOpen.end()) return;
    std::string chain;
    for (; it != mOpen.end(); ++it) chain += it->string() + " -> ";
    chain += target.string();
    throw GpuError(Diagnostic::IncludeCycle,
                   where(includer, lineNumber) + "#include cycle: " + chain);
  }

  std::span<const fs::path> mIncludeDirs;
  std::string mText;
  std::vector<fs::path> mFiles;
  std::map<std::string, int> mNumbers;
  std::vector<fs::path> mOpen;
};

}  // namespace

ShaderSource assembleShaderSource(const std::filesystem::path& file,
                                  std::span<const std::filesystem::path> includeDirs,
                                  std::span<const ShaderDefine> defines) {
  return Assembler(includeDirs).run(file, defines);
}

std::string mapShaderLog(std::string_view log, std::span<const std::filesystem::path> files) {
  auto file = [&](const std::string& number) -> const std::filesystem::path* {
    unsigned long n = std::stoul(number);
    return n < files.size() ? &files[n] : nullptr;
  };
  std::istringstream in{std::string(log)};
  std::string line, out;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string mapped = line, source, lineNumber, column;
    const std::filesystem::path* f = nullptr;
    // Mesa: "S:L(C): message".
    if (Cursor c{line}; c.number(source) && c.literal(":") && c.number(lineNumber) &&
                        c.literal("(") && c.number(column) && c.literal("): ") &&
                        (f = file(source)))
      mapped = f->string() + ":" + lineNumber + ":" + column + ": " + std::string(c.text);
    // glslang-derived drivers: "ERROR: S:L: message" / "WARNING: S:L: message".
    else if (Cursor g{line}; (g.literal("ERROR: ") || g.literal("WARNING: ")) && g.number(source) &&
                             g.literal(":") && g.number(lineNumber) && g.literal(": ") &&
                             (f = file(source)))
      mapped = f->string() + ":" + lineNumber + ": " +
               (line.starts_with("ERROR") ? "error" : "warning") + ": " + std::string(g.text);
    // NVIDIA: "S(L) : message".
    else if (Cursor n{line}; n.number(source) && n.literal("(") && n.number(lineNumber) &&
                             n.literal(") : ") && (f = file(source)))
      mapped = f->string() + ":" + lineNumber + ": " + std::string(n.text);
    out += mapped + '\n';
  }
  return out;
}

std::string firstErrorLine(std::string_view mappedLog) {
  std::istringstream in{std::string(mappedLog)};
  std::string line, firstNonEmpty;
  while (std::getline(in, line)) {
    std::string lower = line;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower.find("error") != std::string::npos) return line;
    if (firstNonEmpty.empty() && line.find_first_not_of(" \t") != std::string::npos)
      firstNonEmpty = line;
  }
  return firstNonEmpty;
}

}  // namespace prism::gpu
