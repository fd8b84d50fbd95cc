// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "progress_bar.h"

#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>

const char* const usage = R"(usage: symmetry_segmentation [MESH] [--resolution N] [--depth D] [--segments M] [--planes K]
         [--lambda L] [--seed S] [--output FILE] [--sdf] [--thickness] [--verbose]

Segments a mesh into parts that follow its symmetric components (hierarchical splits by the
supports of each segment's principal planes), prints the segmentation tree, and writes the
mesh with its faces coloured by segment.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    grid resolution of each segment's plane detection (default 32)
  --depth D         levels of splits (default 3)
  --segments M      no split beyond M segments (default: no limit)
  --planes K        principal planes per segment: its features (default 6)
  --lambda L        weight of the boundary length in the graph cut (default 1)
  --seed S          random seed: the same seed, the same segments (default 0)
  --output FILE     the segmented mesh, .ply (default symmetry_segmentation.ply)
  --sdf             also runs CGAL's SDF segmentation (CGAL::segmentation_via_sdf_values,
                    default parameters) on the same mesh, for comparison: FILE_sdf.ply
  --thickness       clusters the shape diameter function (CGAL::sdf_values) with the planes'
                    supports: parts end where the thickness changes
  --verbose         prints each split
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Segment_map;
namespace ST = CGAL::Symmetry_transform;

void write_segments(const Mesh& mesh, const Segment_map& segment, const std::string& file, const std::string& comment)
{
  examples::write_PLY(file, examples::with_face_colours(mesh, [&](Mesh::Face_index f) {
                        return examples::segment_colour(segment[f]); }), comment);
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

// CGAL's SDF segmentation with its defaults (25 rays, 5 clusters, lambda 0.26), for comparison.
void compare_with_sdf_segmentation(Mesh& mesh, const std::string& prefix)
{
  auto sdf_values = mesh.add_property_map<Mesh::Face_index, double>("f:sdf", 0.).first;
  auto sdf_segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:sdf_segment", 0).first;
  CGAL::Real_timer timer;
  timer.start();
  CGAL::sdf_values(mesh, sdf_values);
  const std::size_t count = CGAL::segmentation_from_sdf_values(mesh, sdf_values, sdf_segment);
  std::cout << "CGAL's SDF segmentation: " << count << " segments in " << timer.time() << " s\n";
  write_segments(mesh, sdf_segment, prefix + "_sdf.ply",
                 "CGAL SDF segmentation: " + std::to_string(count) + " segments, face colour = segment");
  std::cout << "Wrote " << prefix << "_sdf.ply: the same, by CGAL's SDF segmentation\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage, {"--sdf", "--thickness", "--verbose"});
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 32), depth = options.integer("--depth", 3, 0),
                    segments = options.integer("--segments", ST::Symmetry_segment<K>::none),
                    planes = options.integer("--planes", 6), seed = options.integer("--seed", 0, 0);
  const double lambda = options.real("--lambda", 1.);
  const bool sdf = options.flag("--sdf"), thickness = options.flag("--thickness"), verbose = options.flag("--verbose");
  const std::string prefix = examples::without_ply_extension(options.text("--output", "symmetry_segmentation.ply"));
  options.validate();
  Mesh mesh = examples::read_triangle_mesh<Mesh>(filename);

  ST::Segmentation_tree<K> tree;
  Segment_map segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  CGAL::Real_timer timer;
  timer.start();
  const auto np =
    CGAL::parameters::grid_resolution(int(resolution)). // of each segment's detection
                      max_segmentation_depth(depth).    // levels of splits
                      max_number_of_segments(segments). // no split beyond this count
                      max_number_of_planes(planes).     // principal planes per segment: its features
                      smoothing_lambda(lambda).         // weight of the boundary length in the graph cut
                      random_seed(unsigned(seed)).      // the same seed, the same segments
                      verbose(verbose).                 // prints each split
                      callback(examples::progress_bar("Segmentation")). // a progress bar on a terminal
                      segmentation_tree(std::ref(tree)); // receives the tree of splits
  std::size_t count = 0;
  if(thickness) { // the shape diameter function as one more feature of every face
    auto diameter = mesh.add_property_map<Mesh::Face_index, double>("f:diameter", 0.).first;
    CGAL::sdf_values(mesh, diameter);
    count = ST::segment_by_symmetry(mesh, segment, np.face_feature_map(diameter));
  } else
    count = ST::segment_by_symmetry(mesh, segment, np);
  std::cout << std::setprecision(3) << count << " segments (depth <= " << depth << ", grid " << resolution << "^3) in "
            << timer.time() << " s\nSegmentation tree (each segment: its faces, area, what became of it, and the\n"
            << "fraction of its area that each of its principal planes reflects):\n";
  for(std::size_t root : tree.roots()) print_tree(tree, root);
  write_segments(mesh, segment, prefix + ".ply",
                 "symmetry segmentation: " + std::to_string(count) + " segments, face colour = segment");
  std::cout << "Wrote " << prefix << ".ply: the mesh with its faces coloured by segment\n";
  if(sdf) compare_with_sdf_segmentation(mesh, prefix);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
