// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_SCORE_SPHERE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_SCORE_SPHERE_H

// The viewpoint score on an icosphere, for viewpoint_score_sphere().

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/viewpoint/weighted_normals.h>

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <stdexcept>
#include <string>

namespace CGAL::Symmetry_transform::internal {

// The finest icosphere: 10 4^8 + 2 = 655362 vertices, more than a viewer needs; each further
// subdivision would quadruple the memory.
constexpr unsigned int max_sphere_subdivisions = 8;

// A unit icosphere (an icosahedron Loop-subdivided `subdivisions` times, its vertices projected
// onto the sphere) with the score of each vertex's direction in the property map "v:score".
template <typename GT>
Surface_mesh<typename GT::Point_3> score_sphere(const Weighted_normals& planes, unsigned int subdivisions)
{
  typedef typename GT::Point_3 Point_3;
  if(subdivisions > max_sphere_subdivisions)
    throw std::invalid_argument("Symmetry_transform: viewpoint_score_sphere: at most " +
                                std::to_string(max_sphere_subdivisions) + " subdivisions");
  Surface_mesh<Point_3> sphere;
  make_icosahedron(sphere, Point_3(0, 0, 0), 1.);
  if(subdivisions > 0)
    Subdivision_method_3::Loop_subdivision(sphere, parameters::number_of_iterations(int(subdivisions)));
  typedef typename Surface_mesh<Point_3>::Vertex_index Vertex_index;
  auto score = sphere.template add_property_map<Vertex_index, double>("v:score", 0.).first;
  for(auto v : vertices(sphere)) {
    const Vec3 u = unit(to_vec3(sphere.point(v)), "viewpoint_score_sphere");
    sphere.point(v) = to_point<GT>(u);
    score[v] = planes.score(u);
  }
  return sphere;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_SCORE_SPHERE_H
