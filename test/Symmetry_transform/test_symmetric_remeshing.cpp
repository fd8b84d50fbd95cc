// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Symmetric remeshing: on bumpy spheres symmetric by construction (tessellation included), the
// output of symmetric_approximate_triangle_mesh is mirror-matched (reflected vertices land on
// output vertices to 1e-6 of the diagonal, reflected triangles are output triangles), with the
// plane through mesh vertices or across faces (split), with several planes and with the
// strongest plane only; with the two sides tessellated differently, the output stays nearly
// symmetric; without planes its error is that of CGAL's VSA; outputs are valid
// triangle meshes, closed where the input is (the holes left by removed folds are filled); runs
// are deterministic; Surface_mesh and Polyhedron_3 agree; the metrics
// measure what they claim; bad input is rejected.

#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>

#include "Symmetry_transform_soup_defects.h"
#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/generators.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef std::array<std::size_t, 3> Triangle;

struct Soup
{
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
};

// The unit icosphere (Loop-subdivided icosahedron, projected) with its vertices moved radially to
// radius(a, b, c), (a, b, c) the unit direction's coordinates along e1, e2 and m (e1, e2 in the
// plane of normal m): a radius even in c keeps every mirror plane of the icosahedron through m a
// plane of symmetry, tessellation included.
template <typename Mesh, typename Radius>
Mesh radial_sphere(const Vector_3& m, int subdivisions, const Radius& radius)
{
  Mesh mesh;
  CGAL::make_icosahedron(mesh, Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(subdivisions));
  const Plane_3 plane(CGAL::ORIGIN, m);
  const auto axes = in_plane_axes(plane);
  const Vector_3 n = unit_normal(plane);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh)) {
    const Vector_3 p = get(vpm, v) - CGAL::ORIGIN;
    const Vector_3 u = p / std::sqrt(p.squared_length());
    put(vpm, v, CGAL::ORIGIN + radius(u * axes[0], u * axes[1], u * n) * u);
  }
  return mesh;
}

// A bumpy sphere symmetric about the plane of normal m through the origin.
template <typename Mesh>
Mesh bumpy_sphere(const Vector_3& m, int subdivisions = 3)
{
  return radial_sphere<Mesh>(m, subdivisions, [](double a, double b, double c) {
    return 1. + 0.25 * std::sin(3. * a + 0.5) * std::cos(2. * b + 0.7) + 0.4 * c * c + 0.2 * a;
  });
}

// A wavier variant (higher frequencies, larger amplitude), symmetric about the same planes: its
// patches are twisted enough for the Dijkstra-tag triangulation to fold triangles onto each other.
template <typename Mesh>
Mesh wavy_sphere(const Vector_3& m, double frequency, double amplitude)
{
  return radial_sphere<Mesh>(m, 3, [=](double a, double b, double c) {
    return 1. + amplitude * std::sin(frequency * a + 0.5) * std::cos((frequency - 1.) * b + 0.7) + 0.4 * c * c + 0.2 * a +
           amplitude * std::cos(frequency * c * c * 3.);
  });
}

// A mirror plane of the icosahedron that is not a coordinate plane (it cuts faces).
Vector_3 oblique_mirror_normal()
{
  Surface_mesh ico;
  CGAL::make_icosahedron(ico, Point_3(0, 0, 0), 1.);
  std::vector<Point_3> points(ico.points().begin(), ico.points().end());
  for(const Point_3& u : points)
    for(const Point_3& v : points) {
      const Vector_3 n = u - v;
      if(n.squared_length() == 0. || std::abs(n.x()) < 1e-9 || std::abs(n.y()) < 1e-9 || std::abs(n.z()) < 1e-9) continue;
      const Plane_3 plane(CGAL::ORIGIN, n);
      const bool mirror = std::all_of(points.begin(), points.end(), [&](const Point_3& p) {
        return std::any_of(points.begin(), points.end(),
                           [&](const Point_3& q) { return CGAL::squared_distance(reflect(p, plane), q) < 1e-18; });
      });
      if(mirror) return n / std::sqrt(n.squared_length());
    }
  return Vector_3(1, 0, 0);
}

template <typename Mesh>
double diagonal_of(const Mesh& mesh)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

template <typename Mesh, typename NP>
Soup remesh(const Mesh& mesh, const std::vector<Plane_3>& planes, const NP& np)
{
  Soup s;
  ST::symmetric_approximate_triangle_mesh(mesh, planes,
                                          np.anchors(std::back_inserter(s.points)).triangles(std::back_inserter(s.triangles)));
  return s;
}

template <typename Mesh>
Soup cgal_vsa(const Mesh& mesh, std::size_t proxies)
{
  Soup s;
  CGAL::Surface_mesh_approximation::approximate_triangle_mesh(
    mesh, CGAL::parameters::max_number_of_proxies(proxies).anchors(std::back_inserter(s.points)).triangles(std::back_inserter(s.triangles)));
  return s;
}

Surface_mesh mesh_of(Soup s)
{
  Surface_mesh out;
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.triangles))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(s.points, s.triangles);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, out);
  return out;
}

// Per output vertex, the output vertex within `tolerance` of its mirror image, or -1.
std::vector<long> mirror_vertices(const Soup& s, const Plane_3& plane, double tolerance)
{
  std::vector<long> image(s.points.size(), -1);
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    const Point_3 r = reflect(s.points[i], plane);
    for(std::size_t j = 0; j < s.points.size(); ++j)
      if(CGAL::squared_distance(r, s.points[j]) <= tolerance * tolerance) { image[i] = long(j); break; }
  }
  return image;
}

struct Mirror_match
{
  double vertices = 0., triangles = 0.; // matched fractions
};

Mirror_match mirror_match(const Soup& s, const Plane_3& plane, double tolerance)
{
  const std::vector<long> image = mirror_vertices(s, plane, tolerance);
  std::set<Triangle> sorted;
  for(Triangle t : s.triangles) {
    std::sort(t.begin(), t.end());
    sorted.insert(t);
  }
  Mirror_match m;
  m.vertices = double(std::count_if(image.begin(), image.end(), [](long i) { return i >= 0; })) / double(s.points.size());
  std::size_t matched = 0;
  for(const Triangle& t : s.triangles) {
    if(image[t[0]] < 0 || image[t[1]] < 0 || image[t[2]] < 0) continue;
    Triangle r = {std::size_t(image[t[0]]), std::size_t(image[t[1]]), std::size_t(image[t[2]])};
    std::sort(r.begin(), r.end());
    matched += sorted.count(r);
  }
  m.triangles = double(matched) / double(s.triangles.size());
  return m;
}

// Defects of the output soup: those of st_test::soup_defects(), and triangles with repeated
// or collinear corners, or twice the same corners, and directed edges shared by triangles.
struct Soup_defects
{
  std::size_t non_manifold_vertices = 0, border_edges = 0, degenerate = 0, duplicated = 0;
  std::size_t folded = 0; // directed edges in more than one triangle (triangles folded onto each other)
};

Soup_defects defects(const Soup& s)
{
  Soup_defects d;
  const auto manifold = st_test::soup_defects(s.points.size(), s.triangles);
  d.non_manifold_vertices = manifold.non_manifold_vertices;
  d.border_edges = manifold.border_edges;
  std::set<Triangle> seen;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> directed;
  for(const Triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i) d.folded += directed[{t[i], t[(i + 1) % 3]}]++ == 1 ? 1 : 0;
  for(const Triangle& t : s.triangles) {
    Triangle key = t;
    std::sort(key.begin(), key.end());
    if(!seen.insert(key).second) ++d.duplicated;
    if(key[0] == key[1] || key[1] == key[2] || CGAL::collinear(s.points[t[0]], s.points[t[1]], s.points[t[2]])) ++d.degenerate;
  }
  return d;
}

const auto K30 = CGAL::parameters::max_number_of_proxies(30);

// Remeshed with its plane at 30 and 80 proxies, a shape symmetric by construction gives
// mirror-matched vertices (to 1e-6 of the diagonal) and triangles.
void expect_mirror_matched(const Surface_mesh& mesh, const Plane_3& plane)
{
  const double diagonal = diagonal_of(mesh);
  for(std::size_t k : {30u, 80u}) {
    const Soup s = remesh(mesh, {plane}, CGAL::parameters::max_number_of_proxies(k));
    ASSERT_GT(s.triangles.size(), k);
    const Mirror_match m = mirror_match(s, plane, 1e-6 * diagonal);
    std::cout << "  K = " << k << ": " << s.points.size() << " vertices, " << s.triangles.size() << " triangles: "
              << 100. * m.vertices << "% of vertices and " << 100. * m.triangles << "% of triangles mirror-matched\n";
    EXPECT_GE(m.vertices, 0.99) << "K = " << k;
    EXPECT_GE(m.triangles, 0.99) << "K = " << k;
  }
}

TEST(SymmetricRemeshing, OutputOfShapeSymmetricAboutPlaneThroughEdgesIsMirrorMatched)
{
  expect_mirror_matched(bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0)), Plane_3(1, 0, 0, 0));
}

TEST(SymmetricRemeshing, OutputOfShapeSymmetricAboutPlaneAcrossFacesIsMirrorMatched)
{
  const Vector_3 n = oblique_mirror_normal();
  ASSERT_GT(std::min({std::abs(n.x()), std::abs(n.y()), std::abs(n.z())}), 1e-3) << "no oblique mirror plane found";
  expect_mirror_matched(bumpy_sphere<Surface_mesh>(n), Plane_3(CGAL::ORIGIN, n));
}

TEST(SymmetricRemeshing, OutputOfSymmetricShapeUnderRandomMotionIsMirrorMatched)
{
  CGAL::Random rng(5);
  for(int i = 0; i < 2; ++i) {
    const Motion motion = random_motion(rng);
    Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
    CGAL::Polygon_mesh_processing::transform(motion, mesh);
    expect_mirror_matched(mesh, moved(Plane_3(1, 0, 0, 0), motion));
  }
}

TEST(SymmetricRemeshing, PlainVsaLosesMirrorMatchOnTheSameShape)
{
  // The property tested above is not a given: CGAL's VSA on the same shape matches far fewer.
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  const Plane_3 plane(1, 0, 0, 0);
  const Mirror_match m = mirror_match(cgal_vsa(mesh, 60), plane, 1e-6 * diagonal_of(mesh));
  std::cout << "  CGAL VSA: " << 100. * m.vertices << "% of vertices mirror-matched\n";
  EXPECT_LT(m.vertices, 0.9);
}

TEST(SymmetricRemeshing, DifferentTessellationsOfTheTwoSidesStillGiveSymmetricBoundaries)
{
  // Symmetric in geometry, not in tessellation: isotropic remeshing tessellates the two sides of
  // the bumpy sphere differently, so the flooding puts patch boundaries on different faces of the
  // two sides. Relabelling the faces of one side after their mirror faces puts them back in step:
  // mean symmetry error of the output over 20 to 80 proxies 0.61e-3 of the diagonal with that
  // step, 0.79e-3 without it.
  Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(mesh), 0.08, mesh, CGAL::parameters::number_of_iterations(3));
  const Plane_3 plane(1, 0, 0, 0);
  const double diagonal = diagonal_of(mesh);
  ASSERT_LT(ST::symmetry_error(mesh, plane), 2e-4 * diagonal) << "the input should be symmetric in geometry";
  double sum = 0.;
  for(std::size_t k : {20u, 30u, 50u, 80u}) {
    const double e = ST::symmetry_error(mesh_of(remesh(mesh, {plane}, CGAL::parameters::max_number_of_proxies(k))), plane);
    std::cout << "  K = " << k << ": symmetry error " << 1e3 * e / diagonal << "e-3 of the diagonal\n";
    sum += e / diagonal;
  }
  EXPECT_LT(sum / 4., 0.7e-3);
}

TEST(SymmetricRemeshing, WithoutPlanesErrorIsWithinTenPercentOfCgalVsa)
{
  // An asymmetric bumpy sphere, K = 30, 60: the same settings (the L21 metric, position_weight 0;
  // CGAL's defaults otherwise).
  Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(0.3, 0.5, 0.8));
  CGAL::Random rng(4);
  add_vertex_noise(mesh, 0.01, rng);
  for(std::size_t k : {30u, 60u}) {
    const auto np = CGAL::parameters::number_of_points_on_faces(20000);
    const double ours = ST::approximation_error(mesh, mesh_of(remesh(mesh, {}, CGAL::parameters::max_number_of_proxies(k).position_weight(0.))), np).rms;
    const double cgal = ST::approximation_error(mesh, mesh_of(cgal_vsa(mesh, k)), np).rms;
    std::cout << "  K = " << k << ": RMS error " << ours << " (CGAL's VSA " << cgal << ")\n";
    EXPECT_LE(ours, 1.1 * cgal);
  }
}

TEST(SymmetricRemeshing, OutputIsValidTriangleMesh)
{
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(oblique_mirror_normal());
  const Plane_3 plane(CGAL::ORIGIN, oblique_mirror_normal());
  for(std::size_t k : {10u, 30u, 80u}) {
    const Soup_defects ours = defects(remesh(mesh, {plane}, CGAL::parameters::max_number_of_proxies(k)));
    const Soup_defects cgal = defects(cgal_vsa(mesh, k));
    EXPECT_EQ(ours.degenerate, 0u) << "K = " << k;
    EXPECT_EQ(ours.duplicated, 0u) << "K = " << k;
    EXPECT_EQ(ours.folded, 0u) << "K = " << k;
    EXPECT_LE(ours.non_manifold_vertices, cgal.non_manifold_vertices) << "K = " << k;
  }
}

TEST(SymmetricRemeshing, HolesLeftByRemovedFoldsAreFilledMirrorConsistently)
{
  // Closed inputs whose triangulation folds triangles at position_weight 0 (the removal of the
  // folds left 6, 3 and 6 border edges with the plane, 4 without): the output is closed, valid
  // and mirror-matched, at 0 and at the default 0.002 (where, before the anchors of short boundary
  // cycles were chosen independently of where the walk starts, 1.2 % and 1.8 % of the vertices
  // of the last two cases had no mirror image).
  struct Case
  {
    Vector_3 normal;
    double frequency, amplitude;
    std::size_t proxies;
  };
  for(const Case& c : {Case{Vector_3(1, 0, 0), 7., 0.15, 19}, Case{Vector_3(1, 0, 0), 7., 0.15, 49},
                       Case{oblique_mirror_normal(), 7., 0.3, 16}}) {
    const Surface_mesh mesh = wavy_sphere<Surface_mesh>(c.normal, c.frequency, c.amplitude);
    const Plane_3 plane(CGAL::ORIGIN, c.normal);
    const Soup_defects cgal = defects(cgal_vsa(mesh, c.proxies));
    for(double alpha : {0., 0.002}) {
      const Soup s = remesh(mesh, {plane}, CGAL::parameters::max_number_of_proxies(c.proxies).position_weight(alpha));
      const Mirror_match m = mirror_match(s, plane, 1e-6 * diagonal_of(mesh));
      const Soup_defects ours = defects(s);
      const std::string where = "K = " + std::to_string(c.proxies) + ", alpha = " + std::to_string(alpha);
      EXPECT_EQ(ours.border_edges, 0u) << where;
      EXPECT_GE(m.vertices, 0.99) << where;
      EXPECT_GE(m.triangles, 0.99) << where;
      EXPECT_EQ(ours.degenerate, 0u) << where;
      EXPECT_EQ(ours.duplicated, 0u) << where;
      EXPECT_EQ(ours.folded, 0u) << where;
      EXPECT_LE(ours.non_manifold_vertices, cgal.non_manifold_vertices) << where;
    }
  }
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(oblique_mirror_normal());
  const Soup s = remesh(mesh, {}, CGAL::parameters::max_number_of_proxies(20));
  EXPECT_EQ(defects(s).border_edges, 0u);
  EXPECT_EQ(defects(s).duplicated, 0u);
  EXPECT_TRUE(CGAL::is_closed(mesh_of(s)));
}

TEST(SymmetricRemeshing, RunsAreDeterministic)
{
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  const std::vector<Plane_3> planes = {Plane_3(1, 0, 0, 0.01)}; // a plane slightly off: mirrors are approximate
  for(auto method : {CGAL::Surface_mesh_approximation::HIERARCHICAL, CGAL::Surface_mesh_approximation::INCREMENTAL,
                     CGAL::Surface_mesh_approximation::RANDOM}) {
    const auto np = CGAL::parameters::max_number_of_proxies(25).seeding_method(method).random_seed(7).position_weight(0.2);
    const Soup a = remesh(mesh, planes, np), b = remesh(mesh, planes, np.number_of_threads(1));
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.triangles, b.triangles);
  }
}

TEST(SymmetricRemeshing, SurfaceMeshAndPolyhedronGiveTheSameOutput)
{
  // Both built from the same soup, so that their faces come in the same order (the seeding
  // follows the face order, as CGAL's VSA).
  const Surface_mesh sphere = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(sphere, points, polygons);
  Surface_mesh mesh;
  Polyhedron poly;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, poly);
  const std::vector<Plane_3> planes = {Plane_3(1, 0, 0, 0)};
  const Soup a = remesh(mesh, planes, K30), b = remesh(poly, planes, K30);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  // The output mesh option gives the same mesh.
  Polyhedron out;
  EXPECT_TRUE(ST::symmetric_approximate_triangle_mesh(poly, planes, K30.output_mesh(&out)));
  EXPECT_EQ(num_vertices(out), b.points.size());
  EXPECT_EQ(num_faces(out), b.triangles.size());
}

// Two bumpy spheres apart, each symmetric about its own plane, which maps the other far from
// the surface: local symmetries, each kept in its part.
TEST(SymmetricRemeshing, SeveralPlanesAndStrongestPlaneOnlyKeepEachSymmetry)
{
  const Vector_3 n = oblique_mirror_normal();
  Vector_3 c(0, 0, 0);
  for(int i = 0; i < 64 && !(std::abs(c.x()) > 2.5 && std::abs(c * n) > 2.5); ++i)
    c = Vector_3(5. * std::cos(0.1 * i), 5. * std::sin(0.1 * i), 1.);
  ASSERT_TRUE(std::abs(c.x()) > 2.5 && std::abs(c * n) > 2.5);
  Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  Surface_mesh other = bumpy_sphere<Surface_mesh>(n);
  CGAL::Polygon_mesh_processing::transform(Motion(CGAL::TRANSLATION, c), other);
  CGAL::copy_face_graph(other, mesh);
  const std::vector<Plane_3> planes = {Plane_3(1, 0, 0, 0), Plane_3(CGAL::ORIGIN + c, n)};
  const double diagonal = diagonal_of(mesh);
  for(bool strongest : {false, true}) {
    const Soup s = remesh(mesh, planes, CGAL::parameters::max_number_of_proxies(50).strongest_plane_only(strongest));
    for(const Plane_3& plane : planes) {
      // The matched fraction among the vertices of the part the plane maps onto itself.
      Soup part;
      part.triangles = s.triangles;
      part.points = s.points;
      const std::vector<long> image = mirror_vertices(s, plane, 1e-6 * diagonal);
      std::size_t inside = 0, matched = 0;
      for(std::size_t i = 0; i < s.points.size(); ++i) {
        const bool near = std::sqrt(CGAL::squared_distance(s.points[i], plane)) < 2.;
        const bool first_part = std::sqrt((s.points[i] - CGAL::ORIGIN).squared_length()) < 2.;
        if(!near || first_part != (plane == planes[0])) continue;
        ++inside;
        matched += image[i] >= 0 ? 1 : 0;
      }
      std::cout << "  strongest plane only: " << strongest << ", plane " << plane << ": " << matched << " of " << inside
                << " vertices of its part mirror-matched\n";
      EXPECT_GT(inside, 20u);
      EXPECT_GE(double(matched), 0.99 * double(inside));
    }
  }
}

TEST(SymmetricRemeshing, ProxiesAndPatchesAreReported)
{
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  std::map<Surface_mesh::Face_index, std::size_t> proxy, patch;
  std::vector<Plane_3> proxy_planes;
  ST::symmetric_approximate_triangle_mesh(mesh, std::vector<Plane_3>{Plane_3(1, 0, 0, 0)},
                                          K30.face_proxy_map(boost::make_assoc_property_map(proxy))
                                            .face_patch_map(boost::make_assoc_property_map(patch))
                                            .proxies(std::back_inserter(proxy_planes)));
  EXPECT_EQ(proxy_planes.size(), 30u);
  ASSERT_EQ(proxy.size(), num_faces(mesh));
  std::set<std::size_t> used;
  std::size_t reflected = 0;
  for(auto f : faces(mesh)) {
    used.insert(proxy[f]);
    EXPECT_LE(patch[f], 1u);
    reflected += patch[f];
  }
  EXPECT_EQ(used.size(), 30u);
  // Mirror-symmetric patches: about half the faces are in reflected patches.
  EXPECT_NEAR(double(reflected) / double(num_faces(mesh)), 0.5, 0.1);
}

TEST(SymmetricRemeshing, MetricsMeasureDistanceAndSymmetry)
{
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0));
  const ST::Approximation_error same = ST::approximation_error(mesh, mesh);
  EXPECT_LT(same.hausdorff, 1e-12);
  Surface_mesh shifted = mesh;
  CGAL::Polygon_mesh_processing::transform(Motion(CGAL::TRANSLATION, Vector_3(0, 0, 0.01)), shifted);
  const ST::Approximation_error e = ST::approximation_error(mesh, shifted);
  EXPECT_LE(e.hausdorff, 0.0100001);
  EXPECT_GT(e.rms, 0.002);
  EXPECT_LT(ST::symmetry_error(mesh, Plane_3(1, 0, 0, 0)), 1e-9);
  EXPECT_GT(ST::symmetry_error(mesh, Plane_3(0, 0, 1, 0)), 0.01);
  EXPECT_LT(ST::symmetry_error(mesh, Plane_3(1, 0, 0, 0), mesh, 0.01), 1e-9);
}

TEST(SymmetricRemeshing, BadInputIsRejected)
{
  const std::vector<Plane_3> x = {Plane_3(1, 0, 0, 0)};
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { remesh(Surface_mesh(), x, K30); }, "no face"));
  Surface_mesh quads;
  CGAL::make_hexahedron(Point_3(-1, -1, -1), Point_3(1, -1, -1), Point_3(1, 1, -1), Point_3(-1, 1, -1), Point_3(-1, 1, 1),
                        Point_3(-1, -1, 1), Point_3(1, -1, 1), Point_3(1, 1, 1), quads);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { remesh(quads, x, K30); }, "not a triangle"));
  const Surface_mesh mesh = bumpy_sphere<Surface_mesh>(Vector_3(1, 0, 0), 1);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { remesh(mesh, {Plane_3(0, 0, 0, 1)}, K30); }, "degenerate"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { remesh(mesh, x, CGAL::parameters::max_number_of_proxies(0)); }, "max_number_of_proxies"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { remesh(mesh, x, K30.position_weight(1.5)); }, "position_weight"));
  // The input is untouched.
  const Surface_mesh copy = mesh;
  remesh(mesh, x, K30);
  EXPECT_TRUE(std::equal(copy.points().begin(), copy.points().end(), mesh.points().begin()));
}

} // namespace

