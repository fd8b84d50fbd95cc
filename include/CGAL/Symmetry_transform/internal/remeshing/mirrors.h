// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H

// Mirror images in the working mesh of symmetric remeshing: the face that mirrors each face
// through each plane (for the flooding), and the nearest mesh vertex to a point (for the mirror
// images of anchors), both by Kd-tree queries.

#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// The nearest of a set of points to a query (CGAL::Kd_tree), with its index. Queries are
// thread-safe once constructed.
class Nearest_point
{
  typedef CGAL::Search_traits_adapter<std::size_t, CGAL::Pointer_property_map<Dpoint>::const_type, CGAL::Search_traits_3<Dkernel>> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;

public:
  explicit Nearest_point(const std::vector<Eigen::Vector3d>& points)
  {
    for(const Eigen::Vector3d& p : points) points_.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::size_t> indices(points_.size());
    for(std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
    tree_ = std::make_unique<Search::Tree>(indices.begin(), indices.end(), Search::Tree::Splitter(),
                                           Traits(map()));
    tree_->build();
  }

  // The index of the nearest point and its distance.
  std::pair<std::size_t, double> operator()(const Eigen::Vector3d& q) const
  {
    const Search search(*tree_, Dpoint(q.x(), q.y(), q.z()), 1, 0., true,
                        Search::Distance(map()));
    return {search.begin()->first, std::sqrt(search.begin()->second)};
  }

private:
  CGAL::Pointer_property_map<Dpoint>::const_type map() const { return CGAL::make_property_map(points_); }

  std::vector<Dpoint> points_;
  std::unique_ptr<Search::Tree> tree_;
};

// Per face and plane, the face whose centroid lies nearest to the mirror image of its centroid
// (a Kd-tree query made once), or `none` if that is farther than `tolerance` (no symmetric
// counterpart) or the face itself. With `strongest_only`, a face keeps only the plane whose
// image lies closest.
inline std::vector<std::size_t> mirror_faces(const Remeshing_mesh& m, const std::vector<Dplane>& planes,
                                             double tolerance, bool strongest_only, unsigned threads)
{
  const std::size_t nf = m.number_of_faces(), k = planes.size();
  std::vector<std::size_t> mirror(nf * k, Remeshing_mesh::none);
  if(k == 0) return mirror;
  const Nearest_point nearest(m.centroid);
  std::vector<double> distance(nf * k, 0.);
  parallel_for(nf, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
      for(std::size_t j = 0; j < k; ++j) {
        const auto [g, d] = nearest(planes[j].reflect(m.centroid[f]));
        distance[f * k + j] = d;
        if(d <= tolerance && g != f) mirror[f * k + j] = g;
      }
  });
  if(strongest_only && k > 1)
    for(std::size_t f = 0; f < nf; ++f) {
      std::size_t best = Remeshing_mesh::none;
      for(std::size_t j = 0; j < k; ++j)
        if(mirror[f * k + j] != Remeshing_mesh::none && (best == Remeshing_mesh::none || distance[f * k + j] < distance[f * k + best]))
          best = j;
      for(std::size_t j = 0; j < k; ++j)
        if(j != best) mirror[f * k + j] = Remeshing_mesh::none;
    }
  return mirror;
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
