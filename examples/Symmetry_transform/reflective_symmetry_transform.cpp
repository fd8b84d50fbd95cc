// Computes the Planar Reflective Symmetry Transform (PRST) of a mesh, prints its strongest planes
// and writes the mesh coloured by the strongest symmetry of any plane through each vertex.
//
// usage: reflective_symmetry_transform [mesh.off|.ply|.obj|.stl] [--resolution N] [--planes K]
//          [--method monte-carlo|exact] [--samples N] [--seed S] [--output FILE.ply]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Reflective_symmetry_transform<K> PRST;

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

// The strongest local maxima of the PRST, at most `count`. Monte Carlo noise splits one peak
// into neighbouring maxima, and round-off makes maxima of value ~0 far from the shape: keep a
// bin only if no stronger kept one lies within 10 degrees and R/10, and if it exceeds a tenth
// of the strongest (the threshold of the thesis).
std::vector<PRST::Bin> strongest_planes(const PRST& prst, std::size_t count)
{
  std::vector<PRST::Bin> maxima, kept;
  prst.local_maxima(std::back_inserter(maxima));
  for(const PRST::Bin& b : maxima) {
    auto near = [&](const PRST::Bin& q) {
      const double c = prst.plane(b).orthogonal_vector() * prst.plane(q).orthogonal_vector(); // cosine
      return std::abs(c) > std::cos(CGAL_PI / 18.) &&
             std::abs(prst.offset(b[2]) - std::copysign(prst.offset(q[2]), c)) < prst.radius() / 10.;
    };
    if(kept.size() < count && prst.value(b) > prst.value(maxima[0]) / 10. &&
       std::none_of(kept.begin(), kept.end(), near))
      kept.push_back(b);
  }
  return kept;
}

// For each vertex p, the strongest symmetry of any plane through p (the thesis's Figure 3.5):
// for every bin direction n, the plane through p has offset r = n.(p - c); interpolate between
// the two bins around r. Reading the bins directly costs a few operations per direction, where
// prst.value(plane) would also search for the direction of the plane.
Mesh::Property_map<Mesh::Vertex_index, float> strongest_symmetry_through_vertices(const PRST& prst, Mesh& mesh)
{
  const std::size_t n = prst.resolution();
  std::vector<K::Vector_3> normals; // direction ij = i n + j; its bins are values()[ij n + k]
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j) normals.push_back(prst.plane(i, j, 0).orthogonal_vector());
  const std::vector<double>& values = prst.values();
  auto symmetry = mesh.add_property_map<Mesh::Vertex_index, float>("v:symmetry", 0.f).first;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    const K::Vector_3 d = mesh.point(v) - prst.center();
    double best = 0.;
    for(std::size_t ij = 0; ij < n * n; ++ij) {
      // continuous bin index of r (bin k is centred on r = -R + (k + 1/2) 2R/n)
      const double r = normals[ij] * d;
      const double t = std::clamp((r / prst.radius() + 1.) * double(n) / 2. - 0.5, 0., double(n - 1));
      const std::size_t k = std::min(std::size_t(t), n - 2);
      const double* bins = &values[ij * n + k];
      best = std::max(best, bins[0] + (t - double(k)) * (bins[1] - bins[0]));
    }
    symmetry[v] = float(best);
  }
  return symmetry;
}

int main(int argc, char** argv)
try {
  std::string filename, output = "reflective_symmetry_transform.ply";
  std::size_t resolution = 64, samples = 2000000, seed = 0, planes = 5;
  ST::Reflective_symmetry_method method = ST::Reflective_symmetry_method::MONTE_CARLO;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value);
    else if(arg == "--samples") samples = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--planes") planes = integer(arg, value);
    else if(arg == "--output") output = value;
    else if(arg == "--method" && (value == "monte-carlo" || value == "exact"))
      method = value == "exact" ? ST::Reflective_symmetry_method::EXACT
                                : ST::Reflective_symmetry_method::MONTE_CARLO;
    else throw std::invalid_argument("unknown option or value: " + arg + " " + value);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (OFF, PLY, OBJ or STL; with no "
              << "argument, set CGAL_DATA_DIR to the directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  // The transform measures distances to triangles: split polygons first.
  if(!CGAL::is_triangle_mesh(mesh)) {
    const auto polygons = std::count_if(faces(mesh).begin(), faces(mesh).end(),
                                        [&](Mesh::Face_index f) { return degree(f, mesh) != 3; });
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw std::runtime_error("some faces could not be triangulated");
    std::cout << "Triangulated " << polygons << " non-triangle faces: " << num_faces(mesh) << " triangles\n";
  }

  // The GEDT of the surface on a resolution^3 grid, then the PRST on resolution^3 bins (theta, phi, r).
  const auto start = std::chrono::steady_clock::now();
  const PRST prst = ST::reflective_symmetry_transform(mesh,
    CGAL::parameters::grid_resolution(int(resolution)).prst_method(method)
                     .number_of_samples(samples).random_seed(unsigned(seed)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(3) << "PRST of " << resolution << "^3 bins ("
            << (method == ST::Reflective_symmetry_method::EXACT ? std::string("exact")
                                                                : std::to_string(samples) + " Monte Carlo samples")
            << ") in " << seconds << " s, distance transform included\n";

  const std::vector<PRST::Bin> best = strongest_planes(prst, planes);
  const double R = prst.radius(), degrees = 180. / CGAL_PI;
  std::cout << "\nCentre of mass c = (" << prst.center() << "), radius R = " << R << "\n"
            << "Strongest planes n.(x - c) = r, raw bins before refinement:\n"
            << "   #  symmetry   normal n (x y z)             r      r/R   theta    phi\n" << std::fixed;
  for(std::size_t m = 0; m < best.size(); ++m) {
    const PRST::Bin& b = best[m];
    const K::Vector_3 n = prst.plane(b).orthogonal_vector();
    std::cout << std::setw(4) << m + 1 << std::setprecision(3) << std::setw(10) << prst.value(b) << "   ("
              << std::setw(6) << n.x() << ' ' << std::setw(6) << n.y() << ' ' << std::setw(6) << n.z() << ") "
              << std::setw(8) << prst.offset(b[2]) << std::setprecision(2) << std::setw(8) << prst.offset(b[2]) / R
              << std::setprecision(1) << std::setw(7) << prst.theta(b[0]) * degrees << std::setw(7)
              << prst.phi(b[1]) * degrees << "\n";
  }

  auto symmetry = strongest_symmetry_through_vertices(prst, mesh);
  // Stretch the ramp over the range found on this mesh, so that its contrasts show.
  const auto range = std::minmax_element(symmetry.begin(), symmetry.end());
  const float low = *range.first, high = std::max(*range.second, low + 1e-6f);
  auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(Mesh::Vertex_index v : vertices(mesh)) colour[v] = ramp((symmetry[v] - low) / (high - low));

  // Surface_mesh's PLY writer stores the map "v:color" as red/green/blue/alpha and the float map
  // "v:symmetry" as a scalar vertex property `symmetry` (for viewers that colour by a scalar).
  if(!CGAL::IO::write_PLY(output, mesh, "vertex colour: strongest symmetry of a plane through the vertex"))
    throw std::runtime_error("cannot write " + output);
  std::cout << std::setprecision(3) << "\nWrote " << output << ": the mesh coloured by the strongest symmetry of "
            << "a plane through each vertex,\n  from dark (" << low << ") to bright (" << high << ")\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
