// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "progress_bar.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

const char* const usage = R"(usage: symmetric_remeshing [MESH] [--resolution N] [--planes P] [--plane a,b,c,d]...
         [--proxies K] [--alpha A] [--strongest 0|1] [--seed S] [--verbose 0|1] [--output FILE]

Remeshes a mesh coarsely while keeping its symmetry: finds its principal symmetries (or takes
the planes given), runs the symmetric Variational Shape Approximation with K proxies, and
compares it with CGAL's plain VSA with K and 2K proxies on the same input (a symmetric proxy
may have two patches): geometric error to the input and symmetry error of the output.
Writes the symmetric result, and CGAL's with K proxies beside it, as PLY files whose faces
are coloured by their symmetry error (dark: symmetric).

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    grid resolution of the plane detection, at least 8 (default 64)
  --planes P        how many detected planes to keep (default 1)
  --plane a,b,c,d   a plane ax + by + cz + d = 0 to use instead of detected ones (repeatable)
  --proxies K       proxies of the symmetric VSA; CGAL's VSA runs with K and 2K (default 50)
  --alpha A         the position weight of the metric (default 0.002, the thesis's)
  --strongest 0|1   1: each face reflected only through its strongest plane, for several
                    local symmetries (default 0)
  --seed S          random seed: the same seed, the same mesh (default 0)
  --verbose 0|1     1: prints the steps of the symmetric VSA (default 0)
  --output FILE     writes FILE (symmetric VSA) and FILE_cgal_vsa.ply (CGAL's VSA, K proxies)
                    (default symmetric_remeshing.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

// The faces coloured by their symmetry error range from dark blue (0) to yellow (this fraction of
// the bounding box diagonal or more); the second symmetry error of each plane counts only the
// samples whose mirror image lies within it of the input.
constexpr double error_scale = 0.02;

// The planes given as --plane a,b,c,d (the plane ax+by+cz+d=0).
std::vector<K::Plane_3> planes_of(const std::vector<std::string>& texts)
{
  std::vector<K::Plane_3> planes;
  for(const std::string& text : texts) {
    std::istringstream in(text);
    double c[4];
    char comma;
    if(!(in >> c[0] >> comma >> c[1] >> comma >> c[2] >> comma >> c[3]))
      throw std::invalid_argument("--plane expects a,b,c,d (the plane ax+by+cz+d=0), not '" + text + "'");
    planes.emplace_back(c[0], c[1], c[2], c[3]);
  }
  return planes;
}

std::vector<K::Plane_3> detected_planes(const Mesh& mesh, std::size_t resolution, std::size_t count, std::size_t seed)
{
  CGAL::Real_timer timer;
  timer.start();
  std::vector<K::Plane_3> planes;
  for(const auto& s : ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(int(resolution))
                                                              .max_number_of_planes(count).random_seed(unsigned(seed))))
    planes.push_back(s.plane);
  std::cout << "Detected " << planes.size() << " plane(s) on a " << resolution << "^3 grid in " << std::setprecision(3)
            << timer.time() << " s (not counted below)\n";
  if(planes.empty()) std::cout << "No plane: the symmetric VSA is plain VSA here.\n";
  return planes;
}

double diagonal_of(const Mesh& mesh)
{
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// A remeshed surface with its errors: to the input (RMS, Hausdorff) and, per plane, its symmetry
// error, over all samples then over those whose mirror image lies near the input.
struct Result
{
  std::string name;
  Mesh mesh{};
  double seconds = 0.;
  ST::Approximation_error error{0., 0.};
  std::vector<double> symmetry{};
};

Result measured(Result r, const Mesh& input, const std::vector<K::Plane_3>& planes, std::size_t seed)
{
  const auto np = CGAL::parameters::number_of_points_on_faces(20000).random_seed(unsigned(seed));
  r.error = ST::approximation_error(input, r.mesh, np);
  for(const K::Plane_3& p : planes) {
    r.symmetry.push_back(ST::symmetry_error(r.mesh, p, np));
    r.symmetry.push_back(ST::symmetry_error(r.mesh, p, input, error_scale * diagonal_of(input), np));
  }
  return r;
}

// CGAL's VSA with its defaults (hierarchical seeding, 5 relaxations, 20 iterations), k proxies.
Result cgal_vsa(const Mesh& mesh, std::size_t k)
{
  Result r{"CGAL VSA,      K = " + std::to_string(k)};
  std::vector<K::Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::Real_timer timer;
  timer.start();
  CGAL::Surface_mesh_approximation::approximate_triangle_mesh(mesh, CGAL::parameters::max_number_of_proxies(k)
                                                                       .anchors(std::back_inserter(anchors))
                                                                       .triangles(std::back_inserter(triangles)));
  r.seconds = timer.time();
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles)) PMP::orient_polygon_soup(anchors, triangles);
  PMP::polygon_soup_to_polygon_mesh(anchors, triangles, r.mesh);
  return r;
}

void print_errors(const std::vector<Result>& results, double diagonal)
{
  std::cout << "\nErrors in units of 1e-3 of the bounding box diagonal (" << diagonal << "):\n"
            << "  method                  vertices  faces   time (s)  RMS error  Hausdorff  symmetry error per plane\n"
            << std::fixed << std::setprecision(3);
  for(const Result& r : results) {
    std::cout << "  " << std::left << std::setw(24) << r.name << std::right << std::setw(8) << num_vertices(r.mesh)
              << std::setw(7) << num_faces(r.mesh) << std::setw(10) << r.seconds << std::setw(11)
              << 1e3 * r.error.rms / diagonal << std::setw(11) << 1e3 * r.error.hausdorff / diagonal << "  ";
    for(double s : r.symmetry) std::cout << std::setw(8) << 1e3 * s / diagonal;
    std::cout << "\n";
  }
}

// The result with its faces coloured by their symmetry error through the first plane.
void write_result(const Result& r, const std::vector<K::Plane_3>& planes, double diagonal, const std::string& file)
{
  Mesh scored = r.mesh;
  auto error = scored.add_property_map<Mesh::Face_index, double>("f:symmetry_error", 0.).first;
  if(!planes.empty()) ST::face_symmetry_errors(scored, planes.front(), error);
  std::ostringstream comment;
  comment << r.name << "; face colour: distance of the mirrored centroid to the surface, dark blue 0 to "
          << "yellow >= 2% of the diagonal";
  examples::write_PLY(file, planes.empty() ? r.mesh : examples::with_face_colours(r.mesh, [&](Mesh::Face_index f) {
                        return examples::blue_to_yellow(error[f] / (error_scale * diagonal)); }), comment.str());
  std::cout << "Wrote " << file << "\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64, 8), planes_kept = options.integer("--planes", 1),
                    proxies = options.integer("--proxies", 50), seed = options.integer("--seed", 0, 0);
  const double alpha = options.real("--alpha", 0.002); // the default of position_weight
  const bool verbose = options.integer("--verbose", 0, 0) != 0, strongest = options.integer("--strongest", 0, 0) != 0;
  std::vector<K::Plane_3> planes = planes_of(options.all("--plane"));
  const std::string output = options.text("--output", "symmetric_remeshing.ply");
  options.validate();
  const Mesh mesh = examples::read_triangle_mesh<Mesh>(filename);
  if(planes.empty()) planes = detected_planes(mesh, resolution, planes_kept, seed);
  for(const K::Plane_3& p : planes) std::cout << "  plane " << p << "\n";

  std::vector<Result> results = {measured({"input", mesh}, mesh, planes, seed)};
  Result symmetric{"symmetric VSA, K = " + std::to_string(proxies)};
  CGAL::Real_timer timer;
  timer.start();
  ST::symmetric_approximate_triangle_mesh(mesh, planes,    // with no plane, it is plain VSA
    CGAL::parameters::max_number_of_proxies(proxies).    // K; a proxy may cover a patch and its mirror images
                      position_weight(alpha).            // alpha of the metric: positions against normals
                      strongest_plane_only(strongest).   // reflect each face through its strongest plane only
                      random_seed(unsigned(seed)).       // the same seed, the same mesh
                      verbose(verbose).                  // prints the steps
                      callback(examples::progress_bar("Remeshing")). // a progress bar on a terminal
                      output_mesh(&symmetric.mesh));     // the remeshed surface
  symmetric.seconds = timer.time();
  results.push_back(measured(symmetric, mesh, planes, seed));
  for(std::size_t k : {proxies, 2 * proxies}) results.push_back(measured(cgal_vsa(mesh, k), mesh, planes, seed));
  print_errors(results, diagonal_of(mesh));
  write_result(results[1], planes, diagonal_of(mesh), output);
  write_result(results[2], planes, diagonal_of(mesh), examples::without_ply_extension(output) + "_cgal_vsa.ply");
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
