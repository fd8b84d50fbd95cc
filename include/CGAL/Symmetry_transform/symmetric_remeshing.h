// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/remeshing/meshing.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

namespace internal {

// Builds `out` (a MutableFaceGraph) from the anchors and triangles; a soup that is not a
// polygon mesh is oriented first (non-manifold vertices duplicated).
template <typename OutputMesh>
void build_output_mesh(const std::vector<Eigen::Vector3d>& anchors, std::vector<std::array<std::size_t, 3>> triangles,
                       OutputMesh& out)
{
  typedef typename boost::property_traits<typename boost::property_map<OutputMesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> points;
  for(const Eigen::Vector3d& a : anchors) points.push_back(Point(a.x(), a.y(), a.z()));
  clear(out);
  if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles))
    Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, out);
}

template <typename OutputMesh>
void build_output_mesh(const std::vector<Eigen::Vector3d>& anchors, const std::vector<std::array<std::size_t, 3>>& triangles,
                       OutputMesh* out)
{
  if(out) build_output_mesh(anchors, triangles, *out);
}

inline void build_output_mesh(const std::vector<Eigen::Vector3d>&, const std::vector<std::array<std::size_t, 3>>&,
                              internal_np::Param_not_found)
{}

template <typename OutputIterator, typename Value>
void output_values(OutputIterator out, const std::vector<Value>& values)
{
  for(const Value& v : values) *out++ = v;
}

template <typename Value>
void output_values(internal_np::Param_not_found, const std::vector<Value>&)
{}

template <typename FaceMap, typename Face, typename Value>
void output_face_values(FaceMap map, const std::vector<Face>& faces, const std::vector<Value>& values)
{
  for(std::size_t i = 0; i < faces.size(); ++i) put(map, faces[i], values[i]);
}

template <typename Face, typename Value>
void output_face_values(internal_np::Param_not_found, const std::vector<Face>&, const std::vector<Value>&)
{}

} // namespace internal

/*!
\ingroup PkgSymmetryTransformRemeshingRef

Approximates a triangle mesh by a coarse triangle mesh that keeps its symmetries: Variational
Shape Approximation (VSA, Cohen-Steiner et al., as `CGAL::Surface_mesh_approximation::approximate_triangle_mesh()`)
extended to symmetry as in Section 5.1 of Podolak's thesis.

A proxy is a plane that may cover up to one connected patch per transform: the identity and the
reflection through each of `planes`. The faces that cross a plane are first split along it.
Lloyd iterations then alternate:
- flooding, in increasing error, from one seed face per proxy: when a face joins a patch, its
  neighbours are queued for that patch, and the face whose centroid is nearest to the mirror image
  of its centroid through a plane (found with `CGAL::Kd_tree`, within 2% of the bounding box
  diagonal) is offered to the mirrored patch of the same proxy;
- fitting of each proxy over all its patches, each moved back by its transform;
- teleportation of whole proxies (the cheapest merge of two neighbours frees a proxy for the
  worst region) and of patches (a patch of less than 5% of its proxy's largest patch is closed
  for one iteration).

After the last iteration, the patch boundaries of the two sides of each plane are put in step:
the order of the flooding leaves them a face apart here and there, even on a nearly symmetric
mesh, and so also the junctions where the output's anchors go. A face on the negative side of a
plane takes the mirrored patch of its mirror face, where it lies next to that patch and fits it
about as well as its own patch (the flooding's rule); a patch cut in pieces by this keeps its
largest piece.

The error of a face \f$ t \f$ for a patch of proxy \f$ P \f$ is
\f$ E = a_t \left( \alpha \|c_t - c_P\|^2 / A_{avg} + (1 - \alpha) \|n_t - n_P\|^2 \right) \f$,
with \f$ c \f$ the centroids, \f$ n \f$ the unit normals (the proxy's moved by the patch's
transform), \f$ a_t \f$ the area of \f$ t \f$ and \f$ A_{avg} \f$ the mean face area: the
area-weighted form of the thesis's combined metric, the \f$ L^{2,1} \f$ metric of CGAL's VSA for
\f$ \alpha = 0 \f$. The default \f$ \alpha = 0.002 \f$ is the thesis's.

The output mesh is extracted as in CGAL's VSA (anchors where three patches meet, boundary chords
subdivided, a boundary cycle with fewer than three anchors completed with the vertices farthest
from its anchors, a Dijkstra flooding of each patch from its anchors giving the triangles; of the
triangles folded onto each other, sharing a directed edge, only the largest is kept, and the
holes so left, where not on a border of the input, are filled by the triangulation of least
total edge length, or a fan from their centroid, so that a closed input gives a closed output
and a hole and its mirror image get mirror fills), with patches as regions, and symmetry enforced: vertices on a plane where a patch boundary crosses it
become anchors; every anchor's mirror image, if it lies on a boundary of the same proxies (and not next to an anchor), becomes
an anchor too; anchors whose mirror images are mutually nearest among the anchors of the same
proxies are moved to exact mirror positions (those on a plane onto the plane).
With an empty range of planes and `position_weight(0)`, this is plain VSA.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam PlaneRange a range of `geom_traits::Plane_3` (e.g. the `plane` of each `Principal_symmetry`)
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the input mesh (not modified)
\param planes the planes of symmetry to keep (at most 64)
\param np optional named parameters among:

\cgalNamedParamsBegin
  \cgalParamNBegin{max_number_of_proxies}
    \cgalParamDescription{the number of proxies \f$ K \f$ (each with up to one patch per transform)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{as CGAL's VSA: a third of the faces, seeding stopped by `min_error_drop`}
  \cgalParamNEnd
  \cgalParamNBegin{min_error_drop}
    \cgalParamDescription{seeding stops when the error falls below this fraction of the initial error}
    \cgalParamType{`double`}
    \cgalParamDefault{0.1 if `max_number_of_proxies` is not given, else not used}
  \cgalParamNEnd
  \cgalParamNBegin{seeding_method}
    \cgalParamDescription{`CGAL::Surface_mesh_approximation::RANDOM`, `INCREMENTAL` or `HIERARCHICAL`, as in CGAL's VSA}
    \cgalParamType{`CGAL::Surface_mesh_approximation::Seeding_method`}
    \cgalParamDefault{`CGAL::Surface_mesh_approximation::HIERARCHICAL`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_relaxations}
    \cgalParamDescription{iterations after each seeding step; a proxy teleportation is tried every this many iterations}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{iterations after seeding}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{position_weight}
    \cgalParamDescription{\f$ \alpha \in [0,1] \f$ of the metric: the weight of centroid distances against normal deviations}
    \cgalParamType{`double`}
    \cgalParamDefault{0.002, the thesis's value (0 is the \f$ L^{2,1} \f$ metric of CGAL's VSA)}
  \cgalParamNEnd
  \cgalParamNBegin{strongest_plane_only}
    \cgalParamDescription{whether each face may only be reflected through the plane whose mirror
                          image of its centroid lies closest to a face centroid (the thesis's option
                          for several local symmetries, Figure 5.8)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{subdivision_ratio}
    \cgalParamDescription{chord subdivision threshold, as in CGAL's VSA}
    \cgalParamType{`double`}
    \cgalParamDefault{5.0}
  \cgalParamNEnd
  \cgalParamNBegin{relative_to_chord}
    \cgalParamDescription{whether `subdivision_ratio` is relative to the chord length instead of the mean edge length}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{with_dihedral_angle}
    \cgalParamDescription{whether the chord criterion is weighted by the sine of the angle between the patches}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{optimize_anchor_location}
    \cgalParamDescription{whether anchors are placed at the mean of their projections onto their patches' planes}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of `RANDOM` seeding; the result is deterministic for a seed}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads of the mirror-face queries (the result does not depend on it)}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{the hardware concurrency}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{whether to print the main steps and their times on `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the points of the vertices of `tm`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key and `geom_traits::Point_3` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{the kernel of the point type}
  \cgalParamNEnd
\cgalNamedParamsEnd

\cgalNamedParamsBegin{Output Named Parameters}
  \cgalParamNBegin{face_proxy_map}
    \cgalParamDescription{receives the proxy of each face of `tm` (of its largest part if it was split)}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{face_patch_map}
    \cgalParamDescription{receives the transform of the patch of each face: 0 for the identity,
                          \f$ j \f$ for the reflection through the \f$ j \f$-th plane of `planes`}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{proxies}
    \cgalParamDescription{receives the plane of each proxy (its identity patch's; the patch of a
                          reflection has the reflected plane)}
    \cgalParamType{an `OutputIterator` with `geom_traits::Plane_3` as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{anchors}
    \cgalParamDescription{receives the vertices of the output mesh}
    \cgalParamType{an `OutputIterator` with `geom_traits::Point_3` as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{triangles}
    \cgalParamDescription{receives the triangles of the output mesh, as indices into the anchors}
    \cgalParamType{an `OutputIterator` with `std::array<std::size_t, 3>` as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{output_mesh}
    \cgalParamDescription{a pointer to a mesh that receives the output (cleared first; a soup that
                          is not a polygon mesh is oriented first, its non-manifold vertices duplicated)}
    \cgalParamType{a pointer to a model of `MutableFaceGraph`, e.g. `CGAL::Surface_mesh<Point_3>*`}
    \cgalParamDefault{no output}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` if the triangles form a 2-manifold oriented polygon mesh
(`CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`), as CGAL's function.
\throws std::invalid_argument if `tm` has no face, a face that is not a triangle, a non-finite
coordinate or only degenerate faces; if a plane is degenerate or there are more than 64; if
`max_number_of_proxies` is given as 0; if `position_weight` lies outside \f$ [0,1] \f$.
*/
template <typename TriangleMesh, typename PlaneRange, typename NamedParameters = parameters::Default_named_parameters>
bool symmetric_approximate_triangle_mesh(const TriangleMesh& tm, const PlaneRange& planes,
                                         const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef internal::Remeshing_mesh Mesh;
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  const auto vpm = internal::vertex_point_map(tm, np);
  internal::Remeshing_settings settings;
  for(const auto& plane : planes) settings.planes.push_back(internal::to_dplane(plane));
  if(settings.planes.size() > 64) throw std::invalid_argument("Symmetry_transform: at most 64 planes of symmetry");
  settings.max_number_of_proxies = choose_parameter(get_parameter(np, internal_np::max_number_of_proxies), std::size_t(0));
  if(!is_default_parameter<NamedParameters, internal_np::max_number_of_proxies_t>::value && settings.max_number_of_proxies == 0)
    throw std::invalid_argument("Symmetry_transform: max_number_of_proxies must be positive");
  settings.min_error_drop = choose_parameter(get_parameter(np, internal_np::min_error_drop), 0.);
  settings.number_of_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), internal::defaults::remeshing_iterations);
  settings.number_of_relaxations = choose_parameter(get_parameter(np, internal_np::number_of_relaxations), internal::defaults::remeshing_relaxations);
  settings.seeding = choose_parameter(get_parameter(np, internal_np::seeding_method), Surface_mesh_approximation::HIERARCHICAL);
  settings.position_weight = choose_parameter(get_parameter(np, internal_np::st_position_weight), internal::defaults::position_weight);
  if(!(settings.position_weight >= 0. && settings.position_weight <= 1.))
    throw std::invalid_argument("Symmetry_transform: position_weight must lie in [0,1]");
  settings.strongest_plane_only = choose_parameter(get_parameter(np, internal_np::st_strongest_plane_only), false);
  settings.random_seed = choose_parameter(get_parameter(np, internal_np::random_seed), internal::defaults::random_seed);
  settings.threads = choose_parameter(get_parameter(np, internal_np::st_number_of_threads), internal::default_number_of_threads());
  settings.verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  internal::Meshing_settings meshing;
  meshing.subdivision_ratio = choose_parameter(get_parameter(np, internal_np::subdivision_ratio), internal::defaults::subdivision_ratio);
  meshing.relative_to_chord = choose_parameter(get_parameter(np, internal_np::relative_to_chord), false);
  meshing.with_dihedral_angle = choose_parameter(get_parameter(np, internal_np::with_dihedral_angle), false);
  meshing.optimize_anchor_location = choose_parameter(get_parameter(np, internal_np::optimize_anchor_location), true);

  // Input checks (empty mesh, non-triangle faces, non-finite or all degenerate), then the working mesh.
  internal::triangles_of_mesh(tm, np);
  Mesh m;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  for(vertex_descriptor v : vertices(tm)) {
    index.emplace(v, m.points.size());
    const internal::Dpoint p = internal::to_dpoint(get(vpm, v));
    m.points.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<face_descriptor> input_faces;
  for(face_descriptor f : faces(tm)) {
    const auto h = halfedge(f, tm);
    m.faces.push_back({index.at(source(h, tm)), index.at(target(h, tm)), index.at(target(next(h, tm), tm))});
    m.origin.push_back(input_faces.size());
    input_faces.push_back(f);
  }
  Eigen::Vector3d low = m.points.front(), high = low;
  for(const Eigen::Vector3d& p : m.points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  m.diagonal = (high - low).norm();
  const double on_plane = 1e-9 * m.diagonal;
  for(const internal::Dplane& plane : settings.planes) m.split_along(plane, on_plane);
  m.build();
  std::vector<std::uint64_t> vertex_planes(m.points.size(), 0);
  for(std::size_t v = 0; v < m.points.size(); ++v)
    for(std::size_t j = 0; j < settings.planes.size(); ++j)
      if(std::abs(internal::signed_distance(settings.planes[j], m.points[v])) <= on_plane) vertex_planes[v] |= std::uint64_t(1) << j;
  if(settings.verbose)
    std::cerr << "Symmetric VSA: " << input_faces.size() << " faces, " << m.number_of_faces() << " after splitting along "
              << settings.planes.size() << " plane(s) (" << seconds() << " s)\n";

  // Mirror faces: the face whose centroid is nearest the reflected centroid, within 2% of the diagonal.
  const std::vector<std::size_t> mirror =
    internal::mirror_faces(m, settings.planes, 0.02 * m.diagonal, settings.strongest_plane_only, settings.threads);
  if(settings.verbose && !settings.planes.empty()) {
    std::size_t count = 0;
    for(std::size_t g : mirror) count += g != Mesh::none ? 1 : 0;
    std::cerr << "  " << count << " face mirrors (" << seconds() << " s)\n";
  }

  internal::Symmetric_partition partition(m, settings, mirror, vertex_planes);
  partition.run();
  if(settings.verbose) std::cerr << "  partition: " << partition.proxies().size() << " proxies (" << seconds() << " s)\n";

  // Outputs on the input faces: the patch of each face's largest part.
  std::vector<std::size_t> face_proxy(input_faces.size(), 0), face_patch(input_faces.size(), 0);
  std::vector<double> largest(input_faces.size(), -1.);
  const std::size_t transforms = partition.transforms();
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const std::size_t o = m.origin[f];
    if(m.area[f] > largest[o]) {
      largest[o] = m.area[f];
      face_proxy[o] = partition.labels()[f] / transforms;
      face_patch[o] = partition.labels()[f] % transforms;
    }
  }
  internal::output_face_values(get_parameter(np, internal_np::face_proxy_map), input_faces, face_proxy);
  internal::output_face_values(get_parameter(np, internal_np::face_patch), input_faces, face_patch);
  std::vector<typename GT::Plane_3> proxy_planes;
  for(const auto& p : partition.proxies())
    proxy_planes.push_back(typename GT::Plane_3(typename GT::Point_3(p.center.x(), p.center.y(), p.center.z()),
                                                typename GT::Vector_3(p.normal.x(), p.normal.y(), p.normal.z())));
  internal::output_values(get_parameter(np, internal_np::proxies), proxy_planes);

  if(is_default_parameter<NamedParameters, internal_np::anchors_t>::value &&
     is_default_parameter<NamedParameters, internal_np::triangles_t>::value &&
     is_default_parameter<NamedParameters, internal_np::st_output_mesh_t>::value)
    return false;

  // Nearest working vertex to a point.
  std::optional<internal::Nearest_point> nearest;
  if(!settings.planes.empty()) nearest.emplace(m.points);
  auto nearest_vertex = [&nearest](const Eigen::Vector3d& p) { return nearest ? (*nearest)(p).index : Mesh::none; };
  internal::Symmetric_meshing extraction(m, partition, settings.planes, vertex_planes, nearest_vertex);
  internal::Remeshing_output out = extraction.run(meshing);
  if(settings.verbose)
    std::cerr << "  meshing: " << out.anchors.size() << " anchors (" << out.matched_anchors << " mirror-matched), "
              << out.triangles.size() << " triangles (" << seconds() << " s)\n";

  std::vector<typename GT::Point_3> anchor_points;
  for(const Eigen::Vector3d& a : out.anchors) anchor_points.push_back(typename GT::Point_3(a.x(), a.y(), a.z()));
  internal::output_values(get_parameter(np, internal_np::anchors), anchor_points);
  internal::output_values(get_parameter(np, internal_np::triangles), out.triangles);
  internal::build_output_mesh(out.anchors, out.triangles, get_parameter(np, internal_np::st_output_mesh));
  return Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(out.triangles);
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRIC_REMESHING_H
