// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H

// The AABB tree of the triangles of a shape, for the closest-point searches of the distance
// transform and of Iterative Symmetric Points.

#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <CGAL/Bbox_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

#include <cstddef>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The point of triangle abc closest to p, by the Voronoi region of the triangle that p projects
// into (vertex, edge or face): a few dot products, no plane constructed, hence about four
// times cheaper than the kernel's projection, which constructs the plane of the triangle (most
// of the cost of a closest-point search).
inline Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if(d1 <= 0. && d2 <= 0.) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if(d3 >= 0. && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if(d6 >= 0. && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = va + vb + vc;
  if(!(denominator > 0.)) return a; // no area (triangles_of_mesh leaves such triangles out)
  return a + (vb / denominator) * ab + (vc / denominator) * ac;
}

// A triangle of a soup as the AABB tree holds it: whole, or one of the pieces of a fat one
// (triangle_pieces()). The searches measure the distance to the whole triangle, so a piece only
// narrows the box that the tree prunes with.
struct Triangle_piece
{
  std::vector<Dtriangle>::const_iterator triangle;
  CGAL::Bbox_3 box;
  Dpoint reference; // a point of the triangle: the tree splits by it and may start a search there
  CGAL::Bbox_3 bbox() const { return box; }
};

// The primitive of a Triangle_piece: its Id is the whole triangle, so that every search returns
// the triangle of the soup, whether it was cut or not.
class Triangle_piece_primitive
{
public:
  typedef Dpoint Point;
  typedef Triangle_piece Datum;
  typedef std::vector<Dtriangle>::const_iterator Id;
  typedef const Datum& Datum_reference;
  typedef const Point& Point_reference;

  Triangle_piece_primitive() = default;
  explicit Triangle_piece_primitive(std::vector<Triangle_piece>::const_iterator piece) : piece_(piece) {}
  Datum_reference datum() const { return *piece_; }
  Id id() const { return piece_->triangle; }
  Point_reference reference_point() const { return piece_->reference; }

private:
  std::vector<Triangle_piece>::const_iterator piece_;
};

// A search tests every triangle whose box holds its query, however far the triangle is. On a
// surface, few boxes overlap: on average a point of the soup's box lies in at most 12 of them on
// every libcgal-demo mesh (pinion.off; bull.off 0.08). Large faces across the inside of a web
// model put a point in hundreds (2000 random triangles in bull.off's box: 259). Beyond this mean
// overlap, the fat triangles are cut into pieces; below, the tree is that of the triangles.
constexpr double box_overlap_left_whole = 32.;
// A piece is fat when the smallest extent of its box exceeds this fraction of the soup's box
// diagonal: a thin box (a small or an axis-aligned triangle) is visited only near its triangle.
// (Finer pieces, 1/64 and 1/128, gain little more and cost memory: RESULTS.md, issue 14.)
constexpr double fat_triangle_extent = 1. / 32.;

inline double smallest_extent(const CGAL::Bbox_3& box)
{
  return (std::min)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
}

inline double volume(const CGAL::Bbox_3& box)
{
  return (box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) * (box.zmax() - box.zmin());
}

// Cuts triangle abc 1-to-4 at its midpoints until its pieces are not fat, appending them.
inline void append_pieces(std::vector<Dtriangle>::const_iterator triangle, const Dpoint& a, const Dpoint& b,
                          const Dpoint& c, double fat, std::vector<Triangle_piece>& pieces)
{
  const CGAL::Bbox_3 box = a.bbox() + b.bbox() + c.bbox();
  if(!(smallest_extent(box) > fat)) {
    pieces.push_back({triangle, box, CGAL::centroid(a, b, c)});
    return;
  }
  const Dpoint ab = CGAL::midpoint(a, b), bc = CGAL::midpoint(b, c), ca = CGAL::midpoint(c, a);
  append_pieces(triangle, a, ab, ca, fat, pieces);
  append_pieces(triangle, ab, b, bc, fat, pieces);
  append_pieces(triangle, ca, bc, c, fat, pieces);
  append_pieces(triangle, ab, bc, ca, fat, pieces);
}

// The primitives of the AABB tree of `triangles`: each triangle whole (its box, its first corner
// as reference, as CGAL's AABB_triangle_primitive), unless their boxes overlap more than
// box_overlap_left_whole on average; then the fat ones are cut.
inline std::vector<Triangle_piece> triangle_pieces(const std::vector<Dtriangle>& triangles)
{
  CGAL::Bbox_3 all;
  double overlap = 0.;
  for(const Dtriangle& t : triangles) {
    all += t.bbox();
    overlap += volume(t.bbox());
  }
  const bool cut = overlap > box_overlap_left_whole * volume(all); // false on a flat soup (volume 0)
  const double fat = fat_triangle_extent * std::sqrt(CGAL::square(all.xmax() - all.xmin()) +
                                                     CGAL::square(all.ymax() - all.ymin()) +
                                                     CGAL::square(all.zmax() - all.zmin()));
  std::vector<Triangle_piece> pieces;
  pieces.reserve(triangles.size());
  for(auto t = triangles.begin(); t != triangles.end(); ++t) {
    if(cut && smallest_extent(t->bbox()) > fat)
      append_pieces(t, (*t)[0], (*t)[1], (*t)[2], fat, pieces);
    else
      pieces.push_back({t, t->bbox(), (*t)[0]});
  }
  return pieces;
}

// CGAL's AABB traits of triangle pieces, with the closest point of a triangle by
// closest_point_on_triangle().
class Triangle_tree_traits : public CGAL::AABB_traits<Dkernel, Triangle_piece_primitive>
{
public:
  struct Closest_point
  {
    // The closest point of the piece's whole triangle if it is closer to p than `bound`, else `bound`.
    Dpoint operator()(const Dpoint& p, const Triangle_piece_primitive& primitive, const Dpoint& bound) const
    {
      const Dtriangle& t = *primitive.id();
      const Eigen::Vector3d c = closest_point_on_triangle(to_eigen(p), to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2]));
      const Dpoint closest(c.x(), c.y(), c.z());
      return CGAL::squared_distance(p, closest) > CGAL::squared_distance(p, bound) ? bound : closest;
    }
  };

  Closest_point closest_point_object() const { return Closest_point(); }
};

typedef CGAL::AABB_tree<Triangle_tree_traits> Triangle_tree;

// The progress is polled before each split of at least this many triangles (the top splits,
// which partially sort up to all of them), and every tree_splits_per_poll smaller splits.
constexpr std::ptrdiff_t tree_large_split = 4096;
constexpr std::size_t tree_splits_per_poll = 64;

// tree.build(), the same splits, with calls to the progress callback while it builds (progress.h):
// a tree of a million triangles takes a second. The search structure of its distance queries
// (accelerate_distance_queries()) has no such hook.
inline void build_triangle_tree(Triangle_tree& tree)
{
  if(active_progress == nullptr) {
    tree.build();
    return;
  }
  const auto split = tree.traits().split_primitives_object();
  std::size_t splits = 0;
  tree.custom_build(tree.traits().compute_bbox_object(),
                    [&](auto first, auto beyond, const typename Triangle_tree_traits::Bounding_box& box) {
                      if(beyond - first >= tree_large_split || ++splits % tree_splits_per_poll == 0) poll_progress();
                      split(first, beyond, box);
                    });
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H
