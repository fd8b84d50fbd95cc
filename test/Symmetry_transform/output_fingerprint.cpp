// Prints a fingerprint of every public result of the package on one mesh: each value in
// hexadecimal floating point (exact), each array as a 64-bit hash of its bytes. Two builds of
// the library give the same fingerprint if and only if they compute bit-identical results (up
// to a hash collision); scripts/compare_outputs.sh builds it on two revisions and compares.
//
// usage: output_fingerprint mesh.off [resolution]   (default 32; 2 threads everywhere)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

namespace {

std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t h = 1469598103934665603ull)
{
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for(std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

template <typename T>
void print_hash(const std::string& name, const std::vector<T>& values)
{
  std::printf("%s: %zu values, hash %016llx\n", name.c_str(), values.size(),
              (unsigned long long)hash_bytes(values.data(), values.size() * sizeof(T)));
}

void print_value(const std::string& name, double v) { std::printf("%s: %a\n", name.c_str(), v); }

void print_plane(const std::string& name, const K::Plane_3& p)
{
  std::printf("%s: %a %a %a %a\n", name.c_str(), p.a(), p.b(), p.c(), p.d());
}

void print_frame(const std::string& name, const ST::Symmetry_frame<K>& f)
{
  std::printf("%s: centre %a %a %a\n", name.c_str(), f.center.x(), f.center.y(), f.center.z());
  for(const K::Vector_3& a : f.axes) std::printf("  axis %a %a %a\n", a.x(), a.y(), a.z());
}

void print_symmetries(const std::string& name, const std::vector<ST::Principal_symmetry<K>>& symmetries)
{
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    print_plane(name + " " + std::to_string(i), symmetries[i].plane);
    std::printf("  symmetry %a support %a\n", symmetries[i].symmetry, symmetries[i].support);
  }
}

template <typename NP>
void transforms(const Mesh& mesh, const std::vector<K::Point_3>& points, const NP& np)
{
  const ST::Voxel_grid<K> gedt = ST::gaussian_distance_transform(mesh, np);
  print_hash("GEDT", gedt.values());
  print_hash("GEDT of points", ST::gaussian_distance_transform_of_points(points, np).values());
  const ST::Point_symmetry_transform<K> pst = ST::point_symmetry_transform(gedt, np);
  const K::Point_3 c = pst.center_of_symmetry();
  std::printf("PST centre: %a %a %a, value %a\n", c.x(), c.y(), c.z(), pst.value(c));
  const ST::Reflective_symmetry_transform<K> prst = ST::reflective_symmetry_transform(gedt, np);
  print_hash("PRST Monte Carlo", prst.values());
  const ST::Reflective_symmetry_transform<K> exact =
    ST::reflective_symmetry_transform(ST::gaussian_distance_transform(mesh, np.grid_resolution(20)),
                                      np.grid_resolution(20).prst_method(ST::Reflective_symmetry_method::EXACT));
  print_hash("PRST exact 20", exact.values());
  std::ostringstream saved;
  prst.save(saved);
  const std::string bytes = saved.str();
  std::printf("PRST file: %zu bytes, hash %016llx\n", bytes.size(), (unsigned long long)hash_bytes(bytes.data(), bytes.size()));
  print_value("symmetry measure of the strongest bin", ST::symmetry_measure(gedt, prst.plane(prst.maximum())));
  print_value("symmetry measure of the PST centre", ST::symmetry_measure(gedt, c));
}

template <typename NP>
void applications(const Mesh& mesh, const std::vector<K::Point_3>& points, const NP& np)
{
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries(mesh, np);
  print_symmetries("plane", symmetries);
  print_symmetries("plane of points", ST::detect_principal_symmetries_of_points(points, np));
  if(symmetries.empty()) return;
  const K::Plane_3 first = symmetries.front().plane;
  const K::Plane_3 rough(first.a() + 0.05, first.b(), first.c() - 0.03, first.d());
  print_plane("refined", ST::refine_symmetry_plane(mesh, rough, np));
  auto support = get(CGAL::dynamic_face_property_t<double>(), mesh);
  print_value("support", ST::symmetry_support(mesh, first, support, np));
  std::vector<double> supports;
  for(Mesh::Face_index f : faces(mesh)) supports.push_back(get(support, f));
  print_hash("face supports", supports);
  print_frame("symmetry frame", ST::symmetry_frame(mesh, np));
  print_frame("symmetry frame of points", ST::symmetry_frame_of_points(points, np));
  print_frame("PCA frame", ST::pca_frame(mesh, np));
  print_frame("PCA frame of points", ST::pca_frame_of_points(points, np));
  const ST::Symmetry_descriptor<K> d = ST::symmetry_descriptor(mesh, np),
                                   e = ST::symmetry_descriptor_of_points(points, np);
  print_hash("descriptor PRST", d.reflective_symmetry_values());
  print_hash("descriptor GEDT", d.gedt_values());
  print_value("descriptor distance", ST::descriptor_distance(d, e));
  std::ostringstream saved;
  d.save(saved);
  const std::string bytes = saved.str();
  std::printf("descriptor file: %zu bytes, hash %016llx\n", bytes.size(),
              (unsigned long long)hash_bytes(bytes.data(), bytes.size()));
  std::vector<ST::Viewpoint<K>> views;
  ST::best_viewpoints(symmetries, std::back_inserter(views));
  for(const ST::Viewpoint<K>& v : views)
    std::printf("best view %a %a %a score %a\n", v.direction.x(), v.direction.y(), v.direction.z(), v.score);
  const ST::Viewpoint<K> worst = ST::worst_viewpoint(symmetries);
  std::printf("worst view %a %a %a score %a\n", worst.direction.x(), worst.direction.y(), worst.direction.z(), worst.score);
}

template <typename NP>
void remeshing_and_segmentation(const Mesh& mesh, const NP& np)
{
  const std::vector<ST::Principal_symmetry<K>> symmetries =
    ST::detect_principal_symmetries(mesh, np.max_number_of_planes(2));
  std::vector<K::Plane_3> planes;
  for(const auto& s : symmetries) planes.push_back(s.plane);
  std::vector<K::Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  auto proxy = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  Mesh remeshed;
  ST::symmetric_approximate_triangle_mesh(mesh, planes,
                                          CGAL::parameters::max_number_of_proxies(60).number_of_threads(2)
                                            .anchors(std::back_inserter(anchors)).triangles(std::back_inserter(triangles))
                                            .face_proxy_map(proxy).output_mesh(&remeshed));
  std::vector<double> coordinates;
  for(const K::Point_3& p : anchors) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  print_hash("remeshing anchors", coordinates);
  print_hash("remeshing triangles", triangles);
  std::vector<std::size_t> proxies;
  for(Mesh::Face_index f : faces(mesh)) proxies.push_back(get(proxy, f));
  print_hash("remeshing proxies", proxies);
  if(!planes.empty() && !is_empty(remeshed)) {
    const ST::Approximation_error error = ST::approximation_error(mesh, remeshed, CGAL::parameters::number_of_threads(2));
    print_value("RMS error", error.rms);
    print_value("Hausdorff error", error.hausdorff);
    print_value("symmetry error", ST::symmetry_error(remeshed, planes.front(), CGAL::parameters::number_of_threads(2)));
  }
  auto segment = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  ST::Segmentation_tree<K> tree;
  const std::size_t count =
    ST::segment_by_symmetry(mesh, segment, np.max_segmentation_depth(2).segmentation_tree(std::ref(tree)));
  std::vector<std::size_t> ids;
  for(Mesh::Face_index f : faces(mesh)) ids.push_back(get(segment, f));
  std::printf("segments: %zu, tree of %zu\n", count, tree.segments.size());
  print_hash("segment ids", ids);
  for(const auto& segment : tree.segments) print_symmetries("segment plane", segment.planes);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: output_fingerprint mesh.off [resolution]\n";
    return 1;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh)) return 1;
  const int resolution = argc > 2 ? std::stoi(argv[2]) : 32;
  std::vector<K::Point_3> points;
  for(Mesh::Vertex_index v : vertices(mesh)) points.push_back(mesh.point(v));
  const auto np = CGAL::parameters::grid_resolution(resolution).number_of_threads(2).random_seed(7);
  transforms(mesh, points, np);
  applications(mesh, points, np);
  remeshing_and_segmentation(mesh, np);
  return 0;
}
