// `prism cluster script`'s output: a bash script that submits Prism's batch work to Slurm, as
// Slurm runs it with nothing of Prism's own in between — an array job of N tasks (each one
// `prism … --tile I/N`-like command, I = $SLURM_ARRAY_TASK_ID) and, with
// --dependency=afterok on the array, the one job that puts the parts together (`prism merge`,
// `prism validate --collect`, …). A user runs it on a login node: `bash SCRIPT` submits both;
// `bash SCRIPT 3,5` submits only those tasks of the array again (and the finishing job after
// them), which is how a task that died is done again. Each task skips a part already complete,
// so submitting the whole array again also does only what is missing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace prism::batch {

struct SlurmJob {
  std::string name;                 // --job-name
  int cpusPerTask = 1;
  std::int64_t memoryMiB = 1024;    // --mem, per task
  std::string time = "01:00:00";    // --time, per task
  std::string command;              // a shell command line (quoted by shellQuote where it must be)
};

struct SlurmScript {
  std::string summary;              // a line of what it runs, for the script's head
  int tasks = 1;                    // the array's size
  SlurmJob array;                   // runs once per task, with SLURM_ARRAY_TASK_ID set
  SlurmJob finish;                  // runs once, after every task succeeded
  std::filesystem::path logs;       // folder of the jobs' output files, made before submitting
  std::vector<std::string> sbatchOptions;  // more #SBATCH lines for both (e.g. --partition=gpu)
};

// The script's text (bash). It prints "array JOBID finish JOBID" once both are submitted. Error
// for a control character in anything it carries, and for an sbatch option that is none (no
// leading -) or one the script sets itself (--array, --job-name, --cpus-per-task, --mem…,
// --time, --output, --dependency, --kill-on-invalid-dep, --parsable; short forms too).
std::string slurmScriptText(const SlurmScript& script);

// `text` as one word for bash: itself when it holds only [A-Za-z0-9_./:=,+@%-], else in single quotes.
std::string shellQuote(std::string_view text);

// "HH:MM:SS" (or "D-HH:MM:SS") as Slurm's --time takes it; Error naming `option` otherwise.
void checkSlurmTime(std::string_view time, std::string_view option);

}  // namespace prism::batch
