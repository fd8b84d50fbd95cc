// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_OUTPUTS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_OUTPUTS_H

// The outputs of symmetric remeshing, written where the named parameters ask for them (as
// CGAL's VSA, an output not asked for costs nothing): per input face its proxy and patch, the
// proxies' planes, the anchors and triangles, and the output mesh.

#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mesh_extraction.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

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

// Writes values[index of f] to `map` for each face f of `tm`.
template <typename FaceMap, typename TriangleMesh, typename FaceIndexMap, typename Value>
void output_face_values(FaceMap map, const TriangleMesh& tm, const FaceIndexMap& face_index, const std::vector<Value>& values)
{
  for(auto f : faces(tm)) put(map, f, values[get(face_index, f)]);
}

template <typename TriangleMesh, typename FaceIndexMap, typename Value>
void output_face_values(internal_np::Param_not_found, const TriangleMesh&, const FaceIndexMap&, const std::vector<Value>&)
{}

// `face_proxy_map` and `face_patch_map`: the proxy and the transform of the patch of each input
// face, those of its largest part where it was split.
template <typename TriangleMesh, typename NamedParameters>
void write_face_outputs(const TriangleMesh& tm, const Symmetric_partition& partition, const NamedParameters& np)
{
  const Remeshing_mesh& mesh = partition.mesh();
  const std::size_t input_faces = num_faces(tm);
  std::vector<std::size_t> face_proxy(input_faces, 0), face_patch(input_faces, 0);
  std::vector<double> largest(input_faces, -1.);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f) {
    const std::size_t o = mesh.origin[f];
    if(mesh.area[f] > largest[o]) {
      largest[o] = mesh.area[f];
      face_proxy[o] = partition.labels()[f] / partition.transforms();
      face_patch[o] = partition.labels()[f] % partition.transforms();
    }
  }
  const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
  output_face_values(parameters::get_parameter(np, internal_np::face_proxy_map), tm, face_index, face_proxy);
  output_face_values(parameters::get_parameter(np, internal_np::face_patch), tm, face_index, face_patch);
}

// `proxies`: the plane of each proxy (its identity patch's), in the kernel GT and the input's
// coordinates (the partition's are `frame`'s).
template <typename GT, typename NamedParameters>
void write_proxies(const Symmetric_partition& partition, const Local_coordinates& frame, const NamedParameters& np)
{
  std::vector<typename GT::Plane_3> planes;
  for(const auto& p : partition.proxies())
    planes.push_back(typename GT::Plane_3(to_point<GT>(frame.to_input(p.center)), to_vector<GT>(p.normal)));
  output_values(parameters::get_parameter(np, internal_np::proxies), planes);
}

// `anchors`, `triangles` and `output_mesh`, in the input's coordinates (those of `out` are `frame`'s).
template <typename GT, typename NamedParameters>
void write_mesh_outputs(const Remeshing_output& out, const Local_coordinates& frame, const NamedParameters& np)
{
  std::vector<Eigen::Vector3d> anchors;
  std::vector<typename GT::Point_3> anchor_points;
  for(const Eigen::Vector3d& a : out.anchors) {
    anchors.push_back(frame.to_input(a));
    anchor_points.push_back(to_point<GT>(anchors.back()));
  }
  output_values(parameters::get_parameter(np, internal_np::anchors), anchor_points);
  output_values(parameters::get_parameter(np, internal_np::triangles), out.triangles);
  build_output_mesh(anchors, out.triangles, parameters::get_parameter(np, internal_np::st_output_mesh));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_OUTPUTS_H
