// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BOP_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BOP_SYMMETRIES_H

// The symmetries of an object in the fields of the BOP benchmark's models_info.json, to paste
// into the object's entry: "symmetries_discrete", the rotations by 2 pi j / k (j = 1 ... k - 1)
// about each axis of order k as row-major 4x4 matrices (translation in the mesh's units), and
// "symmetries_continuous", the direction ("axis") and a point ("offset") of each continuous axis.

#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

// A 4x4 row-major matrix as a JSON array.
template <typename Transformation>
std::string json_matrix(const Transformation& t)
{
  std::ostringstream out;
  out << std::setprecision(12) << "[";
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) out << (i + j ? ", " : "") << (i < 3 ? t.m(i, j) : (j == 3 ? 1. : 0.));
  return out.str() + "]";
}

// A point or vector as a JSON array of its three coordinates.
template <typename Triple>
std::string json_triple(const Triple& t)
{
  std::ostringstream out;
  out << std::setprecision(12) << "[" << t.x() << ", " << t.y() << ", " << t.z() << "]";
  return out.str();
}

// A JSON list, one item per line.
inline std::string json_list(const std::vector<std::string>& items)
{
  std::string text;
  for(std::size_t i = 0; i < items.size(); ++i) text += (i ? ",\n    " : "\n    ") + items[i];
  return "[" + text + (items.empty() ? "]" : "\n  ]");
}

// The BOP fields of the symmetries: every rotation of each discrete axis, each continuous axis;
// then the point group's name, if given (a field of ours, which BOP's readers skip).
template <typename K>
std::string bop_json(const std::vector<CGAL::Symmetry_transform::Rotational_symmetry<K>>& symmetries,
                     const std::string& point_group = "")
{
  std::vector<std::string> discrete, continuous;
  for(const auto& s : symmetries) {
    if(s.order == 0)
      continuous.push_back("{\"axis\": " + json_triple(s.axis.to_vector()) + ", \"offset\": " +
                           json_triple(s.axis.point()) + "}");
    for(int j = 1; j < s.order; ++j)
      discrete.push_back(json_matrix(CGAL::Symmetry_transform::rotation_about_axis(s.axis, 2. * CGAL_PI * j / s.order)));
  }
  return "{\n  \"symmetries_discrete\": " + json_list(discrete) + ",\n  \"symmetries_continuous\": " +
         json_list(continuous) + (point_group.empty() ? "" : ",\n  \"point_group\": \"" + point_group + "\"") + "\n}\n";
}

template <typename K>
void write_bop_json(const std::string& file, const std::vector<CGAL::Symmetry_transform::Rotational_symmetry<K>>& symmetries,
                    const std::string& point_group = "")
{
  std::ofstream out(file);
  if(!(out << bop_json(symmetries, point_group))) throw std::runtime_error("cannot write " + file);
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BOP_SYMMETRIES_H
