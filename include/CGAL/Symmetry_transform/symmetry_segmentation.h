// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/segmentation/split.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformSegmentationRef
What became of a segment of the segmentation tree of `segment_by_symmetry()`.
*/
enum class Segment_status {
  /// It was split: its children partition it.
  SPLIT,
  /// It lies at the depth `max_segmentation_depth`.
  DEPTH_LIMIT,
  /// Splitting it would have exceeded `max_number_of_segments`.
  COUNT_LIMIT,
  /// No principal plane of the segment reflects between 10 % and 90 % of its area onto it: the
  /// thesis's stopping rule, the segment is symmetric as a whole or not at all.
  NO_PARTIAL_SYMMETRY,
  /// Its faces fell into a single part after the clustering, the graph cut and the merging of
  /// the parts smaller than 3 % of the segment.
  NOT_SEPARABLE,
  /// Less than 1 % of the mesh's area, or fewer than 4 faces: not examined.
  TOO_SMALL
};

/*!
\ingroup PkgSymmetryTransformSegmentationRef
A segment of the segmentation tree of `segment_by_symmetry()`: a connected set of faces.
\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Symmetry_segment
{
  /// The value of `parent` for a root, and of `segment_id` for an inner segment.
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  /// The index of the parent segment in `Segmentation_tree::segments`, or `none` for a root (a
  /// connected component of the mesh).
  std::size_t parent = none;
  /// The indices of the children in `Segmentation_tree::segments`; empty for a leaf.
  std::vector<std::size_t> children;
  /// The depth: 0 for a root, the parent's plus 1 otherwise.
  std::size_t level = 0;
  /// For a leaf, the segment id that `segment_by_symmetry()` wrote for its faces; `none` otherwise.
  std::size_t segment_id = none;
  /// The number of faces of the segment.
  std::size_t number_of_faces = 0;
  /// The area of the segment.
  double area = 0.;
  /// The principal symmetries of the segment, found on the segment alone, strongest first:
  /// the planes whose supports made the feature vectors of its split. Empty if the segment was
  /// not examined (status `DEPTH_LIMIT` or `TOO_SMALL`).
  std::vector<Principal_symmetry<GeomTraits>> planes;
  /// For each plane of `planes`, the fraction of the segment's area that it reflects onto the
  /// segment: the area-weighted mean of the face supports, as returned by `symmetry_support()`.
  std::vector<double> reflected_fractions;
  /// What became of the segment.
  Segment_status status = Segment_status::DEPTH_LIMIT;
};

/*!
\ingroup PkgSymmetryTransformSegmentationRef
The segmentation tree of `segment_by_symmetry()`, filled when it is passed as the named
parameter `segmentation_tree` (wrapped in `std::ref`).

Segments are stored parents first: the roots (the connected components of the mesh, level 0),
then the segments of level 1, and so on. The leaves are the segments of the result.
\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Segmentation_tree
{
  /// The segment type.
  typedef Symmetry_segment<GeomTraits> Segment;
  /// All the segments, parents before their children.
  std::vector<Segment> segments;

  /// The roots of the tree, one per connected component of the mesh.
  /// \returns the indices of the roots in `segments`
  std::vector<std::size_t> roots() const
  {
    std::vector<std::size_t> result;
    for(std::size_t i = 0; i < segments.size(); ++i)
      if(segments[i].parent == Segment::none) result.push_back(i);
    return result;
  }

  /// The leaf of a segment of the result.
  /// \param id a segment id written by `segment_by_symmetry()`
  /// \returns the index in `segments` of the leaf whose faces got the id `id`, `Segment::none` if there is none
  std::size_t leaf(std::size_t id) const
  {
    for(std::size_t i = 0; i < segments.size(); ++i)
      if(segments[i].segment_id == id) return i;
    return Segment::none;
  }
};

/*!
\ingroup PkgSymmetryTransformSegmentationRef

Segments a triangle mesh into parts that follow its symmetric components (thesis, section 5.2).

Each connected component of the mesh is a root of a segmentation tree, and segments are split
level by level, largest first. To split a segment, its principal symmetries are detected on the
segment alone (its own Gaussian distance transform, reflective symmetry transform and refined
planes, by `detect_principal_symmetries()`); each face then gets a feature vector: its support
for each plane (`symmetry_support()`: how well the reflection maps the face onto the segment).
The feature vectors are clustered into two fuzzy clusters (area-weighted 2-means from seeded
k-means++ starts, then fuzzy c-means: the membership of a face falls with its distance to the
centres), and a graph cut on the dual graph (`CGAL::alpha_expansion_graphcut()`) gives the final
labels, minimising the data cost \f$ \sum_f (A_f/\bar A)(-\log u_f) \f$ plus
\f$ \lambda \sum_e (\ell_e/\bar\ell)/(1 + d_e/\bar d) \f$ over the cut edges, with
\f$ d_e = \eta (1 - \cos\alpha_e) \f$ the angular distance of the two faces (Katz and Tal;
\f$ \eta = 1 \f$ on concave edges, 0 on convex ones): boundaries are short and follow concave
creases. Each label is then split into its connected parts, and parts smaller than 5 % of the
segment are merged into the neighbouring part with which they share the longest boundary: the
children of a segment are connected, and there are two or more of them (the four legs of a table
are four children).

A segment is not split (it is a leaf) when it lies at depth `max_segmentation_depth`, when
splitting it would give more than `max_number_of_segments` segments (then, if a smaller split
fits, its smallest parts are merged into their neighbours until it fits), when none of its
planes reflects between 10 % and 90 % of its area onto it (the thesis's stopping rule), when the
graph cut leaves a single part, or when it covers less than 2 % of the mesh's area.

Plane detection, the costliest step, has defaults fitted to segmentation: a \f$ 32^3 \f$ grid
for the mesh, and for a segment a grid with the same voxel size (at least \f$ 24^3 \f$);
\f$ 10^5 \f$ Monte Carlo samples and 5000 refinement samples for the whole mesh, the same
densities on a segment (at least \f$ 2 \cdot 10^4 \f$ and 1000); 6 planes. The named parameters
of `detect_principal_symmetries()` override them (the sample counts then apply to the whole
mesh, and are scaled on segments alike). Segments of the
same level are examined in parallel (`number_of_threads` in all).

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam SegmentIdMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the mesh
\param segment_id_map receives the segment of each face, from 0 to the number of segments minus 1
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones
          listed below, and those of `detect_principal_symmetries()` (`grid_resolution`,
          `gaussian_width`, `number_of_samples`, `number_of_refinement_samples`,
          `number_of_iterations`, `max_number_of_planes`, `symmetry_threshold`,
          `laplacian_threshold`, `prst_method`, `monte_carlo_estimator`), passed to the
          detection on every segment with the defaults above

\cgalNamedParamsBegin
  \cgalParamNBegin{max_segmentation_depth}
    \cgalParamDescription{the largest depth of the tree: at most \f$ 2^d \f$ segments per
                           component if each split gives two parts}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{3}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_segments}
    \cgalParamDescription{the largest number of segments; a mesh with more connected components
                           still gets one segment per component}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{smoothing_lambda}
    \cgalParamDescription{\f$ \lambda \f$, the weight of the boundary in the graph cut: 0 keeps
                           the labels of the clustering, larger values give shorter boundaries}
    \cgalParamType{`double`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{segmentation_tree}
    \cgalParamDescription{receives the segmentation tree (pass `std::ref(tree)`)}
    \cgalParamType{`std::reference_wrapper<Segmentation_tree<GeomTraits>>`}
    \cgalParamDefault{not filled}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the detection's samples and of the clustering's starts}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the number of threads; the result depends on it only through the
                           rounding of sums}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`std::thread::hardware_concurrency()`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key and
                   `GeomTraits::Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class, the kernel of the planes of the tree}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{whether to print a line per examined segment on `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of segments. Every face gets a segment id, and every segment is connected
(through edges of the mesh). Deterministic for a given `random_seed` and number of threads.
\throws std::invalid_argument if the mesh is empty, has a face that is not a triangle, a NaN or
infinite coordinate, or only degenerate (zero-area) faces, or on the other bad inputs of
`detect_principal_symmetries()` (e.g. a grid resolution too small).
*/
template <typename TriangleMesh, typename SegmentIdMap, typename NamedParameters = parameters::Default_named_parameters>
std::size_t segment_by_symmetry(const TriangleMesh& tm, SegmentIdMap segment_id_map,
                                const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  typedef Symmetry_segment<GT> Segment;

  const auto vpm = internal::vertex_point_map(tm, np);
  const std::size_t max_depth = std::size_t(choose_parameter(get_parameter(np, internal_np::st_max_segmentation_depth), internal::defaults::max_segmentation_depth));
  const std::size_t max_segments = std::size_t(
    choose_parameter(get_parameter(np, internal_np::st_max_number_of_segments), Segment::none));
  const double lambda = double(choose_parameter(get_parameter(np, internal_np::st_smoothing_lambda), internal::defaults::smoothing_lambda));
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  const internal::Segmentation_settings settings = internal::segmentation_settings(np);
  if(max_segments == 0) throw std::invalid_argument("segment_by_symmetry: max_number_of_segments must be positive");
  if(!(lambda >= 0.)) throw std::invalid_argument("segment_by_symmetry: smoothing_lambda must be non-negative");

  internal::triangles_of_mesh(tm, np); // the checks of the bad-input contract
  const internal::Segmentation_mesh mesh = internal::segmentation_mesh(tm, vpm);
  const std::size_t n = mesh.number_of_faces();
  const double total_area = std::accumulate(mesh.areas.begin(), mesh.areas.end(), 0.);

  std::vector<Segment> segments;
  std::vector<std::vector<std::size_t>> faces_of; // of each segment
  auto add_segment = [&](std::vector<std::size_t> faces, std::size_t parent) {
    Segment s;
    s.parent = parent;
    s.level = parent == Segment::none ? 0 : segments[parent].level + 1;
    s.number_of_faces = faces.size();
    for(std::size_t f : faces) s.area += mesh.areas[f];
    if(parent != Segment::none) segments[parent].children.push_back(segments.size());
    segments.push_back(s);
    faces_of.push_back(std::move(faces));
  };
  {
    std::vector<std::size_t> all(n), identity(n), region(n, 0);
    std::iota(all.begin(), all.end(), std::size_t(0));
    std::iota(identity.begin(), identity.end(), std::size_t(0));
    for(auto& component : internal::connected_parts(mesh, all, identity, region)) add_segment(std::move(component), Segment::none);
  }

  double root_radius = 0.; // of the largest component
  for(std::size_t s = 0; s < segments.size(); ++s) root_radius = (std::max)(root_radius, internal::radius_of(mesh, faces_of[s]));
  std::size_t leaves = segments.size();
  std::vector<std::size_t> active(segments.size());
  std::iota(active.begin(), active.end(), std::size_t(0));
  for(std::size_t level = 0; !active.empty(); ++level) {
    std::vector<std::size_t> examined;
    for(std::size_t s : active) {
      if(level >= max_depth) segments[s].status = Segment_status::DEPTH_LIMIT;
      else if(segments[s].area < 0.02 * total_area || segments[s].number_of_faces < 4)
        segments[s].status = Segment_status::TOO_SMALL;
      else examined.push_back(s);
    }
    // Largest first: when the segment count runs out, the largest segments are the ones split.
    // With a count limit, segments are examined a few at a time (one per thread), so that no
    // detection runs for a segment that the limit would leave whole.
    std::stable_sort(examined.begin(), examined.end(),
                     [&](std::size_t a, std::size_t b) { return segments[a].area > segments[b].area; });
    const std::size_t batch = max_segments == Segment::none ? examined.size() : std::size_t(settings.threads);
    std::vector<std::size_t> next;
    for(std::size_t first = 0; first < examined.size(); first += batch) {
      const std::vector<std::size_t> some(examined.begin() + std::ptrdiff_t(first),
                                          examined.begin() + std::ptrdiff_t((std::min)(first + batch, examined.size())));
      if(leaves >= max_segments) {
        for(std::size_t s : some) segments[s].status = Segment_status::COUNT_LIMIT;
        continue;
      }
      const std::vector<internal::Split> splits = internal::split_segments(mesh, faces_of, some, settings, lambda, total_area, root_radius);
      for(std::size_t k = 0; k < some.size(); ++k) {
        const std::size_t s = some[k];
        const internal::Split& split = splits[k];
        for(const auto& p : split.planes)
          segments[s].planes.push_back({internal::to_plane<GT>(internal::to_dplane(p.plane)), p.symmetry, p.support});
        segments[s].reflected_fractions = split.reflected_fractions;
        if(verbose)
          std::cerr << "segment " << s << " (level " << level << ", " << segments[s].number_of_faces << " faces): "
                    << split.planes.size() << " planes, " << split.parts.size() << " parts, " << split.seconds
                    << " s (detection " << split.detection_seconds << " s, features " << split.feature_seconds
                    << " s, clustering and graph cut " << split.seconds - split.detection_seconds - split.feature_seconds
                    << " s)\n";
        if(split.parts.size() < 2) {
          segments[s].status = !split.partial_symmetry ? Segment_status::NO_PARTIAL_SYMMETRY : Segment_status::NOT_SEPARABLE;
          continue;
        }
        if(leaves >= max_segments) {
          segments[s].status = Segment_status::COUNT_LIMIT;
          continue;
        }
        std::vector<std::vector<std::size_t>> parts = internal::merge_down_to(mesh, split.parts, max_segments - leaves + 1);
        segments[s].status = Segment_status::SPLIT;
        leaves += parts.size() - 1;
        for(auto& part : parts) {
          add_segment(std::move(part), s);
          next.push_back(segments.size() - 1);
        }
      }
    }
    active = std::move(next);
  }

  std::vector<std::size_t> id_of_face(n, Segment::none);
  std::size_t number_of_segments = 0;
  for(std::size_t s = 0; s < segments.size(); ++s) {
    if(!segments[s].children.empty()) continue;
    segments[s].segment_id = number_of_segments++;
    for(std::size_t f : faces_of[s]) id_of_face[f] = segments[s].segment_id;
  }
  std::size_t i = 0;
  for(auto f : faces(tm)) put(segment_id_map, f, id_of_face[i++]);

  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_segmentation_tree_t>::value)
    parameters::get_parameter_reference(np, internal_np::st_segmentation_tree).segments = std::move(segments);
  return number_of_segments;
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H
