// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_VERTEX_ORBITS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_VERTEX_ORBITS_H

// Vertices that a symmetry maps onto vertices. A mesh whose two sides were tessellated alike
// (modelled symmetric, then edited on one side) keeps its vertices in pairs: the image of a
// vertex under each motion of the group lies near another vertex, nearer than half the shortest
// edge there. Such vertices are symmetrized exactly (orbit_average()); the others follow the
// surface (symmetrize_surface.h).

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/symmetry_group.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// An image is the vertex it lands near if it is within this fraction of the shortest edge there.
constexpr double pairing_fraction_of_edge = 0.5;
constexpr std::size_t no_vertex = std::numeric_limits<std::size_t>::max();

// The shortest edge at each vertex (infinite at a vertex of no face).
inline std::vector<double> shortest_edges(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<std::array<std::size_t, 3>>& faces)
{
  std::vector<double> shortest(points.size(), std::numeric_limits<double>::infinity());
  for(const auto& f : faces)
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = f[k], b = f[(k + 1) % 3];
      const double length = (points[a] - points[b]).norm();
      if(length == 0.) continue; // a degenerate face
      shortest[a] = (std::min)(shortest[a], length);
      shortest[b] = (std::min)(shortest[b], length);
    }
  return shortest;
}

// The vertex nearest to the image of each point under each generator of the group (indexed by
// element; empty for the others): the pairs, and where the searches on the surface start.
typedef std::vector<std::vector<Nearest_point::Answer>> Generator_images;

inline Generator_images generator_images(const std::vector<Eigen::Vector3d>& points, const Symmetry_group& group,
                                         const Nearest_point& nearest, unsigned threads)
{
  Generator_images images(group.motions.size());
  for(std::size_t s : group.generator_element) {
    if(!images[s].empty()) continue;
    images[s].resize(points.size());
    parallel_for(points.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end && parallel_step(); ++i) images[s][i] = nearest(group.motions[s](points[i]));
    });
    throw_if_cancelled();
  }
  return images;
}

// image[i]: the vertex near the image of vertex i (within pairing_fraction_of_edge of the
// shortest edge there), or no_vertex.
inline std::vector<std::size_t> vertex_images(const std::vector<Nearest_point::Answer>& nearest_images,
                                              const std::vector<double>& shortest_edge)
{
  std::vector<std::size_t> image(nearest_images.size(), no_vertex);
  for(std::size_t i = 0; i < image.size(); ++i) {
    const Nearest_point::Answer& a = nearest_images[i];
    const double reach = pairing_fraction_of_edge * shortest_edge[a.index];
    if(a.squared_distance < reach * reach) image[i] = a.index;
  }
  return image;
}

// The permutation of the vertices under every element of the group, where the images of each
// generator land on vertices (no_vertex elsewhere), composed along the multiplication table.
// `shortest`: the shortest edge at each vertex (the spacing at each point of a point set).
inline std::vector<std::vector<std::size_t>> vertex_permutations(const std::vector<double>& shortest,
                                                                 const Symmetry_group& group,
                                                                 const Generator_images& images)
{
  const std::size_t n = shortest.size(), elements = group.motions.size();
  std::vector<std::vector<std::size_t>> permutation(elements);
  permutation[0].resize(n);
  for(std::size_t i = 0; i < n; ++i) permutation[0][i] = i;
  // Breadth first from the identity, as the group was generated: each element from a known one.
  std::vector<std::vector<std::size_t>> step(elements);
  for(std::size_t s : group.generator_element)
    if(step[s].empty()) step[s] = vertex_images(images[s], shortest);
  std::vector<bool> known(elements, false);
  known[0] = true;
  std::vector<std::size_t> order{0};
  for(std::size_t next = 0; next < order.size(); ++next)
    for(std::size_t s : group.generator_element) {
      const std::size_t h = order[next], g = group.product[s][h];
      if(known[g]) continue;
      known[g] = true;
      order.push_back(g);
      permutation[g].assign(n, no_vertex);
      for(std::size_t i = 0; i < n; ++i)
        if(permutation[h][i] != no_vertex) permutation[g][i] = step[s][permutation[h][i]];
    }
  return permutation;
}

// Whether vertex i's orbit is paired consistently: every element maps it, and composing with
// each generator agrees with the table.
inline std::vector<bool> consistent_vertices(const std::vector<std::vector<std::size_t>>& permutation,
                                             const Symmetry_group& group)
{
  const std::size_t n = permutation[0].size();
  std::vector<bool> consistent(n, true);
  for(std::size_t g = 0; g < permutation.size(); ++g)
    for(std::size_t i = 0; i < n; ++i) {
      if(permutation[g][i] == no_vertex) {
        consistent[i] = false;
        continue;
      }
      for(std::size_t s : group.generator_element) {
        const std::size_t sg = group.product[s][g], j = permutation[g][i];
        if(permutation[s][j] == no_vertex || permutation[s][j] != permutation[sg][i]) consistent[i] = false;
      }
    }
  // An orbit is kept whole or not at all.
  for(bool changed = true; changed;) {
    changed = false;
    for(std::size_t g = 0; g < permutation.size(); ++g)
      for(std::size_t i = 0; i < n; ++i)
        if(consistent[i] && !consistent[permutation[g][i]]) consistent[i] = false, changed = true;
  }
  return consistent;
}

// The motion whose linear part has the determinant of `given`'s that maps the points x_i onto
// y_i = points[image[i]] best in the least squares, over the vertices where `use`: Eigen's
// umeyama() fits the rotation Q from given.linear x_i to y_i, and Q given.linear keeps the
// determinant (a reflection stays one).
inline Rigid_motion fitted_motion(const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& image,
                                  const std::vector<bool>& use, const Rigid_motion& given)
{
  const auto count = Eigen::Index(std::count(use.begin(), use.end(), true));
  Eigen::Matrix3Xd from(3, count), to(3, count);
  for(std::size_t i = 0, k = 0; i < points.size(); ++i)
    if(use[i]) {
      from.col(Eigen::Index(k)) = given.linear * points[i];
      to.col(Eigen::Index(k++)) = points[image[i]];
    }
  const Eigen::Matrix4d fit = Eigen::umeyama(from, to, false);
  Rigid_motion m;
  m.linear = fit.topLeftCorner<3, 3>() * given.linear;
  m.translation = fit.topRightCorner<3, 1>();
  return m;
}

// Whether the paired points fix a motion: they span a plane at least (the second moment of
// their spread, in radii squared, above min_spread_for_fit), else a turn about their line is free.
constexpr double min_spread_for_fit = 1e-6;
inline bool pairs_fix_a_motion(const std::vector<Eigen::Vector3d>& points, const std::vector<bool>& paired)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(paired[i]) mean += points[i], ++count;
  if(count < 3) return false;
  mean /= double(count);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < points.size(); ++i)
    if(paired[i]) spread += (points[i] - mean) * (points[i] - mean).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(spread / double(count));
  return svd.singularValues()[1] > min_spread_for_fit;
}

// Each motion of the group refitted to the vertex pairs it makes, so that the symmetries are
// those of the mesh itself: a plane detected on a perturbed mesh, or given slightly off, costs no
// displacement (a mirror pair meets halfway about the plane that fits the pairs best).
inline void refit_motions(Symmetry_group& group, const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::vector<std::size_t>>& permutation, const std::vector<bool>& paired)
{
  if(!pairs_fix_a_motion(points, paired)) return;
  for(std::size_t g = 1; g < group.motions.size(); ++g)
    group.motions[g] = fitted_motion(points, permutation[g], paired, group.motions[g]);
}

// The orbit average of vertex i: the mean over the group of g^-1(points[perm_g(i)]). On a
// consistent orbit, the averages are exactly the images of each other (an orthogonal projection
// onto the symmetric positions: the smallest displacement in the sum of squares).
inline Eigen::Vector3d orbit_average(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::vector<std::size_t>>& permutation,
                                     const std::vector<Rigid_motion>& inverse_motions, std::size_t i)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for(std::size_t g = 0; g < permutation.size(); ++g) sum += inverse_motions[g](points[permutation[g][i]]);
  return sum / double(permutation.size());
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_VERTEX_ORBITS_H
