// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Writes a polygon soup with every defect of web-sourced meshes, for the test that runs an example
// on it (test/Symmetry_transform/CMakeLists.txt), built here at test time rather than committed:
// an ellipsoid (half-axes 1, 0.6, 0.35) whose points are all duplicated (each corner of a face
// takes either copy), every other face flipped and the faces with x > 0.5 given twice (the copy
// reversed: double-sided); crossing it, a 2 x 2 block of boxes of side 0.6 and height 0.4 whose
// points are shared, so that the inner faces are double-sided and the central edge non-manifold;
// degenerate triangles; points that no polygon uses. Planes of symmetry: x = 0, y = 0, z = 0.
//
// usage: make_defective_soup OUTPUT.off

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <map>
#include <vector>

using namespace st_test;
typedef std::vector<std::size_t> Polygon;

// The index of `p` in `points`, added if new: the boxes share their points.
std::size_t shared_point(const Point_3& p, std::vector<Point_3>& points, std::map<Point_3, std::size_t>& index)
{
  const auto found = index.emplace(p, points.size());
  if(found.second) points.push_back(p);
  return found.first->second;
}

void add_ellipsoid(std::vector<Point_3>& points, std::vector<Polygon>& polygons)
{
  const Surface_mesh mesh = ellipsoid<Surface_mesh>().mesh;
  const std::size_t first = points.size(), n = num_vertices(mesh);
  for(int copy = 0; copy < 2; ++copy)
    for(auto v : vertices(mesh)) points.push_back(mesh.point(v));
  CGAL::Random rng(13);
  std::size_t f = 0;
  for(auto face : faces(mesh)) {
    Polygon polygon;
    for(auto v : vertices_around_face(halfedge(face, mesh), mesh)) polygon.push_back(first + std::size_t(v) + (rng.get_bool() ? n : 0));
    if(f++ % 2 == 0) std::swap(polygon[1], polygon[2]);
    polygons.push_back(polygon);
    if(CGAL::centroid(points[polygon[0]], points[polygon[1]], points[polygon[2]]).x() > 0.5)
      polygons.push_back({polygon[0], polygon[2], polygon[1]});
  }
}

void add_block_of_boxes(std::vector<Point_3>& points, std::vector<Polygon>& polygons)
{
  std::map<Point_3, std::size_t> index;
  for(const double x : {-0.6, 0.})
    for(const double y : {-0.6, 0.}) {
      const Surface_mesh box_mesh = box<Surface_mesh>(0.3, 0.3, 0.2).mesh;
      for(auto face : faces(box_mesh)) {
        Polygon polygon;
        for(auto v : vertices_around_face(halfedge(face, box_mesh), box_mesh))
          polygon.push_back(shared_point(box_mesh.point(v) + Vector_3(x + 0.3, y + 0.3, 0.), points, index));
        polygons.push_back(polygon);
      }
    }
}

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: make_defective_soup OUTPUT.off\n";
    return EXIT_FAILURE;
  }
  std::vector<Point_3> points;
  std::vector<Polygon> polygons;
  add_ellipsoid(points, polygons);
  add_block_of_boxes(points, polygons);
  const std::size_t count = polygons.size();
  for(std::size_t p = 0; p < count; p += 50) { // degenerate: repeated corners, collinear corners
    const Polygon& q = polygons[p];
    points.push_back(CGAL::midpoint(points[q[0]], points[q[1]]));
    polygons.push_back({q[0], q[0], q[1]});
    polygons.push_back({q[0], points.size() - 1, q[1]});
  }
  points.emplace_back(50., -50., 50.); // used by no polygon
  points.emplace_back(-50., 20., 0.);
  if(!CGAL::IO::write_polygon_soup(argv[1], points, polygons, CGAL::parameters::stream_precision(17))) {
    std::cerr << "cannot write " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Wrote " << argv[1] << ": " << points.size() << " points, " << polygons.size() << " polygons\n";
  return EXIT_SUCCESS;
}
