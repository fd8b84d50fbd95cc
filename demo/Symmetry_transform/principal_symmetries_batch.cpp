// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include "batch_runner.h"
#include "command_line_options.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

const char* const usage = R"(usage: principal_symmetries_batch [FILE|FOLDER ...] [--list FILE ...] [--output FILE.jsonl]
         [--jobs N] [--shard i/n] [--shrec FOLDER] [--retry-errors] [--timeout SECONDS]
         [--memory-limit GIB] [--resolution N] [--planes K] [--samples N] [--sde-samples N]
         [--seed S] [--threads-per-shape T]

Finds the principal symmetries of every shape of a collection: mesh files (OFF, PLY, OBJ, STL,
read as repaired triangle soups) and point sets (XYZ, PWN, PLY, OFF, LAS, with their normals if
they have some). Writes one JSON Lines record per file: its planes with their symmetry, support
and symmetry distance error, the time taken, or the error and why. A run that is started again
skips the files already recorded; a bad file never stops it (each file is processed in a
process of its own); files are processed in parallel, each on one thread, so that the results
do not depend on the number of jobs. For a cluster, give each task a shard of the same list
(--shard i/n) and an output of its own; concatenate the outputs (see the manual, section
"Real-World Input", for a Slurm job array and GNU parallel).

  FILE|FOLDER           shape files, and folders searched recursively for them
  --list FILE           a file listing shapes, a path per line; '#' starts a comment (repeatable)
  --output FILE.jsonl   the records, appended (default principal_symmetries.jsonl)
  --jobs N              files processed at once (default: the number of cores)
  --shard i/n           processes every n-th file from the i-th only, 0 <= i < n (default: all)
  --shrec FOLDER        also writes a SHREC 2023 result file per shape there (default: none)
  --retry-errors        processes again the files whose record is an error
  --timeout SECONDS     stops a file after this time, an error record (default 0: no limit)
  --memory-limit GIB    the memory of each file's process (default 0: no limit)
  --resolution N        GEDT samples and PRST bins per axis, at least 8 (default 64)
  --planes K            at most K planes per shape, strongest first (default 10)
  --samples N           Monte Carlo samples of the PRST (default 500000)
  --sde-samples N       samples of the symmetry distance error (default 20000)
  --seed S              random seed: the same seed, the same planes (default 0)
  --threads-per-shape T threads of each shape's detection (default 1)
)";

namespace batch = examples::batch;

// The options of each shape's detection; the defaults are the package's.
batch::Settings settings_of(const examples::Command_line_options& options)
{
  batch::Settings s;
  s.resolution = int(options.integer("--resolution", std::size_t(s.resolution), 8));
  s.max_planes = options.integer("--planes", s.max_planes);
  s.monte_carlo_samples = options.integer("--samples", s.monte_carlo_samples);
  s.sde_samples = options.integer("--sde-samples", s.sde_samples);
  s.seed = unsigned(options.integer("--seed", s.seed, 0));
  s.threads_per_shape = unsigned(options.integer("--threads-per-shape", s.threads_per_shape));
  s.shrec_folder = options.text("--shrec", "");
  return s;
}

batch::Job_limits limits_of(const examples::Command_line_options& options)
{
  batch::Job_limits limits;
  limits.jobs = options.integer("--jobs", (std::max)(1u, std::thread::hardware_concurrency()));
  limits.seconds = options.real("--timeout", 0.);
  limits.memory_gib = options.real("--memory-limit", 0.);
  return limits;
}

// The files of this run: the shard of the inputs, less those already in the output.
std::vector<std::string> files_to_do(const examples::Command_line_options& options, const std::vector<std::string>& lists,
                                     const std::string& shard, const std::string& output, bool retry_errors)
{
  const std::vector<std::string> all = batch::shard_of(batch::input_files(options.inputs(), lists), shard);
  if(all.empty()) throw std::invalid_argument("no input: give files, folders or --list FILE");
  const std::set<std::string> done = batch::files_done(output, retry_errors);
  std::vector<std::string> files;
  for(const std::string& f : all)
    if(done.count(f) == 0) files.push_back(f);
  std::cout << all.size() << " files, " << all.size() - files.size() << " already in " << output << ", " << files.size()
            << " to do\n";
  return files;
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage, {"--retry-errors"});
  const std::string output = options.text("--output", "principal_symmetries.jsonl"), shard = options.text("--shard", "");
  const std::vector<std::string> lists = options.all("--list");
  const bool retry_errors = options.flag("--retry-errors");
  const batch::Settings settings = settings_of(options);
  const batch::Job_limits limits = limits_of(options);
  options.validate();
  const std::vector<std::string> files = files_to_do(options, lists, shard, output, retry_errors);
  if(files.empty()) return EXIT_SUCCESS;
  if(!settings.shrec_folder.empty()) std::filesystem::create_directories(settings.shrec_folder);

  std::ofstream out(output, std::ios::app | std::ios::binary); // records are appended, one line each
  if(!out) throw std::runtime_error("cannot write " + output);
  batch::Progress progress(files.size());
  batch::run_jobs(files, settings, limits, out, progress);
  std::cout << files.size() << " files in " << progress.seconds() << " s with " << limits.jobs << " jobs: "
            << files.size() - progress.errors() << " with planes, " << progress.errors() << " errors; records in "
            << output << "\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
