// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The package's named parameters chain with CGAL's own in both orders, their values arrive,
// and the transforms use them.

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include "Symmetry_transform_test_shapes.h"

#include <gtest/gtest.h>

#include <type_traits>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
namespace np = CGAL::internal_np;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;

// Reads a vertex's point twice as far from the origin: a vertex point map a transform can be seen to use.
struct Doubled_point_map
{
  typedef Surface_mesh::Vertex_index key_type;
  typedef Point_3 value_type;
  typedef Point_3 reference;
  typedef boost::readable_property_map_tag category;
  const Surface_mesh* mesh;
  friend Point_3 get(const Doubled_point_map& m, key_type v)
  {
    return CGAL::ORIGIN + 2. * (m.mesh->point(v) - CGAL::ORIGIN);
  }
};

TEST(NamedParameters, OursThenCgalsChainAndKeepTheirValues)
{
  const Surface_mesh mesh = box<Surface_mesh>().mesh;
  const Doubled_point_map vpm{&mesh};
  const auto p = CGAL::parameters::grid_resolution(16).random_seed(3).vertex_point_map(vpm);

  EXPECT_EQ(choose_parameter(get_parameter(p, np::st_grid_resolution), 0), 16);
  EXPECT_EQ(choose_parameter(get_parameter(p, np::random_seed), 0u), 3u);
  static_assert(std::is_same<std::decay_t<decltype(get_parameter(p, np::vertex_point))>, Doubled_point_map>::value,
                "the vertex point map keeps its type");
  const auto v = *vertices(mesh).begin();
  EXPECT_EQ(get(get_parameter(p, np::vertex_point), v), get(vpm, v));
  // A compile-time fact: CGAL's is_default_parameter<>::value is a `static const bool` with no
  // definition, so binding it to EXPECT_TRUE's reference parameter fails to link unless optimised away.
  static_assert(CGAL::parameters::is_default_parameter<decltype(p), np::st_gaussian_width_t>::value,
                "the Gaussian width was not given");
}

TEST(NamedParameters, CgalsThenOursChainAndKeepTheirValues)
{
  const auto p = CGAL::parameters::random_seed(3).grid_resolution(16).gaussian_width(2.0);

  EXPECT_EQ(choose_parameter(get_parameter(p, np::random_seed), 0u), 3u);
  EXPECT_EQ(choose_parameter(get_parameter(p, np::st_grid_resolution), 0), 16);
  EXPECT_EQ(choose_parameter(get_parameter(p, np::st_gaussian_width), 0.), 2.0);
  static_assert(CGAL::parameters::is_default_parameter<decltype(p), np::vertex_point_t>::value,
                "the vertex point map was not given");
}

TEST(NamedParameters, GaussianDistanceTransformUsesChainedResolutionWidthAndVertexPointMap)
{
  const Surface_mesh mesh = box<Surface_mesh>().mesh;
  const Grid plain =
    ST::gaussian_distance_transform(mesh, CGAL::parameters::random_seed(3).grid_resolution(16).gaussian_width(1.0));
  EXPECT_EQ(plain.resolution(), 16u);
  // The default side leaves room for 3 widths around the bounding sphere: 2R / (1 - 6 sigma / n).
  EXPECT_NEAR(plain.side_length(), 2. * plain.radius() / (1. - 6. * 1.0 / 16.), 1e-12);

  const Grid doubled = ST::gaussian_distance_transform(
    mesh, CGAL::parameters::grid_resolution(32).random_seed(3).vertex_point_map(Doubled_point_map{&mesh}));
  EXPECT_EQ(doubled.resolution(), 32u);
  EXPECT_NEAR(doubled.radius(), 2. * plain.radius(), 1e-12);
}

TEST(NamedParameters, ReflectiveSymmetryTransformUsesChainedSeedAndMethod)
{
  const Grid f = ST::gaussian_distance_transform(box<Surface_mesh>().mesh,
                                                 CGAL::parameters::grid_resolution(16).gaussian_width(1.0));
  const auto a = ST::reflective_symmetry_transform(f, CGAL::parameters::number_of_samples(20000).random_seed(3));
  const auto b = ST::reflective_symmetry_transform(f, CGAL::parameters::random_seed(3).number_of_samples(20000));
  const auto c = ST::reflective_symmetry_transform(f, CGAL::parameters::random_seed(4).number_of_samples(20000));
  EXPECT_EQ(a.values(), b.values());
  EXPECT_NE(a.values(), c.values());

  const auto exact = ST::reflective_symmetry_transform(
    f, CGAL::parameters::random_seed(3).prst_method(ST::Reflective_symmetry_method::EXACT));
  const auto exact_other_seed = ST::reflective_symmetry_transform(
    f, CGAL::parameters::prst_method(ST::Reflective_symmetry_method::EXACT).random_seed(4));
  EXPECT_EQ(exact.values(), exact_other_seed.values()) << "the exact method does not depend on the seed";
  EXPECT_NE(exact.values(), a.values());
}

} // namespace
