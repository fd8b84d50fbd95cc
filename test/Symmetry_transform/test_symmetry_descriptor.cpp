// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Symmetry descriptors (matching): the distances are zero for identical shapes, symmetric, the
// two L2 parts satisfy the triangle inequality, the PRST part compares the bins' symmetry
// distances D^(1/4) (a perfect symmetry lost counts more than a middling one lowered as much),
// a noisy copy is nearer than a different shape,
// translation and scaling change little, saving and loading keeps the distances, and
// mismatched resolutions and damaged files are rejected.

#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include "Symmetry_transform_test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Symmetry_descriptor<K> Descriptor;

// 32^3 (the default) and 1e5 Monte Carlo samples, as grid_32 in test_principal_symmetries.cpp.
const auto grid_32 = CGAL::parameters::grid_resolution(32).number_of_samples(100000).random_seed(1);

typedef double (*Distance)(const Descriptor&, const Descriptor&);
const Distance distances[3] = {&ST::reflective_symmetry_descriptor_distance<K>, &ST::gedt_distance<K>, &ST::descriptor_distance<K>};

struct Descriptors
{
  Descriptor box, ellipsoid, hull, noisy_box, noisy_ellipsoid, noisy_hull;
};

// Computed once for all tests: each costs a GEDT and a PRST.
const Descriptors& descriptors()
{
  static const Descriptors d = [] {
    const Surface_mesh shapes[3] = {box<Surface_mesh>().mesh, ellipsoid<Surface_mesh>().mesh,
                                    one_plane_hull<Surface_mesh>().mesh};
    std::vector<Descriptor> clean, noisy;
    CGAL::Random rng(7);
    for(const Surface_mesh& mesh : shapes) {
      clean.push_back(ST::symmetry_descriptor(mesh, grid_32));
      Surface_mesh copy = mesh;
      add_vertex_noise(copy, 0.005 * center_and_radius(mesh).radius, rng);
      noisy.push_back(ST::symmetry_descriptor(copy, grid_32));
    }
    return Descriptors{clean[0], clean[1], clean[2], noisy[0], noisy[1], noisy[2]};
  }();
  return d;
}

TEST(SymmetryDescriptor, HasTheRequestedResolutionAndUnitGedt)
{
  const Descriptor& a = descriptors().box;
  EXPECT_EQ(a.resolution(), 32u);
  EXPECT_EQ(a.reflective_symmetry_values().size(), 32u * 32u * 32u);
  EXPECT_EQ(a.gedt_values().size(), 32u * 32u * 32u);
  double norm = 0.;
  for(float v : a.gedt_values()) norm += double(v) * double(v);
  EXPECT_NEAR(norm, 1., 1e-5);
  // The default resolution is 32 too.
  EXPECT_EQ(ST::symmetry_descriptor(box<Surface_mesh>().mesh, CGAL::parameters::number_of_samples(20000)).resolution(), 32u);
}

TEST(SymmetryDescriptor, DistanceIsZeroForTheSameMeshTwice)
{
  const Surface_mesh mesh = ellipsoid<Surface_mesh>().mesh;
  const Descriptor a = ST::symmetry_descriptor(mesh, grid_32), b = ST::symmetry_descriptor(mesh, grid_32);
  for(Distance d : distances) EXPECT_EQ(d(a, b), 0.);
  for(Distance d : distances) EXPECT_EQ(d(a, a), 0.);
}

TEST(SymmetryDescriptor, DistancesAreSymmetric)
{
  const Descriptors& s = descriptors();
  const Descriptor* all[] = {&s.box, &s.ellipsoid, &s.hull, &s.noisy_box};
  for(const Descriptor* a : all)
    for(const Descriptor* b : all)
      for(Distance d : distances) EXPECT_EQ(d(*a, *b), d(*b, *a));
}

TEST(SymmetryDescriptor, L2PartsSatisfyTheTriangleInequality)
{
  const Descriptors& s = descriptors();
  const Descriptor* all[] = {&s.box, &s.ellipsoid, &s.hull, &s.noisy_box, &s.noisy_hull};
  for(const Descriptor* a : all)
    for(const Descriptor* b : all)
      for(const Descriptor* c : all)
        for(int part = 0; part < 2; ++part)
          EXPECT_LE(distances[part](*a, *c), distances[part](*a, *b) + distances[part](*b, *c) + 1e-9);
}

// A descriptor of resolution n whose PRST bins all hold `measure` but bin `changed`, which holds
// `changed_measure` (the GEDT: one sample, the same for all).
Descriptor synthetic_descriptor(std::size_t n, double measure, std::size_t changed, double changed_measure)
{
  ST::Reflective_symmetry_transform<K> prst(n, Point_3(0, 0, 0), 1.);
  std::fill(prst.values().begin(), prst.values().end(), measure);
  prst.values()[changed] = changed_measure;
  ST::Voxel_grid<K> gedt(n, Point_3(0, 0, 0), 1., 2.);
  gedt.values()[0] = 1.;
  return Descriptor(prst, gedt);
}

TEST(SymmetryDescriptor, PrstDistanceComparesTheSymmetryDistancesToThePowerOneFourth)
{
  const std::size_t n = 4, bin = (1 * n + 2) * n + 3; // theta row 1
  auto distance = [&](double from, double to) {
    return ST::reflective_symmetry_descriptor_distance(synthetic_descriptor(n, 0.7, bin, from),
                                                       synthetic_descriptor(n, 0.7, bin, to));
  };
  // The documented formula, written out: one bin differs, in theta row 1 of n rows of n^2 bins.
  auto compared = [](double sm) { return std::pow(std::sqrt((1. - sm) / 2.), 1. / 4.); };
  double weight_sum = 0.;
  for(std::size_t i = 0; i < n; ++i) weight_sum += std::sqrt(std::sin((i + 0.5) * CGAL_PI / 2. / double(n))) * double(n * n);
  const double row_weight = std::sqrt(std::sin(1.5 * CGAL_PI / 2. / double(n)));
  EXPECT_NEAR(distance(1., 0.9), std::abs(compared(1.) - compared(0.9)) * std::sqrt(row_weight / weight_sum), 1e-6);
  // The same difference of SM (0.1) counts ~30 times more where a perfect symmetry is lost than
  // between two middling planes: the plain difference of the SM would count both alike.
  EXPECT_GT(distance(1., 0.9), 10. * distance(0.6, 0.5));
  EXPECT_DOUBLE_EQ(ST::gedt_distance(synthetic_descriptor(n, 0.7, bin, 1.), synthetic_descriptor(n, 0.7, bin, 0.9)), 0.);
}

TEST(SymmetryDescriptor, NoisyCopyIsNearerThanADifferentShape)
{
  const Descriptors& s = descriptors();
  const Descriptor* clean[3] = {&s.box, &s.ellipsoid, &s.hull};
  const Descriptor* noisy[3] = {&s.noisy_box, &s.noisy_ellipsoid, &s.noisy_hull};
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      if(i == j) continue;
      for(Distance d : distances) {
        EXPECT_LT(d(*clean[i], *noisy[i]), d(*clean[i], *clean[j])) << "shape " << i << " against " << j;
        EXPECT_LT(d(*clean[i], *noisy[i]), d(*clean[i], *noisy[j])) << "shape " << i << " against noisy " << j;
      }
    }
  std::cout << "box: noisy copy " << ST::descriptor_distance(s.box, s.noisy_box) << ", ellipsoid "
            << ST::descriptor_distance(s.box, s.ellipsoid) << ", one-plane hull "
            << ST::descriptor_distance(s.box, s.hull) << "\n";
}

TEST(SymmetryDescriptor, TranslatedAndScaledCopyIsNearerThanADifferentShape)
{
  const Descriptors& s = descriptors();
  CGAL::Random rng(3);
  const Motion m = random_motion(rng, /*rotate=*/false);
  Surface_mesh mesh = ellipsoid<Surface_mesh>().mesh;
  for(auto v : vertices(mesh)) mesh.point(v) = m.transform(mesh.point(v));
  const Descriptor moved = ST::symmetry_descriptor(mesh, grid_32);
  EXPECT_LT(ST::gedt_distance(s.ellipsoid, moved), 0.1 * ST::gedt_distance(s.ellipsoid, s.box));
  EXPECT_LT(ST::descriptor_distance(s.ellipsoid, moved), ST::descriptor_distance(s.ellipsoid, s.noisy_ellipsoid) * 2.);
}

TEST(SymmetryDescriptor, PointSetDescriptorMatchesItsShape)
{
  const Surface_mesh mesh = box<Surface_mesh>().mesh;
  CGAL::Random rng(5);
  const std::vector<Point_3> points = surface_points(mesh, 20000, rng);
  const Descriptor a = ST::symmetry_descriptor_of_points(points, grid_32);
  EXPECT_EQ(a.resolution(), 32u);
  const Descriptors& s = descriptors();
  EXPECT_LT(ST::descriptor_distance(a, s.box), ST::descriptor_distance(a, s.ellipsoid));
  EXPECT_LT(ST::descriptor_distance(a, s.box), ST::descriptor_distance(a, s.hull));
}

TEST(SymmetryDescriptor, SaveLoadRoundTripKeepsTheDistances)
{
  const Descriptors& s = descriptors();
  std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
  s.box.save(stream);
  s.hull.save(stream); // several descriptors follow each other in one stream
  const Descriptor box = Descriptor::load(stream), hull = Descriptor::load(stream);
  EXPECT_EQ(box.reflective_symmetry_values(), s.box.reflective_symmetry_values());
  EXPECT_EQ(box.gedt_values(), s.box.gedt_values());
  for(Distance d : distances) {
    EXPECT_EQ(d(box, s.ellipsoid), d(s.box, s.ellipsoid));
    EXPECT_EQ(d(hull, s.ellipsoid), d(s.hull, s.ellipsoid));
    EXPECT_EQ(d(box, hull), d(s.box, s.hull));
  }
}

TEST(SymmetryDescriptor, RejectsMismatchedResolutions)
{
  const Descriptor coarse =
    ST::symmetry_descriptor(box<Surface_mesh>().mesh, CGAL::parameters::grid_resolution(24).number_of_samples(20000));
  EXPECT_EQ(coarse.resolution(), 24u);
  for(Distance d : distances) {
    EXPECT_THROW(d(coarse, descriptors().box), std::invalid_argument);
    EXPECT_THROW(d(Descriptor(), Descriptor()), std::invalid_argument);
  }
}

TEST(SymmetryDescriptor, RejectsCorruptTruncatedAndForeignFiles)
{
  std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
  descriptors().box.save(stream);
  const std::string bytes = stream.str();
  auto load = [](const std::string& data) {
    std::istringstream is(data, std::ios::binary);
    return Descriptor::load(is);
  };
  EXPECT_NO_THROW(load(bytes));
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = char(flipped[bytes.size() / 2] ^ 0x10);
  EXPECT_THROW(load(flipped), std::runtime_error);
  EXPECT_THROW(load(bytes.substr(0, bytes.size() - 100)), std::runtime_error);
  std::string foreign = bytes;
  foreign[4] = 'X';
  EXPECT_THROW(load(foreign), std::runtime_error);
  std::string bad_resolution = bytes;
  bad_resolution[16] = 3; // the low byte of the resolution
  EXPECT_THROW(load(bad_resolution), std::runtime_error);
  EXPECT_THROW(Descriptor::load(std::string("/nonexistent/descriptor.bin")), std::runtime_error);
}

} // namespace
