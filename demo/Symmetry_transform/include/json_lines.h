// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_JSON_LINES_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_JSON_LINES_H

// The few pieces of JSON the batch command writes and reads back: one object per line (JSON
// Lines), built member by member, and the first member of a line, a string, read back to tell
// which files a previous run has done.

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace examples {

// `text` as a JSON string, quotes included.
inline std::string json_string(const std::string& text)
{
  std::string out = "\"";
  for(const char c : text) {
    switch(c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if(static_cast<unsigned char>(c) < 0x20) {
          char code[8];
          std::snprintf(code, sizeof(code), "\\u%04x", unsigned(c));
          out += code;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

// A number with `digits` significant digits (null if it is not finite: JSON has no NaN).
inline std::string json_number(double x, int digits = 9)
{
  if(!std::isfinite(x)) return "null";
  std::ostringstream out;
  out.precision(digits);
  out << x;
  return out.str();
}

inline std::string json_array(const std::vector<double>& values, int digits = 9)
{
  std::string out = "[";
  for(std::size_t i = 0; i < values.size(); ++i) out += (i == 0 ? "" : ",") + json_number(values[i], digits);
  return out + "]";
}

// An object built member by member, in order; `value` is JSON text already.
class Json_object
{
public:
  Json_object& add(const std::string& name, const std::string& value)
  {
    text_ += (text_.empty() ? "{" : ",") + json_string(name) + ":" + value;
    return *this;
  }
  std::string text() const { return text_.empty() ? "{}" : text_ + "}"; }

private:
  std::string text_;
};

// The value of the first member of a JSON object on one line if it is named `name` and is a
// string (escapes decoded; \u only below 0x80); false otherwise.
inline bool first_string_member(const std::string& line, const std::string& name, std::string& value)
{
  const std::string start = "{" + json_string(name) + ":\"";
  if(line.compare(0, start.size(), start) != 0) return false;
  value.clear();
  for(std::size_t i = start.size(); i < line.size(); ++i) {
    if(line[i] == '"') return true;
    if(line[i] != '\\') { value += line[i]; continue; }
    if(++i == line.size()) return false;
    switch(line[i]) {
      case 'n': value += '\n'; break;
      case 't': value += '\t'; break;
      case 'r': value += '\r'; break;
      case 'u':
        if(i + 4 >= line.size()) return false;
        value += char(std::stoi(line.substr(i + 1, 4), nullptr, 16));
        i += 4;
        break;
      default: value += line[i]; // \" \\ \/
    }
  }
  return false; // no closing quote: a line cut short
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_JSON_LINES_H
