// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H

// The split of one segment of segment_by_symmetry(): its principal symmetries detected on the
// segment alone, the faces' supports of each plane as feature vectors, the stopping rule, the
// fuzzy clustering and graph cut, and the connected parts of the labels. Segments of one level
// are split in parallel.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>
#include <CGAL/Symmetry_transform/internal/detection/face_support.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>
#include <CGAL/Symmetry_transform/internal/segmentation/face_feature.h>
#include <CGAL/Symmetry_transform/internal/segmentation/fuzzy_clustering.h>
#include <CGAL/Symmetry_transform/internal/segmentation/settings.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The largest distance from the area-weighted centroid of the faces to their vertices.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double radius_of(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces);

struct Split
{
  std::vector<Principal_symmetry<Dkernel>> planes; // of the segment, strongest first
  std::vector<double> reflected_fractions;         // of each plane
  bool partial_symmetry = false;                   // the stopping rule: some plane reflects part of the segment
  std::vector<std::vector<std::size_t>> parts;     // the children (faces of the mesh), if split
  double seconds = 0.;                             // in all
  double detection_seconds = 0., feature_seconds = 0.; // of which the detection, the features
};

// Features: the support of each plane on each face (rows: the faces of `faces`), L_ij in the
// thesis, "the average value in the GEDT of a point of face i reflected by plane j", at the
// face_support_points() of the face. The GEDT is evaluated exactly, from the distance to the nearest
// triangle that the detection's closest-triangle field offers, with the Gaussian width `sigma`.
// Points reflected beyond the field's band get 0. The field is in the coordinates `local` (those
// of its surface), the mesh and the planes in the input's.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::MatrixXd face_supports(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces,
                                                                  const std::vector<Principal_symmetry<Dkernel>>& planes,
                                                                  const Closest_triangle_field& field, const Local_coordinates& local, double sigma,
                                                                  unsigned threads);

// The fraction of the segment's area that each plane reflects onto it (the area-weighted mean of
// its column of supports; `area`: the sum of `areas`); sets split.partial_symmetry by the stopping
// rule, a plane reflecting between `partial_fraction` and its complement.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void record_reflected_fractions(const Eigen::MatrixXd& features, const std::vector<double>& areas, double area,
                                                                    double partial_fraction, Split& split);

// The connected parts of the two labels of the clustering and graph cut of the features, the
// parts smaller than settings.smallest_part_fraction of the segment merged into their neighbours.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> parts_of_clustering(const Segmentation_mesh& mesh,
                                                                                              const std::vector<std::size_t>& faces,
                                                                                              const Eigen::MatrixXd& features,
                                                                                              const std::vector<double>& areas, double area,
                                                                                              const Segmentation_settings& settings);

// The split of the segment made of `faces` (connected, sorted), covering `fraction` of the mesh.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Split split_segment(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces, double fraction,
                                                        long resolution, const Segmentation_settings& settings, unsigned threads);

// The splits of the segments `examined` (indices into `faces_of`), in parallel: each of the
// `threads` workers takes whole segments (the detection on a small segment keeps one core busy
// poorly), the threads left over going to the detections themselves.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Split> split_segments(const Segmentation_mesh& mesh,
                                                                      const std::vector<std::vector<std::size_t>>& faces_of,
                                                                      const std::vector<std::size_t>& examined,
                                                                      const Segmentation_settings& settings, double total_area,
                                                                      double root_radius);

// The parts merged, smallest first, into their neighbours until at most `count` remain.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> merge_down_to(const Segmentation_mesh& mesh,
                                                                                        std::vector<std::vector<std::size_t>> parts,
                                                                                        std::size_t count);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double radius_of(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces)
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double area = 0.;
  for(std::size_t f : faces) {
    const auto& t = mesh.triangles[f];
    center += mesh.areas[f] * (t[0] + t[1] + t[2]) / 3.;
    area += mesh.areas[f];
  }
  if(area > 0.) center /= area;
  double r2 = 0.;
  for(std::size_t f : faces)
    for(const Eigen::Vector3d& p : mesh.triangles[f]) r2 = (std::max)(r2, (p - center).squaredNorm());
  return std::sqrt(r2);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::MatrixXd face_supports(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces,
                                                                  const std::vector<Principal_symmetry<Dkernel>>& planes,
                                                                  const Closest_triangle_field& field, const Local_coordinates& local, double sigma,
                                                                  unsigned threads)
{
  const double inverse_two_sigma2 = 1. / (2. * sigma * sigma);
  std::vector<Dplane> mirrors;
  for(const auto& plane : planes) mirrors.push_back(local.to_local(to_dplane(plane.plane)));
  Eigen::MatrixXd features = Eigen::MatrixXd::Zero(Eigen::Index(faces.size()), Eigen::Index(planes.size()));
  // Face by face, the points of a face made when they are used: a table of them would be 96
  // bytes per face, a hundred megabytes on a million faces.
  parallel_for(faces.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i) {
      const std::array<Eigen::Vector3d, 3>& t = mesh.triangles[faces[i]];
      const std::array<Eigen::Vector3d, 4> points =
        face_support_points(local.to_local(t[0]), local.to_local(t[1]), local.to_local(t[2]));
      for(std::size_t j = 0; j < mirrors.size(); ++j) {
        double sum = 0.;
        for(const Eigen::Vector3d& p : points) {
          const Eigen::Vector3d q = mirrors[j].reflect(p);
          const auto [on_surface, triangle] = field.nearest_in_cell(q);
          if(triangle >= 0) sum += std::exp(-(q - on_surface).squaredNorm() * inverse_two_sigma2);
        }
        features(Eigen::Index(i), Eigen::Index(j)) = sum / double(points.size());
      }
      if(!parallel_step()) return;
    }
  });
  return features;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void record_reflected_fractions(const Eigen::MatrixXd& features, const std::vector<double>& areas, double area,
                                                                    double partial_fraction, Split& split)
{
  for(Eigen::Index j = 0; j < features.cols(); ++j) {
    double supported = 0.;
    for(std::size_t i = 0; i < areas.size(); ++i) supported += areas[i] * features(Eigen::Index(i), j);
    const double fraction = supported / area;
    split.reflected_fractions.push_back(fraction);
    if(fraction >= partial_fraction && fraction <= 1. - partial_fraction) split.partial_symmetry = true;
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> parts_of_clustering(const Segmentation_mesh& mesh,
                                                                                              const std::vector<std::size_t>& faces,
                                                                                              const Eigen::MatrixXd& features,
                                                                                              const std::vector<double>& areas, double area,
                                                                                              const Segmentation_settings& settings)
{
  const Fuzzy_two_clusters clusters = fuzzy_two_clusters(features, areas, settings.seed);
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> local(mesh.number_of_faces(), none);
  for(std::size_t i = 0; i < faces.size(); ++i) local[faces[i]] = i;
  const std::vector<std::size_t> labels = graph_cut_labels(mesh, faces, local, clusters.membership, settings.lambda);
  return merge_small_parts(mesh, connected_parts(mesh, faces, local, labels), settings.smallest_part_fraction * area);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Split split_segment(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces, double fraction,
                                                        long resolution, const Segmentation_settings& settings, unsigned threads)
{
  const auto start = std::chrono::steady_clock::now();
  auto since_start = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  Split split;
  const auto np = detection_parameters(settings, fraction, resolution, threads);
  const Triangle_surface<Dkernel> surface(triangles_of_faces(mesh, faces), np);
  split.planes = detection_of_surface(surface, np).symmetries;
  throw_if_cancelled(); // the detection keeps what it has; the segmentation stops
  split.detection_seconds = since_start();

  // Half the detection's Gaussian width: supports closer to 0 or 1 (a face is mirrored or it is
  // not) cluster more cleanly.
  const double sigma = feature_width_factor * isp_settings(np, surface.gedt).sigma;
  const Eigen::MatrixXd features = face_supports(mesh, faces, split.planes, surface.field, surface.local, sigma, threads);
  std::vector<double> areas(faces.size());
  double area = 0.;
  for(std::size_t i = 0; i < faces.size(); ++i) {
    areas[i] = mesh.areas[faces[i]];
    area += areas[i];
  }
  record_reflected_fractions(features, areas, area, settings.partial_symmetry_fraction, split);
  split.feature_seconds = since_start() - split.detection_seconds;
  if(split.partial_symmetry) {
    split.parts = parts_of_clustering(mesh, faces, with_face_feature(features, mesh.face_features, faces), areas, area, settings);
    if(split.parts.size() < 2) split.parts.clear();
  }
  split.seconds = since_start();
  return split;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Split> split_segments(const Segmentation_mesh& mesh,
                                                                      const std::vector<std::vector<std::size_t>>& faces_of,
                                                                      const std::vector<std::size_t>& examined,
                                                                      const Segmentation_settings& settings, double total_area,
                                                                      double root_radius)
{
  std::vector<Split> splits(examined.size());
  if(examined.empty()) return splits;
  const unsigned workers = unsigned((std::min<std::size_t>)(settings.threads, examined.size()));
  const unsigned inner = (std::max)(1u, settings.threads / workers);
  // Round robin over the segments, sorted by decreasing size: the work is shared evenly.
  parallel_for(workers, workers, [&](unsigned worker, std::size_t, std::size_t) {
    for(std::size_t k = worker; k < examined.size() && !stop_requested(); k += workers)
    {
      double area = 0.;
      for(std::size_t f : faces_of[examined[k]]) area += mesh.areas[f];
      const long resolution = segment_resolution(settings, radius_of(mesh, faces_of[examined[k]]), root_radius);
      splits[k] = split_segment(mesh, faces_of[examined[k]], area / total_area, resolution, settings, inner);
    }
  });
  return splits;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> merge_down_to(const Segmentation_mesh& mesh,
                                                                                        std::vector<std::vector<std::size_t>> parts,
                                                                                        std::size_t count)
{
  while(parts.size() > count) {
    double smallest = std::numeric_limits<double>::infinity();
    for(const auto& p : parts) {
      double a = 0.;
      for(std::size_t f : p) a += mesh.areas[f];
      smallest = (std::min)(smallest, a);
    }
    const std::size_t before = parts.size();
    parts = merge_small_parts(mesh, std::move(parts), std::nextafter(smallest, std::numeric_limits<double>::infinity()));
    if(parts.size() == before) break; // no neighbours: cannot happen for the parts of a connected segment
  }
  return parts;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H
