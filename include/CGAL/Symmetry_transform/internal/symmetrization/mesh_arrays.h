// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_MESH_ARRAYS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_MESH_ARRAYS_H

// What symmetrize() reads and writes: a mesh's vertices and triangles as arrays, in the frame
// where the vertices have their mean at the origin and lie within radius 1 (the tolerances of the
// symmetrization are fractions of the shape, whatever its position and size), and the
// symmetries given as motions in that frame.

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Rotational_symmetry.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

struct Mesh_arrays
{
  std::vector<Eigen::Vector3d> points; // by the vertex index map
  std::vector<std::array<std::size_t, 3>> faces;
};

// The index of vertex v in [0, num_vertices(tm)); throws otherwise (a vertex_index_map of the
// user that numbers the vertices otherwise).
template <typename TriangleMesh, typename VertexIndexMap>
std::size_t vertex_index(const TriangleMesh& tm, const VertexIndexMap& index,
                         typename boost::graph_traits<TriangleMesh>::vertex_descriptor v)
{
  const std::size_t i = std::size_t(get(index, v));
  if(i >= num_vertices(tm))
    throw std::invalid_argument("Symmetry_transform: the vertex_index_map gives an index not below the number of "
                                "vertices");
  return i;
}

// The vertex index map of `np`, else an initialized internal one. The user's map is taken as it
// is, vertex_index() checking its indices: CGAL's own initialization asserts on a map out of range
// (in builds with assertions) before our clear error could be thrown.
template <typename TriangleMesh, typename NamedParameters>
auto vertex_index_map_of(const TriangleMesh& tm, const NamedParameters& np)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_index_t>::value)
    return parameters::get_parameter(np, internal_np::vertex_index);
  else
    return CGAL::get_initialized_vertex_index_map(tm, np);
}

// Throws on a mesh with no face, a face that is not a triangle, or a non-finite coordinate.
template <typename TriangleMesh, typename NamedParameters>
Mesh_arrays mesh_arrays(const TriangleMesh& tm, const NamedParameters& np)
{
  const auto vpm = vertex_point_map(tm, np);
  const auto index = vertex_index_map_of(tm, np);
  Mesh_arrays mesh;
  mesh.points.assign(num_vertices(tm), Eigen::Vector3d::Zero()); // removed vertices (garbage) included
  for(auto v : vertices(tm)) mesh.points[vertex_index(tm, index, v)] = to_eigen(to_dpoint(get(vpm, v)));
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    if(!CGAL::is_triangle(h, tm))
      throw std::invalid_argument("Symmetry_transform: the mesh has a face that is not a triangle "
                                  "(triangulate it first, e.g. with "
                                  "CGAL::Polygon_mesh_processing::triangulate_faces)");
    mesh.faces.push_back({std::size_t(get(index, source(h, tm))), std::size_t(get(index, target(h, tm))),
                          std::size_t(get(index, target(next(h, tm), tm)))});
  }
  if(mesh.faces.empty()) throw std::invalid_argument("Symmetry_transform: the mesh has no face");
  return mesh;
}

// The index of each vertex among those that faces use, numbered in the order of their first use,
// or unused_vertex for a vertex that no face uses (isolated, or removed and not collected).
constexpr std::size_t unused_vertex = std::size_t(-1);

inline std::vector<std::size_t> used_vertex_indices(const Mesh_arrays& mesh)
{
  std::vector<std::size_t> used_index(mesh.points.size(), unused_vertex);
  std::size_t count = 0;
  for(const auto& face : mesh.faces)
    for(std::size_t v : face)
      if(used_index[v] == unused_vertex) used_index[v] = count++;
  return used_index;
}

// The vertices that faces use, and the faces on them (`used_index` from used_vertex_indices()).
inline Mesh_arrays used_part(const Mesh_arrays& mesh, const std::vector<std::size_t>& used_index)
{
  Mesh_arrays used;
  used.points.resize(mesh.points.size() - std::size_t(std::count(used_index.begin(), used_index.end(), unused_vertex)));
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(used_index[v] != unused_vertex) used.points[used_index[v]] = mesh.points[v];
  for(auto face : mesh.faces) {
    for(std::size_t& v : face) v = used_index[v];
    used.faces.push_back(face);
  }
  return used;
}

inline Mesh_arrays used_part(const Mesh_arrays& mesh) { return used_part(mesh, used_vertex_indices(mesh)); }

// x_local = (x - center) / radius.
struct Local_frame
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 1.;

  Eigen::Vector3d to_local(const Eigen::Vector3d& x) const { return (x - center) / radius; }
  Eigen::Vector3d to_input(const Eigen::Vector3d& y) const { return center + radius * y; }
  Rigid_motion to_local(const Rigid_motion& m) const
  {
    Rigid_motion r = m;
    r.translation = (m.linear * center + m.translation - center) / radius;
    return r;
  }
  Rigid_motion to_input(const Rigid_motion& m) const
  {
    Rigid_motion r = m;
    r.translation = radius * m.translation + center - m.linear * center;
    return r;
  }
};

// The mean of the points and the largest distance to it. Throws if they all coincide.
inline Local_frame local_frame(const std::vector<Eigen::Vector3d>& points)
{
  Local_frame frame;
  for(const Eigen::Vector3d& p : points) frame.center += p;
  frame.center /= double(points.size());
  frame.radius = 0.;
  for(const Eigen::Vector3d& p : points) frame.radius = (std::max)(frame.radius, (p - frame.center).norm());
  if(!(frame.radius > 0.)) throw std::invalid_argument("Symmetry_transform: all points of the shape coincide");
  return frame;
}

template <typename Plane>
const Plane& plane_of(const Plane& plane)
{
  return plane;
}
template <typename GT>
const typename GT::Plane_3& plane_of(const Principal_symmetry<GT>& symmetry)
{
  return symmetry.plane;
}

// The reflection through `plane` (unit normal).
inline Rigid_motion reflection(const Dplane& plane)
{
  Rigid_motion r;
  r.linear -= 2. * plane.normal * plane.normal.transpose();
  r.translation = 2. * plane.offset * plane.normal;
  return r;
}

// The plane of a reflection (the -1 eigenvector of its linear part), its normal on the side of `like`.
inline Dplane mirror_of(const Rigid_motion& reflection, const Eigen::Vector3d& like)
{
  const Eigen::Matrix3d projector = 0.5 * (Eigen::Matrix3d::Identity() - reflection.linear); // n n^T
  Eigen::Index column;
  projector.colwise().norm().maxCoeff(&column);
  Eigen::Vector3d n = projector.col(column).normalized();
  if(n.dot(like) < 0.) n = -n;
  return {n, 0.5 * n.dot(reflection.translation)};
}

// The rotation by 2 pi / order about the axis. Throws on a continuous symmetry (order 0), which no
// finite group holds, or an order below 0.
template <typename GT>
Rigid_motion rotation_generator(const Rotational_symmetry<GT>& r)
{
  if(r.order < 1)
    throw std::invalid_argument("Symmetry_transform: a rotational symmetry of order " + std::to_string(r.order) +
                                " cannot be made exact (give continuous symmetries an order, e.g. 64)");
  const Eigen::Vector3d direction = to_eigen(to_dpoint(CGAL::ORIGIN + r.axis.to_vector())) ;
  if(!(direction.norm() > 0.)) throw std::invalid_argument("Symmetry_transform: degenerate rotation axis");
  return rotation_about(to_eigen(to_dpoint(r.axis.point(0))), direction.normalized(), 2. * CGAL_PI / double(r.order));
}

// The axis of a rotation (its +1 eigenvector, on the side of `like`) and the point of it nearest
// to `near`.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> axis_of(const Rigid_motion& rotation, const Eigen::Vector3d& like,
                                                           const Eigen::Vector3d& near)
{
  const Eigen::Matrix3d sym = rotation.linear + rotation.linear.transpose() - Eigen::Matrix3d::Identity() *
                                                                                  (rotation.linear.trace() - 1.);
  Eigen::Index column;
  sym.colwise().norm().maxCoeff(&column);
  Eigen::Vector3d u = sym.col(column).normalized();
  if(u.dot(like) < 0.) u = -u;
  // The fixed points x = L x + t: least squares, pinned to `near` along the axis.
  Eigen::Matrix<double, 4, 3> a;
  a.topRows<3>() = Eigen::Matrix3d::Identity() - rotation.linear;
  a.row(3) = u.transpose();
  Eigen::Vector4d b;
  b.head<3>() = rotation.translation;
  b[3] = u.dot(near);
  return {u, a.colPivHouseholderQr().solve(b)};
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_MESH_ARRAYS_H
