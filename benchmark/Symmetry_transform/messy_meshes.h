// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Hard inputs for the detection: a clean mesh made messy in code, as real files are.
// Each variant is a triangle soup (every face with its own three corners, hence one component
// per face, as a soup read without repair), built from the mesh's triangles:
//   - components: the mesh plus `count` small tetrahedra scattered in its bounding box;
//   - interior copy: the mesh plus a copy shrunk to half about the centroid (faces inside);
//   - random interior triangles: the mesh plus 20 or 2000 triangles whose corners are drawn in its
//     bounding box (large faces across the inside);
//   - slivers: each face split into `count` needles by points along its longest edge;
//   - fine part: the faces whose centroid lies in the top 20 % of the x extent split 1-to-4
//     `levels` times (one part tessellated 4^levels times finer than the rest).

#ifndef SYMMETRY_TRANSFORM_BENCHMARK_MESSY_MESHES_H
#define SYMMETRY_TRANSFORM_BENCHMARK_MESSY_MESHES_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace messy_meshes {

template <typename Point>
using Triangle = std::array<Point, 3>;

template <typename Mesh>
std::vector<Triangle<typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type>>
triangles_of(const Mesh& mesh)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  std::vector<Triangle<Point>> triangles;
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto f : faces(mesh)) {
    Triangle<Point> t;
    std::size_t i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      if(i < 3) t[i++] = get(vpm, target(h, mesh));
    triangles.push_back(t);
  }
  return triangles;
}

// A mesh of the soup: each triangle with its own corners.
template <typename Mesh, typename Point>
Mesh mesh_of(const std::vector<Triangle<Point>>& triangles)
{
  Mesh mesh;
  for(const Triangle<Point>& t : triangles) {
    if(CGAL::collinear(t[0], t[1], t[2])) continue;
    mesh.add_face(mesh.add_vertex(t[0]), mesh.add_vertex(t[1]), mesh.add_vertex(t[2]));
  }
  return mesh;
}

template <typename Point>
CGAL::Bbox_3 bbox_of(const std::vector<Triangle<Point>>& triangles)
{
  CGAL::Bbox_3 box;
  for(const Triangle<Point>& t : triangles) box += t[0].bbox() + t[1].bbox() + t[2].bbox();
  return box;
}

template <typename Point>
Point random_point_in(const CGAL::Bbox_3& box, CGAL::Random& random)
{
  return Point(random.get_double(box.xmin(), box.xmax()), random.get_double(box.ymin(), box.ymax()),
               random.get_double(box.zmin(), box.zmax()));
}

template <typename Point>
std::vector<Triangle<Point>> with_components(std::vector<Triangle<Point>> triangles, std::size_t count, CGAL::Random& random)
{
  const CGAL::Bbox_3 box = bbox_of(triangles);
  const double size = 0.005 * (box.xmax() - box.xmin() + box.ymax() - box.ymin() + box.zmax() - box.zmin());
  for(std::size_t c = 0; c < count; ++c) {
    const Point p = random_point_in<Point>(box, random);
    const Point a(p.x() + size, p.y(), p.z()), b(p.x(), p.y() + size, p.z()), d(p.x(), p.y(), p.z() + size);
    triangles.push_back({p, b, a});
    triangles.push_back({p, a, d});
    triangles.push_back({p, d, b});
    triangles.push_back({a, b, d});
  }
  return triangles;
}

template <typename Point>
std::vector<Triangle<Point>> with_interior_copy(std::vector<Triangle<Point>> triangles)
{
  const CGAL::Bbox_3 box = bbox_of(triangles);
  const Point c((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  const std::size_t n = triangles.size();
  for(std::size_t i = 0; i < n; ++i) {
    Triangle<Point> t;
    for(int k = 0; k < 3; ++k) t[k] = CGAL::midpoint(c, triangles[i][k]);
    triangles.push_back(t);
  }
  return triangles;
}

// Large triangles across the inside: corners drawn uniformly in the bounding box.
template <typename Point>
std::vector<Triangle<Point>> with_random_triangles(std::vector<Triangle<Point>> triangles, std::size_t count,
                                                   CGAL::Random& random)
{
  const CGAL::Bbox_3 box = bbox_of(triangles);
  for(std::size_t i = 0; i < count; ++i)
    triangles.push_back({random_point_in<Point>(box, random), random_point_in<Point>(box, random),
                         random_point_in<Point>(box, random)});
  return triangles;
}

template <typename Point>
std::vector<Triangle<Point>> with_slivers(const std::vector<Triangle<Point>>& triangles, std::size_t count)
{
  std::vector<Triangle<Point>> result;
  for(const Triangle<Point>& t : triangles) {
    int longest = 0; // the edge (longest, longest + 1) is split, the opposite corner is the apex
    for(int k = 1; k < 3; ++k)
      if(CGAL::squared_distance(t[k], t[(k + 1) % 3]) > CGAL::squared_distance(t[longest], t[(longest + 1) % 3]))
        longest = k;
    const Point& a = t[longest];
    const Point& b = t[(longest + 1) % 3];
    const Point& apex = t[(longest + 2) % 3];
    for(std::size_t s = 0; s < count; ++s)
      result.push_back({CGAL::barycenter(a, 1. - double(s) / double(count), b),
                        CGAL::barycenter(a, 1. - double(s + 1) / double(count), b), apex});
  }
  return result;
}

template <typename Point>
std::vector<Triangle<Point>> with_fine_part(std::vector<Triangle<Point>> triangles, int levels)
{
  const CGAL::Bbox_3 box = bbox_of(triangles);
  const double threshold = box.xmax() - 0.2 * (box.xmax() - box.xmin());
  for(int level = 0; level < levels; ++level) {
    std::vector<Triangle<Point>> next;
    for(const Triangle<Point>& t : triangles) {
      if(CGAL::centroid(t[0], t[1], t[2]).x() < threshold) {
        next.push_back(t);
        continue;
      }
      const Point m01 = CGAL::midpoint(t[0], t[1]), m12 = CGAL::midpoint(t[1], t[2]), m20 = CGAL::midpoint(t[2], t[0]);
      next.insert(next.end(), {{t[0], m01, m20}, {m01, t[1], m12}, {m20, m12, t[2]}, {m01, m12, m20}});
    }
    triangles.swap(next);
  }
  return triangles;
}

// The messy variants of `mesh`, named, for a fixed seed.
template <typename Mesh>
std::vector<std::pair<std::string, Mesh>> messy_variants(const Mesh& mesh, unsigned seed = 14)
{
  CGAL::Random random(seed);
  const auto triangles = triangles_of(mesh);
  std::vector<std::pair<std::string, Mesh>> variants;
  variants.emplace_back("+2000 tetrahedra", mesh_of<Mesh>(with_components(triangles, 2000, random)));
  variants.emplace_back("+interior copy", mesh_of<Mesh>(with_interior_copy(triangles)));
  variants.emplace_back("+20 random interior triangles", mesh_of<Mesh>(with_random_triangles(triangles, 20, random)));
  variants.emplace_back("+2000 random interior triangles", mesh_of<Mesh>(with_random_triangles(triangles, 2000, random)));
  variants.emplace_back("slivers x8", mesh_of<Mesh>(with_slivers(triangles, 8)));
  variants.emplace_back("fine part 4^3", mesh_of<Mesh>(with_fine_part(triangles, 3)));
  return variants;
}

} // namespace messy_meshes

#endif // SYMMETRY_TRANSFORM_BENCHMARK_MESSY_MESHES_H
