// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Helpers shared by the benchmark programs: comma-separated lists, medians, sample mesh paths,
// "--name value" options.

#ifndef SYMMETRY_TRANSFORM_BENCHMARK_UTILITIES_H
#define SYMMETRY_TRANSFORM_BENCHMARK_UTILITIES_H

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace benchmark_utilities {

// The non-empty items of a comma-separated list.
inline std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  for(std::string item; std::getline(in, item, ',');)
    if(!item.empty()) items.push_back(item);
  return items;
}

// The median (the mean of the two middle values for an even count).
inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// A mesh given as a bare name is one of CGAL's sample meshes, in SYMMETRY_TRANSFORM_DATA_DIR/meshes/;
// a name with a '/' is a path.
inline std::string mesh_path(const std::string& name)
{
  return name.find('/') == std::string::npos ? std::string(SYMMETRY_TRANSFORM_DATA_DIR) + "/meshes/" + name : name;
}

// The "--name value" pairs of a command line, in order (a name without a value: invalid_argument).
inline std::vector<std::pair<std::string, std::string>> option_pairs(int argc, char** argv)
{
  std::vector<std::pair<std::string, std::string>> pairs;
  for(int a = 1; a < argc; a += 2) {
    if(a + 1 == argc) throw std::invalid_argument(std::string(argv[a]) + " expects a value");
    pairs.emplace_back(argv[a], argv[a + 1]);
  }
  return pairs;
}

// Every .off file of CGAL's sample meshes (SYMMETRY_TRANSFORM_DATA_DIR/meshes), sorted by name.
inline std::vector<std::string> all_sample_meshes()
{
  std::vector<std::string> names;
  for(const auto& entry : std::filesystem::directory_iterator(std::string(SYMMETRY_TRANSFORM_DATA_DIR) + "/meshes"))
    if(entry.path().extension() == ".off") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Prints "program: message" and the program's usage (its options after its name) on std::cerr,
// then exits with status 2.
[[noreturn]] inline void fail_with_usage(const char* program, const char* usage_options, const std::string& message)
{
  std::cerr << program << ": " << message << "\nusage: " << program << usage_options;
  std::exit(2);
}

// The value of `option` as a positive integer (or non-negative if `zero_allowed`); fails with
// the usage otherwise.
inline unsigned natural_option(const char* program, const char* usage_options, const std::string& option,
                               const std::string& value, bool zero_allowed)
{
  std::size_t end = 0;
  long v = 0;
  try { v = std::stol(value, &end); } catch(const std::exception&) { end = 0; }
  if(end != value.size() || v < (zero_allowed ? 0 : 1))
    fail_with_usage(program, usage_options,
                    option + " needs a " + (zero_allowed ? "non-negative" : "positive") + " integer, not '" + value + "'");
  return unsigned(v);
}

} // namespace benchmark_utilities

#endif // SYMMETRY_TRANSFORM_BENCHMARK_UTILITIES_H
