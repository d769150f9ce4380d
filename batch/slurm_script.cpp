#include "batch/slurm_script.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"

namespace prism::batch {
namespace {

std::string jobText(const SlurmJob& job, const SlurmScript& script, bool array) {
  std::string text = "#!/bin/bash\n";
  text += fmt::format("#SBATCH --job-name={}\n", job.name);
  if (array) text += fmt::format("#SBATCH --array=0-{}\n", script.tasks - 1);
  text += fmt::format("#SBATCH --cpus-per-task={}\n", job.cpusPerTask);
  text += fmt::format("#SBATCH --mem={}M\n", job.memoryMiB);
  text += fmt::format("#SBATCH --time={}\n", job.time);
  // A '%' of the folder's own is Slurm's pattern character: written %% to stand for itself.
  std::string logs;
  for (char c : script.logs.string()) logs += c == '%' ? std::string("%%") : std::string(1, c);
  text += fmt::format("#SBATCH --output={}\n",
                      shellQuote(logs + "/" + job.name + (array ? "-%A_%a.out" : "-%j.out")));
  // Quoted as a shell word, which sbatch's reading of #SBATCH lines unquotes: "--comment=a b" is
  // one option, not two words.
  for (const std::string& option : script.sbatchOptions) text += fmt::format("#SBATCH {}\n", shellQuote(option));
  text += "set -euo pipefail\n";
  text += "exec " + job.command + "\n";
  return text;
}

// Error unless `option` is an sbatch option the script does not set itself: one it sets as well
// would override its own for both jobs (--array=0-5 made the one finishing job an array of six).
void checkSbatchOption(std::string_view option) {
  if (option.size() < 2 || option[0] != '-')
    throw Error(fmt::format("--sbatch {}: not an sbatch option (they start with -, e.g. --partition=gpu)", excerpt(option)));
  const std::string_view name = option[1] == '-' ? option.substr(0, option.find('=')) : option.substr(0, 2);
  struct Own {
    std::string_view longName, shortName, instead;
  };
  for (const Own& own : {Own{"--array", "-a", "--tasks sets the array"}, Own{"--job-name", "-J", "the script names its jobs"},
                         Own{"--cpus-per-task", "-c", "--cpus sets the array's"},
                         Own{"--mem", "", "the script sets each job's memory"},
                         Own{"--mem-per-cpu", "", "the script sets each job's memory with --mem"},
                         Own{"--mem-per-gpu", "", "the script sets each job's memory with --mem"},
                         Own{"--time", "-t", "--time sets the array's"},
                         Own{"--output", "-o", "the logs go to the parts' folder"},
                         Own{"--dependency", "-d", "the finishing job waits for the array"},
                         Own{"--kill-on-invalid-dep", "", "the finishing job waits for the array"},
                         Own{"--parsable", "", "the script reads the job IDs"}}) {
    if (name == own.longName || (!own.shortName.empty() && name == own.shortName))
      throw Error(fmt::format("--sbatch {}: the script sets {} itself ({})", excerpt(option), own.longName, own.instead));
  }
}

}  // namespace

std::string shellQuote(std::string_view text) {
  // Characters no shell gives a meaning to in a word: such a word goes unquoted.
  auto plain = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("_./:=,+@%-").find(c) != std::string_view::npos;
  };
  if (!text.empty() && std::all_of(text.begin(), text.end(), plain)) return std::string(text);
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Written out rather than as a std::regex, whose GCC 12 internals -Wmaybe-uninitialized flags in
// the sanitizer build.
void checkSlurmTime(std::string_view time, std::string_view option) {
  auto digits = [](std::string_view t) {
    return !t.empty() && std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  std::string_view clock = time;
  if (std::size_t dash = time.find('-'); dash != std::string_view::npos) {
    if (!digits(time.substr(0, dash))) clock = {};
    else clock = time.substr(dash + 1);
  }
  // [H]H:MM:SS, minutes and seconds below 60.
  const std::size_t colon = clock.find(':');
  const bool valid = colon != std::string_view::npos && colon >= 1 && colon <= 2 && digits(clock.substr(0, colon)) &&
                     clock.size() == colon + 6 && clock[colon + 3] == ':' && digits(clock.substr(colon + 1, 2)) &&
                     digits(clock.substr(colon + 4, 2)) && clock[colon + 1] <= '5' && clock[colon + 4] <= '5';
  if (!valid) throw Error(fmt::format("{}: expected HH:MM:SS or D-HH:MM:SS, got \"{}\"", option, excerpt(time)));
}

std::string slurmScriptText(const SlurmScript& s) {
  PRISM_CHECK(s.tasks >= 1);
  // A line break in a path or an option would end the summary's comment or a here-document early
  // and run the rest as commands: every text the script carries is refused with one.
  std::vector<std::string> carried = {s.summary, s.logs.string(), s.array.command, s.finish.command};
  carried.insert(carried.end(), s.sbatchOptions.begin(), s.sbatchOptions.end());
  for (const std::string& text : carried) {
    const auto control = std::find_if(text.begin(), text.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
    if (control == text.end()) continue;
    const std::size_t at = static_cast<std::size_t>(control - text.begin());
    throw Error(fmt::format("cluster script: a path or option holds a control character (a line break, a tab), which a "
                            "job script cannot carry: \"{}\" (shown as '?')",
                            excerpt(std::string_view(text).substr(at > 40 ? at - 40 : 0))));
  }
  for (const std::string& option : s.sbatchOptions) checkSbatchOption(option);
  std::string text = "#!/bin/bash\n";
  text += "# " + s.summary + "\n";
  text += fmt::format(
      "# On a login node, `bash THIS_SCRIPT` submits the {}-task array and, once every task has\n"
      "# succeeded, the job {}; `bash THIS_SCRIPT 3,5` submits tasks 3 and 5 again, and {}\n"
      "# after them. Each task writes its part atomically and skips a part already complete.\n",
      s.tasks, s.finish.name, s.finish.name);
  text += "set -euo pipefail\n";
  text += fmt::format("mkdir -p {}\n", shellQuote(s.logs.string()));
  // --parsable prints "JOBID[;CLUSTER]"; a quoted here-document is the job script, expanded when it runs.
  text += "array=$(sbatch --parsable ${1:+--array=\"$1\"} <<'PRISM_ARRAY_JOB'\n";
  text += jobText(s.array, s, true);
  text += "PRISM_ARRAY_JOB\n)\n";
  text += "array=${array%%;*}\n";
  text += "finish=$(sbatch --parsable --dependency=afterok:\"$array\" --kill-on-invalid-dep=yes <<'PRISM_FINISH_JOB'\n";
  text += jobText(s.finish, s, false);
  text += "PRISM_FINISH_JOB\n)\n";
  text += "finish=${finish%%;*}\n";
  text += "echo \"array $array finish $finish\"\n";
  return text;
}

}  // namespace prism::batch
