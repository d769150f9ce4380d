#include "batch/slurm_script.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/error_test_support.h"

namespace prism::batch {
namespace {

TEST(SlurmScript, QuotesWordsForBash) {
  EXPECT_EQ(shellQuote("/work/scenes/a.json"), "/work/scenes/a.json");
  EXPECT_EQ(shellQuote("lights.0.spd=F11"), "lights.0.spd=F11");
  EXPECT_EQ(shellQuote("a b"), "'a b'");
  EXPECT_EQ(shellQuote("it's $HOME"), "'it'\\''s $HOME'");
  EXPECT_EQ(shellQuote(""), "''");
}

TEST(SlurmScript, ChecksTimeLimits) {
  EXPECT_NO_THROW(checkSlurmTime("01:00:00", "--time"));
  EXPECT_NO_THROW(checkSlurmTime("2-12:30:00", "--time"));
  EXPECT_NO_THROW(checkSlurmTime("5:00:59", "--time"));
  for (const char* bad : {"1h", "1:00", "01:60:00", "01:00:60", "01:00:00; rm -rf /", "", "-01:00:00", "x-01:00:00",
                          "123:00:00", "1:0:00", "01:00:0", "1-2-01:00:00", "01:00:00 "}) {
    EXPECT_THROW(checkSlurmTime(bad, "--time"), Error) << bad;
  }
}

// A reference render's script of eight tasks, its parts in `logs`.
SlurmScript referenceScript(const std::filesystem::path& logs, const std::string& sbatchOption) {
  SlurmScript s;
  s.summary = "a test";
  s.tasks = 8;
  s.array = {"prism-reference", 2, 512, "02:00:00", "prism reference --tile \"$SLURM_ARRAY_TASK_ID/8\""};
  s.finish = {"prism-merge", 1, 256, "00:30:00", "prism merge parts/part-*-of-8.exr -o out.exr"};
  s.logs = logs;
  s.sbatchOptions = {sbatchOption};
  return s;
}

TEST(SlurmScript, SubmitsTheArrayThenItsFinishAfterEveryTask) {
  const std::string text = slurmScriptText(referenceScript("/work/my parts", "--partition=gpu"));
  for (const char* line : {"#SBATCH --array=0-7\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --mem=512M\n",
                           "#SBATCH --time=02:00:00\n", "#SBATCH --partition=gpu\n", "mkdir -p '/work/my parts'\n",
                           "#SBATCH --output='/work/my parts/prism-reference-%A_%a.out'\n",
                           "array=$(sbatch --parsable ${1:+--array=\"$1\"} <<'PRISM_ARRAY_JOB'\n",
                           "--dependency=afterok:\"$array\" --kill-on-invalid-dep=yes",
                           "exec prism merge parts/part-*-of-8.exr -o out.exr\n", "echo \"array $array finish $finish\"\n"}) {
    EXPECT_NE(text.find(line), std::string::npos) << line << " is not in\n" << text;
  }
  // The finishing job is one job, not an array, and comes after the array's.
  EXPECT_EQ(text.find("--array=0-7"), text.rfind("--array=0-7"));
  EXPECT_LT(text.find("PRISM_ARRAY_JOB\n)"), text.find("--job-name=prism-merge"));
}

// What a user's paths and options may hold: a '%' stands for itself in #SBATCH --output (Slurm
// expanded "%j" in a folder's name), an option with a space stays one, and a line break, which
// ended the summary's comment and ran the rest as commands, is refused.
TEST(SlurmScript, CarriesOddPathsAndOptionsSafely) {
  const SlurmScript s = referenceScript("/work/o%j 100%", "--comment=a b");
  const std::string text = slurmScriptText(s);
  EXPECT_NE(text.find("#SBATCH --output='/work/o%%j 100%%/prism-reference-%A_%a.out'\n"), std::string::npos) << text;
  EXPECT_NE(text.find("#SBATCH '--comment=a b'\n"), std::string::npos) << text;
  for (auto edit : {+[](SlurmScript& t) { t.logs = "/work/a\ntouch /tmp/x"; },
                    +[](SlurmScript& t) { t.summary = "into /tmp/a\nPRISM_ARRAY_JOB"; },
                    +[](SlurmScript& t) { t.sbatchOptions = {"--comment=a\nrm -rf ~"}; },
                    +[](SlurmScript& t) { t.finish.command = "prism merge -o '/tmp/a\tb'"; }}) {
    SlurmScript bad = s;
    edit(bad);
    EXPECT_THROW(slurmScriptText(bad), Error);
  }
}

// An option the script sets itself would override it for both jobs (--array=0-5 made the one
// finishing job an array of six); a word without a dash is no option.
TEST(SlurmScript, RefusesOptionsItSetsItselfAndWordsThatAreNone) {
  EXPECT_EQ(errorOf([] { slurmScriptText(referenceScript("/work/p", "--array=0-5")); }),
            "--sbatch --array=0-5: the script sets --array itself (--tasks sets the array)");
  EXPECT_EQ(errorOf([] { slurmScriptText(referenceScript("/work/p", "-J name")); }),
            "--sbatch -J name: the script sets --job-name itself (the script names its jobs)");
  EXPECT_EQ(errorOf([] { slurmScriptText(referenceScript("/work/p", "foo")); }),
            "--sbatch foo: not an sbatch option (they start with -, e.g. --partition=gpu)");
  for (const char* own : {"--mem-per-cpu=2G", "--time=1:00:00", "-o x.out", "--dependency=afterok:1", "--parsable"})
    EXPECT_THROW(slurmScriptText(referenceScript("/work/p", own)), Error) << own;
  // Others pass, --mem-bind too, whose name begins as --mem's does.
  for (const char* other : {"--partition=gpu", "--mem-bind=local", "--account=astro", "-p gpu", "--exclusive"})
    EXPECT_NO_THROW(slurmScriptText(referenceScript("/work/p", other))) << other;
}

}  // namespace
}  // namespace prism::batch
