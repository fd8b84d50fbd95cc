// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Every public function of the package instantiated and run with
// CGAL::Exact_predicates_exact_constructions_kernel: a Surface_mesh of Epeck points, a range of
// Epeck points, Epeck planes and vectors. The package computes in double precision whatever the
// kernel (only the kernel's types are used), so each result must equal the one obtained with
// Epick on the same shape, up to round-off in the last conversions (`same`), and be right: the
// box's planes and centre found, the known viewpoints of three orthogonal planes, and so on.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/property_map.h>

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
#include <CGAL/Symmetry_transform/symmetrization.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include "Symmetry_transform_test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

namespace {

namespace ST = CGAL::Symmetry_transform;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef st_test::K IK;
typedef CGAL::Surface_mesh<EK::Point_3> Exact_mesh;
typedef st_test::Surface_mesh Mesh;

// Epeck and Epick results: the same double computations; only the conversions of the results
// to the kernel's number type differ, in the last bits.
constexpr double same = 1e-9;
constexpr int resolution = 32;
// A box of sides 2 x 1.4 x 0.9, centred on the origin: its planes of symmetry are x = 0, y = 0
// and z = 0, its centre the origin.
constexpr double half_sides[3] = {1., 0.7, 0.45};

// The options of every call: a small grid and few Monte Carlo samples keep the test short.
auto options()
{
  return CGAL::parameters::grid_resolution(resolution).number_of_samples(200000).random_seed(1);
}

// `mesh` rebuilt vertex by vertex and face by face in the kernel of `Target`: built the same way
// in both kernels, the two copies have the same vertices, faces and halfedges, hence the same
// triangles with their corners in the same order (a copy by CGAL::copy_face_graph may start a
// face at another corner, which changes the surface samples drawn in it).
template <typename Target>
Target rebuilt(const Mesh& mesh)
{
  typedef typename CGAL::Kernel_traits<typename Target::Point>::Kernel Kernel;
  const CGAL::Cartesian_converter<IK, Kernel> convert;
  Target result;
  std::vector<typename Target::Vertex_index> vertex(num_vertices(mesh));
  for(Mesh::Vertex_index v : vertices(mesh)) vertex[std::size_t(v)] = result.add_vertex(convert(mesh.point(v)));
  for(Mesh::Face_index f : faces(mesh)) {
    std::vector<typename Target::Vertex_index> corners;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh)) corners.push_back(vertex[std::size_t(v)]);
    result.add_face(corners);
  }
  return result;
}

// A shape in both kernels: the mesh, and points sampled on it.
struct Both_kernels
{
  Mesh mesh;
  Exact_mesh exact_mesh;
  std::vector<IK::Point_3> points;
  std::vector<EK::Point_3> exact_points;
};

Both_kernels in_both_kernels(const Mesh& mesh)
{
  Both_kernels shape;
  shape.mesh = rebuilt<Mesh>(mesh);
  shape.exact_mesh = rebuilt<Exact_mesh>(mesh);
  CGAL::Random rng(7);
  shape.points = st_test::surface_points(shape.mesh, 3000, rng);
  const CGAL::Cartesian_converter<IK, EK> to_exact;
  for(const IK::Point_3& p : shape.points) shape.exact_points.push_back(to_exact(p));
  return shape;
}

const Both_kernels& box()
{
  static const Both_kernels shape =
    in_both_kernels(st_test::box<Mesh>(half_sides[0], half_sides[1], half_sides[2]).mesh);
  return shape;
}

// An ellipsoid of half-axes 1, 0.6 and 0.35 (1280 faces), symmetric about the coordinate planes
// only, and with no partial symmetry.
const Both_kernels& ellipsoid()
{
  static const Both_kernels shape = in_both_kernels(st_test::ellipsoid<Mesh>(1., 0.6, 0.35, 3).mesh);
  return shape;
}

template <typename Kernel>
std::vector<typename Kernel::Plane_3> coordinate_planes()
{
  return {typename Kernel::Plane_3(1, 0, 0, 0), typename Kernel::Plane_3(0, 1, 0, 0),
          typename Kernel::Plane_3(0, 0, 1, 0)};
}

template <typename Point>
std::array<double, 3> coordinates(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <typename Plane>
std::array<double, 4> unit_coefficients(const Plane& p)
{
  const double a = CGAL::to_double(p.a()), b = CGAL::to_double(p.b()), c = CGAL::to_double(p.c()),
               d = CGAL::to_double(p.d()), l = std::sqrt(a * a + b * b + c * c);
  return {a / l, b / l, c / l, d / l};
}

template <std::size_t N>
void expect_near(const std::array<double, N>& a, const std::array<double, N>& b, double tolerance)
{
  for(std::size_t i = 0; i < N; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << "coordinate " << i;
}

void expect_same_plane(const EK::Plane_3& exact, const IK::Plane_3& inexact)
{
  expect_near(unit_coefficients(exact), unit_coefficients(inexact), same);
}

void expect_same_grid(const ST::Voxel_grid<EK>& exact, const ST::Voxel_grid<IK>& inexact)
{
  ASSERT_EQ(exact.resolution(), inexact.resolution());
  expect_near(coordinates(exact.center()), coordinates(inexact.center()), same);
  EXPECT_NEAR(exact.radius(), inexact.radius(), same);
  double largest = 0.;
  for(std::size_t i = 0; i < exact.values().size(); ++i)
    largest = std::max(largest, std::abs(exact.values()[i] - inexact.values()[i]));
  EXPECT_LE(largest, same);
}

void expect_same_transform(const ST::Reflective_symmetry_transform<EK>& exact,
                           const ST::Reflective_symmetry_transform<IK>& inexact)
{
  ASSERT_EQ(exact.resolution(), inexact.resolution());
  expect_near(coordinates(exact.center()), coordinates(inexact.center()), same);
  double largest = 0.;
  for(std::size_t i = 0; i < exact.values().size(); ++i)
    largest = std::max(largest, std::abs(exact.values()[i] - inexact.values()[i]));
  EXPECT_LE(largest, same);
}

template <typename Kernel>
void expect_same_symmetries(const std::vector<ST::Principal_symmetry<EK>>& exact,
                            const std::vector<ST::Principal_symmetry<Kernel>>& inexact)
{
  ASSERT_EQ(exact.size(), inexact.size());
  for(std::size_t i = 0; i < exact.size(); ++i) {
    expect_same_plane(exact[i].plane, inexact[i].plane);
    EXPECT_NEAR(exact[i].symmetry, inexact[i].symmetry, same);
    EXPECT_NEAR(exact[i].support, inexact[i].support, same);
  }
}

// The index of the coordinate plane that `plane` is (normal within `degrees` of the axis, within
// `offset` of the origin), or -1.
template <typename Plane>
int coordinate_plane_of(const Plane& plane, double degrees = 1., double offset = 1e-2)
{
  const std::array<double, 4> u = unit_coefficients(plane);
  for(int axis = 0; axis < 3; ++axis)
    if(std::abs(u[axis]) > std::cos(degrees * CGAL_PI / 180.) && std::abs(u[3]) < offset) return axis;
  return -1;
}

// Whether the three strongest planes are the three coordinate planes, in any order.
template <typename Kernel>
void expect_box_planes_first(const std::vector<ST::Principal_symmetry<Kernel>>& symmetries)
{
  ASSERT_GE(symmetries.size(), 3u);
  std::array<int, 3> found = {0, 0, 0};
  for(std::size_t i = 0; i < 3; ++i) {
    const int axis = coordinate_plane_of(symmetries[i].plane);
    ASSERT_GE(axis, 0) << "plane " << i << ": " << symmetries[i].plane;
    ++found[std::size_t(axis)];
  }
  EXPECT_EQ(found, (std::array<int, 3>{1, 1, 1}));
}

// Whether each axis of the frame is a coordinate axis (up to sign), each axis once.
template <typename Kernel>
void expect_coordinate_axes(const ST::Symmetry_frame<Kernel>& frame, double tolerance)
{
  std::array<int, 3> found = {0, 0, 0};
  for(const auto& a : frame.axes) {
    const std::array<double, 3> u = coordinates(a);
    for(int axis = 0; axis < 3; ++axis)
      if(std::abs(std::abs(u[std::size_t(axis)]) - 1.) < tolerance) ++found[std::size_t(axis)];
  }
  EXPECT_EQ(found, (std::array<int, 3>{1, 1, 1}));
}

template <typename Kernel>
void expect_same_frame(const ST::Symmetry_frame<EK>& exact, const ST::Symmetry_frame<Kernel>& inexact)
{
  expect_near(coordinates(exact.center), coordinates(inexact.center), same);
  for(std::size_t i = 0; i < 3; ++i) expect_near(coordinates(exact.axes[i]), coordinates(inexact.axes[i]), same);
}

} // namespace

TEST(ExactKernel, GaussianDistanceTransformsOfMeshAndPointsEqualEpicksAndAreCentredOnTheBox)
{
  const ST::Voxel_grid<EK> of_mesh = ST::gaussian_distance_transform(box().exact_mesh, options());
  expect_same_grid(of_mesh, ST::gaussian_distance_transform(box().mesh, options()));
  expect_near(coordinates(of_mesh.center()), {0., 0., 0.}, 1e-12);
  double squares = 0.;
  for(double v : of_mesh.values()) squares += v * v;
  EXPECT_NEAR(squares, 1., 1e-9);

  const ST::Voxel_grid<EK> of_points = ST::gaussian_distance_transform_of_points(box().exact_points, options());
  expect_same_grid(of_points, ST::gaussian_distance_transform_of_points(box().points, options()));
  expect_near(coordinates(of_points.center()), {0., 0., 0.}, 0.05); // the mean of random surface points
}

TEST(ExactKernel, SymmetryMeasureIsOneForTheBoxPlanesAndCentreAsWithEpick)
{
  const ST::Voxel_grid<EK> f = ST::gaussian_distance_transform(box().exact_mesh, options());
  const ST::Voxel_grid<IK> g = ST::gaussian_distance_transform(box().mesh, options());
  for(std::size_t i = 0; i < 3; ++i) {
    const double measure = ST::symmetry_measure(f, coordinate_planes<EK>()[i]);
    EXPECT_GT(measure, 0.999) << "plane " << i;
    EXPECT_NEAR(measure, ST::symmetry_measure(g, coordinate_planes<IK>()[i]), same);
  }
  // A plane through a quarter of the box's length is no symmetry of it.
  const double off_centre = ST::symmetry_measure(f, EK::Plane_3(1, 0, 0, -0.5));
  EXPECT_LT(off_centre, 0.8);
  EXPECT_NEAR(off_centre, ST::symmetry_measure(g, IK::Plane_3(1, 0, 0, -0.5)), same);

  const double centre = ST::symmetry_measure(f, EK::Point_3(0, 0, 0));
  EXPECT_GT(centre, 0.999);
  EXPECT_NEAR(centre, ST::symmetry_measure(g, IK::Point_3(0, 0, 0)), same);
  EXPECT_NEAR(ST::symmetry_transform_value(centre), std::sqrt((1. + centre) / 2.), 1e-15);
}

TEST(ExactKernel, PointSymmetryTransformsFindTheBoxCentreAsWithEpick)
{
  const ST::Point_symmetry_transform<EK> of_mesh = ST::point_symmetry_transform(box().exact_mesh, options());
  const ST::Point_symmetry_transform<IK> inexact = ST::point_symmetry_transform(box().mesh, options());
  expect_same_grid(of_mesh.grid(), inexact.grid());
  expect_near(coordinates(of_mesh.center_of_symmetry()), coordinates(inexact.center_of_symmetry()), same);
  expect_near(coordinates(of_mesh.center_of_symmetry()), {0., 0., 0.}, 0.1 * of_mesh.grid().voxel_size());
  EXPECT_NEAR(of_mesh.value(EK::Point_3(0, 0, 0)), inexact.value(IK::Point_3(0, 0, 0)), same);

  const ST::Point_symmetry_transform<EK> of_grid =
    ST::point_symmetry_transform(ST::gaussian_distance_transform(box().exact_mesh, options()));
  expect_same_grid(of_grid.grid(), inexact.grid());

  const ST::Point_symmetry_transform<EK> of_points = ST::point_symmetry_transform_of_points(box().exact_points, options());
  const ST::Point_symmetry_transform<IK> inexact_of_points = ST::point_symmetry_transform_of_points(box().points, options());
  expect_near(coordinates(of_points.center_of_symmetry()), coordinates(inexact_of_points.center_of_symmetry()), same);
  expect_near(coordinates(of_points.center_of_symmetry()), {0., 0., 0.}, 0.05);
}

TEST(ExactKernel, ReflectiveSymmetryTransformsEqualEpicksAndPeakOnTheBoxPlanes)
{
  // Monte Carlo: the strongest bin is one of the box's planes (within the bins' width).
  const ST::Reflective_symmetry_transform<EK> monte_carlo = ST::reflective_symmetry_transform(box().exact_mesh, options());
  expect_same_transform(monte_carlo, ST::reflective_symmetry_transform(box().mesh, options()));
  EXPECT_GE(coordinate_plane_of(monte_carlo.plane(monte_carlo.maximum()), 15., 0.1), 0)
    << monte_carlo.plane(monte_carlo.maximum());
  for(const EK::Plane_3& plane : coordinate_planes<EK>())
    EXPECT_GT(monte_carlo.value(plane), monte_carlo.value(EK::Plane_3(1, 0, 0, -0.5)));

  // Exact, on a smaller grid (the smallest even one above 12 Gaussian widths): the box's planes
  // are among the largest values of the transform.
  const auto exact_options = options().grid_resolution(20).prst_method(ST::Reflective_symmetry_method::EXACT);
  const ST::Reflective_symmetry_transform<EK> exact = ST::reflective_symmetry_transform(box().exact_mesh, exact_options);
  expect_same_transform(exact, ST::reflective_symmetry_transform(box().mesh, exact_options));
  const double strongest = exact.value(exact.maximum());
  for(const EK::Plane_3& plane : coordinate_planes<EK>()) EXPECT_GT(exact.value(plane), 0.9 * strongest) << plane;

  // From a grid, and of points.
  expect_same_transform(ST::reflective_symmetry_transform(ST::gaussian_distance_transform(box().exact_mesh, options()),
                                                          options()),
                        ST::reflective_symmetry_transform(box().mesh, options()));
  expect_same_transform(ST::reflective_symmetry_transform_of_points(box().exact_points, options()),
                        ST::reflective_symmetry_transform_of_points(box().points, options()));
}

TEST(ExactKernel, SavedTransformLoadsBackUnchanged)
{
  const ST::Reflective_symmetry_transform<EK> prst = ST::reflective_symmetry_transform(box().exact_mesh, options());
  std::stringstream file(std::ios::in | std::ios::out | std::ios::binary);
  prst.save(file);
  const ST::Reflective_symmetry_transform<EK> loaded = ST::Reflective_symmetry_transform<EK>::load(file);
  EXPECT_EQ(loaded.values(), prst.values());
  EXPECT_EQ(loaded.center(), prst.center());
  EXPECT_EQ(loaded.radius(), prst.radius());
}

TEST(ExactKernel, PrincipalSymmetriesAreTheBoxPlanesAsWithEpick)
{
  const std::vector<ST::Principal_symmetry<EK>> detected = ST::detect_principal_symmetries(box().exact_mesh, options());
  expect_same_symmetries(detected, ST::detect_principal_symmetries(box().mesh, options()));
  expect_box_planes_first(detected);
  for(std::size_t i = 0; i < 3; ++i) EXPECT_GT(detected[i].support, 0.95) << "plane " << i;

  const ST::Reflective_symmetry_transform<EK> prst = ST::reflective_symmetry_transform(box().exact_mesh, options());
  const std::vector<ST::Principal_symmetry<EK>> from_transform = ST::principal_symmetries(box().exact_mesh, prst, options());
  expect_same_symmetries(from_transform, ST::principal_symmetries(box().mesh, ST::reflective_symmetry_transform(
                                                                                box().mesh, options()), options()));
  expect_box_planes_first(from_transform);

  const std::vector<ST::Principal_symmetry<EK>> of_points =
    ST::detect_principal_symmetries_of_points(box().exact_points, options());
  expect_same_symmetries(of_points, ST::detect_principal_symmetries_of_points(box().points, options()));
  expect_box_planes_first(of_points);
}

TEST(ExactKernel, RefinementAndSupportOfAPlaneAsWithEpick)
{
  // A plane 3 degrees and 0.02 away from x = 0 converges to it.
  const EK::Plane_3 rough(std::cos(CGAL_PI / 60.), std::sin(CGAL_PI / 60.), 0, -0.02);
  const EK::Plane_3 refined = ST::refine_symmetry_plane(box().exact_mesh, rough, options());
  expect_same_plane(refined, ST::refine_symmetry_plane(box().mesh, IK::Plane_3(std::cos(CGAL_PI / 60.),
                                                                               std::sin(CGAL_PI / 60.), 0, -0.02),
                                                       options()));
  EXPECT_EQ(coordinate_plane_of(refined, 0.1, 1e-3), 0) << refined;

  Exact_mesh exact_mesh = box().exact_mesh;
  auto exact_support = exact_mesh.add_property_map<Exact_mesh::Face_index, double>("f:support", 0.).first;
  Mesh mesh = box().mesh;
  auto support = mesh.add_property_map<Mesh::Face_index, double>("f:support", 0.).first;
  const double fraction = ST::symmetry_support(exact_mesh, EK::Plane_3(0, 1, 0, 0), exact_support, options());
  EXPECT_NEAR(fraction, ST::symmetry_support(mesh, IK::Plane_3(0, 1, 0, 0), support, options()), same);
  EXPECT_GT(fraction, 0.99);
  for(Exact_mesh::Face_index f : faces(exact_mesh)) EXPECT_NEAR(exact_support[f], support[Mesh::Face_index(f)], same);
}

TEST(ExactKernel, SymmetryAndPcaFramesAreTheBoxAxesAsWithEpick)
{
  const ST::Symmetry_frame<EK> frame = ST::symmetry_frame(box().exact_mesh, options());
  expect_same_frame(frame, ST::symmetry_frame(box().mesh, options()));
  expect_near(coordinates(frame.center), {0., 0., 0.}, 1e-3);
  expect_coordinate_axes(frame, 1e-4);

  const ST::Symmetry_frame<EK> of_points = ST::symmetry_frame_of_points(box().exact_points, options());
  expect_same_frame(of_points, ST::symmetry_frame_of_points(box().points, options()));
  expect_coordinate_axes(of_points, 1e-2);

  // PCA: the largest variance along x, then y, then z (sides 2, 1.4, 0.9).
  const ST::Symmetry_frame<EK> pca = ST::pca_frame(box().exact_mesh);
  expect_same_frame(pca, ST::pca_frame(box().mesh));
  for(std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(coordinates(pca.axes[i])[i]), 1., 1e-9) << "axis " << i;
  const ST::Symmetry_frame<EK> pca_of_points = ST::pca_frame_of_points(box().exact_points);
  expect_same_frame(pca_of_points, ST::pca_frame_of_points(box().points));
  EXPECT_NEAR(std::abs(coordinates(pca_of_points.axes[0])[0]), 1., 1e-2);

  // to_canonical takes the centre to the origin and the first axis to x.
  const EK::Aff_transformation_3 motion = ST::to_canonical(frame);
  expect_near(coordinates(motion.transform(frame.center)), {0., 0., 0.}, 1e-12);
  expect_near(coordinates(motion.transform(frame.axes[0])), {1., 0., 0.}, 1e-12);
}

TEST(ExactKernel, DescriptorsAndTheirDistancesAsWithEpick)
{
  const ST::Symmetry_descriptor<EK> of_mesh = ST::symmetry_descriptor(box().exact_mesh, options());
  const ST::Symmetry_descriptor<EK> of_points = ST::symmetry_descriptor_of_points(box().exact_points, options());
  const ST::Symmetry_descriptor<IK> inexact_of_mesh = ST::symmetry_descriptor(box().mesh, options());
  const ST::Symmetry_descriptor<IK> inexact_of_points = ST::symmetry_descriptor_of_points(box().points, options());
  EXPECT_EQ(of_mesh.reflective_symmetry_values(), inexact_of_mesh.reflective_symmetry_values());
  EXPECT_EQ(of_mesh.gedt_values(), inexact_of_mesh.gedt_values());

  EXPECT_EQ(ST::reflective_symmetry_descriptor_distance(of_mesh, of_mesh), 0.);
  EXPECT_EQ(ST::gedt_distance(of_mesh, of_mesh), 0.);
  const double prst = ST::reflective_symmetry_descriptor_distance(of_mesh, of_points),
               gedt = ST::gedt_distance(of_mesh, of_points);
  EXPECT_NEAR(prst, ST::reflective_symmetry_descriptor_distance(inexact_of_mesh, inexact_of_points), same);
  EXPECT_NEAR(gedt, ST::gedt_distance(inexact_of_mesh, inexact_of_points), same);
  EXPECT_NEAR(ST::descriptor_distance(of_mesh, of_points), prst * gedt, 1e-15);
  EXPECT_GT(prst, 0.);

  std::stringstream file(std::ios::in | std::ios::out | std::ios::binary);
  of_mesh.save(file);
  const ST::Symmetry_descriptor<EK> loaded = ST::Symmetry_descriptor<EK>::load(file);
  EXPECT_EQ(loaded.reflective_symmetry_values(), of_mesh.reflective_symmetry_values());
  EXPECT_EQ(loaded.gedt_values(), of_mesh.gedt_values());
}

TEST(ExactKernel, ViewpointsOfThreeOrthogonalPlanesAreTheKnownOnes)
{
  // Planes x = 0, y = 0, z = 0 of symmetries 0.9, 0.6, 0.3: S(v) = 0.9|x| + 0.6|y| + 0.3|z|, of
  // maximum along (0.9, 0.6, 0.3) and minimum along z.
  const double m[3] = {0.9, 0.6, 0.3};
  std::vector<ST::Principal_symmetry<EK>> exact;
  std::vector<ST::Principal_symmetry<IK>> inexact;
  for(std::size_t i = 0; i < 3; ++i) {
    exact.push_back({coordinate_planes<EK>()[i], m[i], 1.});
    inexact.push_back({coordinate_planes<IK>()[i], m[i], 1.});
  }
  EXPECT_NEAR(ST::viewpoint_score(exact, EK::Vector_3(2, 0, 0)), 0.9, 1e-15);
  EXPECT_NEAR(ST::viewpoint_score(exact, EK::Vector_3(1, 1, 1)), 1.8 / std::sqrt(3.), 1e-15);

  std::vector<ST::Viewpoint<EK>> best;
  ST::best_viewpoints(exact, std::back_inserter(best));
  std::vector<ST::Viewpoint<IK>> inexact_best;
  ST::best_viewpoints(inexact, std::back_inserter(inexact_best));
  ASSERT_FALSE(best.empty());
  ASSERT_EQ(best.size(), inexact_best.size());
  const double norm = std::sqrt(0.81 + 0.36 + 0.09);
  std::array<double, 3> direction = coordinates(best.front().direction);
  for(double& c : direction) c = std::abs(c);
  expect_near(direction, {0.9 / norm, 0.6 / norm, 0.3 / norm}, 1e-12);
  EXPECT_NEAR(best.front().score, norm, 1e-12);
  for(std::size_t i = 0; i < best.size(); ++i)
    expect_near(coordinates(best[i].direction), coordinates(inexact_best[i].direction), same);

  const ST::Viewpoint<EK> worst = ST::worst_viewpoint(exact);
  expect_near(coordinates(worst.direction), {0., 0., 1.}, 1e-12);
  EXPECT_NEAR(worst.score, 0.3, 1e-12);

  Exact_mesh sphere = ST::viewpoint_score_sphere(exact, 2);
  Mesh inexact_sphere = ST::viewpoint_score_sphere(inexact, 2);
  EXPECT_EQ(num_vertices(sphere), 10u * 16u + 2u);
  const auto score = sphere.add_property_map<Exact_mesh::Vertex_index, double>("v:score").first;
  const auto inexact_score = inexact_sphere.add_property_map<Mesh::Vertex_index, double>("v:score").first;
  for(Exact_mesh::Vertex_index v : vertices(sphere)) {
    const std::array<double, 3> p = coordinates(sphere.point(v));
    EXPECT_NEAR(score[v], 0.9 * std::abs(p[0]) + 0.6 * std::abs(p[1]) + 0.3 * std::abs(p[2]), 1e-12);
    EXPECT_NEAR(score[v], inexact_score[Mesh::Vertex_index(v)], same);
  }
}

// The fraction of `points` whose mirror image through x = 0 is one of them, within `tolerance`.
double mirror_matched_fraction(const std::vector<EK::Point_3>& points, double tolerance)
{
  std::size_t matched = 0;
  for(const EK::Point_3& p : points) {
    const std::array<double, 3> a = coordinates(p);
    matched += std::any_of(points.begin(), points.end(), [&](const EK::Point_3& q) {
      const std::array<double, 3> b = coordinates(q);
      return std::abs(a[0] + b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance && std::abs(a[2] - b[2]) <= tolerance;
    }) ? 1 : 0;
  }
  return double(matched) / double(points.size());
}

TEST(ExactKernel, SymmetricRemeshingAndItsMetricsAsWithEpick)
{
  // The ellipsoid remeshed about its plane x = 0, and without plane (plain VSA).
  const Both_kernels& shape = ellipsoid();
  const std::vector<EK::Plane_3> planes = {EK::Plane_3(1, 0, 0, 0)};
  const std::vector<IK::Plane_3> inexact_planes = {IK::Plane_3(1, 0, 0, 0)};
  std::vector<EK::Point_3> anchors;
  std::vector<IK::Point_3> inexact_anchors;
  std::vector<std::array<std::size_t, 3>> triangles, inexact_triangles;
  Exact_mesh remeshed, plain;
  Mesh inexact_remeshed;
  ST::symmetric_approximate_triangle_mesh(shape.exact_mesh, planes,
                                          CGAL::parameters::max_number_of_proxies(30).anchors(std::back_inserter(anchors))
                                            .triangles(std::back_inserter(triangles)).output_mesh(&remeshed));
  ST::symmetric_approximate_triangle_mesh(shape.mesh, inexact_planes,
                                          CGAL::parameters::max_number_of_proxies(30)
                                            .anchors(std::back_inserter(inexact_anchors))
                                            .triangles(std::back_inserter(inexact_triangles))
                                            .output_mesh(&inexact_remeshed));
  ST::symmetric_approximate_triangle_mesh(shape.exact_mesh, std::vector<EK::Plane_3>(),
                                          CGAL::parameters::max_number_of_proxies(30).output_mesh(&plain));
  ASSERT_EQ(anchors.size(), inexact_anchors.size());
  ASSERT_FALSE(triangles.empty());
  EXPECT_EQ(triangles, inexact_triangles);
  for(std::size_t i = 0; i < anchors.size(); ++i) expect_near(coordinates(anchors[i]), coordinates(inexact_anchors[i]), same);
  EXPECT_EQ(num_faces(remeshed), num_faces(inexact_remeshed));
  // The output's vertices come in mirror pairs (those on the plane are their own images).
  EXPECT_GE(mirror_matched_fraction(anchors, 1e-6), 0.99);

  const ST::Approximation_error error = ST::approximation_error(shape.exact_mesh, remeshed);
  const ST::Approximation_error inexact_error = ST::approximation_error(shape.mesh, inexact_remeshed);
  EXPECT_NEAR(error.rms, inexact_error.rms, same);
  EXPECT_NEAR(error.hausdorff, inexact_error.hausdorff, same);
  EXPECT_LT(error.rms, 0.05); // a coarse approximation, of the ellipsoid

  // Symmetric, unlike plain VSA's output.
  const double symmetry = ST::symmetry_error(remeshed, planes[0]);
  EXPECT_NEAR(symmetry, ST::symmetry_error(inexact_remeshed, inexact_planes[0]), same);
  EXPECT_LT(symmetry, 0.1 * ST::symmetry_error(plain, planes[0]));
  const double near_input = ST::symmetry_error(remeshed, planes[0], shape.exact_mesh, 0.1);
  EXPECT_NEAR(near_input, ST::symmetry_error(inexact_remeshed, inexact_planes[0], shape.mesh, 0.1), same);
  EXPECT_LE(near_input, symmetry + 1e-12);

  auto face_error = remeshed.add_property_map<Exact_mesh::Face_index, double>("f:error", -1.).first;
  auto inexact_face_error = inexact_remeshed.add_property_map<Mesh::Face_index, double>("f:error", -1.).first;
  const double largest = ST::face_symmetry_errors(remeshed, planes[0], face_error);
  EXPECT_NEAR(largest, ST::face_symmetry_errors(inexact_remeshed, inexact_planes[0], inexact_face_error), same);
  std::size_t exact_mirrors = 0;
  for(Exact_mesh::Face_index f : faces(remeshed)) {
    EXPECT_GE(face_error[f], 0.);
    EXPECT_LE(face_error[f], largest);
    EXPECT_NEAR(face_error[f], inexact_face_error[Mesh::Face_index(f)], same);
    exact_mirrors += face_error[f] < 1e-9 ? 1 : 0;
  }
  EXPECT_GE(double(exact_mirrors), 0.9 * double(num_faces(remeshed))) << "faces whose mirrored centroid lies on the output";
}

TEST(ExactKernel, SegmentationKeepsTheEllipsoidWholeAsWithEpick)
{
  Exact_mesh exact_mesh = ellipsoid().exact_mesh;
  Mesh mesh = ellipsoid().mesh;
  auto exact_segment = exact_mesh.add_property_map<Exact_mesh::Face_index, std::size_t>("f:segment", 99).first;
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 99).first;
  ST::Segmentation_tree<EK> tree;
  ST::Segmentation_tree<IK> inexact_tree;
  const auto segmentation_options = CGAL::parameters::grid_resolution(resolution).random_seed(1);
  const std::size_t count =
    ST::segment_by_symmetry(exact_mesh, exact_segment, segmentation_options.segmentation_tree(std::ref(tree)));
  EXPECT_EQ(count, ST::segment_by_symmetry(mesh, segment, segmentation_options.segmentation_tree(std::ref(inexact_tree))));
  for(Exact_mesh::Face_index f : faces(exact_mesh)) EXPECT_EQ(exact_segment[f], segment[Mesh::Face_index(f)]);
  ASSERT_EQ(tree.segments.size(), inexact_tree.segments.size());
  for(std::size_t i = 0; i < tree.segments.size(); ++i) {
    expect_same_symmetries(tree.segments[i].planes, inexact_tree.segments[i].planes);
    EXPECT_EQ(tree.segments[i].reflected_fractions, inexact_tree.segments[i].reflected_fractions);
  }

  // Its planes reflect the whole ellipsoid onto itself: no split.
  EXPECT_EQ(count, 1u);
  ASSERT_EQ(tree.segments.size(), 1u);
  EXPECT_EQ(tree.segments[0].status, ST::Segment_status::NO_PARTIAL_SYMMETRY);
  ASSERT_FALSE(tree.segments[0].planes.empty());
  for(double x : tree.segments[0].reflected_fractions) EXPECT_GT(x, 0.9);
}

// The ellipsoid with the vertices of one side moved, symmetrized about x = 0 and z = 0: the same
// vertices as with Epick, and exactly symmetric.
TEST(ExactKernel, SymmetrizationMovesTheVerticesAsWithEpick)
{
  Mesh mesh = ellipsoid().mesh;
  CGAL::Random rng(2);
  for(Mesh::Vertex_index v : vertices(mesh))
    if(mesh.point(v).x() > 1e-9)
      mesh.point(v) = mesh.point(v) + 0.002 * IK::Vector_3(st_test::gaussian(rng), st_test::gaussian(rng), st_test::gaussian(rng));
  Exact_mesh exact_mesh = rebuilt<Exact_mesh>(mesh);
  const auto exact = ST::symmetrize(exact_mesh, std::vector<EK::Plane_3>{EK::Plane_3(1, 0, 0, 0), EK::Plane_3(0, 0, 1, 0)});
  const auto inexact = ST::symmetrize(mesh, std::vector<IK::Plane_3>{IK::Plane_3(1, 0, 0, 0), IK::Plane_3(0, 0, 1, 0)});
  EXPECT_EQ(exact.group_size, 4u);
  EXPECT_EQ(exact.paired_vertices, num_vertices(mesh));
  EXPECT_EQ(exact.paired_vertices, inexact.paired_vertices);
  EXPECT_NEAR(CGAL::to_double(exact.max_displacement), inexact.max_displacement, same);
  for(Mesh::Vertex_index v : vertices(mesh))
    for(int i = 0; i < 3; ++i) EXPECT_NEAR(CGAL::to_double(exact_mesh.point(v)[i]), mesh.point(v)[i], same);
  ASSERT_EQ(exact.planes.size(), 2u);
  EXPECT_LE(ST::symmetry_distance_error(exact_mesh, exact.planes[0]), 1e-6);
  EXPECT_LE(ST::symmetry_distance_error(exact_mesh, exact.planes[1]), 1e-6);
}

// The ellipsoid's vertices with x < 0.3 (with the faces among them, for the mesh) completed about
// x = 0, then symmetrized about z = 0: the same points and faces added, the same points moved, as
// with Epick.
TEST(ExactKernel, CompletionAndPointSetSymmetrizationAsWithEpick)
{
  const Mesh mesh = ellipsoid().mesh;
  std::vector<IK::Point_3> points;
  std::vector<EK::Point_3> exact_points;
  for(Mesh::Vertex_index v : vertices(mesh))
    if(mesh.point(v).x() < 0.3) {
      points.push_back(mesh.point(v));
      exact_points.push_back(EK::Point_3(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()));
    }
  std::vector<std::pair<IK::Point_3, IK::Vector_3>> added;
  std::vector<std::pair<EK::Point_3, EK::Vector_3>> exact_added;
  ST::complete_by_symmetry_of_points(points, std::vector<IK::Plane_3>{IK::Plane_3(1, 0, 0, 0)}, std::back_inserter(added));
  ST::complete_by_symmetry_of_points(exact_points, std::vector<EK::Plane_3>{EK::Plane_3(1, 0, 0, 0)},
                                     std::back_inserter(exact_added));
  ASSERT_EQ(added.size(), exact_added.size());
  EXPECT_GT(added.size(), 0u);
  for(std::size_t i = 0; i < added.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(CGAL::to_double(exact_added[i].first[k]), added[i].first[k], same);
  ST::symmetrize_point_set(points, std::vector<IK::Plane_3>{IK::Plane_3(0, 0, 1, 0)});
  ST::symmetrize_point_set(exact_points, std::vector<EK::Plane_3>{EK::Plane_3(0, 0, 1, 0)});
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(CGAL::to_double(exact_points[i][k]), points[i][k], same);
  Mesh cut = mesh;
  for(Mesh::Face_index f : faces(mesh))
    if(mesh.point(target(halfedge(f, mesh), mesh)).x() > 0.3) CGAL::Euler::remove_face(halfedge(f, cut), cut);
  Exact_mesh exact_cut = rebuilt<Exact_mesh>(cut);
  std::vector<Mesh::Face_index> faces_added;
  std::vector<Exact_mesh::Face_index> exact_faces_added;
  ST::complete_by_symmetry(cut, std::vector<IK::Plane_3>{IK::Plane_3(1, 0, 0, 0)}, std::back_inserter(faces_added));
  ST::complete_by_symmetry(exact_cut, std::vector<EK::Plane_3>{EK::Plane_3(1, 0, 0, 0)},
                           std::back_inserter(exact_faces_added));
  EXPECT_GT(faces_added.size(), 0u);
  EXPECT_EQ(faces_added.size(), exact_faces_added.size());
}

// The triangle soup forms, on the box's faces as a soup of Epeck points, the point-set detection
// with normals, and the symmetry distance error of a mesh, a soup and a point set.
TEST(ExactKernel, TriangleSoupFormsNormalsAndSymmetryDistanceErrorAsWithEpick)
{
  std::vector<EK::Point_3> exact_points(box().exact_mesh.points().begin(), box().exact_mesh.points().end());
  std::vector<IK::Point_3> points(box().mesh.points().begin(), box().mesh.points().end());
  std::vector<std::array<std::size_t, 3>> triangles;
  for(Mesh::Face_index f : faces(box().mesh)) {
    const auto h = halfedge(f, box().mesh);
    triangles.push_back({std::size_t(source(h, box().mesh)), std::size_t(target(h, box().mesh)),
                         std::size_t(target(next(h, box().mesh), box().mesh))});
  }
  expect_same_grid(ST::gaussian_distance_transform_of_triangle_soup(exact_points, triangles, options()),
                   ST::gaussian_distance_transform_of_triangle_soup(points, triangles, options()));
  expect_same_transform(ST::reflective_symmetry_transform_of_triangle_soup(exact_points, triangles, options()),
                        ST::reflective_symmetry_transform_of_triangle_soup(points, triangles, options()));
  const auto detected = ST::detect_principal_symmetries_of_triangle_soup(exact_points, triangles, options());
  expect_same_symmetries(detected, ST::detect_principal_symmetries_of_triangle_soup(points, triangles, options()));
  expect_box_planes_first(detected);
  expect_same_plane(ST::refine_symmetry_plane_of_triangle_soup(exact_points, triangles, EK::Plane_3(1, 0.05, 0, 0.01), options()),
                    ST::refine_symmetry_plane_of_triangle_soup(points, triangles, IK::Plane_3(1, 0.05, 0, 0.01), options()));
  std::vector<double> exact_support, support;
  EXPECT_NEAR(ST::symmetry_support_of_triangle_soup(exact_points, triangles, EK::Plane_3(0, 1, 0, 0),
                                                    std::back_inserter(exact_support), options()),
              ST::symmetry_support_of_triangle_soup(points, triangles, IK::Plane_3(0, 1, 0, 0), std::back_inserter(support),
                                                    options()), same);
  const ST::Symmetry_frame<EK> frame = ST::symmetry_frame_of_triangle_soup(exact_points, triangles, options());
  expect_same_frame(frame, ST::symmetry_frame_of_triangle_soup(points, triangles, options()));
  expect_coordinate_axes(frame, 1e-4);
  expect_same_frame(ST::pca_frame_of_triangle_soup(exact_points, triangles), ST::pca_frame_of_triangle_soup(points, triangles));

  // Normals: +-x, +-y or +-z, that of the face nearest to each point of the box.
  typedef std::pair<EK::Point_3, EK::Vector_3> Exact_point_with_normal;
  std::vector<Exact_point_with_normal> oriented;
  for(const EK::Point_3& p : box().exact_points) {
    const std::array<double, 3> c = coordinates(p);
    std::size_t axis = 0;
    for(std::size_t a = 1; a < 3; ++a)
      if(half_sides[a] - std::abs(c[a]) < half_sides[axis] - std::abs(c[axis])) axis = a;
    std::array<double, 3> n = {0., 0., 0.};
    n[axis] = c[axis] > 0. ? 1. : -1.;
    oriented.emplace_back(p, EK::Vector_3(n[0], n[1], n[2]));
  }
  const auto with_normals = ST::detect_principal_symmetries_of_points(
    oriented, options().point_map(CGAL::First_of_pair_property_map<Exact_point_with_normal>())
                .normal_map(CGAL::Second_of_pair_property_map<Exact_point_with_normal>()));
  expect_box_planes_first(with_normals);

  // The box's planes are exact symmetries; the plane turned by 1 degree about z has the SDE of
  // the formula of test_real_world_input (within its 3 %).
  const double t = CGAL_PI / 180., a = half_sides[0], b = half_sides[1], c = half_sides[2];
  const EK::Plane_3 turned(std::cos(t), std::sin(t), 0, 0);
  const double sde = ST::symmetry_distance_error(box().exact_mesh, turned);
  EXPECT_NEAR(sde, ST::symmetry_distance_error(box().mesh, IK::Plane_3(std::cos(t), std::sin(t), 0, 0)), same);
  EXPECT_NEAR(sde, t * c * (a * a + b * b) / (a * b + b * c + c * a) / (2. * std::sqrt(a * a + b * b + c * c)), 0.03 * sde);
  EXPECT_NEAR(ST::symmetry_distance_error_of_triangle_soup(exact_points, triangles, turned), sde, same);
  EXPECT_LT(ST::symmetry_distance_error(box().exact_mesh, EK::Plane_3(0, 0, 1, 0)), 1e-12);
  EXPECT_NEAR(ST::symmetry_distance_error_of_points(box().exact_points, turned),
              ST::symmetry_distance_error_of_points(box().points, IK::Plane_3(std::cos(t), std::sin(t), 0, 0)), same);
}
