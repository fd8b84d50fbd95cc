// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_RUNNER_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_RUNNER_H

// How the batch command runs over a collection: the list of files (folders searched, list files
// read, one shard of them kept), the files a previous run has done (their records in the output),
// and the jobs: each file in a process of its own (POSIX fork), so that no file can stop the run,
// not even one that crashes, exhausts memory or never ends; the parent alone appends the records
// to the output, one line each, flushed, and prints the progress on stderr.

#include "batch_shape.h"
#include "json_lines.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {
namespace batch {

// The file extensions searched for in a folder: those CGAL reads as polygons or points.
inline bool has_shape_extension(const std::filesystem::path& path)
{
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl" || e == ".xyz" || e == ".pwn" || e == ".las";
}

// The files of a run, each once, in order: the `arguments` (a file as it is, a folder searched
// recursively, its files sorted) and the lines of the `lists` (a path per line; blank lines and
// lines starting with '#' skipped). A path is the key of its record: kept as written.
inline std::vector<std::string> input_files(const std::vector<std::string>& arguments, const std::vector<std::string>& lists)
{
  std::vector<std::string> files;
  for(const std::string& a : arguments) {
    if(!std::filesystem::is_directory(a)) { files.push_back(a); continue; }
    std::vector<std::string> found;
    for(const auto& entry : std::filesystem::recursive_directory_iterator(a))
      if(entry.is_regular_file() && has_shape_extension(entry.path())) found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  for(const std::string& list : lists) {
    std::ifstream is(list);
    if(!is) throw std::runtime_error("cannot read the list " + list);
    for(std::string line; std::getline(is, line);) {
      while(!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if(!line.empty() && line[0] != '#') files.push_back(line);
    }
  }
  std::set<std::string> seen;
  files.erase(std::remove_if(files.begin(), files.end(), [&](const std::string& f) { return !seen.insert(f).second; }),
              files.end());
  return files;
}

// Shard `index` of `count` ("i/n", 0 <= i < n): every n-th file from the i-th, so that n tasks
// given the same list share it out.
inline std::vector<std::string> shard_of(const std::vector<std::string>& files, const std::string& shard)
{
  std::size_t index = 0, count = 1;
  char slash = 0;
  std::istringstream in(shard);
  if(!shard.empty() && (!(in >> index >> slash >> count) || slash != '/' || count == 0 || index >= count || !in.eof()))
    throw std::invalid_argument("--shard expects i/n with 0 <= i < n, not '" + shard + "'");
  std::vector<std::string> kept;
  for(std::size_t f = index; f < files.size(); f += count) kept.push_back(files[f]);
  return kept;
}

// The files that have a record in `output`, which is cleaned first: a last line cut short (a run
// killed while writing) is dropped, and with `retry_errors` the records of errors too, so that
// these files are done again.
inline std::set<std::string> files_done(const std::string& output, bool retry_errors)
{
  std::ifstream is(output, std::ios::binary);
  if(!is) return {};
  std::vector<std::string> kept;
  std::set<std::string> done;
  bool dropped = false;
  std::string line, file;
  while(std::getline(is, line)) {
    const bool complete = !is.eof() && first_string_member(line, "file", file);
    const bool error = line.find("\"status\":\"error\"") != std::string::npos;
    if(!complete || (retry_errors && error)) { dropped = true; continue; }
    kept.push_back(line);
    done.insert(file);
  }
  if(dropped) {
    is.close();
    const std::string temporary = output + ".tmp";
    std::ofstream os(temporary, std::ios::binary | std::ios::trunc);
    for(const std::string& l : kept) os << l << '\n';
    if(!os.flush()) throw std::runtime_error("cannot rewrite " + output);
    os.close();
    std::filesystem::rename(temporary, output);
  }
  return done;
}

// How a run goes: done / total, rate, time left, errors; on a terminal one line kept up to
// date, elsewhere (a cluster's log) a line per percent.
class Progress
{
public:
  explicit Progress(std::size_t total) : total_(total), terminal_(isatty(STDERR_FILENO) != 0) {}

  void completed(bool error)
  {
    ++done_;
    errors_ += error ? 1 : 0;
    if(terminal_ || done_ % (std::max)(std::size_t(1), total_ / 100) == 0 || done_ == total_) print();
  }

  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  std::size_t errors() const { return errors_; }

private:
  static std::string duration(double seconds)
  {
    const long s = long(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    return text;
  }

  void print() const
  {
    const double elapsed = seconds(), rate = double(done_) / (std::max)(elapsed, 1e-9);
    std::ostringstream line;
    line.precision(3);
    line << "[" << done_ << "/" << total_ << "] " << rate << " shapes/s, " << duration(elapsed) << " elapsed, "
         << duration(double(total_ - done_) / (std::max)(rate, 1e-9)) << " left, " << errors_ << " errors";
    std::cerr << (terminal_ ? "\r" : "") << line.str() << (terminal_ && done_ < total_ ? "   " : "\n") << std::flush;
  }

  std::size_t total_, done_ = 0, errors_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// How the jobs run: how many at once, and the limits of each (0: none).
struct Job_limits
{
  std::size_t jobs = 1;
  double seconds = 0.;
  double memory_gib = 0.;
};

// One file in its own process: its pipe, where the child writes the record.
struct Job
{
  pid_t pid = -1;
  int pipe = -1;
  std::string file, output;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  bool killed = false, ended = false;
};

inline void write_all(int fd, const std::string& text)
{
  for(std::size_t written = 0; written < text.size();) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if(n <= 0) return;
    written += std::size_t(n);
  }
}

inline Job start_job(const std::string& file, const Settings& settings, const Job_limits& limits)
{
  int fds[2];
  if(::pipe(fds) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if(pid < 0) throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  if(pid == 0) { // the child: one file, its record on the pipe
    ::close(fds[0]);
    if(limits.memory_gib > 0.) {
      const rlim_t bytes = rlim_t(limits.memory_gib * 1073741824.);
      const rlimit limit{bytes, bytes};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    write_all(fds[1], shape_record(file, settings) + "\n");
    ::_exit(0);
  }
  ::close(fds[1]);
  Job job;
  job.pid = pid;
  job.pipe = fds[0];
  job.file = file;
  return job;
}

// The record of a job whose process has ended with `status`: the child's, or an error that
// says how it ended.
inline std::string record_of_ended_job(const Job& job, int status, const Job_limits& limits)
{
  if(WIFEXITED(status) && !job.output.empty() && job.output.back() == '\n')
    return job.output.substr(0, job.output.size() - 1);
  std::string reason;
  if(job.killed) reason = "stopped after the time limit of " + json_number(limits.seconds, 6) + " s";
  else if(WIFSIGNALED(status))
    reason = "crashed (signal " + std::to_string(WTERMSIG(status)) + ": " + ::strsignal(WTERMSIG(status)) + ")";
  else reason = "ended without a result (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
  return Json_object()
    .add("file", json_string(job.file))
    .add("status", json_string("error"))
    .add("reason", json_string(reason))
    .add("seconds", json_number(seconds, 4))
    .text();
}

// Reads what a job's child has written; marks the job ended at the end of its pipe.
inline void read_pipe(Job& job)
{
  char buffer[65536];
  const ssize_t n = ::read(job.pipe, buffer, sizeof(buffer));
  if(n > 0) job.output.append(buffer, std::size_t(n));
  else if(n == 0 || errno != EINTR) job.ended = true;
}

// Runs the files, `limits.jobs` at a time, appending each record to `output` as it comes.
inline void run_jobs(const std::vector<std::string>& files, const Settings& settings, const Job_limits& limits,
                     std::ofstream& output, Progress& progress)
{
  std::vector<Job> running;
  std::size_t next = 0;
  while(next < files.size() || !running.empty()) {
    while(running.size() < limits.jobs && next < files.size()) running.push_back(start_job(files[next++], settings, limits));
    std::vector<pollfd> fds;
    for(const Job& job : running) fds.push_back({job.pipe, POLLIN, 0});
    ::poll(fds.data(), nfds_t(fds.size()), 200);
    for(std::size_t j = 0; j < running.size(); ++j)
      if(fds[j].revents != 0) read_pipe(running[j]);
    for(auto job = running.begin(); job != running.end();) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job->start).count();
      if(!job->ended && limits.seconds > 0. && seconds > limits.seconds && !job->killed) {
        ::kill(job->pid, SIGKILL);
        job->killed = true;
      }
      if(!job->ended) { ++job; continue; }
      int status = 0;
      ::waitpid(job->pid, &status, 0);
      ::close(job->pipe);
      const std::string record = record_of_ended_job(*job, status, limits);
      output << record << '\n' << std::flush;
      progress.completed(record.find("\"status\":\"error\"") != std::string::npos);
      job = running.erase(job);
    }
  }
}

} // namespace batch
} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_RUNNER_H
