// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FACE_FEATURE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FACE_FEATURE_H

// The user's per-face feature of segment_by_symmetry() (named parameter face_feature_map; e.g.
// the shape diameter function of CGAL::sdf_values()), read once by face index and clustered with
// the planes' supports: symmetry tells which faces belong together, the feature (thickness) where
// a part ends, e.g. the root of a wing that the fuselage's planes reflect as well as the wing.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The values of the named parameter face_feature_map, indexed by `face_index` (a numbering of the
// faces from 0 to n - 1); empty if it is not given.
template <typename TriangleMesh, typename FaceIndexMap, typename NamedParameters>
std::vector<double> face_feature_values(const TriangleMesh& tm, const FaceIndexMap& face_index, const NamedParameters& np)
{
  std::vector<double> values;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_face_feature_map_t>::value) {
    const auto feature = parameters::get_parameter(np, internal_np::st_face_feature_map);
    values.resize(number_of_faces(tm));
    for(auto f : faces(tm)) {
      const double v = double(get(feature, f));
      if(!std::isfinite(v)) throw std::invalid_argument("segment_by_symmetry: a value of face_feature_map is not finite");
      values[std::size_t(get(face_index, f))] = v;
    }
  }
  return values;
}

// The supports of a segment's planes (rows: the faces of `faces`) with the feature as one more
// column, if there is one: rescaled to [0, 1] over the segment (the supports' range; a segment's
// own contrast, as each segment's planes are its own), times the square root of the number of
// planes, so that the feature weighs as much in the clustering's squared distances as all the
// planes together. A feature constant over the segment adds nothing.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::MatrixXd with_face_feature(const Eigen::MatrixXd& supports, const std::vector<double>& values,
                                                                      const std::vector<std::size_t>& faces);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::MatrixXd with_face_feature(const Eigen::MatrixXd& supports, const std::vector<double>& values,
                                                                      const std::vector<std::size_t>& faces)
{
  if(values.empty()) return supports;
  double lowest = values[faces.front()], highest = lowest;
  for(std::size_t f : faces) {
    lowest = (std::min)(lowest, values[f]);
    highest = (std::max)(highest, values[f]);
  }
  const double weight = std::sqrt(double((std::max)(Eigen::Index(1), supports.cols())));
  Eigen::MatrixXd features(supports.rows(), supports.cols() + 1);
  features.leftCols(supports.cols()) = supports;
  for(std::size_t i = 0; i < faces.size(); ++i)
    features(Eigen::Index(i), supports.cols()) = highest > lowest ? weight * (values[faces[i]] - lowest) / (highest - lowest) : 0.;
  return features;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FACE_FEATURE_H
