// Computes the Point Symmetry Transform (PST) of a mesh, prints its centre of symmetry and writes
// three slices of the transform through that centre, coloured by symmetry.
//
// usage: point_symmetry_transform [mesh.off|.ply|.obj|.stl] [--resolution N] [--output FILE.ply]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

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

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The PST is a function of space: three orthogonal slices of its grid through the sample
// `through`, as triangles between samples, coloured by value from dark (0) to bright (the
// maximum), where it exceeds `maximum / 20` (the rest would hide the mesh). Opened together with
// the input mesh, they show where the shape is point-symmetric and how fast that fades. (The
// PST at the vertices of the mesh would mostly show their distance to the centre of symmetry.)
Mesh slices(const ST::Voxel_grid<K>& pst, const std::array<std::size_t, 3>& through, double maximum)
{
  Mesh result;
  auto colour = result.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  auto symmetry = result.add_property_map<Mesh::Vertex_index, float>("v:symmetry", 0.f).first;
  const std::size_t n = pst.resolution();
  for(int axis = 0; axis < 3; ++axis) { // the slice orthogonal to `axis`
    std::vector<Mesh::Vertex_index> v;
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = 0; b < n; ++b) {
        std::array<std::size_t, 3> ijk = through;
        ijk[(axis + 1) % 3] = a;
        ijk[(axis + 2) % 3] = b;
        v.push_back(result.add_vertex(pst.point(ijk[0], ijk[1], ijk[2])));
        symmetry[v.back()] = float(pst(ijk[0], ijk[1], ijk[2]));
        colour[v.back()] = ramp(symmetry[v.back()] / maximum);
      }
    for(std::size_t a = 0; a + 1 < n; ++a)
      for(std::size_t b = 0; b + 1 < n; ++b) {
        const Mesh::Vertex_index q[4] = {v[a * n + b], v[(a + 1) * n + b], v[(a + 1) * n + b + 1],
                                         v[a * n + b + 1]};
        if(std::all_of(q, q + 4, [&](Mesh::Vertex_index x) { return symmetry[x] > maximum / 20.; })) {
          result.add_face(q[0], q[1], q[2]);
          result.add_face(q[0], q[2], q[3]);
        }
      }
  }
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(result);
  result.collect_garbage();
  return result;
}

int main(int argc, char** argv)
try {
  std::string filename, output = "point_symmetry_transform.ply";
  int resolution = 64;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    std::size_t end = 0; // characters of `value` read
    try {
      if(arg == "--resolution") resolution = std::stoi(value, &end);
      else if(arg == "--output") end = (output = value).size();
    } catch(const std::logic_error&) {} // not a number: end stays 0
    if(end == 0 || end != value.size() || resolution < 1)
      throw std::invalid_argument("unknown option or value: " + arg + " " + value);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (OFF, PLY, OBJ or STL; with no "
              << "argument, set CGAL_DATA_DIR to the directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  // The distance transform measures distances to triangles: split polygons first.
  if(!CGAL::is_triangle_mesh(mesh)) {
    const auto polygons = std::count_if(faces(mesh).begin(), faces(mesh).end(),
                                        [&](Mesh::Face_index f) { return degree(f, mesh) != 3; });
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw std::runtime_error("some faces could not be triangulated");
    std::cout << "Triangulated " << polygons << " non-triangle faces: " << num_faces(mesh) << " triangles\n";
  }

  // Two steps, timed apart: the Gaussian distance transform f of the surface on a resolution^3
  // grid, then the PST, the symmetry of f about every sample of that grid, by FFT.
  auto start = std::chrono::steady_clock::now();
  const ST::Voxel_grid<K> f =
    ST::gaussian_distance_transform(mesh, CGAL::parameters::grid_resolution(resolution));
  const double gedt_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const ST::Point_symmetry_transform<K> pst = ST::point_symmetry_transform(f);
  std::cout << std::setprecision(3) << "Distance transform of " << resolution << "^3 samples in " << gedt_seconds
            << " s, PST in " << seconds_since(start) << " s\n";

  // A perfect point symmetry can only be about the centre of mass; the distance from it to the
  // centre of symmetry, and their symmetries, tell how far the shape is from one.
  const K::Point_3 center = f.center(), symmetry_center = pst.center_of_symmetry();
  const double distance = std::sqrt(CGAL::squared_distance(center, symmetry_center));
  std::cout << "\nCentre of mass      (" << center << "), symmetry " << pst.value(center) << "\n"
            << "Centre of symmetry  (" << symmetry_center << "), symmetry " << pst.value(symmetry_center)
            << " (measured directly on the grid: " << ST::symmetry_measure(f, symmetry_center) << ")\n"
            << "Distance between them: " << distance / f.radius() << " R, with R = " << f.radius()
            << " the radius of the shape\n";

  // Slice through the strongest sample, which center_of_symmetry() refines below the voxel size.
  const std::vector<double>& values = pst.grid().values();
  const std::size_t best = std::size_t(std::max_element(values.begin(), values.end()) - values.begin());
  const std::size_t n = f.resolution(); // in values(), i varies fastest
  Mesh planes = slices(pst.grid(), {best % n, best / n % n, best / (n * n)}, values[best]);
  if(!CGAL::IO::write_PLY(output, planes, "three slices of the point symmetry transform; colour: dark = weak"))
    throw std::runtime_error("cannot write " + output);
  std::cout << "\nWrote " << output << ": three slices of the PST through the centre of symmetry, coloured from\n"
            << "  dark (symmetry 0) to bright (" << values[best] << "); open it together with the mesh\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
