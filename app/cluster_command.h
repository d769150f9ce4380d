// `prism cluster script reference|validate|lut|prt …`: the bash script that submits Prism's batch work
// to Slurm as an array of --tasks tasks and the job that puts their parts together after them
// (batch/slurm_script.h), with each job's resources: --cpus per task (prism's --threads), memory
// estimated from what the task holds (below), and --time. Paths in it are absolute, and the jobs
// run this prism executable: a cluster's login and compute nodes share the file system. Jobs get
// the environment of the shell that submits them (sbatch's default): PRISM_CACHE_DIR and
// PRISM_DATA_DIR reach them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/prt_commands.h"
#include "app/reference_commands.h"
#include "app/upsampling_commands.h"
#include "harness/validate.h"

namespace prism::app {

struct ClusterOptions {
  int tasks = 0;
  int cpusPerTask = 1;
  std::string time = "01:00:00";
  std::vector<std::string> sbatchOptions;  // more #SBATCH lines
  // reference
  ReferenceOptions reference;
  std::string split = "rows";              // rows | samples
  std::filesystem::path parts;             // default: OUT.parts beside the output
  // validate
  harness::ValidateOptions validate;
  // lut
  LutOptions lut;
  // prt
  PrtBakeOptions prt;
};

void printReferenceClusterScript(const ClusterOptions& options);
void printValidateClusterScript(const ClusterOptions& options);
void printLutClusterScript(const ClusterOptions& options);
void printPrtClusterScript(const ClusterOptions& options);

}  // namespace prism::app
