// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Segments a mesh into parts that follow its symmetric components (hierarchical splits by the
// supports of each segment's principal planes), prints the segmentation tree, and writes the
// mesh with its faces coloured by segment. With --sdf, also runs CGAL's SDF segmentation
// (CGAL::segmentation_via_sdf_values, default parameters) on the same mesh, for comparison.
//
// usage: symmetry_segmentation [mesh.off|.ply|.obj|.stl] [--resolution N] [--depth D]
//          [--segments M] [--planes K] [--lambda L] [--seed S] [--output FILE.ply] [--sdf] [--verbose]
// writes FILE.ply (default symmetry_segmentation.ply) and, with --sdf, FILE_sdf.ply

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

// Distinct colours for the first segments (a qualitative palette), then hues spread by the
// golden ratio.
CGAL::IO::Color segment_colour(std::size_t id)
{
  static const unsigned char palette[12][3] = {{230, 159, 0},  {86, 180, 233}, {0, 158, 115},   {240, 228, 66},
                                               {0, 114, 178},  {213, 94, 0},   {204, 121, 167}, {120, 120, 120},
                                               {153, 68, 153}, {136, 204, 238}, {68, 170, 153}, {221, 204, 119}};
  if(id < 12) return CGAL::IO::Color(palette[id][0], palette[id][1], palette[id][2]);
  const double h = std::fmod(0.618033988749895 * double(id), 1.) * 6.;
  const int i = int(h);
  const double f = h - i;
  const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  auto c = [&](int k) { return (unsigned char)std::lround(60. + 170. * rgb[i][k]); };
  return CGAL::IO::Color(c(0), c(1), c(2));
}

std::size_t integer(const std::string& option, const std::string& text, std::size_t minimum = 1)
{
  if(text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos ||
     std::stoull(text) < minimum)
    throw std::invalid_argument(option + " expects an integer >= " + std::to_string(minimum) + ", not '" + text + "'");
  return std::size_t(std::stoull(text));
}

void write_coloured(const Mesh& mesh, const Mesh::Property_map<Mesh::Face_index, std::size_t>& segment,
                    const std::string& file, const std::string& comment)
{
  Mesh out = mesh;
  auto colour = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : faces(out)) colour[f] = segment_colour(segment[f]);
  if(!CGAL::IO::write_PLY(file, out, comment)) throw std::runtime_error("cannot write " + file);
}

void print_tree(const ST::Segmentation_tree<K>& tree, std::size_t s)
{
  static const char* status[] = {"split", "depth limit", "segment count limit", "no partial symmetry",
                                 "not separable", "too small"};
  const ST::Symmetry_segment<K>& segment = tree.segments[s];
  std::cout << std::string(2 * segment.level + 2, ' ') << "#" << s << ": " << segment.number_of_faces << " faces, area "
            << segment.area;
  if(segment.children.empty()) std::cout << ", segment " << segment.segment_id;
  std::cout << " (" << status[int(segment.status)] << ")";
  if(!segment.planes.empty()) {
    std::cout << "; planes (fraction reflected):";
    for(std::size_t i = 0; i < segment.planes.size(); ++i) std::cout << " " << segment.reflected_fractions[i];
  }
  std::cout << "\n";
  for(std::size_t c : segment.children) print_tree(tree, c);
}

int main(int argc, char** argv)
try {
  std::string filename, output = "symmetry_segmentation.ply";
  std::size_t resolution = 32, depth = 3, segments = 0, seed = 0, planes = 6;
  double lambda = 1.;
  bool sdf = false, verbose = false;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--sdf") { sdf = true; continue; }
    if(arg == "--verbose") { verbose = true; continue; }
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value);
    else if(arg == "--depth") depth = integer(arg, value, 0);
    else if(arg == "--segments") segments = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--planes") planes = integer(arg, value);
    else if(arg == "--lambda") lambda = std::stod(value);
    else if(arg == "--output") output = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");
  std::string prefix = output;
  if(prefix.size() > 4 && prefix.compare(prefix.size() - 4, 4, ".ply") == 0) prefix.resize(prefix.size() - 4);

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (OFF, PLY, OBJ or STL; with no "
              << "argument, set CGAL_DATA_DIR to the directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  if(!CGAL::is_triangle_mesh(mesh)) {
    if(!PMP::triangulate_faces(mesh)) throw std::runtime_error("some faces could not be triangulated");
    std::cout << "Triangulated the polygons: " << num_faces(mesh) << " triangles\n";
  }

  ST::Segmentation_tree<K> tree;
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  auto np = CGAL::parameters::grid_resolution(int(resolution)).max_segmentation_depth(depth).max_number_of_planes(planes)
              .smoothing_lambda(lambda).random_seed(unsigned(seed)).verbose(verbose).segmentation_tree(std::ref(tree));
  auto start = std::chrono::steady_clock::now();
  const std::size_t count = segments > 0 ? ST::segment_by_symmetry(mesh, segment, np.max_number_of_segments(segments))
                                         : ST::segment_by_symmetry(mesh, segment, np);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(3) << count << " segments (depth <= " << depth << ", grid " << resolution << "^3) in "
            << seconds << " s\nSegmentation tree (each segment: its faces, area, what became of it, and the\n"
            << "fraction of its area that each of its principal planes reflects):\n";
  for(std::size_t root : tree.roots()) print_tree(tree, root);
  write_coloured(mesh, segment, prefix + ".ply",
                 "symmetry segmentation: " + std::to_string(count) + " segments, face colour = segment");
  std::cout << "Wrote " << prefix << ".ply: the mesh with its faces coloured by segment\n";

  if(sdf) {
    // CGAL's SDF segmentation with its defaults (25 rays, 5 clusters, lambda 0.26).
    auto sdf_values = mesh.add_property_map<Mesh::Face_index, double>("f:sdf", 0.).first;
    auto sdf_segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:sdf_segment", 0).first;
    start = std::chrono::steady_clock::now();
    CGAL::sdf_values(mesh, sdf_values);
    const std::size_t sdf_count = CGAL::segmentation_from_sdf_values(mesh, sdf_values, sdf_segment);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "CGAL's SDF segmentation: " << sdf_count << " segments in " << seconds << " s\n";
    write_coloured(mesh, sdf_segment, prefix + "_sdf.ply",
                   "CGAL SDF segmentation: " + std::to_string(sdf_count) + " segments, face colour = segment");
    std::cout << "Wrote " << prefix << "_sdf.ply: the same, by CGAL's SDF segmentation\n";
  }
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
