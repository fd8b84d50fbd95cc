// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H

// The command line of the examples: an input file (or several, for a batch), `--name value`
// (or `--name=value`) options and `--flag`s, in any order; `--` ends the options (for a file
// whose name starts with '-'). Each example gives its usage text once, to the constructor:
// `--help` or `-h` prints it and exits with status 0. An example reads each option it knows
// once, then calls validate(), so that a misspelt option stops it before any work instead of
// being silently ignored. The errors of the command line name the option and point to --help.

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

class Command_line_options
{
public:
  // `usage` is what --help prints: the command line, what the program does, its arguments and
  // options with their defaults; `flags` names the options that take no value (e.g. "--sdf").
  Command_line_options(int argc, char** argv, const char* usage, const std::set<std::string>& flags = {})
    : program_(argc > 0 ? std::filesystem::path(argv[0]).filename().string() : std::string("example")), usage_(usage)
  {
    const std::vector<std::string> arguments(argv + (argc > 0 ? 1 : 0), argv + argc);
    print_usage_if_asked(arguments);
    bool options_ended = false;
    for(std::size_t a = 0; a < arguments.size(); ++a) {
      const std::string& argument = arguments[a];
      if(options_ended || !is_option(argument)) { inputs_.push_back(argument); continue; }
      if(argument == "--") { options_ended = true; continue; }
      const std::size_t equal = argument.find('=');
      if(argument.rfind("--", 0) == 0 && equal != std::string::npos)
        values_.emplace(argument.substr(0, equal), argument.substr(equal + 1));
      else if(flags.count(argument) != 0) values_.emplace(argument, std::string());
      else if(a + 1 < arguments.size() && !is_option(arguments[a + 1])) values_.emplace(argument, arguments[++a]);
      else values_.emplace(argument, std::nullopt); // an error if the program knows it, see all()
    }
  }

  // The file given on the command line or, with none, `data_file` of CGAL's sample data (e.g.
  // "meshes/bull.off", found through the environment variable CGAL_DATA_DIR); validate() says
  // so if that one is missing. Throws if more than one file is given.
  std::string input_file(const std::string& data_file) const
  {
    if(inputs_.size() > 1)
      throw usage_error("one input file expected, not " + std::to_string(inputs_.size()) + " ('" + inputs_[0] + "', '" +
                        inputs_[1] + "'" + (inputs_.size() > 2 ? ", ..." : "") + ")");
    if(!inputs_.empty()) return inputs_.front();
    default_input_ = data_file;
    return sample_data_path(data_file);
  }

  // Every argument that is no option, in command-line order (the inputs of a batch).
  const std::vector<std::string>& inputs() const { return inputs_; }

  // The last value of `--name`, an integer of at least `minimum`, or `default_value`.
  std::size_t integer(const std::string& name, std::size_t default_value, std::size_t minimum = 1) const
  {
    const std::string text = last(name);
    if(text.empty()) return default_value;
    if(text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos || std::stoull(text) < minimum)
      throw usage_error(name + " expects an integer >= " + std::to_string(minimum) + ", not '" + text + "'");
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
    throw usage_error(name + " expects a number, not '" + text + "'");
  }

  std::string text(const std::string& name, const std::string& default_value) const
  {
    const std::string value = last(name);
    return value.empty() ? default_value : value;
  }

  bool flag(const std::string& name) const
  {
    const std::vector<std::string> values = all(name);
    for(const std::string& v : values)
      if(!v.empty()) throw usage_error(name + " takes no value, not '" + v + "'");
    return !values.empty();
  }

  // Every value of a repeatable option, in command-line order.
  std::vector<std::string> all(const std::string& name) const
  {
    known_.insert(name);
    std::vector<std::string> values;
    const auto range = values_.equal_range(name);
    for(auto v = range.first; v != range.second; ++v) {
      if(!v->second) throw usage_error(name + " expects a value");
      values.push_back(*v->second);
    }
    return values;
  }

  // To call once every option is read: throws on an option the program does not know and, when
  // no file was given, if the default file of CGAL's sample data is missing. Throws
  // std::logic_error on an option the program reads but its usage text does not mention.
  void validate() const
  {
    for(const auto& option : values_)
      if(known_.count(option.first) == 0) throw usage_error("unknown option '" + option.first + "'");
    for(const std::string& name : known_)
      if(usage_.find(name) == std::string::npos) throw std::logic_error("the usage text does not mention " + name);
    if(default_input_.empty() || std::filesystem::is_regular_file(sample_data_path(default_input_))) return;
    const char* directory = std::getenv("CGAL_DATA_DIR");
    throw std::runtime_error("no file given, and the default input " + default_input_ + " is not in CGAL's sample data (" +
                             (directory == nullptr ? std::string("CGAL_DATA_DIR is not set")
                                                   : "CGAL_DATA_DIR is '" + std::string(directory) + "'") +
                             "): give a file, or set CGAL_DATA_DIR to the folder of CGAL's sample data (package "
                             "libcgal-demo); see " + program_ + " --help");
  }

private:
  // An option: '-' then a letter or '-' ("-1.5" and "-" are no options).
  static bool is_option(const std::string& argument)
  {
    return argument.size() > 1 && argument[0] == '-' && argument.find_first_of("0123456789.", 1) != 1;
  }

  // `data_file` in CGAL's sample data, as CGAL::data_file_path() makes it (without its warning:
  // validate() explains a missing file).
  static std::string sample_data_path(const std::string& data_file)
  {
    const char* directory = std::getenv("CGAL_DATA_DIR");
#ifdef CGAL_DATA_DIR
    if(directory == nullptr) directory = CGAL_DATA_DIR;
#endif
    std::string path = directory == nullptr ? std::string() : std::string(directory);
    if(!path.empty() && path.back() != '/') path += '/';
    return path + data_file;
  }

  // Prints the usage and exits if an argument before "--" is --help or -h.
  void print_usage_if_asked(const std::vector<std::string>& arguments) const
  {
    for(const std::string& argument : arguments) {
      if(argument == "--") return;
      if(argument != "--help" && argument != "-h") continue;
      std::cout << usage_ << (usage_.empty() || usage_.back() == '\n' ? "" : "\n")
                << "\nOptions may come in any order, as --name value or --name=value; -- ends them (for a file\n"
                << "whose name starts with -). -h, --help: prints this help.\n";
      std::exit(EXIT_SUCCESS);
    }
  }

  std::invalid_argument usage_error(const std::string& what) const
  {
    return std::invalid_argument(what + " (see " + program_ + " --help)");
  }

  std::string last(const std::string& name) const
  {
    const std::vector<std::string> values = all(name);
    return values.empty() ? std::string() : values.back();
  }

  std::string program_, usage_;
  std::vector<std::string> inputs_;
  std::multimap<std::string, std::optional<std::string>> values_; // no value: given without one
  mutable std::set<std::string> known_;                             // the options asked for so far
  mutable std::string default_input_;                               // the sample data file used, if no file was given
};

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COMMAND_LINE_OPTIONS_H
