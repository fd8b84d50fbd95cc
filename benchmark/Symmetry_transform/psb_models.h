// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Reading the Princeton Shape Benchmark's models (research use only: read from the folder given
// on the command line, never committed) for the programs that run on it: retrieval_benchmark,
// viewpoint_experiment, peer_comparison. Its .off files are polygon soups with every defect, made
// meshes here.

#ifndef SYMMETRY_TRANSFORM_PSB_MODELS_H
#define SYMMETRY_TRANSFORM_PSB_MODELS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "retrieval_evaluation.h"

namespace psb_models {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef std::vector<K::Point_3> Points;
typedef std::vector<std::vector<std::size_t>> Polygons;

// Drops the polygons with fewer than 3 corners or a non-finite corner (the library refuses NaN).
inline std::size_t drop_unusable_polygons(const Points& points, Polygons& polygons)
{
  const std::size_t before = polygons.size();
  polygons.erase(std::remove_if(polygons.begin(), polygons.end(), [&](const std::vector<std::size_t>& p) {
                   if(p.size() < 3) return true;
                   for(std::size_t v : p)
                     if(v >= points.size() || !std::isfinite(points[v].x()) || !std::isfinite(points[v].y()) ||
                        !std::isfinite(points[v].z()))
                       return true;
                   return false;
                 }),
                 polygons.end());
  return before - polygons.size();
}

// The faces of `mesh` as a triangle soup, each polygon cut into a fan around its first corner
// (the fallback for the polygons that PMP::triangulate_faces could not triangulate).
inline void fan_triangulated(Mesh& mesh)
{
  Points points(mesh.points().begin(), mesh.points().end());
  Polygons triangles;
  for(Mesh::Face_index f : faces(mesh)) {
    std::vector<std::size_t> corners;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh)) corners.push_back(std::size_t(v));
    for(std::size_t i = 1; i + 1 < corners.size(); ++i) triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  PMP::orient_polygon_soup(points, triangles);
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
}

// Reads any polygon file as a soup, repairs it (merged duplicate points, degenerate and duplicate
// polygons removed, orientation made consistent, non-manifold vertices duplicated), makes a
// mesh of it and triangulates it. Returns what had to be done ("" for a clean triangle mesh);
// throws if nothing usable is left.
inline std::string read_triangle_mesh(const std::string& file, Mesh& mesh)
{
  Points points;
  Polygons polygons;
  if(!CGAL::IO::read_polygon_soup(file, points, polygons) || polygons.empty())
    throw std::runtime_error("not a readable polygon file");
  std::ostringstream note;
  const std::size_t read = polygons.size();
  std::size_t non_triangles = 0;
  for(const auto& p : polygons) non_triangles += p.size() != 3;
  if(const std::size_t dropped = drop_unusable_polygons(points, polygons)) note << dropped << " unusable polygons dropped; ";
  PMP::repair_polygon_soup(points, polygons);
  if(polygons.size() != read) note << "repair kept " << polygons.size() << " of " << read << " polygons; ";
  if(polygons.empty()) throw std::runtime_error("no usable polygon");
  if(!PMP::orient_polygon_soup(points, polygons)) note << "non-manifold or non-orientable: points duplicated; ";
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(non_triangles > 0) {
    note << non_triangles << " polygons with more than 3 corners triangulated";
    if(!PMP::triangulate_faces(mesh)) {
      fan_triangulated(mesh);
      note << " (some as fans)";
    }
    note << "; ";
  }
  std::string text = note.str();
  return text.empty() ? text : text.substr(0, text.size() - 2);
}

// The file of model `id` in the benchmark's folder `data`: db/<id / 100>/m<id>/m<id>.off.
inline std::filesystem::path model_path(const std::filesystem::path& data, int id)
{
  const std::string m = "m" + std::to_string(id);
  return data / "db" / std::to_string(id / 100) / m / (m + ".off");
}

// A model of the benchmark: "m<id> (<class>)" and its file.
struct Model
{
  std::string name;
  std::filesystem::path path;
};

// The first model of every class of the benchmark's test set (classes in the file's order).
inline std::vector<Model> first_test_models(const std::string& data)
{
  std::ifstream in(std::filesystem::path(data) / "classification" / "test.cla");
  const retrieval_evaluation::Classification c = retrieval_evaluation::read_classification(in);
  std::vector<Model> models;
  for(std::size_t i = 0; i < c.model_ids.size(); ++i) {
    if(i > 0 && c.class_of[i] == c.class_of[i - 1]) continue;
    const int id = c.model_ids[i];
    models.push_back({"m" + std::to_string(id) + " (" + c.class_names[c.class_of[i]] + ")", model_path(data, id)});
  }
  return models;
}

struct Named_mesh
{
  std::string name;
  Mesh mesh;
};

// Those models read with read_triangle_mesh(); the unreadable ones are reported and skipped.
inline std::vector<Named_mesh> psb_shapes(const std::string& data)
{
  std::vector<Named_mesh> shapes;
  for(const Model& m : first_test_models(data)) {
    Named_mesh s{m.name, Mesh()};
    try {
      read_triangle_mesh(m.path.string(), s.mesh);
      shapes.push_back(std::move(s));
    } catch(const std::exception& e) {
      std::cerr << "skipped " << s.name << ": " << e.what() << "\n";
    }
  }
  return shapes;
}

} // namespace psb_models

#endif // SYMMETRY_TRANSFORM_PSB_MODELS_H
