// Finds the rotational symmetries of a mesh (axes and orders), prints them, and writes
// - a PLY file: the mesh in grey with each axis drawn as a thin coloured cylinder;
// - a JSON file with the fields of the BOP benchmark's models_info.json for this object, to
//   paste into its entry: "symmetries_discrete" (the rotations by 2 pi j / k about each axis of
//   order k, j = 1 ... k - 1, as row-major 4x4 matrices, translation in the mesh's units) and
//   "symmetries_continuous" (the axis and a point on it, "offset", of each continuous symmetry).
//
// usage: rotational_symmetries [mesh.off|.ply|.obj|.stl] [--resolution N] [--max-order K]
//          [--seed S] [--output FILE.ply]
// writes FILE.ply and FILE.json (default rotational_symmetries.ply and .json)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// The colours of the axes, in turn; the mesh is grey.
const CGAL::IO::Color axis_colours[] = {{230, 60, 40}, {40, 120, 230}, {40, 170, 70}, {240, 170, 20}, {150, 70, 200}};
const CGAL::IO::Color mesh_colour(200, 200, 200);

// Appends the cylinder of radius r along `axis`, from t = -half to t = half around axis.point().
void add_axis(Mesh& mesh, const K::Line_3& axis, double half, double r, const CGAL::IO::Color& colour)
{
  const K::Vector_3 d = axis.to_vector() / std::sqrt(axis.to_vector().squared_length());
  K::Vector_3 u = axis.perpendicular_plane(CGAL::ORIGIN).base1();
  u = u / std::sqrt(u.squared_length());
  const K::Vector_3 v = CGAL::cross_product(d, u);
  constexpr int sides = 12;
  std::vector<Mesh::Vertex_index> ring[2];
  for(int end = 0; end < 2; ++end)
    for(int i = 0; i < sides; ++i) {
      const double a = 2. * CGAL_PI * i / sides;
      ring[end].push_back(mesh.add_vertex(axis.point() + (end ? half : -half) * d + r * (std::cos(a) * u + std::sin(a) * v)));
    }
  auto colours = mesh.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(int i = 0; i < sides; ++i) {
    const int j = (i + 1) % sides;
    colours[mesh.add_face(ring[0][i], ring[0][j], ring[1][j])] = colour;
    colours[mesh.add_face(ring[0][i], ring[1][j], ring[1][i])] = colour;
  }
}

// A 4x4 row-major matrix as a JSON array.
std::string json_matrix(const K::Aff_transformation_3& t)
{
  std::ostringstream out;
  out << std::setprecision(12) << "[";
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) out << (i + j ? ", " : "") << (i < 3 ? t.m(i, j) : (j == 3 ? 1. : 0.));
  return out.str() + "]";
}

std::string json_triple(double x, double y, double z)
{
  std::ostringstream out;
  out << std::setprecision(12) << "[" << x << ", " << y << ", " << z << "]";
  return out.str();
}

// The BOP fields of the symmetries: every rotation of each discrete axis, each continuous axis.
std::string bop_json(const std::vector<ST::Rotational_symmetry<K>>& symmetries)
{
  std::vector<std::string> discrete, continuous;
  for(const auto& s : symmetries) {
    const K::Vector_3 d = s.axis.to_vector();
    if(s.order == 0)
      continuous.push_back("{\"axis\": " + json_triple(d.x(), d.y(), d.z()) + ", \"offset\": " +
                           json_triple(s.axis.point().x(), s.axis.point().y(), s.axis.point().z()) + "}");
    for(int j = 1; j < s.order; ++j)
      discrete.push_back(json_matrix(ST::rotation_about_axis(s.axis, 2. * CGAL_PI * j / s.order)));
  }
  auto list = [](const std::vector<std::string>& items) {
    std::string text;
    for(std::size_t i = 0; i < items.size(); ++i) text += (i ? ",\n    " : "\n    ") + items[i];
    return "[" + text + (items.empty() ? "]" : "\n  ]");
  };
  return "{\n  \"symmetries_discrete\": " + list(discrete) + ",\n  \"symmetries_continuous\": " + list(continuous) + "\n}\n";
}

int main(int argc, char** argv)
try {
  std::string filename, output = "rotational_symmetries.ply";
  int resolution = 64, max_order = 12;
  unsigned seed = 0;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = std::stoi(value);
    else if(arg == "--max-order") max_order = std::stoi(value);
    else if(arg == "--seed") seed = unsigned(std::stoul(value));
    else if(arg == "--output") output = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/pinion.off");
  const std::string base = output.size() > 4 && output.compare(output.size() - 4, 4, ".ply") == 0
                             ? output.substr(0, output.size() - 4) : output;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (with no argument, set CGAL_DATA_DIR to the "
              << "directory holding meshes/pinion.off)." << std::endl;
    return EXIT_FAILURE;
  }
  if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " triangles\n";

  const auto np = CGAL::parameters::grid_resolution(resolution).max_order(max_order).random_seed(seed);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ST::Rotational_symmetry<K>> symmetries = ST::detect_rotational_symmetries(mesh, np);
  std::cout << std::setprecision(3) << symmetries.size() << " rotational symmetries (grid " << resolution << "^3) in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n"
            << "order 0: continuous; support: the fraction of the area the rotation maps onto the surface\n"
            << "   #  order  point on the axis (nearest to the    direction                 symmetry  support\n"
            << "             centre of mass)\n"
            << std::fixed;
  auto triple = [](double x, double y, double z) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3) << "(" << std::setw(8) << x << std::setw(8) << y << std::setw(8) << z << ")";
    return out.str();
  };
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const auto& s = symmetries[i];
    const K::Point_3 p = s.axis.point();
    const K::Vector_3 d = s.axis.to_vector();
    std::cout << std::setw(4) << i + 1 << std::setw(7) << s.order << "  " << triple(p.x(), p.y(), p.z()) << "  "
              << triple(d.x(), d.y(), d.z()) << std::setw(10) << s.symmetry << std::setw(9) << s.support << "\n";
  }

  // The mesh and its axes; the axes reach 20 % beyond the bounding box's half-diagonal.
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double half = 0.6 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
  Mesh out = mesh;
  out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color", mesh_colour);
  std::ostringstream comment;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const CGAL::IO::Color& c = axis_colours[i % (sizeof axis_colours / sizeof axis_colours[0])];
    add_axis(out, symmetries[i].axis, half, 0.008 * half, c);
    comment << (i ? "\n" : "") << "axis " << i + 1 << ": order " << symmetries[i].order << "; symmetry "
            << symmetries[i].symmetry << "; support " << symmetries[i].support << "; colour " << int(c.r()) << " "
            << int(c.g()) << " " << int(c.b());
  }
  if(!CGAL::IO::write_PLY(base + ".ply", out, comment.str())) throw std::runtime_error("cannot write " + base + ".ply");
  std::ofstream(base + ".json") << bop_json(symmetries);
  std::cout << "\nWrote " << base << ".ply (the mesh, each axis a coloured cylinder) and " << base
            << ".json (BOP's symmetries_discrete and symmetries_continuous)\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
