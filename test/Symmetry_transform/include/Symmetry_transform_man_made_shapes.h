// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Man-made objects built in code, with the perfect symmetries of the thesis's models (Princeton
// Shape Benchmark: chairs, tables, mugs, cars, airplanes, lamps, ...): each is a union of closed
// parts put side by side (boxes, prisms, solids of revolution, tori), overlapping where they meet,
// in one Surface_mesh (a soup of closed components, as the GEDT and a ray tracer take it). Every
// shape is built in its true frame: x across its left-right plane, y from back to front, z up
// (what a person would choose), the exact planes of symmetry listed with it.

#ifndef CGAL_SYMMETRY_TRANSFORM_MAN_MADE_SHAPES_H
#define CGAL_SYMMETRY_TRANSFORM_MAN_MADE_SHAPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace st_man_made {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef K::Plane_3 Plane_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;

// A shape and what it has by construction: its exact planes of symmetry (unit normals).
struct Man_made_shape
{
  std::string name;
  Surface_mesh mesh;
  std::vector<Plane_3> planes;
};

// Closed parts accumulated as a soup of triangles, made a mesh at the end.
class Parts
{
public:
  // A prism: the convex polygon `base` (counter-clockwise seen from the side `extrusion` points
  // to) swept along `extrusion`.
  void prism(const std::vector<Point_3>& base, const Vector_3& extrusion)
  {
    const std::size_t n = base.size(), first = points_.size();
    for(const Point_3& p : base) points_.push_back(p);
    for(const Point_3& p : base) points_.push_back(p + extrusion);
    for(std::size_t i = 1; i + 1 < n; ++i) {
      triangles_.push_back({first, first + i + 1, first + i});
      triangles_.push_back({first + n, first + n + i, first + n + i + 1});
    }
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      triangles_.push_back({first + i, first + j, first + n + j});
      triangles_.push_back({first + i, first + n + j, first + n + i});
    }
  }

  // An axis-aligned box of centre `c` and half-sides `h`.
  void box(const Point_3& c, const Vector_3& h)
  {
    prism({c + Vector_3(-h.x(), -h.y(), -h.z()), c + Vector_3(h.x(), -h.y(), -h.z()), c + Vector_3(h.x(), h.y(), -h.z()),
           c + Vector_3(-h.x(), h.y(), -h.z())},
          Vector_3(0, 0, 2. * h.z()));
  }

  // A solid of revolution about the axis from `base` along `axis` (unit): the profile gives
  // (height along the axis, radius) from bottom to top; an end of radius 0 is a pole, one of
  // positive radius a flat cap. `scale_x` and `scale_y` stretch it across the axis (ellipsoids).
  void lathe(const Point_3& base, const Vector_3& axis, const std::vector<std::pair<double, double>>& profile,
             int sides = 32, double scale_1 = 1., double scale_2 = 1.)
  {
    const std::array<Vector_3, 2> e = across(axis);
    std::vector<std::size_t> rings;
    for(const auto& [h, r] : profile) {
      rings.push_back(points_.size());
      const int count = r > 0. ? sides : 1;
      for(int j = 0; j < count; ++j) {
        const double a = 2. * CGAL_PI * j / sides;
        points_.push_back(base + h * axis + r * scale_1 * std::cos(a) * e[0] + r * scale_2 * std::sin(a) * e[1]);
      }
    }
    const auto at = [&](std::size_t k, int j) {
      return profile[k].second > 0. ? rings[k] + std::size_t(j % sides) : rings[k];
    };
    for(std::size_t k = 0; k + 1 < profile.size(); ++k)
      for(int j = 0; j < sides; ++j) {
        if(profile[k].second > 0.) triangles_.push_back({at(k, j), at(k, j + 1), at(k + 1, j + 1)});
        if(profile[k + 1].second > 0.) triangles_.push_back({at(k, j), at(k + 1, j + 1), at(k + 1, j)});
      }
    cap(base + profile.front().first * axis, rings.front(), profile.front().second, sides, true);
    cap(base + profile.back().first * axis, rings.back(), profile.back().second, sides, false);
  }

  // A cylinder of radius r from `a` to `b`.
  void cylinder(const Point_3& a, const Point_3& b, double r, int sides = 32)
  {
    const double length = std::sqrt((b - a).squared_length());
    lathe(a, (b - a) / length, {{0., r}, {length, r}}, sides);
  }

  // An ellipsoid of centre c and half-axes (rx, ry, rz) along x, y, z.
  void ellipsoid(const Point_3& c, double rx, double ry, double rz, int rows = 16)
  {
    std::vector<std::pair<double, double>> profile;
    for(int k = 0; k <= rows; ++k) {
      const double t = CGAL_PI * (1. - double(k) / rows);
      profile.emplace_back(rz * std::cos(t), k == 0 || k == rows ? 0. : std::sin(t));
    }
    lathe(c, Vector_3(0, 0, 1), profile, 32, rx, ry);
  }

  // A torus of centre c in the plane spanned by e1, e2 (unit, orthogonal), radii R and r, over the
  // angles [from, to] (radians) of the circle of radius R; a whole turn is closed.
  void torus(const Point_3& c, const Vector_3& e1, const Vector_3& e2, double R, double r, double from = 0.,
             double to = 2. * CGAL_PI, int along = 32, int around = 12)
  {
    const Vector_3 normal = CGAL::cross_product(e1, e2);
    const bool closed = to - from >= 2. * CGAL_PI - 1e-12;
    const int rows = closed ? along : along + 1;
    const std::size_t first = points_.size();
    for(int i = 0; i < rows; ++i) {
      const double u = from + (to - from) * i / along;
      const Vector_3 radial = std::cos(u) * e1 + std::sin(u) * e2;
      for(int j = 0; j < around; ++j) {
        const double v = 2. * CGAL_PI * j / around;
        points_.push_back(c + (R + r * std::cos(v)) * radial + r * std::sin(v) * normal);
      }
    }
    const auto at = [&](int i, int j) { return first + std::size_t((i % rows) * around + (j % around)); };
    for(int i = 0; i < along; ++i)
      for(int j = 0; j < around; ++j) {
        triangles_.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        triangles_.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }

  // A wheel: a cylinder of radius r and width w about the x axis, centred on c.
  void wheel(const Point_3& c, double r, double w) { cylinder(c - Vector_3(w / 2, 0, 0), c + Vector_3(w / 2, 0, 0), r, 24); }

  Surface_mesh mesh() const
  {
    Surface_mesh m;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points_, triangles_, m);
    return m;
  }

private:
  static std::array<Vector_3, 2> across(const Vector_3& axis)
  {
    const Vector_3 helper = std::abs(axis.x()) < 0.9 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
    Vector_3 e1 = CGAL::cross_product(helper, axis);
    e1 = e1 / std::sqrt(e1.squared_length());
    return {e1, CGAL::cross_product(axis, e1)};
  }

  void cap(const Point_3& centre, std::size_t ring, double r, int sides, bool bottom)
  {
    if(!(r > 0.)) return;
    const std::size_t c = points_.size();
    points_.push_back(centre);
    for(int j = 0; j < sides; ++j) {
      const std::size_t a = ring + std::size_t(j), b = ring + std::size_t((j + 1) % sides);
      triangles_.push_back(bottom ? std::array<std::size_t, 3>{c, b, a} : std::array<std::size_t, 3>{c, a, b});
    }
  }

  std::vector<Point_3> points_;
  std::vector<std::array<std::size_t, 3>> triangles_;
};

inline const Plane_3 left_right(1, 0, 0, 0), front_back(0, 1, 0, 0);

// Four legs at (+-x, +-y), from the floor (z = 0) to height h, of half-width w.
inline void four_legs(Parts& p, double x, double y, double h, double w)
{
  for(double sx : {-1., 1.})
    for(double sy : {-1., 1.}) p.box(Point_3(sx * x, sy * y, h / 2), Vector_3(w, w, h / 2));
}

inline Man_made_shape chair(bool arms)
{
  Parts p;
  four_legs(p, 0.4, 0.4, 0.9, 0.04);
  p.box(Point_3(0, 0, 0.95), Vector_3(0.46, 0.46, 0.05));   // seat
  p.box(Point_3(0, -0.42, 1.55), Vector_3(0.46, 0.04, 0.55)); // back
  if(arms)
    for(double s : {-1., 1.}) {
      p.box(Point_3(s * 0.43, 0.3, 1.15), Vector_3(0.03, 0.03, 0.17));
      p.box(Point_3(s * 0.43, -0.05, 1.33), Vector_3(0.05, 0.4, 0.03));
    }
  return {arms ? "chair_with_arms" : "chair", p.mesh(), {left_right}};
}

inline Man_made_shape stool()
{
  Parts p;
  four_legs(p, 0.25, 0.25, 1.0, 0.03);
  p.lathe(Point_3(0, 0, 1.0), Vector_3(0, 0, 1), {{0., 0.4}, {0.08, 0.4}});
  return {"stool", p.mesh(), {left_right, front_back}};
}

inline Man_made_shape table(double half_length, double half_width, const std::string& name)
{
  Parts p;
  four_legs(p, half_length - 0.1, half_width - 0.1, 1.4, 0.05);
  p.box(Point_3(0, 0, 1.45), Vector_3(half_length, half_width, 0.05));
  return {name, p.mesh(), {left_right, front_back}};
}

inline Man_made_shape round_table()
{
  Parts p;
  p.lathe(Point_3(0, 0, 0), Vector_3(0, 0, 1), {{0., 0.5}, {0.06, 0.5}, {0.1, 0.08}, {1.4, 0.08}, {1.4, 1.0}, {1.5, 1.0}}, 48);
  for(double s : {-1., 1.}) p.box(Point_3(0, s * 0.3, 1.3), Vector_3(0.05, 0.3, 0.04)); // braces under the top
  return {"round_table", p.mesh(), {left_right, front_back}};
}

inline Man_made_shape mug(bool handle)
{
  Parts p;
  p.lathe(Point_3(0, 0, 0), Vector_3(0, 0, 1), {{0., 0.5}, {1.2, 0.5}, {1.2, 0.44}, {0.08, 0.44}}, 48);
  if(handle)
    p.torus(Point_3(0, 0.5, 0.62), Vector_3(0, 1, 0), Vector_3(0, 0, 1), 0.3, 0.06, -CGAL_PI / 2, CGAL_PI / 2);
  return {handle ? "mug" : "cup", p.mesh(), {left_right}};
}

// A solid of revolution about the z axis, from its profile (height, radius) pairs.
inline Man_made_shape turned(const std::string& name, const std::vector<std::pair<double, double>>& profile)
{
  Parts p;
  p.lathe(Point_3(0, 0, 0), Vector_3(0, 0, 1), profile);
  return {name, p.mesh(), {left_right, front_back}};
}

inline Man_made_shape bottle()
{
  return turned("bottle", {{0., 0.35}, {1.3, 0.35}, {1.6, 0.12}, {2.0, 0.12}, {2.0, 0.14}, {2.1, 0.14}});
}

inline Man_made_shape wine_glass()
{
  return turned("wine_glass", {{0., 0.35}, {0.04, 0.35}, {0.08, 0.04}, {0.8, 0.04}, {0.9, 0.3}, {1.3, 0.4}, {1.5, 0.36}});
}

inline Man_made_shape floor_lamp()
{
  return turned("floor_lamp", {{0., 0.35}, {0.08, 0.35}, {0.08, 0.03}, {2.2, 0.03}, {2.2, 0.45}, {2.7, 0.25}});
}

inline Man_made_shape desk_lamp()
{
  Parts p;
  p.box(Point_3(0, 0, 0.05), Vector_3(0.3, 0.4, 0.05));
  p.cylinder(Point_3(0, -0.25, 0.08), Point_3(0, 0.1, 0.9), 0.04, 16);
  p.cylinder(Point_3(0, 0.1, 0.9), Point_3(0, 0.55, 0.7), 0.035, 16);
  p.lathe(Point_3(0, 0.55, 0.7), Vector_3(0, 0, -1), {{-0.1, 0.06}, {0.25, 0.22}});
  return {"desk_lamp", p.mesh(), {left_right}};
}

inline Man_made_shape car(bool truck)
{
  Parts p;
  const double length = truck ? 1.6 : 1.0;
  p.box(Point_3(0, 0, 0.45), Vector_3(0.45, length, 0.2)); // body
  if(truck) {
    p.box(Point_3(0, 1.15, 0.95), Vector_3(0.43, 0.35, 0.3));  // cab
    p.box(Point_3(0, -0.4, 1.05), Vector_3(0.47, 1.15, 0.4));  // cargo box
  } else {
    p.prism({Point_3(-0.4, -0.5, 0.65), Point_3(-0.4, 0.35, 0.65), Point_3(-0.4, 0.15, 0.95), Point_3(-0.4, -0.35, 0.95)},
            Vector_3(0.8, 0, 0)); // cabin, a trapezoid across
  }
  for(double y : truck ? std::vector<double>{1.15, -0.3, -1.05} : std::vector<double>{0.65, -0.65})
    for(double s : {-1., 1.}) p.wheel(Point_3(s * 0.43, y, 0.25), 0.25, 0.14);
  return {truck ? "truck" : "car", p.mesh(), {left_right}};
}

inline Man_made_shape airplane(bool glider)
{
  Parts p;
  const double span = glider ? 2.4 : 1.5;
  p.lathe(Point_3(0, -1.2, 0.5), Vector_3(0, 1, 0), {{0., 0.}, {0.15, 0.1}, {1.8, 0.17}, {2.2, 0.15}, {2.5, 0.}}, 24);
  p.prism({Point_3(-span, 0.1, 0.5), Point_3(-span, 0.3, 0.5), Point_3(-0.1, 0.6, 0.5), Point_3(-0.1, 0.1, 0.5)},
          Vector_3(0, 0, 0.04));
  p.prism({Point_3(span, 0.3, 0.5), Point_3(span, 0.1, 0.5), Point_3(0.1, 0.1, 0.5), Point_3(0.1, 0.6, 0.5)},
          Vector_3(0, 0, 0.04));
  p.box(Point_3(0, -1.05, 0.55), Vector_3(0.5, 0.12, 0.02));                                                 // stabiliser
  p.prism({Point_3(-0.02, -1.2, 0.6), Point_3(-0.02, -0.85, 0.6), Point_3(-0.02, -1.15, 1.0)}, Vector_3(0.04, 0, 0)); // fin
  if(!glider)
    for(double s : {-1., 1.}) p.cylinder(Point_3(s * 0.6, 0.0, 0.42), Point_3(s * 0.6, 0.55, 0.42), 0.08, 16);
  return {glider ? "glider" : "airplane", p.mesh(), {left_right}};
}

inline Man_made_shape bed()
{
  Parts p;
  four_legs(p, 0.65, 1.05, 0.25, 0.05);
  p.box(Point_3(0, 0, 0.4), Vector_3(0.7, 1.1, 0.15));       // frame and mattress
  p.box(Point_3(0, -1.12, 0.7), Vector_3(0.72, 0.04, 0.45)); // headboard
  p.box(Point_3(0, 1.12, 0.5), Vector_3(0.72, 0.04, 0.25));  // footboard
  return {"bed", p.mesh(), {left_right}};
}

inline Man_made_shape sofa()
{
  Parts p;
  p.box(Point_3(0, 0, 0.3), Vector_3(1.0, 0.45, 0.2));    // seat
  p.box(Point_3(0, -0.38, 0.75), Vector_3(1.0, 0.1, 0.3)); // back
  for(double s : {-1., 1.}) p.box(Point_3(s * 1.05, 0, 0.45), Vector_3(0.1, 0.45, 0.3));
  for(double sx : {-1., 1.})
    for(double sy : {-1., 1.}) p.box(Point_3(sx * 1.0, sy * 0.38, 0.05), Vector_3(0.05, 0.05, 0.05));
  return {"sofa", p.mesh(), {left_right}};
}

inline Man_made_shape bookshelf()
{
  Parts p;
  for(double s : {-1., 1.}) p.box(Point_3(s * 0.5, 0, 1.0), Vector_3(0.03, 0.2, 1.0));
  for(double z : {0.05, 0.55, 1.05, 1.55, 1.97}) p.box(Point_3(0, 0, z), Vector_3(0.5, 0.2, 0.03));
  p.box(Point_3(0, -0.19, 1.0), Vector_3(0.5, 0.01, 1.0)); // back
  return {"bookshelf", p.mesh(), {left_right}};
}

inline Man_made_shape bench()
{
  Parts p;
  p.box(Point_3(0, 0, 0.5), Vector_3(1.0, 0.22, 0.04));
  for(double s : {-1., 1.}) p.box(Point_3(s * 0.8, 0, 0.24), Vector_3(0.04, 0.2, 0.24));
  p.box(Point_3(0, 0, 0.2), Vector_3(0.8, 0.03, 0.03)); // stretcher
  return {"bench", p.mesh(), {left_right, front_back}};
}

inline Man_made_shape mailbox()
{
  Parts p;
  p.box(Point_3(0, 0, 0.6), Vector_3(0.05, 0.05, 0.6));                                       // post
  p.box(Point_3(0, 0.1, 1.3), Vector_3(0.2, 0.45, 0.1));                                     // box
  p.lathe(Point_3(0, -0.35, 1.4), Vector_3(0, 1, 0), {{0., 0.2}, {0.9, 0.2}}, 32, 1., 1.); // rounded top
  p.box(Point_3(0.22, 0.4, 1.45), Vector_3(0.01, 0.02, 0.12));                                 // flag
  return {"mailbox", p.mesh(), {}};
}

inline Man_made_shape rocket()
{
  Parts p;
  p.lathe(Point_3(0, 0, 0.2), Vector_3(0, 0, 1), {{0., 0.2}, {1.8, 0.2}, {2.4, 0.}}, 32);
  for(int k = 0; k < 4; ++k) {
    const double a = k * CGAL_PI / 2;
    const Vector_3 out(std::cos(a), std::sin(a), 0), side(-std::sin(a), std::cos(a), 0);
    const Point_3 o = CGAL::ORIGIN - 0.015 * side; // fins 0.03 thick, centred on their plane
    p.prism({o + 0.18 * out, o + 0.55 * out, o + 0.18 * out + Vector_3(0, 0, 0.8)}, 0.03 * side);
  }
  return {"rocket", p.mesh(), {left_right, front_back}};
}

inline Man_made_shape dumbbell()
{
  Parts p;
  p.cylinder(Point_3(-0.8, 0, 0.3), Point_3(0.8, 0, 0.3), 0.05, 16);
  for(double s : {-1., 1.}) p.ellipsoid(Point_3(s * 0.8, 0, 0.3), 0.25, 0.3, 0.3);
  return {"dumbbell", p.mesh(), {left_right, front_back}};
}

inline Man_made_shape teapot()
{
  Parts p;
  p.ellipsoid(Point_3(0, 0, 0.5), 0.6, 0.6, 0.45);
  p.cylinder(Point_3(0, 0.45, 0.45), Point_3(0, 0.95, 0.85), 0.06, 16);                                 // spout
  p.torus(Point_3(0, -0.6, 0.55), Vector_3(0, -1, 0), Vector_3(0, 0, 1), 0.22, 0.04, -CGAL_PI / 2, CGAL_PI / 2); // handle
  p.lathe(Point_3(0, 0, 0.93), Vector_3(0, 0, 1), {{0., 0.2}, {0.05, 0.2}, {0.05, 0.04}, {0.15, 0.04}, {0.2, 0.}}, 24);
  return {"teapot", p.mesh(), {left_right}};
}

inline Man_made_shape house()
{
  Parts p;
  p.box(Point_3(0, 0, 0.5), Vector_3(0.8, 0.6, 0.5));
  p.prism({Point_3(-0.85, -0.65, 1.0), Point_3(-0.85, 0.65, 1.0), Point_3(-0.85, 0., 1.6)}, Vector_3(1.7, 0, 0));
  p.box(Point_3(0.45, 0.3, 1.5), Vector_3(0.08, 0.08, 0.3)); // chimney
  return {"house_with_chimney", p.mesh(), {}};
}

inline Man_made_shape monitor()
{
  Parts p;
  p.box(Point_3(0, 0, 0.02), Vector_3(0.3, 0.25, 0.02));  // base
  p.box(Point_3(0, -0.05, 0.3), Vector_3(0.05, 0.03, 0.3)); // neck
  p.box(Point_3(0, 0, 0.85), Vector_3(0.7, 0.04, 0.42));   // screen
  return {"monitor", p.mesh(), {left_right}};
}

// The set of the alignment experiment: 26 objects, among them variations of one kind (chairs
// with and without arms, square, long and round tables, a mug and a cup, a car and a truck, an
// airplane and a glider, a floor lamp and a desk lamp).
inline std::vector<std::function<Man_made_shape()>> man_made_shapes()
{
  return {[] { return chair(false); }, [] { return chair(true); }, stool,
          [] { return table(0.8, 0.8, "square_table"); }, [] { return table(1.4, 0.7, "long_table"); }, round_table,
          [] { return mug(true); }, [] { return mug(false); }, bottle, wine_glass, floor_lamp, desk_lamp,
          [] { return car(false); }, [] { return car(true); }, [] { return airplane(false); },
          [] { return airplane(true); }, bed, sofa, bookshelf, bench, mailbox, rocket, dumbbell, teapot, house,
          monitor};
}

} // namespace st_man_made

#endif // CGAL_SYMMETRY_TRANSFORM_MAN_MADE_SHAPES_H
