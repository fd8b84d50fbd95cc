// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRIZATION_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRIZATION_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Rotational_symmetry.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/completion.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/mesh_arrays.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/symmetrize_vertices.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * What `symmetrize()` did: the symmetries that the mesh now has exactly, and how far it moved.
 * \tparam GeomTraits a model of `Kernel`
 */
template <typename GeomTraits>
struct Symmetrization
{
  /// The mirror planes of the result, one per plane given, in the same order: each is the given
  /// plane fitted to the vertex pairs it makes (the least squares), then moved by the least that
  /// makes all the symmetries one exact group. Hundredths of a degree from a plane detected on a
  /// noisy mesh; tenths where one side is bent as a whole, which the fitted plane follows halfway.
  std::vector<typename GeomTraits::Plane_3> planes;
  /// The rotational symmetries of the result, one per rotation given, as the planes.
  std::vector<Rotational_symmetry<GeomTraits>> rotations;
  /// The number of motions of the group that the symmetries generate (2 for one plane, 48 for
  /// the nine planes of a cube).
  std::size_t group_size = 0;
  /// The vertices whose images under the group lie on vertices (within half the shortest edge
  /// there): these are placed exactly symmetric, each orbit at its mean, the least displacement.
  std::size_t paired_vertices = 0;
  /// The mean displacement of a vertex.
  typename GeomTraits::FT mean_displacement = 0;
  /// The largest displacement of a vertex.
  typename GeomTraits::FT max_displacement = 0;
};

namespace internal {

template <typename T>
struct Is_rotation_range : std::false_type
{};
template <typename GT, typename Allocator>
struct Is_rotation_range<std::vector<Rotational_symmetry<GT>, Allocator>> : std::true_type
{};

// The motions of the planes, then of the rotations, in the local frame.
template <typename PlaneRange, typename RotationRange>
std::vector<Rigid_motion> generators_in(const Local_frame& frame, const PlaneRange& planes, const RotationRange& rotations)
{
  std::vector<Rigid_motion> generators;
  for(const auto& p : planes) generators.push_back(frame.to_local(reflection(to_dplane(plane_of(p)))));
  for(const auto& r : rotations) generators.push_back(frame.to_local(rotation_generator(r)));
  if(generators.empty()) throw std::invalid_argument("Symmetry_transform: no symmetry given to symmetrize with");
  return generators;
}

// The exact symmetries of the result, in the user's frame, each on the side of the one given.
template <typename GT, typename PlaneRange, typename RotationRange>
void exact_symmetries(const Symmetrized_vertices& s, const Local_frame& frame, const PlaneRange& planes,
                      const RotationRange& rotations, Symmetrization<GT>& result)
{
  std::size_t k = 0;
  for(const auto& p : planes) {
    const Rigid_motion m = frame.to_input(s.motions[s.generator_element[k++]]);
    result.planes.push_back(to_plane<GT>(mirror_of(m, to_dplane(plane_of(p)).normal)));
  }
  for(Rotational_symmetry<GT> r : rotations) {
    const Rigid_motion m = frame.to_input(s.motions[s.generator_element[k++]]);
    if(r.order > 1) {
      const Eigen::Vector3d given = to_eigen(to_dpoint(CGAL::ORIGIN + r.axis.to_vector()));
      const auto [direction, point] = axis_of(m, given, to_eigen(to_dpoint(r.axis.point(0))));
      r.axis = typename GT::Line_3(to_point<GT>(point), to_vector<GT>(direction));
    }
    result.rotations.push_back(r);
  }
}

// What the symmetrization `s` made exact: the symmetries, the group's size, the paired points.
template <typename GT, typename PlaneRange, typename RotationRange>
Symmetrization<GT> symmetrization_of(const Symmetrized_vertices& s, const Local_frame& frame, const PlaneRange& planes,
                                     const RotationRange& rotations)
{
  Symmetrization<GT> result;
  exact_symmetries(s, frame, planes, rotations, result);
  result.group_size = s.motions.size();
  result.paired_vertices = std::size_t(std::count(s.paired.begin(), s.paired.end(), true));
  return result;
}

// The points of a point range and their unit normals (none without a `normal_map`).
template <typename PointRange, typename NamedParameters>
std::pair<std::vector<Eigen::Vector3d>, std::vector<Eigen::Vector3d>> point_arrays(const PointRange& points,
                                                                                   const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  std::vector<Eigen::Vector3d> positions, normals;
  for(const Dpoint& p : points_of_range(points, NP_helper::get_const_point_map(points, np))) positions.push_back(to_eigen(p));
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value)
    normals = unit_normals_of_range(points, NP_helper::get_normal_map(points, np));
  return {positions, normals};
}

// Writes the symmetrized positions (`moved`, of the used vertices `used_index`, in the local frame)
// to the vertices of `tm`, and their displacement; a vertex that no face uses stays. Sets the
// displacement figures of `result`.
template <typename GT, typename TriangleMesh, typename NamedParameters>
void write_positions(TriangleMesh& tm, const std::vector<std::size_t>& used_index, const Mesh_arrays& used,
                     const std::vector<Eigen::Vector3d>& moved, const Local_frame& frame, const NamedParameters& np,
                     Symmetrization<GT>& result)
{
  auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                          get_property_map(CGAL::vertex_point, tm));
  const auto index = vertex_index_map_of(tm, np);
  double sum = 0., largest = 0.;
  for(auto v : vertices(tm)) {
    const std::size_t i = used_index[vertex_index(tm, index, v)];
    Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
    if(i != unused_vertex) {
      displacement = frame.radius * (moved[i] - used.points[i]);
      put(vpm, v, to_point<GT>(frame.to_input(moved[i])));
    }
    sum += displacement.norm();
    largest = (std::max)(largest, displacement.norm());
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_vertex_displacement_map_t>::value)
      put(parameters::get_parameter(np, internal_np::st_vertex_displacement_map), v, to_vector<GT>(displacement));
  }
  result.mean_displacement = sum / double(vertices(tm).size());
  result.max_displacement = largest;
}

// symmetrize() on the vertices that faces use: isolated and removed vertices take no part.
template <typename GT, typename TriangleMesh, typename PlaneRange, typename RotationRange, typename NamedParameters>
Symmetrization<GT> symmetrize_mesh(TriangleMesh& tm, const PlaneRange& planes, const RotationRange& rotations,
                                   const NamedParameters& np)
{
  check_named_parameters(np);
  const unsigned threads = read_number_of_threads(np);
  const bool whole = parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_whole_mesh), false);
  const Mesh_arrays all = mesh_arrays(tm, np);
  const std::vector<std::size_t> used_index = used_vertex_indices(all);
  Mesh_arrays mesh = used_part(all, used_index);
  const Local_frame frame = local_frame(mesh.points);
  const std::vector<Rigid_motion> generators = generators_in(frame, planes, rotations);
  for(Eigen::Vector3d& p : mesh.points) p = frame.to_local(p);
  const std::optional<Symmetrized_vertices> s = with_progress(
    np, [&] { return std::optional(symmetrize_vertices(mesh.points, mesh.faces, generators, whole, threads)); },
    [] { return std::optional<Symmetrized_vertices>(); });
  if(!s) return Symmetrization<GT>();
  Symmetrization<GT> result = symmetrization_of<GT>(*s, frame, planes, rotations);
  write_positions(tm, used_index, mesh, s->points, frame, np, result);
  return result;
}

// symmetrize() for a point set, through its point map (and normal map, if given).
template <typename GT, typename PointRange, typename PlaneRange, typename RotationRange, typename NamedParameters>
Symmetrization<GT> symmetrize_points(PointRange& points, const PlaneRange& planes, const RotationRange& rotations,
                                     const NamedParameters& np)
{
  check_named_parameters(np);
  const unsigned threads = read_number_of_threads(np);
  const bool whole = parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_whole_mesh), false);
  const auto point_map = Point_set_processing_3_np_helper<PointRange, NamedParameters>::get_point_map(points, np);
  std::vector<Eigen::Vector3d> local, normals;
  std::tie(local, normals) = point_arrays(points, np);
  const Local_frame frame = local_frame(local);
  const std::vector<Rigid_motion> generators = generators_in(frame, planes, rotations);
  for(Eigen::Vector3d& p : local) p = frame.to_local(p);
  const std::optional<Symmetrized_vertices> s = with_progress(
    np, [&] { return std::optional(symmetrize_point_positions(local, normals, generators, whole, threads)); },
    [] { return std::optional<Symmetrized_vertices>(); });
  if(!s) return Symmetrization<GT>();
  Symmetrization<GT> result = symmetrization_of<GT>(*s, frame, planes, rotations);
  double sum = 0., largest = 0.;
  std::size_t i = 0;
  for(auto& p : points) {
    const double moved = frame.radius * (s->points[i] - local[i]).norm();
    put(point_map, p, to_point<GT>(frame.to_input(s->points[i++])));
    sum += moved;
    largest = (std::max)(largest, moved);
  }
  result.mean_displacement = sum / double(local.size());
  result.max_displacement = largest;
  return result;
}

// The exact group that the symmetries generate, in the local frame (motions[0] the identity).
template <typename PlaneRange, typename RotationRange>
std::vector<Rigid_motion> exact_group_in(const Local_frame& frame, const PlaneRange& planes,
                                         const RotationRange& rotations)
{
  Symmetry_group group = generated_group(generators_in(frame, planes, rotations));
  make_group_exact(group);
  return group.motions;
}

// The coverage_distance of the completion in the local frame; 0 if not given (the default).
template <typename NamedParameters>
double local_coverage_distance(const NamedParameters& np, const Local_frame& frame)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::st_coverage_distance_t>::value)
    return 0.;
  else
    return read_real(np, internal_np::st_coverage_distance, 0., parameter_ranges::coverage_distance) / frame.radius;
}

template <typename GT, typename PointRange, typename PlaneRange, typename RotationRange, typename OutputIterator,
          typename NamedParameters>
OutputIterator complete_points(const PointRange& points, const PlaneRange& planes, const RotationRange& rotations,
                               OutputIterator out, const NamedParameters& np)
{
  check_named_parameters(np);
  const unsigned threads = read_number_of_threads(np);
  std::vector<Eigen::Vector3d> local, normals;
  std::tie(local, normals) = point_arrays(points, np);
  const Local_frame frame = local_frame(local);
  const std::vector<Rigid_motion> group = exact_group_in(frame, planes, rotations);
  const double coverage = local_coverage_distance(np, frame);
  for(Eigen::Vector3d& p : local) p = frame.to_local(p);
  const std::vector<Added_point> added = with_progress(
    np, [&] { return completion_of_points(local, normals, group, coverage, threads); },
    [] { return std::vector<Added_point>(); });
  for(const Added_point& a : added)
    *out++ = std::make_pair(to_point<GT>(frame.to_input(a.point)), to_vector<GT>(a.normal));
  return out;
}

// The vertices of `tm` by the index of the vertices that faces use (`used_index`).
template <typename TriangleMesh, typename NamedParameters>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
used_vertices(const TriangleMesh& tm, const std::vector<std::size_t>& used_index, std::size_t used_count,
              const NamedParameters& np)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> result(used_count);
  const auto index = vertex_index_map_of(tm, np);
  for(auto v : vertices(tm)) {
    const std::size_t i = used_index[vertex_index(tm, index, v)];
    if(i != unused_vertex) result[i] = v;
  }
  return result;
}

// Adds the faces of `completion` to `tm` (`vertex_of`: its vertices that faces use, numbered as in
// `completion`). An added vertex joined by a stitch to an earlier one is not made: the faces use
// the earlier vertex, so the input's vertices stay, and no border is left between the two.
template <typename GT, typename TriangleMesh, typename VertexPointMap, typename OutputIterator>
OutputIterator add_completion(TriangleMesh& tm, VertexPointMap vpm, const Stitched_completion& completion,
                              std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertex_of,
                              const Local_frame& frame, OutputIterator out)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t input_count = vertex_of.size();
  const std::vector<std::size_t> id = joined_ids(input_count + completion.added.points.size(), completion.stitches);
  for(std::size_t a = 0; a < completion.added.points.size(); ++a) {
    const std::size_t v = input_count + a;
    if(id[v] != v) { // joined to a vertex of smaller number, made already
      vertex_of.push_back(vertex_of[id[v]]);
      continue;
    }
    vertex_of.push_back(add_vertex(tm));
    put(vpm, vertex_of.back(), to_point<GT>(frame.to_input(completion.added.points[a])));
  }
  for(const auto& f : completion.added.faces) {
    const std::array<vertex_descriptor, 3> corners{vertex_of[input_count + f[0]], vertex_of[input_count + f[1]],
                                                   vertex_of[input_count + f[2]]};
    const auto face = CGAL::Euler::add_face(corners, tm);
    if(face != boost::graph_traits<TriangleMesh>::null_face()) *out++ = face;
  }
  return out;
}

template <typename GT, typename TriangleMesh, typename PlaneRange, typename RotationRange, typename OutputIterator,
          typename NamedParameters>
OutputIterator complete_mesh(TriangleMesh& tm, const PlaneRange& planes, const RotationRange& rotations,
                             OutputIterator out, const NamedParameters& np)
{
  check_named_parameters(np);
  const unsigned threads = read_number_of_threads(np);
  const bool stitch = parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_stitch_borders), false);
  const Mesh_arrays all = mesh_arrays(tm, np);
  const std::vector<std::size_t> used_index = used_vertex_indices(all);
  Mesh_arrays mesh = used_part(all, used_index);
  const Local_frame frame = local_frame(mesh.points);
  const std::vector<Rigid_motion> group = exact_group_in(frame, planes, rotations);
  const double coverage = local_coverage_distance(np, frame);
  for(Eigen::Vector3d& p : mesh.points) p = frame.to_local(p);
  const Stitched_completion completion = with_progress(
    np,
    [&] {
      return stitch ? stitched_completion_of_mesh(mesh.points, mesh.faces, group, coverage, threads)
                    : Stitched_completion{completion_of_mesh(mesh.points, mesh.faces, group, coverage, threads), {}};
    },
    [] { return Stitched_completion(); });
  auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                          get_property_map(CGAL::vertex_point, tm));
  return add_completion<GT>(tm, vpm, completion, used_vertices(tm, used_index, mesh.points.size(), np), frame, out);
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * Moves the vertices of `tm` so that its surface becomes symmetric under the mirror planes
 * `planes` (and the rotations of `rotations`), each vertex as little as possible: every vertex and
 * the images of its counterparts meet at their mean (Golovinskiy, Podolak and Funkhouser,
 * "Symmetry-Aware Mesh Processing", 2009). The faces and the order of the vertices are unchanged.
 *
 * The symmetries generate a finite group of motions (two for one plane, 48 for the nine planes of
 * a cube, \f$ 2k \f$ for a plane through a \f$ k \f$-fold axis), made exact first: planes
 * detected to a hundredth of a degree meet at angles of a group only to that precision (the
 * symmetries of the result are returned). A vertex whose images under the group lie on vertices,
 * as on a mesh modelled symmetric and then edited, takes the mean of its orbit: the result is
 * symmetric to rounding, and the displacement the least in the sum of squares (a mirror pair
 * meets halfway). The other vertices take the mean of the images of the closest points of the
 * surface to their images, a few times over, with their displacement smoothed so that neighbours
 * move alike: the surface then becomes nearly symmetric. A vertex that no face uses stays.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam RotationRange a `std::vector` of `Rotational_symmetry<GT>`
 * \param tm the mesh, modified
 * \param planes the mirror planes (possibly none)
 * \param rotations the rotational symmetries, each of order at least 1 (a continuous symmetry,
 *        order 0, has no finite group: give it an order)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{whole_mesh}
 *     \cgalParamDescription{whether every vertex moves; if `false`, only where the symmetries hold: a vertex moves fully if its images lie within 5 % of the radius of the surface, not at all if one lies beyond 15 %, and in part in between (a raised arm with no counterpart stays where it is)}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_displacement_map}
 *     \cgalParamDescription{receives the displacement of each vertex}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GT::Vector_3` as value type}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamThreads{the threads of the closest-point searches\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamCallback{the empty `Symmetrization`\, the mesh unchanged}
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type of `tm`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 * \returns the symmetries of the result, the group's size, the paired vertices and the
 *          displacement
 * \throws std::invalid_argument on a mesh with no face, a face that is not a triangle, a non-finite
 *         coordinate, no symmetry given, a degenerate plane or axis, a rotation of order 0, or
 *         symmetries that generate no finite group of at most 120 motions
 */
template <typename TriangleMesh, typename PlaneRange, typename RotationRange,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<internal::Is_rotation_range<RotationRange>::value, int> = 0
#endif
          >
Symmetrization<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
symmetrize(TriangleMesh& tm, const PlaneRange& planes, const RotationRange& rotations,
           const NamedParameters& np = parameters::default_values())
{
  return internal::symmetrize_mesh<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>(tm, planes, rotations, np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * `symmetrize()` with mirror planes only, as `detect_principal_symmetries()` returns them.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \param tm the mesh, modified
 * \param planes the mirror planes, at least one
 * \param np the named parameters of `symmetrize()`
 * \returns the planes of the result, the group's size, the paired vertices and the displacement
 * \throws std::invalid_argument as `symmetrize()`
 */
template <typename TriangleMesh, typename PlaneRange, typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<!internal::Is_rotation_range<NamedParameters>::value, int> = 0
#endif
          >
Symmetrization<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
symmetrize(TriangleMesh& tm, const PlaneRange& planes, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::symmetrize_mesh<GT>(tm, planes, std::vector<Rotational_symmetry<GT>>(), np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * `symmetrize()` for a point set: moves the points so that the set becomes symmetric under the
 * mirror planes `planes` (and the rotations of `rotations`), each as little as possible. A point
 * whose images under the group land on points (within half the distance from each to its third
 * nearest neighbour), as on a scan of a symmetric object sampled alike on both sides, takes the mean of
 * its orbit: the set becomes symmetric to rounding, with the least displacement. The others take
 * the mean of the images of the surface near their images, a few times over: the surface near a
 * point is its tangent plane if the points have normals (`normal_map`), the point itself otherwise. The order of the points is unchanged; their normals
 * are not updated.
 *
 * \tparam PointRange a model of `Range` whose value type is the key type of the point map
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam RotationRange a `std::vector` of `Rotational_symmetry<GT>`
 * \param points the points, moved through the point map
 * \param planes the mirror planes (possibly none)
 * \param rotations the rotational symmetries, each of order at least 1
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{whole_mesh}
 *     \cgalParamDescription{whether every point moves; if `false`, only where the symmetries hold (as for a mesh: fully if the images of the point lie within 5 % of the radius of the set, not at all if one lies beyond 15 %)}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamThreads{the threads of the nearest-point searches\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamCallback{the empty `Symmetrization`\, the points unchanged}
 *   \cgalParamNBegin{point_map}
 *     \cgalParamDescription{a property map associating points to the elements of the point set `points`}
 *     \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type of the iterator of `PointRange` and whose value type is `GT::Point_3`}
 *     \cgalParamDefault{`CGAL::Identity_property_map<GT::Point_3>`}
 *   \cgalParamNEnd
 *   \cgalParamNormalMap{if given\, the surface near a point is its tangent plane; a zero normal leaves it a point}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 * \returns the symmetries of the result, the group's size, the paired points and the displacement
 * \throws std::invalid_argument as `symmetrize()`, or on an empty point set or points that all coincide
 */
template <typename PointRange, typename PlaneRange, typename RotationRange,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<internal::Is_rotation_range<RotationRange>::value, int> = 0
#endif
          >
Symmetrization<Geom_traits_of_points<PointRange, NamedParameters>>
symmetrize_point_set(PointRange& points, const PlaneRange& planes, const RotationRange& rotations,
                     const NamedParameters& np = parameters::default_values())
{
  return internal::symmetrize_points<Geom_traits_of_points<PointRange, NamedParameters>>(points, planes, rotations, np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * `symmetrize_point_set()` with mirror planes only, as `detect_principal_symmetries_of_points()` returns them.
 *
 * \tparam PointRange a model of `Range` whose value type is the key type of the point map
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \param points the points, moved through the point map
 * \param planes the mirror planes, at least one
 * \param np the named parameters of `symmetrize_point_set()`
 * \returns the planes of the result, the group's size, the paired points and the displacement
 * \throws std::invalid_argument as `symmetrize_point_set()`
 */
template <typename PointRange, typename PlaneRange, typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<!internal::Is_rotation_range<NamedParameters>::value, int> = 0
#endif
          >
Symmetrization<Geom_traits_of_points<PointRange, NamedParameters>>
symmetrize_point_set(PointRange& points, const PlaneRange& planes, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::symmetrize_points<GT>(points, planes, std::vector<Rotational_symmetry<GT>>(), np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * Completes a point set that misses part of a symmetric shape (a scan's far side): adds the images,
 * under the group of motions that `planes` and `rotations` generate, of the points whose image has
 * no point of the set nearby. An image is added where no point lies within the coverage distance,
 * neither an input point nor one added before: nothing is added where the input already has
 * surface, and a part that several motions map to the same place is added once. The group is made
 * exact first, as in `symmetrize()`. Every symmetry is taken to hold on the whole shape: a part
 * with no counterpart on the real object (a raised arm) gets one.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam RotationRange a `std::vector` of `Rotational_symmetry<GT>`
 * \tparam OutputIterator an output iterator accepting `std::pair<GT::Point_3, GT::Vector_3>`
 * \param points the points
 * \param planes the mirror planes (possibly none)
 * \param rotations the rotational symmetries, each of order at least 1
 * \param out receives each added point with its normal (the image of the normal of its source; the
 *        zero vector without `normal_map`)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{coverage_distance}
 *     \cgalParamDescription{an image with a point within this distance is not added}
 *     \cgalParamType{`double`\, positive}
 *     \cgalParamDefault{3 times the median distance from a point to its nearest neighbour (a scan is up to three times sparser where it grazes the surface)\, at least 5 % of the radius of the point set (the distance within which `symmetrize()` takes a symmetry to hold fully)}
 *   \cgalParamNEnd
 *   \cgalParamThreads{the threads of the nearest-point searches\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamCallback{nothing added}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{if given\, the normals of the added points are the images of the normals}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 * \returns the output iterator past the added points
 * \throws std::invalid_argument on an empty point set, points that all coincide, a non-finite
 *         coordinate, no symmetry given, a degenerate plane or axis, a rotation of order 0,
 *         symmetries that generate no finite group of at most 120 motions, or a coverage distance
 *         that is not positive
 */
template <typename PointRange, typename PlaneRange, typename RotationRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<internal::Is_rotation_range<RotationRange>::value, int> = 0
#endif
          >
OutputIterator complete_by_symmetry_of_points(const PointRange& points, const PlaneRange& planes,
                                              const RotationRange& rotations, OutputIterator out,
                                              const NamedParameters& np = parameters::default_values())
{
  return internal::complete_points<Geom_traits_of_points<PointRange, NamedParameters>>(points, planes, rotations, out, np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * `complete_by_symmetry_of_points()` with mirror planes only, as `detect_principal_symmetries_of_points()` returns them.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam OutputIterator an output iterator accepting `std::pair<GT::Point_3, GT::Vector_3>`
 * \param points the points
 * \param planes the mirror planes, at least one
 * \param out receives each added point with its normal
 * \param np the named parameters of `complete_by_symmetry_of_points()`
 * \returns the output iterator past the added points
 * \throws std::invalid_argument as `complete_by_symmetry_of_points()`
 */
template <typename PointRange, typename PlaneRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<!internal::Is_rotation_range<OutputIterator>::value, int> = 0
#endif
          >
OutputIterator complete_by_symmetry_of_points(const PointRange& points, const PlaneRange& planes, OutputIterator out,
                                              const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::complete_points<GT>(points, planes, std::vector<Rotational_symmetry<GT>>(), out, np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * Completes a mesh that misses part of a symmetric shape (a scanned mesh, a model cut open): adds
 * to `tm` the images, under the group of motions that `planes` and `rotations` generate, of the
 * faces whose image has no surface of the mesh nearby (its centroid farther than the coverage
 * distance from the surface and from the faces added before), as `complete_by_symmetry_of_points()`
 * does for points. The added faces form new components, with their own vertices, oriented as
 * the faces they are images of; the faces of the input are unchanged. The gap between the input
 * and the added part is at most about the coverage distance. With `stitch_borders(true)`, the
 * added faces reach up to the borders of the input, and are stitched to it along the border edges
 * whose two ends lie within a quarter of the median edge length of the ends of a border edge of
 * the input (or of the images added before), where every vertex stays manifold: the added faces
 * then use the input's vertices there (no input vertex, face or position changes). A model cut at
 * its mirror planes is closed up; elsewhere a gap narrower than an edge stays (fill it with
 * `CGAL::Polygon_mesh_processing::triangulate_hole()` where needed).
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` whose faces are triangles
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam RotationRange a `std::vector` of `Rotational_symmetry<GT>`
 * \tparam OutputIterator an output iterator accepting `boost::graph_traits<TriangleMesh>::%face_descriptor`
 * \param tm the mesh, to which faces are added
 * \param planes the mirror planes (possibly none)
 * \param rotations the rotational symmetries, each of order at least 1
 * \param out receives each added face
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{coverage_distance}
 *     \cgalParamDescription{the image of a face whose centroid lies within this distance of the surface is not added}
 *     \cgalParamType{`double`\, positive}
 *     \cgalParamDefault{twice the median edge length\, at least 5 % of the radius of the mesh}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{stitch_borders}
 *     \cgalParamDescription{whether the added faces reach up to the input's borders and are stitched to them where their vertices meet}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`: the added faces are separate components}
 *   \cgalParamNEnd
 *   \cgalParamThreads{the threads of the closest-point searches\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamCallback{nothing added}
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type of `tm`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 * \returns the output iterator past the added faces
 * \throws std::invalid_argument as `complete_by_symmetry_of_points()`, or on a mesh with no face or
 *         a face that is not a triangle
 */
template <typename TriangleMesh, typename PlaneRange, typename RotationRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<internal::Is_rotation_range<RotationRange>::value, int> = 0
#endif
          >
OutputIterator complete_by_symmetry(TriangleMesh& tm, const PlaneRange& planes, const RotationRange& rotations,
                                    OutputIterator out, const NamedParameters& np = parameters::default_values())
{
  return internal::complete_mesh<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>(tm, planes, rotations, out, np);
}

/*!
 * \ingroup PkgSymmetryTransformSymmetrizationRef
 * `complete_by_symmetry()` with mirror planes only, as `detect_principal_symmetries()` returns them.
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` whose faces are triangles
 * \tparam PlaneRange a range of `GT::Plane_3` or of `Principal_symmetry<GT>`
 * \tparam OutputIterator an output iterator accepting `boost::graph_traits<TriangleMesh>::%face_descriptor`
 * \param tm the mesh, to which faces are added
 * \param planes the mirror planes, at least one
 * \param out receives each added face
 * \param np the named parameters of `complete_by_symmetry()`
 * \returns the output iterator past the added faces
 * \throws std::invalid_argument as `complete_by_symmetry()`
 */
template <typename TriangleMesh, typename PlaneRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          ,
          std::enable_if_t<!internal::Is_rotation_range<OutputIterator>::value, int> = 0
#endif
          >
OutputIterator complete_by_symmetry(TriangleMesh& tm, const PlaneRange& planes, OutputIterator out,
                                    const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::complete_mesh<GT>(tm, planes, std::vector<Rotational_symmetry<GT>>(), out, np);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRIZATION_H
