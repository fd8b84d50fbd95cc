// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Shapes built in code whose rotational symmetries are known by construction, all with their
// axis along z through the origin: k-pointed star solids, tapered (a single k-fold axis),
// straight (k mirror planes through the axis) or twisted (none), propellers with pitched blades
// (no mirror plane), and surfaces of revolution; and the axis moved with a shape.

#ifndef CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_TEST_SHAPES_H
#define CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_TEST_SHAPES_H

#include "Symmetry_transform_test_shapes.h"


#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace st_test {

typedef K::Line_3 Line_3;

// A triangle soup, turned into a mesh of any type.
struct Soup
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;

  // The mesh, each face starting at the first corner of its triangle (mesh_from_triangle_soup()).
  template <typename Mesh>
  Mesh mesh() const
  {
    Mesh m;
    mesh_from_triangle_soup(points, triangles, m);
    return m;
  }

  // Rings of `per_ring` points, from ring(l, i) for l = 0 ... rings - 1, joined into a closed
  // surface: quads between consecutive rings split along the same diagonal, and the first and
  // last rings closed by fans around `bottom` and `top`. Rings must turn counterclockwise about z
  // as l grows along z.
  void add_closed_rings(int rings, int per_ring, const std::function<Point_3(int, int)>& ring, const Point_3& bottom,
                        const Point_3& top)
  {
    const std::size_t first = points.size();
    for(int l = 0; l < rings; ++l)
      for(int i = 0; i < per_ring; ++i) points.push_back(ring(l, i));
    auto at = [&](int l, int i) { return first + std::size_t(l * per_ring + (i % per_ring)); };
    for(int l = 0; l + 1 < rings; ++l)
      for(int i = 0; i < per_ring; ++i) {
        triangles.push_back({at(l, i), at(l, i + 1), at(l + 1, i + 1)});
        triangles.push_back({at(l, i), at(l + 1, i + 1), at(l + 1, i)});
      }
    const std::size_t b = points.size(), t = b + 1;
    points.push_back(bottom);
    points.push_back(top);
    for(int i = 0; i < per_ring; ++i) {
      triangles.push_back({b, at(0, i + 1), at(0, i)});
      triangles.push_back({t, at(rings - 1, i), at(rings - 1, i + 1)});
    }
  }
};

// A k-pointed star (outer radius 1, inner radius `inner`) swept along z over `height`, its
// section shrinking linearly to 1 - taper at the top (so no 2-fold axis across z) and turning by
// `twist_degrees` from bottom to top. Untwisted: the k-fold axis z and k mirror planes through
// it. Twisted: the axis z alone, no mirror plane (a screw-like, chiral solid).
inline Soup star_solid_soup(int k, double twist_degrees, int layers = 8, double inner = 0.5, double height = 1.2,
                            double taper = 0.45)
{
  Soup soup;
  const double twist = twist_degrees * CGAL_PI / 180.;
  soup.add_closed_rings(layers + 1, 2 * k, [&](int l, int i) {
    const double t = double(l) / double(layers), s = (1. - taper * t) * (i % 2 == 0 ? 1. : inner);
    const double a = CGAL_PI * double(i) / double(k) + twist * t;
    return Point_3(s * std::cos(a), s * std::sin(a), height * (t - 0.5));
  }, Point_3(0, 0, -height / 2.), Point_3(0, 0, height / 2.));
  return soup;
}

template <typename Mesh>
Mesh star_solid(int k, double twist_degrees)
{
  return star_solid_soup(k, twist_degrees).mesh<Mesh>();
}

// A box of half-sides a, b, c, centred at (radius, skew, z), tilted by `pitch` about the
// radial line through its centre and turned by `angle` about the z axis.
inline void add_blade(Soup& soup, double a, double b, double c, double radius, double skew, double angle, double pitch,
                      double z)
{
  const std::size_t first = soup.points.size();
  const double ca = std::cos(angle), sa = std::sin(angle), cp = std::cos(pitch), sp = std::sin(pitch);
  for(int corner = 0; corner < 8; ++corner) {
    const double x = (corner & 1 ? a : -a) + radius, y0 = corner & 2 ? b : -b, z0 = corner & 4 ? c : -c;
    const double y = cp * y0 - sp * z0 + skew, zz = sp * y0 + cp * z0 + z; // pitch about the radial (x) axis
    soup.points.emplace_back(ca * x - sa * y, sa * x + ca * y, zz);
  }
  // Faces of the box [x-, x+] x [y-, y+] x [z-, z+], outward.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads) {
    soup.triangles.push_back({first + std::size_t(q[0]), first + std::size_t(q[1]), first + std::size_t(q[2])});
    soup.triangles.push_back({first + std::size_t(q[0]), first + std::size_t(q[2]), first + std::size_t(q[3])});
  }
}

// A propeller: a tapered hub (a frustum of 8k sides) and k blades pitched by 30 degrees about
// their radial lines, above the hub's middle, and skewed (moved along their chord off the
// radial line). Its symmetries: the k-fold axis z; no mirror plane (the pitch); no 2-fold axis
// across z (the taper, and the skew: a flip about a horizontal axis would skew the blades the
// other way).
template <typename Mesh>
Mesh propeller(int k)
{
  Soup soup;
  const int sides = 8 * k;
  soup.add_closed_rings(2, sides, [&](int l, int i) {
    const double r = l == 0 ? 0.32 : 0.22, a = 2. * CGAL_PI * double(i) / double(sides);
    return Point_3(r * std::cos(a), r * std::sin(a), l == 0 ? -0.3 : 0.3);
  }, Point_3(0, 0, -0.3), Point_3(0, 0, 0.3));
  for(int j = 0; j < k; ++j)
    add_blade(soup, 0.38, 0.14, 0.025, 0.62, 0.08, 2. * CGAL_PI * double(j) / double(k), CGAL_PI / 6., 0.1);
  return soup.mesh<Mesh>();
}

// A vase: the profile r(z) = 0.55 + 0.2 sin(5 z + 0.5) + 0.1 z, z in [-0.8, 0.8], turned about
// z in `segments` sides and closed at both ends. With 96 sides, its facets deviate from the
// surface of revolution by at most 5e-4 of the radius.
template <typename Mesh>
Mesh vase(int segments = 96, int rings = 24)
{
  Soup soup;
  soup.add_closed_rings(rings, segments, [&](int l, int i) {
    const double z = -0.8 + 1.6 * double(l) / double(rings - 1), r = 0.55 + 0.2 * std::sin(5. * z + 0.5) + 0.1 * z;
    const double a = 2. * CGAL_PI * double(i) / double(segments);
    return Point_3(r * std::cos(a), r * std::sin(a), z);
  }, Point_3(0, 0, -0.8), Point_3(0, 0, 0.8));
  return soup.mesh<Mesh>();
}

inline Line_3 z_axis() { return Line_3(Point_3(0, 0, 0), Vector_3(0, 0, 1)); }

inline Line_3 moved(const Line_3& line, const Motion& m)
{
  return Line_3(m.transform(line.point()), m.transform(line.to_vector()));
}

} // namespace st_test

#endif // CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_TEST_SHAPES_H
