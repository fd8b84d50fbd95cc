// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>
#include <CGAL/Symmetry_transform/internal/segmentation/hierarchy.h>
#include <CGAL/Symmetry_transform/internal/segmentation/settings.h>

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformSegmentationRef
 * What became of a segment of the segmentation tree of `segment_by_symmetry()`.
*/
enum class Segment_status {
  /// It was split: its children partition it.
  SPLIT,
  /// It lies at the depth `max_segmentation_depth`.
  DEPTH_LIMIT,
  /// Splitting it would have exceeded `max_number_of_segments`.
  COUNT_LIMIT,
  /// No principal plane of the segment reflects between 10 % and 90 % of its area onto it (the
  /// bounds set by `partial_symmetry_fraction`): the thesis's stopping rule, the segment is
  /// symmetric as a whole or not at all.
  NO_PARTIAL_SYMMETRY,
  /// Its faces fell into a single part after the clustering, the graph cut and the merging of
  /// the parts smaller than 5 % of the segment (`smallest_part_fraction`).
  NOT_SEPARABLE,
  /// Less than 2 % of the mesh's area, or fewer than 4 faces: not examined.
  TOO_SMALL
};

/*!
 * \ingroup PkgSymmetryTransformSegmentationRef
 * A segment of the segmentation tree of `segment_by_symmetry()`: a connected set of faces.
 * \tparam GeomTraits a model of `Kernel`
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
 * \ingroup PkgSymmetryTransformSegmentationRef
 * The segmentation tree of `segment_by_symmetry()`, filled when it is passed as the named
 * parameter `segmentation_tree` (wrapped in `std::ref`).
 *
 * Segments are stored parents first: the roots (the connected components of the mesh, level 0),
 * then the segments of level 1, and so on. The leaves are the segments of the result.
 * \tparam GeomTraits a model of `Kernel`
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
 * \ingroup PkgSymmetryTransformSegmentationRef
 *
 * Segments a triangle mesh into parts that follow its symmetric components (thesis, section 5.2).
 * Each connected component is the root of a segmentation tree whose segments are split level by
 * level: the principal symmetries of a segment are detected on the segment alone, the faces are
 * clustered by their supports of these planes, and a graph cut on the dual graph draws short
 * boundaries along concave creases. The algorithm, its stopping rules and its defaults are
 * described in \ref SymmetryTransformSegmentation.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam SegmentIdMap a model of `WritablePropertyMap` with
 *         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param segment_id_map receives the segment of each face, from 0 to the number of segments minus 1
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed
 *           below, and the other named parameters of `detect_principal_symmetries()`, passed on to
 *           the detection on every segment
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{max_segmentation_depth}
 *     \cgalParamDescription{the largest depth of the tree: at most \f$ 2^d \f$ segments per
 *                            component if each split gives two parts}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{3}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_number_of_segments}
 *     \cgalParamDescription{the largest number of segments; a mesh with more connected components
 *                            still gets one segment per component}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{no limit}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{smoothing_lambda}
 *     \cgalParamDescription{\f$ \lambda \f$, the weight of the boundary in the graph cut: 0 keeps
 *                            the labels of the clustering, larger values give shorter boundaries}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{partial_symmetry_fraction}
 *     \cgalParamDescription{\f$ p \f$: a segment is split only if one of its principal planes
 *                            reflects between \f$ p \f$ and \f$ 1 - p \f$ of its area onto it (the
 *                            thesis's rule, 10 % and 90 %). Smaller values also split shapes whose
 *                            asymmetric parts are small (a cup's handle: 5 to 10 % of its area)}
 *     \cgalParamType{`double`, in \f$ [0, 0.5] \f$}
 *     \cgalParamDefault{0.1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{smallest_part_fraction}
 *     \cgalParamDescription{the parts of a split smaller than this fraction of the segment's area
 *                            are merged into the neighbouring part with which they share the
 *                            longest boundary. Smaller values keep small parts (a table's legs)}
 *     \cgalParamType{`double`, in \f$ [0, 1) \f$}
 *     \cgalParamDefault{0.05}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_feature_map}
 *     \cgalParamDescription{a value per face clustered with the supports of the planes, e.g. the
 *                            shape diameter function of `CGAL::sdf_values()`: symmetry groups the
 *                            faces, the feature (thickness) shows where a part ends, e.g. the
 *                            root of a wing that the fuselage's planes reflect as well as the wing.
 *                            Rescaled to \f$ [0, 1] \f$ over each segment and weighted by the
 *                            square root of the segment's number of planes, so that it counts as
 *                            much as all the planes together; the stopping rule is unchanged.
 *                            Measured on the Princeton Segmentation Benchmark in
 *                            \ref SymmetryTransformSegmentation}
 *     \cgalParamType{a model of `ReadablePropertyMap` with
 *                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and a number
 *                    type convertible to `double` as value type}
 *     \cgalParamDefault{none: the planes' supports alone (the thesis)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{segmentation_tree}
 *     \cgalParamDescription{receives the segmentation tree (pass `std::ref(tree)`)}
 *     \cgalParamType{`std::reference_wrapper<Segmentation_tree<GeomTraits>>`}
 *     \cgalParamDefault{not filled}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{grid_resolution}
 *     \cgalParamDescription{the grid resolution of the detection on the whole mesh; a segment gets
 *                            a grid of the same voxel size, at least \f$ 24^3 \f$}
 *     \cgalParamType{`int`}
 *     \cgalParamDefault{32}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_samples}
 *     \cgalParamDescription{the Monte Carlo samples of the detection's transform on the whole mesh;
 *                            a segment gets the same density, at least \f$ 2 \cdot 10^4 \f$}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{\f$ 10^5 \f$}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_refinement_samples}
 *     \cgalParamDescription{the refinement samples of the detection on the whole mesh; a segment
 *                            gets the same density, at least 1000}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{5000}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_number_of_planes}
 *     \cgalParamDescription{the largest number of planes of a segment, the features of its clustering}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{6}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of the detection's samples and of the clustering's starts}
 *   \cgalParamThreads{the number of threads\, shared by the segments of a level\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamNBegin{face_index_map}
 *     \cgalParamDescription{a property map associating to each face of `tm` a unique index between
 *                            0 and `num_faces(tm) - 1`; if the indices have gaps (a `Surface_mesh`
 *                            with removed faces not yet collected), the order of `faces(tm)` is used}
 *     \cgalParamType{a model of `ReadablePropertyMap` with
 *                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and
 *                    `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamGeomTraits
 *   \cgalParamVerbose{whether to print a line per examined segment on `std::cerr`}
 *   \cgalParamCallback{0\, and writes neither `segment_id_map` nor `segmentation_tree`}
 * \cgalNamedParamsEnd
 *
 * \returns the number of segments. Every face gets a segment id, and every segment is connected
 * (through edges of the mesh). Deterministic for a given `random_seed`, whatever the number of threads.
 * \throws std::invalid_argument if the mesh is empty, has a face that is not a triangle, a NaN or
 * infinite coordinate, or only degenerate (zero-area) faces, if a numeric named parameter lies out of its range (the message names it and the range) (e.g.
 * `partial_symmetry_fraction` or `smallest_part_fraction`), if a value of `face_feature_map` is not
 * finite, or on the other bad inputs of
 * `detect_principal_symmetries()` (e.g. a grid resolution too small).
*/
template <typename TriangleMesh, typename SegmentIdMap, typename NamedParameters = parameters::Default_named_parameters>
std::size_t segment_by_symmetry(const TriangleMesh& tm, SegmentIdMap segment_id_map,
                                const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  const internal::Segmentation_settings settings = internal::segmentation_settings(np);
  internal::triangles_of_mesh(tm, np); // the checks of the bad-input contract
  const auto vpm = internal::vertex_point_map(tm, np);
  const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<Symmetry_segment<GT>> segments;
  const std::size_t number_of_segments = internal::with_progress(np, [&] {
    return internal::numbers_the_faces(tm, face_index)
             ? internal::segment_mesh<GT>(tm, vpm, face_index, segment_id_map, settings, segments, np)
             : internal::segment_mesh<GT>(tm, vpm, internal::face_index_in_order(tm), segment_id_map, settings, segments, np);
  }, [] { return std::size_t(0); });
  if(number_of_segments == 0) return 0; // cancelled: nothing written
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_segmentation_tree_t>::value)
    parameters::get_parameter_reference(np, internal_np::st_segmentation_tree).segments = std::move(segments);
  return number_of_segments;
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_SEGMENTATION_H
