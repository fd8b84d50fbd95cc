// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H

// The split of one segment of segment_by_symmetry(): its principal symmetries detected on the
// segment alone, the faces' supports of each plane as feature vectors, the stopping rule, the
// fuzzy clustering and graph cut, and the connected parts of the labels. Segments of one level
// are split in parallel.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/segmentation/fuzzy_clustering.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// A segment reflected by none of its planes over more than this fraction of its area, or by all
// of them over more than its complement, is not split (thesis, section 5.2.2).
constexpr double least_partial_fraction = 0.1;
// The Gaussian width of the feature vectors, relative to the detection's (see split_segment()).
constexpr double feature_width_factor = 0.5;
// Parts of a split smaller than this fraction of the segment are merged into a neighbour.
constexpr double least_part_fraction = 0.05;

// The detection settings of segment_by_symmetry(): those of detect_principal_symmetries() with
// defaults fitted to segmentation.
struct Segmentation_settings
{
  long grid_resolution;
  double gaussian_width;
  std::size_t number_of_samples;
  std::size_t number_of_refinement_samples;
  unsigned number_of_iterations;
  std::size_t max_number_of_planes;
  double symmetry_threshold;
  double laplacian_threshold;
  Reflective_symmetry_method method;
  Monte_carlo_estimator estimator;
  unsigned seed;
  unsigned threads;
};

template <typename NamedParameters>
Segmentation_settings segmentation_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Segmentation_settings s;
  s.grid_resolution = long(choose_parameter(get_parameter(np, internal_np::st_grid_resolution), defaults::segmentation_grid_resolution));
  s.gaussian_width = double(choose_parameter(get_parameter(np, internal_np::st_gaussian_width), defaults::gaussian_width));
  s.number_of_samples = std::size_t(choose_parameter(get_parameter(np, internal_np::number_of_samples), defaults::segmentation_monte_carlo_pairs));
  s.number_of_refinement_samples =
    std::size_t(choose_parameter(get_parameter(np, internal_np::st_number_of_refinement_samples), defaults::segmentation_refinement_samples));
  s.number_of_iterations = unsigned(choose_parameter(get_parameter(np, internal_np::number_of_iterations), defaults::isp_iterations));
  s.max_number_of_planes = std::size_t(choose_parameter(get_parameter(np, internal_np::st_max_number_of_planes), defaults::segmentation_max_number_of_planes));
  s.symmetry_threshold = double(choose_parameter(get_parameter(np, internal_np::st_symmetry_threshold), defaults::symmetry_threshold));
  s.laplacian_threshold = double(choose_parameter(get_parameter(np, internal_np::st_laplacian_threshold), defaults::laplacian_threshold));
  s.method = choose_parameter(get_parameter(np, internal_np::st_prst_method), Reflective_symmetry_method::MONTE_CARLO);
  s.estimator =
    choose_parameter(get_parameter(np, internal_np::st_monte_carlo_estimator), Monte_carlo_estimator::STRATIFIED_LINES);
  s.seed = unsigned(choose_parameter(get_parameter(np, internal_np::random_seed), defaults::random_seed));
  s.threads = (std::max)(1u, unsigned(choose_parameter(get_parameter(np, internal_np::st_number_of_threads),
                                                      default_number_of_threads())));
  if(s.max_number_of_planes == 0)
    throw std::invalid_argument("segment_by_symmetry: max_number_of_planes must be positive");
  return s;
}

// Refinement samples and Monte Carlo samples of a segment covering `fraction` of the mesh's
// area: the density of the whole mesh's, at least these many.
constexpr std::size_t least_refinement_samples = 1000;
constexpr std::size_t least_monte_carlo_samples = 20000;

// `count` scaled by `fraction`, at least `least` (or `count` if smaller).
inline std::size_t samples_of_fraction(std::size_t count, double fraction, std::size_t least)
{
  return (std::max)((std::min)(least, count), std::size_t(std::lround(fraction * double(count))));
}

// The smallest grid of a segment below the root, if the root's is larger.
constexpr long least_segment_resolution = 24;

// The grid resolution of a segment of radius `radius` in a mesh whose largest component has the
// radius `root_radius`: the voxels keep their size, down to least_segment_resolution (or 12
// Gaussian widths, the smallest grid allowed), an even number.
inline long segment_resolution(const Segmentation_settings& s, double radius, double root_radius)
{
  // even, as the transform requires
  const long least = (std::min)(s.grid_resolution, (std::max)(least_segment_resolution, 2 * (long(6. * s.gaussian_width) + 1)));
  const long scaled = 2 * long(std::lround(0.5 * double(s.grid_resolution) * radius / root_radius));
  return (std::max)(least, (std::min)(s.grid_resolution, scaled));
}

// The named parameters of the detection on a segment's sub-mesh.
inline auto detection_parameters(const Segmentation_settings& s, double fraction, long resolution, unsigned threads)
{
  return CGAL::parameters::grid_resolution(resolution)
    .gaussian_width(s.gaussian_width)
    .number_of_samples(samples_of_fraction(s.number_of_samples, fraction, least_monte_carlo_samples))
    .number_of_refinement_samples(samples_of_fraction(s.number_of_refinement_samples, fraction, least_refinement_samples))
    .number_of_iterations(s.number_of_iterations)
    .max_number_of_planes(s.max_number_of_planes)
    .symmetry_threshold(s.symmetry_threshold)
    .laplacian_threshold(s.laplacian_threshold)
    .prst_method(s.method)
    .monte_carlo_estimator(s.estimator)
    .random_seed(s.seed)
    .number_of_threads(threads);
}

// The largest distance from the area-weighted centroid of the faces to their vertices.
inline double radius_of(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces)
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

struct Split
{
  std::vector<Principal_symmetry<Dkernel>> planes; // of the segment, strongest first
  std::vector<double> reflected_fractions;         // of each plane
  bool partial_symmetry = false;                   // some plane reflects 10 % to 90 % of the segment
  std::vector<std::vector<std::size_t>> parts;     // the children (faces of the mesh), if split
  double seconds = 0.;                             // in all
  double detection_seconds = 0., feature_seconds = 0.; // of which the detection, the features
};

// The split of the segment made of `faces` (connected, sorted).
inline Split split_segment(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces, double fraction,
                           long resolution, const Segmentation_settings& settings, double lambda, unsigned threads)
{
  const auto start = std::chrono::steady_clock::now();
  Split split;
  const auto np = detection_parameters(settings, fraction, resolution, threads);
  const Triangle_surface<Dkernel> surface(triangles_of_faces(mesh, faces), np);
  split.planes = detection_of_surface(surface, np).symmetries;
  auto since_start = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  split.detection_seconds = since_start();

  // Features: the support of each plane on each face, L_ij in the thesis, "the average value in
  // the GEDT of a point of face i reflected by plane j", at the centroid and three interior
  // points of the face (as symmetry_support()). The GEDT is evaluated exactly, from the distance
  // to the nearest triangle that the detection's closest-triangle field offers, with half the
  // detection's Gaussian width: supports closer to 0 or 1 (a face is mirrored or it is not)
  // cluster more cleanly. Points reflected beyond the field's band get 0.
  const double sigma = feature_width_factor * isp_settings(np, surface.gedt).sigma;
  const double inverse_two_sigma2 = 1. / (2. * sigma * sigma);
  std::vector<double> weights(faces.size());
  std::vector<std::array<Eigen::Vector3d, 4>> points(faces.size());
  double area = 0.;
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const auto& t = mesh.triangles[faces[i]];
    weights[i] = mesh.areas[faces[i]];
    points[i] = {(t[0] + t[1] + t[2]) / 3., (4. * t[0] + t[1] + t[2]) / 6., (t[0] + 4. * t[1] + t[2]) / 6.,
                 (t[0] + t[1] + 4. * t[2]) / 6.};
    area += weights[i];
  }
  Eigen::MatrixXd features = Eigen::MatrixXd::Zero(Eigen::Index(faces.size()), Eigen::Index(split.planes.size()));
  for(std::size_t j = 0; j < split.planes.size(); ++j) {
    const Dplane mirror = to_dplane(split.planes[j].plane);
    parallel_for(faces.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i) {
        double sum = 0.;
        for(const Eigen::Vector3d& p : points[i]) {
          const Eigen::Vector3d q = mirror.reflect(p);
          const auto [on_surface, triangle] = surface.field.nearest_in_cell(q);
          if(triangle >= 0) sum += std::exp(-(q - on_surface).squaredNorm() * inverse_two_sigma2);
        }
        features(Eigen::Index(i), Eigen::Index(j)) = sum / 4.;
      }
    });
    double supported = 0.;
    for(std::size_t i = 0; i < faces.size(); ++i) supported += weights[i] * features(Eigen::Index(i), Eigen::Index(j));
    const double fraction = supported / area;
    split.reflected_fractions.push_back(fraction);
    if(fraction >= least_partial_fraction && fraction <= 1. - least_partial_fraction) split.partial_symmetry = true;
  }
  split.feature_seconds = since_start() - split.detection_seconds;
  if(split.partial_symmetry) {
    const Fuzzy_two_clusters clusters = fuzzy_two_clusters(features, weights, settings.seed);
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> local(mesh.number_of_faces(), none);
    for(std::size_t i = 0; i < faces.size(); ++i) local[faces[i]] = i;
    const std::vector<std::size_t> labels = graph_cut_labels(mesh, faces, local, clusters.membership, lambda);
    split.parts = merge_small_parts(mesh, connected_parts(mesh, faces, local, labels), least_part_fraction * area);
    if(split.parts.size() < 2) split.parts.clear();
  }
  split.seconds = since_start();
  return split;
}

// The splits of the segments `examined` (indices into `faces_of`), in parallel: each of the
// `threads` workers takes whole segments (the detection on a small segment keeps one core busy
// poorly), the threads left over going to the detections themselves.
inline std::vector<Split> split_segments(const Segmentation_mesh& mesh,
                                         const std::vector<std::vector<std::size_t>>& faces_of,
                                         const std::vector<std::size_t>& examined,
                                         const Segmentation_settings& settings, double lambda, double total_area,
                                         double root_radius)
{
  std::vector<Split> splits(examined.size());
  if(examined.empty()) return splits;
  const unsigned workers = unsigned((std::min<std::size_t>)(settings.threads, examined.size()));
  const unsigned inner = (std::max)(1u, settings.threads / workers);
  // Round robin over the segments, sorted by decreasing size: the work is shared evenly.
  parallel_for(workers, workers, [&](unsigned worker, std::size_t, std::size_t) {
    for(std::size_t k = worker; k < examined.size(); k += workers)
    {
      double area = 0.;
      for(std::size_t f : faces_of[examined[k]]) area += mesh.areas[f];
      const long resolution = segment_resolution(settings, radius_of(mesh, faces_of[examined[k]]), root_radius);
      splits[k] = split_segment(mesh, faces_of[examined[k]], area / total_area, resolution, settings, lambda, inner);
    }
  });
  return splits;
}

// The parts merged, smallest first, into their neighbours until at most `count` remain.
inline std::vector<std::vector<std::size_t>> merge_down_to(const Segmentation_mesh& mesh,
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

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SPLIT_H
