// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Completion by symmetry: virtual scans of shapes symmetric by construction, 20 to 50 % of their
// surface unseen, moved at random, completed under their planes (and axes): the whole surface lies
// at least twice nearer to the completed set than to the scan, no point is added within half the
// scan's spacing of a scan point, the added normals point out; meshes cut open get the images of
// the missing faces, oriented outward, none where the mesh has surface; results move with the
// shape, do not depend on the threads, agree on Surface_mesh and Polyhedron_3; stitched, halves
// and quarters cut at their planes close up, and a cut across the plane is met without a gap or
// an overlap; a cancel adds nothing; bad input is rejected.

#include <CGAL/Symmetry_transform/symmetrization.h>

#include "Rotational_symmetry_test_shapes.h"
#include "Symmetry_transform_test_shapes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef std::pair<Point_3, Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef ST::Rotational_symmetry<K> Rotation;

template <typename Mesh>
using Tree = CGAL::AABB_tree<ST::internal::AABB_traits_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

// The first hit of a ray: a point (boost::variant before CGAL 6.0, std::variant since).
template <typename Intersection>
const Point_3* point_of(const Intersection& intersection)
{
#if CGAL_VERSION_NR >= 1060000000
  return std::get_if<Point_3>(&intersection);
#else
  return boost::get<Point_3>(&intersection);
#endif
}

// A virtual range scan of `mesh` along each of `directions` (unit): rays x rays parallel rays over
// a square around the mesh, each giving the first point hit and the outward normal of its face.
template <typename Mesh>
std::vector<Point_with_normal> scan(const Mesh& mesh, const std::vector<Vector_3>& directions, int rays)
{
  const auto [center, radius] = center_and_radius(mesh);
  const Tree<Mesh> tree(faces(mesh).first, faces(mesh).second, mesh);
  std::vector<Point_with_normal> points;
  for(const Vector_3& d : directions) {
    const std::array<Vector_3, 2> across = in_plane_axes(Plane_3(CGAL::ORIGIN, d));
    for(int i = 0; i < rays; ++i)
      for(int j = 0; j < rays; ++j) {
        const double u = radius * (2. * (i + 0.5) / rays - 1.), v = radius * (2. * (j + 0.5) / rays - 1.);
        const auto hit = tree.first_intersection(K::Ray_3(center - 3. * radius * d + u * across[0] + v * across[1], d));
        if(!hit) continue;
        if(const Point_3* p = point_of(hit->first)) points.emplace_back(*p, PMP::compute_face_normal(hit->second, mesh));
      }
  }
  return points;
}

std::vector<Point_3> positions(const std::vector<Point_with_normal>& points)
{
  std::vector<Point_3> result;
  for(const auto& p : points) result.push_back(p.first);
  return result;
}

double nearest_distance(const Point_3& q, const std::vector<Point_3>& points)
{
  double best = std::numeric_limits<double>::max();
  for(const Point_3& p : points) best = (std::min)(best, CGAL::squared_distance(q, p));
  return std::sqrt(best);
}

// The median distance from a point of the scan to its nearest other point.
double median_spacing(const std::vector<Point_3>& points)
{
  std::vector<double> d;
  for(std::size_t i = 0; i < points.size(); ++i) {
    double best = std::numeric_limits<double>::max();
    for(std::size_t j = 0; j < points.size(); ++j)
      if(j != i) best = (std::min)(best, CGAL::squared_distance(points[i], points[j]));
    d.push_back(std::sqrt(best));
  }
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  return d[d.size() / 2];
}

double mean_distance(const std::vector<Point_3>& from, const std::vector<Point_3>& to)
{
  double sum = 0.;
  for(const Point_3& q : from) sum += nearest_distance(q, to);
  return sum / double(from.size());
}

struct Scan_case
{
  const char* name;
  Shape<Surface_mesh> shape;
  std::vector<Vector_3> directions;
};

std::vector<Scan_case> scan_cases()
{
  return {{"box from a corner", box<Surface_mesh>(1., 0.7, 0.45), {Vector_3(-0.6, -0.5, -0.62)}},
          {"ellipsoid from two sides", ellipsoid<Surface_mesh>(), {Vector_3(-1, -0.7, 0.3), Vector_3(-0.7, -1, -0.2)}},
          {"one-plane hull from its side", one_plane_hull<Surface_mesh>(), {Vector_3(-1, 0.3, -0.2), Vector_3(-1, -0.3, 0.4)}}};
}

Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

TEST(SymmetricCompletion, ScansAreCompletedWithoutDuplicatingWhatWasSeen)
{
  CGAL::Random rng(3801);
  for(const Scan_case& c : scan_cases()) {
    const Motion m = random_motion(rng);
    const Shape<Surface_mesh> s = moved(c.shape, m);
    std::vector<Vector_3> directions;
    for(const Vector_3& d : c.directions) directions.push_back(unit(m.transform(d)));
    const std::vector<Point_with_normal> seen = scan(s.mesh, directions, 70);
    std::vector<Point_with_normal> added;
    ST::complete_by_symmetry_of_points(seen, s.planes, std::back_inserter(added),
                                       CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
    const std::vector<Point_3> scan_points = positions(seen), whole = surface_points(s.mesh, 3000, rng);
    std::vector<Point_3> completed = scan_points;
    for(const auto& a : added) completed.push_back(a.first);
    const double spacing = median_spacing(scan_points);
    std::size_t unseen = 0, missing = 0;
    for(const Point_3& q : whole) {
      unseen += nearest_distance(q, scan_points) > 3. * spacing;
      missing += nearest_distance(q, completed) > 3. * spacing;
    }
    const double to_scan = mean_distance(whole, scan_points), to_completed = mean_distance(whole, completed);
    std::cout << c.name << ": " << 100. * double(unseen) / double(whole.size()) << " % unseen ("
              << 100. * double(missing) / double(whole.size()) << " % after completion), " << seen.size()
              << " points seen, " << added.size() << " added; mean distance of the surface to the scan "
              << to_scan / spacing << " spacings, to the completed set " << to_completed / spacing << "\n";
    EXPECT_GE(double(unseen) / double(whole.size()), 0.2) << c.name;
    EXPECT_LE(double(unseen) / double(whole.size()), 0.5) << c.name;
    EXPECT_LE(2. * to_completed, to_scan) << c.name;
    double closest = std::numeric_limits<double>::max();
    const Point_3 center = center_and_radius(s.mesh).center; // inside: the shapes are convex
    for(const auto& a : added) {
      closest = (std::min)(closest, nearest_distance(a.first, scan_points));
      EXPECT_NEAR(a.second.squared_length(), 1., 1e-9) << c.name;
      EXPECT_GT(a.second * (a.first - center), 0.) << c.name << ": an added normal points inward";
    }
    EXPECT_GT(closest, 0.5 * spacing) << c.name;
  }
}

template <typename Mesh>
double distance_to(const Tree<Mesh>& tree, const Point_3& q)
{
  return std::sqrt(CGAL::squared_distance(q, tree.closest_point(q)));
}

template <typename Mesh>
double median_edge_length(const Mesh& mesh)
{
  std::vector<double> lengths;
  for(auto e : edges(mesh))
    lengths.push_back(std::sqrt(CGAL::squared_distance(get(CGAL::vertex_point, mesh, source(e, mesh)),
                                                       get(CGAL::vertex_point, mesh, target(e, mesh)))));
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

template <typename Mesh>
std::vector<Point_3> face_centroids(const Mesh& mesh, const std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& chosen)
{
  std::vector<Point_3> result;
  for(auto f : chosen) {
    const auto h = halfedge(f, mesh);
    result.push_back(CGAL::centroid(get(CGAL::vertex_point, mesh, source(h, mesh)), get(CGAL::vertex_point, mesh, target(h, mesh)),
                                    get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh))));
  }
  return result;
}

// An ellipsoid of 20480 faces with 30 % of its surface cut away (a cap across its plane x = 0),
// moved: completed under that plane, or under its three planes with 40 % cut away.
TEST(SymmetricCompletion, MeshCutOpenGetsTheMissingFacesOrientedOutwardAndNoneWhereItHasSurface)
{
  CGAL::Random rng(3802);
  for(int planes : {1, 3}) {
    const Motion m = random_motion(rng);
    const Shape<Surface_mesh> whole = moved(ellipsoid<Surface_mesh>(1., 0.6, 0.35, 5), m);
    Surface_mesh mesh = cut_away(whole.mesh, m.transform(Vector_3(1, 0.2, 0.1)), planes == 1 ? 0.3 : 0.4);
    const Tree<Surface_mesh> input_tree(faces(mesh).first, faces(mesh).second, mesh);
    const std::vector<Plane_3> symmetries(whole.planes.begin(), whole.planes.begin() + planes);
    std::vector<Surface_mesh::Face_index> added;
    ST::complete_by_symmetry(mesh, symmetries, std::back_inserter(added));
    const std::vector<Point_3> samples = surface_points(whole.mesh, 3000, rng);
    const Tree<Surface_mesh> completed_tree(faces(mesh).first, faces(mesh).second, mesh);
    double to_cut = 0., to_completed = 0., farthest = 0.;
    for(const Point_3& q : samples) {
      to_cut += distance_to(input_tree, q);
      to_completed += distance_to(completed_tree, q);
      farthest = (std::max)(farthest, distance_to(completed_tree, q));
    }
    const auto [center, radius] = center_and_radius(whole.mesh);
    std::cout << planes << " plane(s): " << added.size() << " faces added; mean distance of the whole surface to the "
              << "cut mesh " << to_cut / double(samples.size()) / radius << " R, to the completed one "
              << to_completed / double(samples.size()) / radius << " R\n";
    EXPECT_GT(added.size(), 0u);
    EXPECT_LE(4. * to_completed, to_cut);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    // The gap between the cut and the added faces is that of the sampling (two edges), not the 5 %
    // of the radius that a missing region must reach somewhere.
    const double edge = median_edge_length(whole.mesh);
    std::cout << "  largest distance of the whole surface to the completed mesh " << farthest / edge << " edges, "
              << farthest / radius << " R\n";
    EXPECT_LE(farthest, 2. * edge);
    EXPECT_LT(2. * edge, 0.05 * radius);
    for(const Point_3& c : face_centroids(mesh, added)) EXPECT_GT(distance_to(input_tree, c), edge);
    for(auto f : added) {
      const auto h = halfedge(f, mesh);
      EXPECT_GT(PMP::compute_face_normal(f, mesh) * (get(CGAL::vertex_point, mesh, source(h, mesh)) - center), 0.)
        << "an added face is oriented inward";
    }
  }
}

// The faces of `mesh` whose centroids do not lie on the positive side of any of `planes`.
template <typename Mesh>
Mesh part_behind(Mesh mesh, const std::vector<Plane_3>& planes)
{
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> beyond;
  for(auto f : faces(mesh)) {
    const Point_3 c = face_centroids(mesh, {f})[0];
    if(std::any_of(planes.begin(), planes.end(), [&](const Plane_3& p) { return p.a() * c.x() + p.b() * c.y() + p.c() * c.z() + p.d() > 1e-9; }))
      beyond.push_back(f);
  }
  for(auto f : beyond) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  mesh.collect_garbage();
  return mesh;
}

// Halves, quarters and eighths of an ellipsoid (a subdivided icosahedron, its tessellation
// symmetric under its three planes), moved and completed with stitching: closed up into the
// whole ellipsoid, a valid mesh without self-intersection, of the whole's faces, vertices and
// volume, the input's vertices kept where they were; Polyhedron_3 agrees.
TEST(SymmetricCompletion, StitchingClosesUpModelsCutAtTheirPlanes)
{
  CGAL::Random rng(3806);
  const Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.6, 0.35, 4);
  for(std::size_t cuts : {1, 2, 3}) {
    const Motion m = random_motion(rng);
    const Shape<Surface_mesh> whole = moved(shape, m);
    const std::vector<Plane_3> planes(whole.planes.begin(), whole.planes.begin() + std::ptrdiff_t(cuts));
    Surface_mesh mesh = part_behind(shape.mesh, std::vector<Plane_3>(shape.planes.begin(), shape.planes.begin() + std::ptrdiff_t(cuts)));
    PMP::transform(m, mesh);
    const Surface_mesh input = mesh;
    Polyhedron polyhedron;
    CGAL::copy_face_graph(mesh, polyhedron);
    std::vector<Surface_mesh::Face_index> added;
    std::vector<Polyhedron::Facet_handle> added_to_polyhedron;
    const auto np = CGAL::parameters::stitch_borders(true);
    ST::complete_by_symmetry(mesh, planes, std::back_inserter(added), np);
    ST::complete_by_symmetry(polyhedron, planes, std::back_inserter(added_to_polyhedron), np);
    const double volume = PMP::volume(mesh), whole_volume = PMP::volume(whole.mesh);
    std::cout << "cut by " << cuts << " plane(s): " << num_faces(input) << " faces, " << added.size()
              << " added; volume " << volume / whole_volume << " of the whole\n";
    EXPECT_EQ(num_faces(mesh), num_faces(whole.mesh)) << cuts;
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh)) << cuts;
    EXPECT_TRUE(CGAL::is_closed(mesh)) << cuts;
    EXPECT_FALSE(PMP::does_self_intersect(mesh)) << cuts;
    EXPECT_NEAR(volume / whole_volume, 1., 1e-9) << cuts;
    EXPECT_EQ(mesh.number_of_vertices(), whole.mesh.number_of_vertices()) << cuts; // the cut's vertices shared
    for(auto v : vertices(input)) {
      EXPECT_FALSE(mesh.is_removed(v)) << cuts;
      EXPECT_EQ(mesh.point(v), input.point(v)) << cuts;
    }
    EXPECT_EQ(added_to_polyhedron.size(), added.size()) << cuts;
    EXPECT_TRUE(CGAL::is_closed(polyhedron)) << cuts;
  }
}

// A mesh cut away across its plane (not at it): the added faces reach up to the cut, neither
// overlapping the input nor leaving a gap wider than an edge; the area is the whole shape's.
TEST(SymmetricCompletion, StitchingReachesTheBorderOfACutAcrossThePlane)
{
  CGAL::Random rng(3807);
  const Motion m = random_motion(rng);
  const Shape<Surface_mesh> whole = moved(ellipsoid<Surface_mesh>(1., 0.6, 0.35, 5), m);
  const Surface_mesh cut = cut_away(whole.mesh, m.transform(Vector_3(1, 0.2, 0.1)), 0.3);
  const std::vector<Plane_3> plane{whole.planes[0]};
  const double edge = median_edge_length(whole.mesh), whole_area = PMP::area(whole.mesh);
  const auto farthest_and_area = [&](const auto& np) {
    Surface_mesh mesh = cut;
    std::vector<Surface_mesh::Face_index> added;
    ST::complete_by_symmetry(mesh, plane, std::back_inserter(added), np);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    const Tree<Surface_mesh> tree(faces(mesh).first, faces(mesh).second, mesh);
    double farthest = 0.;
    CGAL::Random samples_rng(3808);
    for(const Point_3& q : surface_points(whole.mesh, 3000, samples_rng)) farthest = (std::max)(farthest, distance_to(tree, q));
    return std::make_pair(farthest / edge, PMP::area(mesh) / whole_area);
  };
  const auto [separate_gap, separate_area] = farthest_and_area(CGAL::parameters::default_values());
  const auto [stitched_gap, stitched_area] = farthest_and_area(CGAL::parameters::stitch_borders(true));
  std::cout << "largest gap " << separate_gap << " edges and area " << separate_area << " of the whole as separate "
            << "components; " << stitched_gap << " edges, area " << stitched_area << " stitched\n";
  EXPECT_LE(stitched_gap, 1.);
  EXPECT_NEAR(stitched_area, 1., 0.01);
  EXPECT_LT(stitched_gap, separate_gap);
  EXPECT_LT(std::abs(stitched_area - 1.), std::abs(separate_area - 1.));
  const auto completed_points = [&](unsigned threads) {
    Surface_mesh mesh = cut;
    std::vector<Surface_mesh::Face_index> added;
    ST::complete_by_symmetry(mesh, plane, std::back_inserter(added),
                             CGAL::parameters::stitch_borders(true).number_of_threads(threads));
    std::vector<Point_3> points;
    for(auto v : vertices(mesh)) points.push_back(mesh.point(v));
    return points;
  };
  EXPECT_EQ(completed_points(1), completed_points(2));
}

// The added points, in the frame of the shape (the inverse of `m` applied).
std::vector<Point_3> moved_back(const std::vector<Point_with_normal>& added, const Motion& m)
{
  std::vector<Point_3> result;
  for(const auto& a : added) result.push_back(m.inverse().transform(a.first));
  return result;
}

TEST(SymmetricCompletion, AddedPointsMoveWithTheShapeAndDoNotDependOnTheThreads)
{
  CGAL::Random rng(3803);
  const Shape<Surface_mesh> shape = box<Surface_mesh>(1., 0.7, 0.45);
  const std::vector<Point_with_normal> seen = scan(shape.mesh, {unit(Vector_3(-0.6, -0.5, -0.62))}, 50);
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  std::vector<Point_with_normal> here, there, one_thread;
  ST::complete_by_symmetry_of_points(seen, shape.planes, std::back_inserter(here), np);
  ST::complete_by_symmetry_of_points(seen, shape.planes, std::back_inserter(one_thread), np.number_of_threads(1));
  ASSERT_EQ(here.size(), one_thread.size());
  for(std::size_t i = 0; i < here.size(); ++i) EXPECT_EQ(here[i], one_thread[i]);
  for(int trial = 0; trial < 2; ++trial) {
    const Motion m = random_motion(rng);
    std::vector<Point_with_normal> moved_scan;
    for(const auto& p : seen) moved_scan.emplace_back(m.transform(p.first), unit(m.transform(p.second)));
    std::vector<Plane_3> planes;
    for(const Plane_3& p : shape.planes) planes.push_back(moved(p, m));
    there.clear();
    ST::complete_by_symmetry_of_points(moved_scan, planes, std::back_inserter(there), np);
    ASSERT_EQ(there.size(), here.size()) << "motion " << trial;
    const std::vector<Point_3> a = positions(here), b = moved_back(there, m);
    double farthest = 0.;
    for(const Point_3& q : b) farthest = (std::max)(farthest, nearest_distance(q, a));
    EXPECT_LT(farthest, 1e-9) << "motion " << trial;
  }
}

TEST(SymmetricCompletion, AddedFacesMoveWithTheMeshAndDoNotDependOnTheThreads)
{
  CGAL::Random rng(3805);
  const Shape<Surface_mesh> whole = ellipsoid<Surface_mesh>(1., 0.6, 0.35, 3);
  const Surface_mesh cut = cut_away(whole.mesh, Vector_3(1, 0.2, 0.1), 0.3);
  const auto completed = [&](const Motion& m, unsigned threads) {
    Surface_mesh mesh = cut;
    PMP::transform(m, mesh);
    std::vector<Surface_mesh::Face_index> added;
    ST::complete_by_symmetry(mesh, std::vector<Plane_3>{moved(whole.planes[0], m)}, std::back_inserter(added),
                             CGAL::parameters::number_of_threads(threads));
    std::vector<Point_3> centroids;
    for(const Point_3& c : face_centroids(mesh, added)) centroids.push_back(m.inverse().transform(c));
    return centroids;
  };
  const std::vector<Point_3> here = completed(Motion(CGAL::IDENTITY), 2);
  EXPECT_GT(here.size(), 0u);
  EXPECT_EQ(completed(Motion(CGAL::IDENTITY), 1), here);
  for(int trial = 0; trial < 2; ++trial) {
    const std::vector<Point_3> there = completed(random_motion(rng), 2);
    ASSERT_EQ(there.size(), here.size()) << "motion " << trial;
    double farthest = 0.;
    for(std::size_t i = 0; i < here.size(); ++i) farthest = (std::max)(farthest, std::sqrt(CGAL::squared_distance(here[i], there[i])));
    EXPECT_LT(farthest, 1e-9) << "motion " << trial;
  }
}

TEST(SymmetricCompletion, RotationsCompleteAndPolyhedronAgreesWithSurfaceMesh)
{
  const Shape<Surface_mesh> whole = ellipsoid<Surface_mesh>(1., 0.6, 0.35, 3);
  Surface_mesh mesh = cut_away(whole.mesh, Vector_3(1, 0.3, 0.2), 0.25);
  Polyhedron polyhedron;
  CGAL::copy_face_graph(mesh, polyhedron);
  const std::vector<Plane_3> planes{Plane_3(0, 0, 1, 0)};
  const std::vector<Rotation> rotations{{z_axis(), 2, 1., 1.}};
  std::vector<Surface_mesh::Face_index> added;
  std::vector<Polyhedron::Facet_handle> added_to_polyhedron;
  ST::complete_by_symmetry(mesh, planes, rotations, std::back_inserter(added));
  ST::complete_by_symmetry(polyhedron, planes, rotations, std::back_inserter(added_to_polyhedron));
  EXPECT_GT(added.size(), 0u);
  EXPECT_EQ(added.size(), added_to_polyhedron.size());
  EXPECT_EQ(faces(mesh).size(), faces(polyhedron).size());
  // The cap cut away on the side x > 0 is the image of the opposite cap under the half-turn about
  // z: no point of the whole surface is left farther from the completed mesh than the gap
  // between the input and the added part (at most the coverage distance, two edges).
  const Tree<Surface_mesh> tree(faces(mesh).first, faces(mesh).second, mesh);
  double farthest = 0.;
  CGAL::Random rng(3804);
  for(const Point_3& q : surface_points(whole.mesh, 2000, rng)) farthest = (std::max)(farthest, distance_to(tree, q));
  EXPECT_LE(farthest, 2. * median_edge_length(whole.mesh));
}

TEST(SymmetricCompletion, CancelAddsNothingAndBadInputIsRejected)
{
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6, 1);
  Surface_mesh mesh = cut_away(shape.mesh, Vector_3(1, 0, 0), 0.3);
  const std::size_t faces_before = num_faces(mesh);
  std::vector<Surface_mesh::Face_index> added;
  ST::complete_by_symmetry(mesh, shape.planes, std::back_inserter(added),
                           CGAL::parameters::callback([](double) { return false; }));
  EXPECT_TRUE(added.empty());
  EXPECT_EQ(num_faces(mesh), faces_before);
  std::vector<Point_with_normal> out;
  std::vector<Point_3> points;
  for(auto v : vertices(shape.mesh)) points.push_back(get(CGAL::vertex_point, shape.mesh, v));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::complete_by_symmetry_of_points(std::vector<Point_3>(), shape.planes, std::back_inserter(out)); },
    "empty"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::complete_by_symmetry_of_points(points, std::vector<Plane_3>(), std::back_inserter(out)); },
    "no symmetry given"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] {
      ST::complete_by_symmetry_of_points(points, shape.planes, std::back_inserter(out),
                                         CGAL::parameters::coverage_distance(0.));
    },
    "coverage_distance must be a number in (0, inf)"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] {
      ST::complete_by_symmetry(mesh, shape.planes, std::back_inserter(added),
                               CGAL::parameters::coverage_distance(std::nan("")));
    },
    "coverage_distance"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] {
      ST::complete_by_symmetry_of_points(points, shape.planes, std::back_inserter(out),
                                         CGAL::parameters::number_of_threads(-1));
    },
    "number_of_threads"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::complete_by_symmetry_of_points(std::vector<Point_3>(3, Point_3(1, 2, 3)), shape.planes, std::back_inserter(out)); },
    "coincide"));
  Surface_mesh quad;
  CGAL::make_quad(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), quad);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::complete_by_symmetry(quad, std::vector<Plane_3>{Plane_3(1, 0, 0, -0.5)}, std::back_inserter(added)); },
    "not a triangle"));
}

} // namespace
