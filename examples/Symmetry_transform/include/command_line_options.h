// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H

// The command line of the examples: an input file (or several, for a batch), `--name value`
// options and `--flag`s, in any order. An example reads each option it knows once, then calls
// reject_unknown(), so that a misspelt option stops it before any work instead of being silently
// ignored.

#include <CGAL/config.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

class Command_line_options
{
public:
  // `flags` names the options that take no value (e.g. "--sdf").
  Command_line_options(int argc, char** argv, const std::set<std::string>& flags = {})
  {
    for(int a = 1; a < argc; ++a) {
      const std::string argument = argv[a];
      if(argument.rfind("--", 0) != 0) { inputs_.push_back(argument); continue; }
      if(flags.count(argument) != 0) { values_.emplace(argument, ""); continue; }
      if(a + 1 == argc) throw std::invalid_argument(argument + " expects a value");
      values_.emplace(argument, argv[++a]);
    }
  }

  // The file given on the command line or, with none, `data_file` of CGAL's sample data
  // (e.g. "meshes/bull.off", found through the environment variable CGAL_DATA_DIR).
  std::string input_file(const std::string& data_file) const
  {
    return inputs_.empty() ? CGAL::data_file_path(data_file) : inputs_.back();
  }

  // Every argument that is no option, in command-line order (the inputs of a batch).
  const std::vector<std::string>& inputs() const { return inputs_; }

  // The last value of `--name`, an integer of at least `minimum`, or `default_value`.
  std::size_t integer(const std::string& name, std::size_t default_value, std::size_t minimum = 1) const
  {
    const std::string text = last(name);
    if(text.empty()) return default_value;
    if(text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos || std::stoull(text) < minimum)
      throw std::invalid_argument(name + " expects an integer >= " + std::to_string(minimum) + ", not '" + text + "'");
    return std::size_t(std::stoull(text));
  }

  double real(const std::string& name, double default_value) const
  {
    const std::string text = last(name);
    std::size_t read = 0;
    try {
      const double value = text.empty() ? default_value : std::stod(text, &read);
      if(read == text.size()) return value;
    } catch(const std::logic_error&) {} // not a number
    throw std::invalid_argument(name + " expects a number, not '" + text + "'");
  }

  std::string text(const std::string& name, const std::string& default_value) const
  {
    const std::string value = last(name);
    return value.empty() ? default_value : value;
  }

  bool flag(const std::string& name) const
  {
    known_.insert(name);
    return values_.count(name) != 0;
  }

  // Every value of a repeatable option, in command-line order.
  std::vector<std::string> all(const std::string& name) const
  {
    known_.insert(name);
    std::vector<std::string> values;
    const auto range = values_.equal_range(name);
    for(auto v = range.first; v != range.second; ++v) values.push_back(v->second);
    return values;
  }

  void reject_unknown() const
  {
    for(const auto& option : values_)
      if(known_.count(option.first) == 0) throw std::invalid_argument("unknown option: " + option.first);
  }

private:
  std::string last(const std::string& name) const
  {
    const std::vector<std::string> values = all(name);
    return values.empty() ? std::string() : values.back();
  }

  std::vector<std::string> inputs_;
  std::multimap<std::string, std::string> values_; // equal keys keep their command-line order
  mutable std::set<std::string> known_;            // the options asked for so far
};

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H
