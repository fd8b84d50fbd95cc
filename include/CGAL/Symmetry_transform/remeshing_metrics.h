// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H
#define CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H

// How good a remeshed surface is: its distance to the original (geometric error) and to its own
// mirror image (symmetry error), both from area-uniform seeded samples and exact closest points
// (CGAL::AABB_tree).

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformRemeshingRef
The distance between two surfaces, measured from samples of each to the other.
*/
struct Approximation_error
{
  /// The root mean square of the distances of the samples of both surfaces to the other surface.
  double rms;
  /// The largest of these distances (the sampled two-sided Hausdorff distance).
  double hausdorff;
};

namespace internal {

// Defects of a triangle soup (triangles as index triples): border edges (an undirected edge of
// one triangle only) and non-manifold vertices (whose triangles do not form one fan: their link
// is not a single path or cycle). For the tests and the comparison with CGAL's VSA.
struct Soup_defects
{
  std::size_t border_edges = 0, non_manifold_vertices = 0;
};

template <typename Triangle>
Soup_defects soup_defects(std::size_t number_of_points, const std::vector<Triangle>& triangles)
{
  Soup_defects d;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edges;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> link(number_of_points);
  for(const Triangle& t : triangles)
    for(int i = 0; i < 3; ++i) {
      ++edges[std::minmax<std::size_t>(t[i], t[(i + 1) % 3])];
      link[t[i]].push_back({t[(i + 1) % 3], t[(i + 2) % 3]});
    }
  for(const auto& e : edges) d.border_edges += e.second == 1 ? 1 : 0;
  for(const auto& l : link) {
    if(l.empty()) continue;
    std::map<std::size_t, std::vector<std::size_t>> adjacent;
    for(const auto& [a, b] : l) {
      adjacent[a].push_back(b);
      adjacent[b].push_back(a);
    }
    const bool branching = std::any_of(adjacent.begin(), adjacent.end(), [](const auto& a) { return a.second.size() > 2; });
    std::set<std::size_t> reached = {adjacent.begin()->first};
    std::vector<std::size_t> stack = {adjacent.begin()->first};
    while(!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      for(std::size_t w : adjacent[v])
        if(reached.insert(w).second) stack.push_back(w);
    }
    if(branching || reached.size() != adjacent.size()) ++d.non_manifold_vertices;
  }
  return d;
}

template <typename TriangleMesh, typename NamedParameters>
std::vector<Dtriangle> metric_triangles(const TriangleMesh& tm, const NamedParameters& np)
{
  return triangles_of_mesh(tm, np);
}

template <typename NamedParameters>
std::vector<Eigen::Vector3d> metric_samples(const std::vector<Dtriangle>& triangles, const NamedParameters& np)
{
  const std::size_t count = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_points_on_faces),
                                                         internal::defaults::metric_samples);
  const unsigned seed = parameters::choose_parameter(parameters::get_parameter(np, internal_np::random_seed), internal::defaults::random_seed);
  return surface_samples(triangles, parameters::number_of_refinement_samples(count).random_seed(seed));
}

// Distances from the points, moved by `map`, to the triangles.
template <typename Map>
std::vector<double> distances_to(const std::vector<Eigen::Vector3d>& points, const Map& map,
                                 const std::vector<Dtriangle>& triangles, unsigned threads)
{
  const Triangle_matcher matcher(triangles);
  std::vector<double> d(points.size());
  parallel_for(points.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    Triangle_matcher::Hint hint;
    for(std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d q = map(points[i]);
      d[i] = (matcher.closest(q, hint, i > begin).first - q).norm();
    }
  });
  return d;
}

template <typename NamedParameters>
unsigned metric_threads(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_number_of_threads),
                                      default_number_of_threads());
}

inline double root_mean_square(const std::vector<double>& d)
{
  double sum = 0.;
  for(double x : d) sum += x * x;
  return d.empty() ? 0. : std::sqrt(sum / double(d.size()));
}

} // namespace internal

/*!
\ingroup PkgSymmetryTransformRemeshingRef

Measures how far two triangle meshes are from each other (e.g. an input mesh and its
approximation): `number_of_points_on_faces` area-uniform samples of each are matched to their
closest points on the other.
\tparam TriangleMesh1, TriangleMesh2 models of `FaceListGraph` whose faces are triangles
\param a, b the meshes
\param np named parameters: `number_of_points_on_faces` (per mesh, default 20000), `random_seed`
       (default 0), `number_of_threads`; the points are those of the `vertex_point` property maps
\returns the root mean square and the largest of the distances of both sets of samples.
\throws std::invalid_argument if a mesh is empty, has a face that is not a triangle, a non-finite
coordinate, or only degenerate faces.
*/
template <typename TriangleMesh1, typename TriangleMesh2, typename NamedParameters = parameters::Default_named_parameters>
Approximation_error approximation_error(const TriangleMesh1& a, const TriangleMesh2& b,
                                        const NamedParameters& np = parameters::default_values())
{
  const std::vector<internal::Dtriangle> ta = internal::metric_triangles(a, parameters::default_values()),
                                         tb = internal::metric_triangles(b, parameters::default_values());
  const auto identity = [](const Eigen::Vector3d& p) { return p; };
  std::vector<double> d = internal::distances_to(internal::metric_samples(ta, np), identity, tb, internal::metric_threads(np));
  const std::vector<double> back =
    internal::distances_to(internal::metric_samples(tb, np), identity, ta, internal::metric_threads(np));
  d.insert(d.end(), back.begin(), back.end());
  return {internal::root_mean_square(d), d.empty() ? 0. : *std::max_element(d.begin(), d.end())};
}

/*!
\ingroup PkgSymmetryTransformRemeshingRef

Measures how far a triangle mesh is from its mirror image through `plane` (the symmetry error
of the thesis, Section 5.1.3): the root mean square of the distances from the reflections of
`number_of_points_on_faces` area-uniform samples of the mesh to the mesh. 0 for an exact symmetry.
\param tm the mesh
\param plane the plane of reflection
\param np named parameters: `number_of_points_on_faces` (default 20000), `random_seed` (default 0),
       `number_of_threads`, `vertex_point_map`
\returns the root mean square distance, in the units of the mesh.
\throws std::invalid_argument if `plane` is degenerate, or on the bad meshes of `approximation_error()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_error(const TriangleMesh& tm,
                      const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const std::vector<internal::Dtriangle> triangles = internal::metric_triangles(tm, np);
  return internal::root_mean_square(internal::distances_to(internal::metric_samples(triangles, np),
                                                           [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); },
                                                           triangles, internal::metric_threads(np)));
}

/*!
\ingroup PkgSymmetryTransformRemeshingRef

Measures the symmetry error of a triangle mesh in the region where another mesh (typically the
original of a remeshed surface) is symmetric: as `symmetry_error(tm, plane, np)`, but over the
samples of `tm` whose mirror images lie within `max_distance` of `reference`. For an
approximately or partially symmetric shape, this leaves out the parts the plane does not map
(a turned head, a missing limb), whose error no remeshing can remove.
\param tm the mesh
\param plane the plane of reflection
\param reference the mesh whose symmetric region is measured
\param max_distance the largest distance from a mirrored sample of `tm` to `reference` in the region
\param np named parameters as `symmetry_error(tm, plane, np)`
\returns the root mean square distance over the region (0 if the region is empty).
\throws std::invalid_argument on the bad input of `symmetry_error()`.
*/
template <typename TriangleMesh, typename ReferenceMesh, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_error(const TriangleMesh& tm,
                      const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                      const ReferenceMesh& reference, double max_distance,
                      const NamedParameters& np = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const std::vector<internal::Dtriangle> triangles = internal::metric_triangles(tm, np),
                                         region = internal::metric_triangles(reference, parameters::default_values());
  const std::vector<Eigen::Vector3d> samples = internal::metric_samples(triangles, np);
  const auto reflect = [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); };
  const std::vector<double> to_reference = internal::distances_to(samples, reflect, region, internal::metric_threads(np)),
                            to_self = internal::distances_to(samples, reflect, triangles, internal::metric_threads(np));
  std::vector<double> inside;
  for(std::size_t i = 0; i < samples.size(); ++i)
    if(to_reference[i] <= max_distance) inside.push_back(to_self[i]);
  return internal::root_mean_square(inside);
}

/*!
\ingroup PkgSymmetryTransformRemeshingRef

Computes, for each face of a triangle mesh, the distance from the mirror image of its centroid
through `plane` to the mesh (0 where the mesh is symmetric), e.g. to colour a remeshed surface
as in the thesis's Figure 5.6.
\tparam FaceErrorMap a model of `WritablePropertyMap` with the face descriptor as key and `double` as value
\param tm the mesh
\param plane the plane of reflection
\param face_error_map receives the distance of each face
\param np named parameters: `number_of_threads`, `vertex_point_map`
\returns the largest distance.
\throws std::invalid_argument on the bad input of `symmetry_error()`.
*/
template <typename TriangleMesh, typename FaceErrorMap, typename NamedParameters = parameters::Default_named_parameters>
double face_symmetry_errors(const TriangleMesh& tm,
                            const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                            FaceErrorMap face_error_map, const NamedParameters& np = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const auto vpm = internal::vertex_point_map(tm, np);
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  std::vector<Eigen::Vector3d> centroids;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_list;
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const internal::Dpoint a = internal::to_dpoint(get(vpm, source(h, tm))), b = internal::to_dpoint(get(vpm, target(h, tm))),
                           c = internal::to_dpoint(get(vpm, target(next(h, tm), tm)));
    centroids.push_back(internal::to_eigen(CGAL::centroid(a, b, c)));
    face_list.push_back(f);
  }
  const std::vector<double> d = internal::distances_to(
    centroids, [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); }, triangles, internal::metric_threads(np));
  double largest = 0.;
  for(std::size_t i = 0; i < face_list.size(); ++i) {
    put(face_error_map, face_list[i], d[i]);
    largest = (std::max)(largest, d[i]);
  }
  return largest;
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H
