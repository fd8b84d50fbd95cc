// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_SYMMETRIZE_VERTICES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_SYMMETRIZE_VERTICES_H

// Symmetrization of a triangle mesh given as plain arrays, in the spirit of Golovinskiy, Podolak
// and Funkhouser, "Symmetry-Aware Mesh Processing" (2009): every point and the images of its
// counterparts meet at their mean, so that the surface becomes symmetric while each point moves as
// little as possible. Vertices whose images land on vertices (vertex_orbits.h) take their orbit's
// mean, exactly symmetric and the least displacement in the sum of squares. The others, on a mesh
// whose sides are tessellated differently, take the mean of the images of the closest points of
// the surface to their own images, a few times over, the displacement smoothed over the mesh
// between steps so that neighbouring vertices move alike and the mesh does not fold.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/nearby_surface.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/symmetry_group.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/vertex_orbits.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstddef>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Steps of the surface symmetrization of the unpaired vertices: each halves, about, what is left
// of their asymmetry.
constexpr int surface_symmetrization_steps = 6;
// Smoothing of their displacement after each step: steps, and the share of the neighbours' mean.
constexpr int displacement_smoothing_steps = 2;
constexpr double displacement_smoothing_share = 0.5;

// Where a symmetry holds (its support), the vertices move fully; where it does not, not at all.
// A vertex whose images under the generators all lie within support_full_distance of the surface
// (in radii) moves fully; one with an image beyond support_zero_distance stays; in between, its
// move falls off smoothly. Noise, bumps and warps of a few hundredths of the radius are inside;
// a raised arm is outside.
constexpr double support_full_distance = 0.05;
constexpr double support_zero_distance = 0.15;

struct Symmetrized_vertices
{
  std::vector<Eigen::Vector3d> points;
  std::vector<Rigid_motion> motions; // the exact group, motions[0] the identity
  std::vector<std::size_t> generator_element;
  std::vector<bool> paired; // per vertex: symmetrized exactly, with its orbit
};

inline std::vector<std::vector<std::size_t>> vertex_neighbours(std::size_t n,
                                                               const std::vector<std::array<std::size_t, 3>>& faces)
{
  std::vector<std::vector<std::size_t>> neighbours(n);
  for(const auto& f : faces)
    for(int k = 0; k < 3; ++k) {
      neighbours[f[k]].push_back(f[(k + 1) % 3]);
      neighbours[f[(k + 1) % 3]].push_back(f[k]);
    }
  return neighbours;
}

// Each free vertex's displacement from `before` moved towards its neighbours' mean.
inline void smooth_displacements(std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& before,
                                 const std::vector<bool>& fixed, const std::vector<std::vector<std::size_t>>& neighbours)
{
  for(int step = 0; step < displacement_smoothing_steps; ++step) {
    std::vector<Eigen::Vector3d> smoothed = points;
    for(std::size_t i = 0; i < points.size(); ++i) {
      if(fixed[i] || neighbours[i].empty()) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(std::size_t j : neighbours[i]) mean += points[j] - before[j];
      mean /= double(neighbours[i].size());
      const Eigen::Vector3d own = points[i] - before[i];
      smoothed[i] = before[i] + (1. - displacement_smoothing_share) * own + displacement_smoothing_share * mean;
    }
    points = std::move(smoothed);
  }
}

// One step for the unpaired vertices: each takes the mean over the group of g^-1 of the closest
// point of the surface to g(p). `near[i * |G| + g]`: the vertex where the search for the image of
// vertex i under element g starts, kept from step to step.
template <typename Surface>
void surface_symmetrization_step(std::vector<Eigen::Vector3d>& points, const Surface& surface,
                                 const std::vector<bool>& paired, const std::vector<Rigid_motion>& motions,
                                 std::vector<std::size_t>& near, unsigned threads)
{
  std::vector<Rigid_motion> inverse_motions;
  for(const Rigid_motion& m : motions) inverse_motions.push_back(inverse(m));
  std::vector<Eigen::Vector3d> moved = points;
  parallel_for(points.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(); ++i) {
      if(paired[i]) continue;
      Eigen::Vector3d sum = points[i];
      for(std::size_t g = 1; g < motions.size(); ++g)
        sum += inverse_motions[g](surface.closest(motions[g](points[i]), points, near[i * motions.size() + g]));
      moved[i] = sum / double(motions.size());
    }
  });
  throw_if_cancelled();
  points = std::move(moved);
}

// The distinct positions of the vertices, and that of each vertex: coincident vertices (the
// seams of a mesh cut for textures) move as one.
struct Distinct_points
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::size_t> of_vertex;
};

inline Distinct_points distinct_points(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<std::size_t> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto less = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(points[a].data(), points[a].data() + 3, points[b].data(), points[b].data() + 3);
  };
  std::stable_sort(order.begin(), order.end(), less);
  Distinct_points d;
  d.of_vertex.resize(points.size());
  std::vector<std::size_t> first_at(points.size());
  for(std::size_t k = 0; k < order.size(); ++k) {
    if(k == 0 || points[order[k]] != points[order[k - 1]]) first_at[order[k]] = order[k];
    else first_at[order[k]] = first_at[order[k - 1]];
  }
  std::vector<std::size_t> index_of(points.size(), no_vertex);
  for(std::size_t i = 0; i < points.size(); ++i) { // numbered in the order of the vertices
    if(index_of[first_at[i]] == no_vertex) {
      index_of[first_at[i]] = d.points.size();
      d.points.push_back(points[i]);
    }
    d.of_vertex[i] = index_of[first_at[i]];
  }
  return d;
}

// How much of its move each vertex makes: 1 where every generator maps it onto the surface, 0
// where one maps it far from it (see support_full_distance). The searches start at the vertices
// nearest to the images (`images`).
template <typename Surface>
std::vector<double> support_weights(const std::vector<Eigen::Vector3d>& points, const Surface& surface,
                                    const Symmetry_group& group, const Generator_images& images, unsigned threads)
{
  std::vector<double> weight(points.size(), 1.);
  parallel_for(points.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(); ++i) {
      double farthest = 0.;
      for(std::size_t s : group.generator_element) {
        const Eigen::Vector3d image = group.motions[s](points[i]);
        std::size_t start = images[s][i].index;
        farthest = (std::max)(farthest, (image - surface.closest(image, points, start)).norm());
      }
      const double t = std::clamp((support_zero_distance - farthest) / (support_zero_distance - support_full_distance), 0., 1.);
      weight[i] = t * t * (3. - 2. * t); // smoothstep
    }
  });
  throw_if_cancelled();
  return weight;
}

// The paired vertices at their orbit's mean, under the group made exact (symmetrize_near()).
inline Symmetrized_vertices orbit_symmetrized(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<double>& spacing, Symmetry_group group,
                                              const Generator_images& images)
{
  const std::vector<std::vector<std::size_t>> permutation = vertex_permutations(spacing, group, images);
  const std::vector<bool> paired = consistent_vertices(permutation, group);
  refit_motions(group, points, permutation, paired);
  make_group_exact(group);
  std::vector<Rigid_motion> inverse_motions;
  for(const Rigid_motion& m : group.motions) inverse_motions.push_back(inverse(m));
  Symmetrized_vertices result{points, group.motions, group.generator_element, paired};
  for(std::size_t i = 0; i < points.size(); ++i)
    if(paired[i]) result.points[i] = orbit_average(points, permutation, inverse_motions, i);
  return result;
}

// The symmetrization of distinct points on a shape whose surface `surface` finds near a query
// (Nearby_surface for a mesh, Nearby_points for a point set): `spacing` at each point (its shortest
// edge, or its distance to its nearest neighbour) sets how near an image must land to pair, and
// `neighbours()` gives the neighbours of each point for the smoothing (made only if needed).
template <typename Surface, typename Neighbours>
Symmetrized_vertices symmetrize_near(const std::vector<Eigen::Vector3d>& points, const Surface& surface,
                                     const Nearest_point& nearest, const std::vector<double>& spacing,
                                     const Neighbours& neighbours, const std::vector<Rigid_motion>& generators,
                                     bool whole, unsigned threads)
{
  const Symmetry_group group = generated_group(generators); // as given: for the searches
  const Generator_images images = generator_images(points, group, nearest, threads);
  Symmetrized_vertices result = orbit_symmetrized(points, spacing, group, images);
  if(std::find(result.paired.begin(), result.paired.end(), false) != result.paired.end()) {
    const std::vector<std::vector<std::size_t>> around = neighbours();
    const std::size_t elements = result.motions.size();
    std::vector<std::size_t> near(points.size() * elements, Surface::unknown);
    for(std::size_t s : group.generator_element)
      for(std::size_t i = 0; i < points.size(); ++i) near[i * elements + s] = images[s][i].index;
    for(int step = 0; step < surface_symmetrization_steps; ++step) {
      report_progress(step, surface_symmetrization_steps);
      surface_symmetrization_step(result.points, surface, result.paired, result.motions, near, threads);
      smooth_displacements(result.points, points, result.paired, around);
    }
  }
  if(!whole) {
    const std::vector<double> weight = support_weights(points, surface, group, images, threads);
    for(std::size_t i = 0; i < points.size(); ++i) result.points[i] = points[i] + weight[i] * (result.points[i] - points[i]);
  }
  return result;
}

// The symmetrization of the distinct vertices of a mesh (symmetrize_vertices()).
inline Symmetrized_vertices symmetrize_distinct(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::array<std::size_t, 3>>& faces,
                                                const std::vector<Rigid_motion>& generators, bool whole,
                                                unsigned threads)
{
  const Nearest_point nearest(points);
  const Nearby_surface surface(nearest, faces, points.size());
  return symmetrize_near(points, surface, nearest, shortest_edges(points, faces),
                         [&] { return vertex_neighbours(points.size(), faces); }, generators, whole, threads);
}

// `symmetrize(distinct)` on the distinct positions of `points` (Distinct_points), then per point.
template <typename SymmetrizeDistinct>
Symmetrized_vertices on_distinct_points(const std::vector<Eigen::Vector3d>& points, const SymmetrizeDistinct& symmetrize)
{
  const Distinct_points distinct = distinct_points(points);
  Symmetrized_vertices result = symmetrize(distinct);
  std::vector<Eigen::Vector3d> moved(points.size());
  std::vector<bool> paired(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    moved[i] = result.points[distinct.of_vertex[i]];
    paired[i] = result.paired[distinct.of_vertex[i]];
  }
  result.points = std::move(moved);
  result.paired = std::move(paired);
  return result;
}

// `points` (centred, of radius about 1) symmetrized under the group that `generators` generate, on
// the whole mesh or (`whole` false) on the support of the symmetries only.
inline Symmetrized_vertices symmetrize_vertices(const std::vector<Eigen::Vector3d>& points,
                                                std::vector<std::array<std::size_t, 3>> faces,
                                                const std::vector<Rigid_motion>& generators, bool whole,
                                                unsigned threads)
{
  return on_distinct_points(points, [&](const Distinct_points& distinct) {
    for(auto& f : faces)
      for(std::size_t& v : f) v = distinct.of_vertex[v];
    return symmetrize_distinct(distinct.points, faces, generators, whole, threads);
  });
}

// The spacing at a point of a point set, as the shortest edge at a vertex: its distance to this
// nearest neighbour. A random sampling puts some points very near to one another: the nearest
// would make their pairing fail on noise far below the spacing.
constexpr std::size_t pairing_neighbour = 3;

// A point set (centred, of radius about 1, with unit normals or none) symmetrized as
// symmetrize_vertices() does a mesh: a point pairs with the point its images land on (within half
// the distance from that point to its third nearest neighbour); the others move to the mean of the
// images of the surface near their images (Nearby_points).
inline Symmetrized_vertices symmetrize_point_positions(const std::vector<Eigen::Vector3d>& points,
                                                       const std::vector<Eigen::Vector3d>& normals,
                                                       const std::vector<Rigid_motion>& generators, bool whole,
                                                       unsigned threads)
{
  return on_distinct_points(points, [&](const Distinct_points& distinct) {
    std::vector<Eigen::Vector3d> distinct_normals;
    if(!normals.empty()) {
      distinct_normals.resize(distinct.points.size());
      for(std::size_t i = 0; i < points.size(); ++i) distinct_normals[distinct.of_vertex[i]] = normals[i];
    }
    const std::vector<Eigen::Vector3d>& p = distinct.points;
    const Nearest_point nearest(p);
    const Nearby_points surface(nearest, distinct_normals);
    const std::vector<std::vector<std::size_t>> neighbours =
      nearest_neighbourhoods(nearest, p.size(), point_neighbours, threads);
    std::vector<double> spacing(p.size(), std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < p.size(); ++i)
      if(neighbours[i].size() >= pairing_neighbour) spacing[i] = (p[neighbours[i][pairing_neighbour - 1]] - p[i]).norm();
    // No smoothing: points do not fold, and the noise of each point is its own.
    const auto no_neighbours = [&] { return std::vector<std::vector<std::size_t>>(p.size()); };
    return symmetrize_near(p, surface, nearest, spacing, no_neighbours, generators, whole, threads);
  });
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_SYMMETRIZE_VERTICES_H
