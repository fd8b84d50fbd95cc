// Chooses the best views of a mesh from its symmetries (thesis, Section 4.3): finds its principal
// planes of symmetry, scores each view direction v by S(v) = sum |v.u| M(u) over the planes (unit
// normals u, symmetry M(u)), prints the best views (local maxima of S: the views wasting the least
// of the image on mirror-redundant content) and the worst one, and writes the score as a sphere
// coloured from dark (worst) to bright (best), centred on the mesh and of its radius, to be viewed
// with the mesh.
//
// usage: best_viewpoint [mesh.off|.ply|.obj|.stl] [--resolution N] [--samples N] [--seed S]
//          [--views K] [--output FILE.ply]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

// A dark-to-bright colour ramp (close to matplotlib's "inferno"): 0 is black, 1 is pale yellow.
CGAL::IO::Color ramp(double t)
{
  static const double stops[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
  t = std::clamp(t, 0., 1.) * 4.;
  const int s = std::min(int(t), 3);
  auto channel = [&](int c) {
    return (unsigned char)std::lround(stops[s][c] + (t - s) * (stops[s + 1][c] - stops[s][c]));
  };
  return CGAL::IO::Color(channel(0), channel(1), channel(2));
}

std::size_t integer(const std::string& option, const std::string& text, std::size_t minimum = 1)
{
  if(text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos ||
     std::stoull(text) < minimum)
    throw std::invalid_argument(option + " expects an integer >= " + std::to_string(minimum) +
                                ", not '" + text + "'");
  return std::size_t(std::stoull(text));
}

std::string direction(const K::Vector_3& v)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << "(" << std::setw(6) << v.x() << ' ' << std::setw(6) << v.y() << ' '
    << std::setw(6) << v.z() << ")";
  return s.str();
}

int main(int argc, char** argv)
try {
  std::string filename, output = "best_viewpoint.ply";
  std::size_t resolution = 64, samples = 500000, seed = 0, views = 5; // samples: detection's default
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value);
    else if(arg == "--samples") samples = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--views") views = integer(arg, value);
    else if(arg == "--output") output = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");

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

  // The principal planes: GEDT and PRST on resolution^3 grids, local maxima refined by ISP.
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries(
    mesh, CGAL::parameters::grid_resolution(int(resolution)).number_of_samples(samples).random_seed(unsigned(seed)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution
            << "^3) in " << seconds << " s:\n   #   normal u                   M(u)\n";
  double total = 0.;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Vector_3 n = symmetries[i].plane.orthogonal_vector();
    std::cout << std::setw(4) << i + 1 << "   " << direction(n / std::sqrt(n.squared_length())) << std::fixed
              << std::setw(10) << symmetries[i].symmetry << std::defaultfloat << "\n";
    total += symmetries[i].symmetry;
  }

  // The views: local maxima of S (best first) and its global minimum.
  std::vector<ST::Viewpoint<K>> best;
  ST::best_viewpoints(symmetries, std::back_inserter(best));
  if(best.empty()) {
    std::cout << "No plane of symmetry: every view scores S = 0, none is better than another.\n";
  } else {
    std::cout << "\nS(v) = sum |v.u| M(u), in [0, " << total << "]; v and -v are the same view (shown with z > 0).\n"
              << "Best views (local maxima of S), best first:\n" << std::fixed;
    for(std::size_t i = 0; i < std::min(best.size(), views); ++i) {
      double off = 90.; // angle to the nearest plane normal
      for(const auto& s : symmetries) {
        const K::Vector_3 n = s.plane.orthogonal_vector();
        const double c = std::abs(best[i].direction * n) / std::sqrt(n.squared_length());
        off = std::min(off, std::acos(std::min(1., c)) * 180. / CGAL_PI);
      }
      std::cout << std::setw(4) << i + 1 << "   v = " << direction(best[i].direction) << "   S = "
                << std::setprecision(3) << best[i].score << "   " << std::setprecision(1) << off
                << " deg from the nearest plane normal\n";
    }
    if(best.size() > views) std::cout << "     (" << best.size() - views << " more)\n";
  }
  const ST::Viewpoint<K> worst = ST::worst_viewpoint(symmetries);
  std::cout << std::fixed << std::setprecision(3) << "Worst view (global minimum of S):   v = "
            << direction(worst.direction) << "   S = " << worst.score << "\n";

  // The score sphere, placed on the mesh: centred on its centre of mass (area-weighted, as the
  // library's), of its radius (the largest distance from there to a vertex).
  Mesh sphere = ST::viewpoint_score_sphere(symmetries, 5);
  K::Vector_3 sum = CGAL::NULL_VECTOR;
  double area = 0.;
  for(Mesh::Face_index f : faces(mesh)) {
    const Mesh::Halfedge_index h = halfedge(f, mesh);
    const K::Point_3 centroid = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                               mesh.point(target(next(h, mesh), mesh)));
    sum = sum + PMP::face_area(f, mesh) * (centroid - CGAL::ORIGIN);
    area += PMP::face_area(f, mesh);
  }
  const K::Point_3 center = CGAL::ORIGIN + sum / area;
  double radius = 0.;
  for(Mesh::Vertex_index v : vertices(mesh))
    radius = std::max(radius, std::sqrt(CGAL::squared_distance(center, mesh.point(v))));
  const auto score = sphere.property_map<Mesh::Vertex_index, double>("v:score").first;
  auto colour = sphere.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  const double low = worst.score, high = best.empty() ? worst.score : best.front().score;
  for(Mesh::Vertex_index v : vertices(sphere)) {
    colour[v] = ramp(high > low ? (score[v] - low) / (high - low) : 0.);
    sphere.point(v) = center + radius * (sphere.point(v) - CGAL::ORIGIN);
  }
  std::ostringstream comment;
  comment << std::setprecision(4) << "viewpoint score S(v) of " << filename << " on a sphere of radius " << radius
          << " centred at " << center << "; vertex colour: S from dark " << low << " (worst) to bright " << high
          << " (best)";
  if(!CGAL::IO::write_PLY(output, sphere, comment.str())) throw std::runtime_error("cannot write " + output);
  std::cout << "\nWrote " << output << ": " << num_vertices(sphere) << " vertices, the score sphere centred on the "
            << "mesh,\n  coloured from dark (worst view) to bright (best view)\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
