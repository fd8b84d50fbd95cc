// Remeshes a mesh coarsely while keeping its symmetry: finds its principal symmetries (or takes
// the planes given), runs the symmetric Variational Shape Approximation with K proxies, and
// compares it with CGAL's plain VSA with K and 2K proxies on the same input (a symmetric proxy
// may have two patches): geometric error to the input and symmetry error of the output.
// Writes the symmetric result, and CGAL's with K proxies beside it, as PLY files whose faces
// are coloured by their symmetry error (dark: symmetric).
//
// usage: symmetric_remeshing [mesh.off|.ply|.obj|.stl] [--resolution N] [--planes P]
//          [--plane a,b,c,d]... [--proxies K] [--alpha A] [--strongest 0|1] [--seed S]
//          [--output FILE.ply]
//   --resolution: grid resolution of the plane detection (default 64)
//   --planes: how many detected planes to keep (default 1); --plane gives one instead (repeatable)
//   --alpha: the position weight of the metric (default 0.002, the thesis's); --strongest 1: each face reflected
//   only through its strongest plane (for several local symmetries)
//   writes FILE.ply (symmetric VSA) and FILE_cgal_vsa.ply (CGAL's VSA, K proxies)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace VSA = CGAL::Surface_mesh_approximation;

std::size_t integer(const std::string& option, const std::string& text, std::size_t minimum = 1)
{
  if(text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos ||
     std::stoull(text) < minimum)
    throw std::invalid_argument(option + " expects an integer >= " + std::to_string(minimum) + ", not '" + text + "'");
  return std::size_t(std::stoull(text));
}

K::Plane_3 plane_of(const std::string& text)
{
  std::istringstream in(text);
  double c[4];
  char comma;
  if(!(in >> c[0] >> comma >> c[1] >> comma >> c[2] >> comma >> c[3]))
    throw std::invalid_argument("--plane expects a,b,c,d (the plane ax+by+cz+d=0), not '" + text + "'");
  return K::Plane_3(c[0], c[1], c[2], c[3]);
}

// Dark blue (symmetric) to yellow (asymmetric): t in [0,1].
CGAL::IO::Color ramp(double t)
{
  static const double stops[4][3] = {{20, 30, 110}, {30, 150, 160}, {120, 200, 80}, {250, 230, 40}};
  t = std::clamp(t, 0., 1.) * 3.;
  const int s = std::min(int(t), 2);
  auto channel = [&](int c) { return (unsigned char)std::lround(stops[s][c] + (t - s) * (stops[s + 1][c] - stops[s][c])); };
  return CGAL::IO::Color(channel(0), channel(1), channel(2));
}

struct Result
{
  std::string name;
  Mesh mesh;
  double seconds = 0.;
  ST::Approximation_error error{0., 0.};
  std::vector<double> symmetry; // per plane
};

Mesh mesh_of(std::vector<K::Point_3> points, std::vector<std::array<std::size_t, 3>> triangles)
{
  Mesh out;
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles)) PMP::orient_polygon_soup(points, triangles);
  PMP::polygon_soup_to_polygon_mesh(points, triangles, out);
  return out;
}

int main(int argc, char** argv)
try {
  std::string filename, output = "symmetric_remeshing.ply";
  std::size_t resolution = 64, planes_kept = 1, proxies = 50, seed = 0;
  double alpha = 0.002; // the default of position_weight
  bool verbose = false, strongest = false;
  std::vector<K::Plane_3> planes;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value, 8);
    else if(arg == "--planes") planes_kept = integer(arg, value);
    else if(arg == "--plane") planes.push_back(plane_of(value));
    else if(arg == "--proxies") proxies = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--alpha") alpha = std::stod(value);
    else if(arg == "--output") output = value;
    else if(arg == "--verbose") verbose = value == "1";
    else if(arg == "--strongest") strongest = value == "1";
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");
  const std::string stem = output.size() > 4 && output.compare(output.size() - 4, 4, ".ply") == 0
                             ? output.substr(0, output.size() - 4) : output;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (OFF, PLY, OBJ or STL; with no "
              << "argument, set CGAL_DATA_DIR to the directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  if(!CGAL::is_triangle_mesh(mesh) && !PMP::triangulate_faces(mesh))
    throw std::runtime_error("some faces could not be triangulated");
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";

  if(planes.empty()) {
    const auto start = std::chrono::steady_clock::now();
    const auto found = ST::detect_principal_symmetries(
      mesh, CGAL::parameters::grid_resolution(int(resolution)).max_number_of_planes(planes_kept).random_seed(unsigned(seed)));
    for(const auto& s : found) planes.push_back(s.plane);
    std::cout << "Detected " << planes.size() << " plane(s) on a " << resolution << "^3 grid in " << std::setprecision(3)
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s (not counted below)\n";
  }
  for(const K::Plane_3& p : planes) std::cout << "  plane " << p << "\n";
  if(planes.empty()) std::cout << "No plane: the symmetric VSA is plain VSA here.\n";

  double diagonal = 0.;
  {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                         CGAL::square(box.zmax() - box.zmin()));
  }
  // The same settings for all runs: CGAL's defaults (hierarchical seeding, 5 relaxations, 20
  // iterations) with the number of proxies given.
  std::vector<Result> results;
  auto measure = [&](Result& r) {
    const auto np = CGAL::parameters::number_of_points_on_faces(20000).random_seed(unsigned(seed));
    r.error = ST::approximation_error(mesh, r.mesh, np);
    for(const K::Plane_3& p : planes) {
      r.symmetry.push_back(ST::symmetry_error(r.mesh, p, np));
      r.symmetry.push_back(ST::symmetry_error(r.mesh, p, mesh, 0.02 * diagonal, np));
    }
    results.push_back(std::move(r));
  };
  {
    Result r;
    r.name = "input";
    r.mesh = mesh;
    measure(r);
  }
  {
    Result r;
    r.name = "symmetric VSA, K = " + std::to_string(proxies);
    const auto start = std::chrono::steady_clock::now();
    ST::symmetric_approximate_triangle_mesh(mesh, planes, CGAL::parameters::max_number_of_proxies(proxies)
                                                            .position_weight(alpha).strongest_plane_only(strongest)
                                                            .random_seed(unsigned(seed)).verbose(verbose)
                                                            .output_mesh(&r.mesh));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    measure(r);
  }
  for(std::size_t k : {proxies, 2 * proxies}) {
    Result r;
    r.name = "CGAL VSA,      K = " + std::to_string(k);
    std::vector<K::Point_3> anchors;
    std::vector<std::array<std::size_t, 3>> triangles;
    const auto start = std::chrono::steady_clock::now();
    VSA::approximate_triangle_mesh(mesh, CGAL::parameters::max_number_of_proxies(k).anchors(std::back_inserter(anchors))
                                           .triangles(std::back_inserter(triangles)));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.mesh = mesh_of(anchors, triangles);
    measure(r);
  }

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

  // PLY files, faces coloured by the symmetry error of the first plane.
  for(std::size_t i = 1; i < 3; ++i) {
    Mesh out = results[i].mesh;
    const std::string file = i == 1 ? output : stem + "_cgal_vsa.ply";
    if(!planes.empty()) {
      auto error = out.add_property_map<Mesh::Face_index, double>("f:symmetry_error", 0.).first;
      ST::face_symmetry_errors(out, planes.front(), error);
      auto colour = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
      for(Mesh::Face_index f : faces(out)) colour[f] = ramp(error[f] / (0.02 * diagonal));
      out.remove_property_map(error);
    }
    std::ostringstream comment;
    comment << results[i].name << "; face colour: distance of the mirrored centroid to the surface, dark blue 0 to "
            << "yellow >= 2% of the diagonal";
    if(!CGAL::IO::write_PLY(file, out, comment.str())) throw std::runtime_error("cannot write " + file);
    std::cout << "Wrote " << file << "\n";
  }
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
