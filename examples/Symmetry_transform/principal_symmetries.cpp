// Finds the principal symmetries of a mesh (its planes of reflective symmetry, refined),
// prints them, and writes one PLY file per plane: the mesh with each face coloured by how much
// the reflection through the plane maps it onto the surface, and the plane drawn as a square.
//
// usage: principal_symmetries [mesh.off|.ply|.obj|.stl] [--resolution N] [--planes K]
//          [--samples N] [--seed S] [--output PREFIX]
// writes PREFIX_1.ply, PREFIX_2.ply, ... (strongest plane first; a trailing ".ply" of PREFIX is dropped)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <algorithm>
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

// The colour of the plane's square: a blue that the ramp below never takes.
const CGAL::IO::Color plane_colour(64, 160, 255);

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

// Appends the square of side `size` in `plane`, centred on the projection of `center`, as two
// triangles of colour plane_colour.
void add_plane_square(Mesh& mesh, const K::Plane_3& plane, const K::Point_3& center, double size)
{
  const K::Point_3 o = plane.projection(center);
  K::Vector_3 u = plane.base1(), v = plane.base2();
  u = u * (size / 2. / std::sqrt(u.squared_length()));
  v = v * (size / 2. / std::sqrt(v.squared_length()));
  const Mesh::Vertex_index a = mesh.add_vertex(o - u - v), b = mesh.add_vertex(o + u - v),
                           c = mesh.add_vertex(o + u + v), d = mesh.add_vertex(o - u + v);
  auto colour = mesh.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : {mesh.add_face(a, b, c), mesh.add_face(a, c, d)}) colour[f] = plane_colour;
}

int main(int argc, char** argv)
try {
  std::string filename, prefix = "principal_symmetries";
  std::size_t resolution = 64, samples = 500000, seed = 0, planes = 6; // samples: detection's default
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value);
    else if(arg == "--samples") samples = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--planes") planes = integer(arg, value);
    else if(arg == "--output") prefix = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");
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

  // GEDT and PRST on resolution^3 grids, local maxima, each refined by Iterative Symmetric Points.
  const auto np = CGAL::parameters::grid_resolution(int(resolution)).max_number_of_planes(planes)
                    .number_of_samples(samples).random_seed(unsigned(seed));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries(mesh, np);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution
            << "^3, " << samples << " Monte Carlo samples) in " << seconds << " s\n";

  // Centre of mass (area-weighted, as the library's) and radius, to place and size the squares.
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

  std::cout << "Centre of mass c = (" << center << "), radius R = " << radius << "\n"
            << "Planes n.x + d = 0 with |n| = 1, strongest first; r = -(n.c + d): n.(x - c) = r;\n"
            << "support: the fraction of the area that the reflection maps onto the surface.\n"
            << "   #   normal n (x y z)             d      r/R  symmetry  support\n" << std::fixed;
  const Mesh shape = mesh; // each file starts from a copy made before the map below is added
  auto support = mesh.add_property_map<Mesh::Face_index, double>("f:support", 0.).first;
  std::vector<std::string> written;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Plane_3& plane = symmetries[i].plane;
    const double fraction = ST::symmetry_support(mesh, plane, support, np);
    const K::Vector_3 n = plane.orthogonal_vector();
    std::cout << std::setw(4) << i + 1 << "   (" << std::setprecision(3) << std::setw(6) << n.x() << ' '
              << std::setw(6) << n.y() << ' ' << std::setw(6) << n.z() << ") " << std::setw(8) << plane.d()
              << std::setw(9) << -(n * (center - CGAL::ORIGIN) + plane.d()) / radius << std::setw(10)
              << symmetries[i].symmetry << std::setw(9) << fraction << "\n";

    // A copy of the mesh, faces coloured by support (thesis, Figure 3.7), plus the plane.
    Mesh out = shape;
    auto colour = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
    for(Mesh::Face_index f : faces(mesh)) colour[f] = ramp(support[f]);
    add_plane_square(out, plane, center, 2.2 * radius);
    const std::string file = prefix + "_" + std::to_string(i + 1) + ".ply";
    std::ostringstream comment;
    comment << std::setprecision(4) << "plane " << i + 1 << ": " << plane << "; symmetry " << symmetries[i].symmetry
            << "; support " << fraction << "; face colour: support (dark 0, bright 1); last 2 faces: the plane";
    if(!CGAL::IO::write_PLY(file, out, comment.str())) throw std::runtime_error("cannot write " + file);
    written.push_back(file);
  }

  if(written.empty()) { std::cout << "No plane found: nothing written.\n"; return EXIT_SUCCESS; }
  std::cout << "\nWrote " << written.front() << (written.size() > 1 ? " ... " + written.back() : std::string())
            << ": per plane, the mesh with faces coloured by support,\n  from dark (none) to bright (full), "
            << "and the plane as a blue square\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
