// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H

#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mesh_extraction.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/outputs.h>
#include <CGAL/Symmetry_transform/internal/remeshing/proxy_generation.h>
#include <CGAL/Symmetry_transform/internal/remeshing/settings.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform {

namespace internal {

// symmetric_approximate_triangle_mesh(): the outputs are written once all is computed, so that a
// cancelled run writes none.
template <typename GT, typename TriangleMesh, typename PlaneRange, typename NamedParameters>
bool symmetric_remeshing(const TriangleMesh& tm, const PlaneRange& planes, const NamedParameters& np)
{
  using parameters::is_default_parameter;
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  Progress_stage stage(0., progress_shares::remeshing_preparation);
  Remeshing_settings settings = remeshing_settings(planes, np);
  const Remeshing_mesh mesh = make_working_mesh(tm, settings.planes, np); // the planes in its local coordinates
  if(settings.verbose)
    std::cerr << "Symmetric VSA: " << mesh.number_of_input_faces << " faces, " << mesh.number_of_faces() << " after splitting along "
              << settings.planes.size() << " plane(s) (" << seconds() << " s)\n";
  const std::vector<std::size_t> mirror = mirror_faces(mesh, settings.planes, settings.strongest_plane_only, settings.threads);
  if(settings.verbose && !settings.planes.empty())
    std::cerr << "  " << std::count_if(mirror.begin(), mirror.end(), [](std::size_t g) { return g != Remeshing_mesh::none; })
              << " face mirrors (" << seconds() << " s)\n";

  stage.move_to(progress_shares::remeshing_preparation, progress_shares::remeshing_extraction);
  Symmetric_partition partition(mesh, settings, mirror);
  generate_proxies(partition);
  if(settings.verbose) std::cerr << "  partition: " << partition.proxies().size() << " proxies (" << seconds() << " s)\n";

  const bool wants_mesh = !is_default_parameter<NamedParameters, internal_np::anchors_t>::value ||
                          !is_default_parameter<NamedParameters, internal_np::triangles_t>::value ||
                          !is_default_parameter<NamedParameters, internal_np::st_output_mesh_t>::value;
  stage.move_to(progress_shares::remeshing_extraction, 1.);
  std::optional<Remeshing_output> out;
  if(wants_mesh) out = extract_mesh(partition, meshing_settings(np));
  if(wants_mesh && settings.verbose)
    std::cerr << "  meshing: " << out->anchors.size() << " anchors (" << out->matched_anchors << " mirror-matched), "
              << out->triangles.size() << " triangles (" << seconds() << " s)\n";
  throw_if_cancelled();
  write_face_outputs(tm, partition, np);
  write_proxies<GT>(partition, mesh.frame, np);
  if(!wants_mesh) return false;
  write_mesh_outputs<GT>(*out, mesh.frame, np);
  return Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(out->triangles);
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 *
 * Approximates a triangle mesh by a coarse triangle mesh that keeps the given planes of
 * symmetry: the Variational Shape Approximation of
 * `CGAL::Surface_mesh_approximation::approximate_triangle_mesh()`, whose proxies may each cover
 * one patch per transform (the identity and the reflection through each plane), as in Section 5.1
 * of the thesis \ref SymmetryTransformRefThesis "[1]". The algorithm and its metric are described
 * in \ref SymmetryTransformRemeshing; with no plane and `position_weight(0)`, it is plain VSA.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam PlaneRange a range of `geom_traits::Plane_3` (e.g. the `plane` of each `Principal_symmetry`)
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the input mesh (not modified)
 * \param planes the planes of symmetry to keep (at most 64)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin{Approximation Named Parameters}
 *   \cgalParamNBegin{seeding_method}
 *     \cgalParamDescription{the seeding, as in \cgal's VSA (a program that names it includes `CGAL/Variational_shape_approximation.h`, which this package does not include)}
 *     \cgalParamType{`CGAL::Surface_mesh_approximation::Seeding_method`}
 *     \cgalParamDefault{`CGAL::Surface_mesh_approximation::HIERARCHICAL`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_number_of_proxies}
 *     \cgalParamDescription{the largest number of proxies, each with up to one patch per transform}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{a third of the faces of `tm` split along the planes, also the upper bound of a given value}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{min_error_drop}
 *     \cgalParamDescription{the seeding stops when the error falls below this fraction of the error of one proxy per connected component (a value outside \f$ (0, 1) \f$ counts as not given)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{0.1 if `max_number_of_proxies` is not given, else not used, as in \cgal's VSA}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_relaxations}
 *     \cgalParamDescription{the iterations after each seeding step; after seeding, a proxy teleportation is tried every this many iterations}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{5}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the iterations after seeding}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{20}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{position_weight}
 *     \cgalParamDescription{\f$ \alpha \in [0,1] \f$ of the metric: the weight of centroid distances against normal deviations}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{0.002, the thesis's value (0 is the \f$ L^{2,1} \f$ metric of \cgal's VSA)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{strongest_plane_only}
 *     \cgalParamDescription{whether each face may only be reflected through the plane whose mirror image of its centroid lies closest to a face centroid (the thesis's option for several local symmetries, Figure 5.8)}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of `RANDOM` seeding: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads of the mirror-face queries\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamVerbose{whether to print the main steps and their times on `std::cerr`}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1` (the result does not depend on it)}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key and `std::size_t` as value}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_index_map}
 *     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1` (the result does not depend on it)}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \cgalNamedParamsBegin{Meshing Named Parameters}
 *   \cgalParamNBegin{subdivision_ratio}
 *     \cgalParamDescription{the chord subdivision threshold, as in \cgal's VSA}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{5.0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{relative_to_chord}
 *     \cgalParamDescription{whether `subdivision_ratio` is relative to the chord length instead of the mean edge length}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{with_dihedral_angle}
 *     \cgalParamDescription{whether the chord criterion is weighted by the sine of the angle between the patches}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{optimize_anchor_location}
 *     \cgalParamDescription{whether anchors are placed at the mean of their projections onto their patches' planes}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \cgalNamedParamsBegin{Output Named Parameters}
 *   \cgalParamNBegin{face_proxy_map}
 *     \cgalParamDescription{receives the proxy of each face of `tm` (of its largest part if it was split)}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_patch_map}
 *     \cgalParamDescription{receives the transform of the patch of each face: 0 for the identity, \f$ j \f$ for the reflection through the \f$ j \f$-th plane of `planes`}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{proxies}
 *     \cgalParamDescription{receives the plane of each proxy (its identity patch's; the patch of a reflection has the reflected plane)}
 *     \cgalParamType{an `OutputIterator` with `geom_traits::Plane_3` as value type}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{anchors}
 *     \cgalParamDescription{receives the vertices of the output mesh}
 *     \cgalParamType{an `OutputIterator` with `geom_traits::Point_3` as value type}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{triangles}
 *     \cgalParamDescription{receives the triangles of the output mesh, as indices into the anchors}
 *     \cgalParamType{an `OutputIterator` with `std::array<std::size_t, 3>` as value type}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{output_mesh}
 *     \cgalParamDescription{a pointer to a mesh that receives the output (cleared first; a soup that is not a polygon mesh is oriented first, its non-manifold vertices duplicated)}
 *     \cgalParamType{a pointer to a model of `MutableFaceGraph`, e.g. `CGAL::Surface_mesh<Point_3>*`}
 *     \cgalParamDefault{no output}
 *   \cgalParamNEnd
 *   \cgalParamCallback{`false`\, and writes no output}
 * \cgalNamedParamsEnd
 *
 * \returns `true` if the triangles form a 2-manifold oriented polygon mesh
 * (`CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`), as \cgal's function;
 * `false` if they do not, or if no output of the mesh (`anchors`, `triangles`, `output_mesh`) is
 * asked for. The outputs asked for are written in either case: with `false`, `triangles` is a
 * soup that is not a 2-manifold oriented mesh, and `output_mesh` receives it repaired as said above.
 * \throws std::invalid_argument if `tm` has no face, a face that is not a triangle, a non-finite
 * coordinate or only degenerate faces; if an index map does not give distinct indices below
 * `num_vertices(tm)` or `num_faces(tm)`; if a plane is degenerate or there are more than 64; if a numeric named parameter lies out of its range (the message names it and the range)
 * (`max_number_of_proxies` given as 0, `position_weight` outside \f$ [0,1] \f$, ...).
*/
template <typename TriangleMesh, typename PlaneRange, typename NamedParameters = parameters::Default_named_parameters>
bool symmetric_approximate_triangle_mesh(const TriangleMesh& tm, const PlaneRange& planes,
                                         const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::with_progress(np, [&] { return internal::symmetric_remeshing<GT>(tm, planes, np); },
                                 [] { return false; });
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H
