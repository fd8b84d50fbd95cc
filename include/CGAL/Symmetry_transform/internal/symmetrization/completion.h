// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_COMPLETION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_COMPLETION_H

// Completion by symmetry: the images, under each motion of a finite group, of the parts of a shape
// whose counterparts are missing (the far side of a scan). The image of a point (or of a face's
// centroid) is missing where nothing lies within the coverage distance of it, neither the input
// nor an image added under an earlier motion of the group: where the input has surface, nothing is
// duplicated, and a part seen twice in the images (a box's hidden face is the image of its opposite
// face under two motions) is added once. Two distances decide: the fine one, of the sampling (a few
// spacings), and the coarse one, at least where symmetrize() takes a symmetry to hold. A missing
// region must reach beyond the coarse distance somewhere, and extends through neighbouring images
// beyond the fine one: a hole is filled up to its border, while a part of the shape that is only a
// little asymmetric (its image a few spacings off the surface) is not given a second layer.
// Every image is measured independently and the regions do not depend on the order in which they
// grow: the result does not depend on the threads. Asked to stitch, the regions of a mesh grow on
// up to the borders of what is present (completion_to_borders), and the parts are then stitched
// where their border vertices meet (border_stitching.h).
// All in the frame where the shape has its centre at the origin and radius about 1.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/border_stitching.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/nearby_surface.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/symmetry_group.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/vertex_orbits.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The default coverage distance, in spacings of the input: the median distance from a point to its
// nearest neighbour, or the median edge length of a mesh. A scan is sparser where it grazes the
// surface (three times along the surface at 70 degrees): images there find a neighbour within 3.
constexpr double point_coverage_spacings = 3.;
// A mesh's images are measured to its surface, not to its vertices: two edge lengths absorb the
// noise of a scanned mesh and the hundredths of a degree of a detected plane.
constexpr double mesh_coverage_spacings = 2.;
// The coarse distance (in radii): where symmetrize() takes a symmetry to hold fully.
constexpr double least_coverage_distance = 0.05;
// The spacing is the median over at most this many points or edges, evenly spread.
constexpr std::size_t spacing_samples = 10000;

struct Added_point
{
  Eigen::Vector3d point;
  Eigen::Vector3d normal; // zero when the input has no normals
};

// The median of the positive values of `lengths`, 0 if none.
inline double median_of_positive(std::vector<double> lengths)
{
  lengths.erase(std::remove_if(lengths.begin(), lengths.end(), [](double d) { return !(d > 0.); }), lengths.end());
  if(lengths.empty()) return 0.;
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

inline std::size_t spacing_stride(std::size_t count) { return (std::max)(std::size_t(1), count / spacing_samples); }

inline double median_point_spacing(const std::vector<Eigen::Vector3d>& points, const Nearest_point& nearest)
{
  std::vector<double> distances;
  for(std::size_t i = 0; i < points.size(); i += spacing_stride(points.size()))
    for(std::size_t j : nearest.nearest_others(i, 1)) distances.push_back((points[j] - points[i]).norm());
  return median_of_positive(std::move(distances));
}

inline double median_edge_length(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<std::array<std::size_t, 3>>& faces)
{
  std::vector<double> lengths;
  for(std::size_t f = 0; f < faces.size(); f += spacing_stride(faces.size()))
    for(int k = 0; k < 3; ++k) lengths.push_back((points[faces[f][k]] - points[faces[f][(k + 1) % 3]]).norm());
  return median_of_positive(std::move(lengths));
}

// For each of `queries`, its distance to what is present: the nearest point of `added` (if any)
// or the input, as `distance_to_input` measures it.
template <typename DistanceToInput>
std::vector<double> distances_to_present(const std::vector<Eigen::Vector3d>& queries,
                                         const std::vector<Eigen::Vector3d>& added,
                                         const DistanceToInput& distance_to_input, unsigned threads)
{
  const std::unique_ptr<Nearest_point> nearest_added = added.empty() ? nullptr : std::make_unique<Nearest_point>(added);
  std::vector<double> result(queries.size());
  parallel_for(queries.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(); ++i) {
      result[i] = distance_to_input(queries[i]);
      if(nearest_added) result[i] = (std::min)(result[i], std::sqrt((*nearest_added)(queries[i]).squared_distance));
    }
  });
  throw_if_cancelled();
  return result;
}

struct Coverage
{
  double fine, coarse;
};

// The items whose images are missing (see the head of this file): the connected regions, through
// `for_each_neighbour(i, f)` (f called on each neighbour of item i), of the images that
// `extends(i)`, beyond the fine distance, that reach beyond the coarse one.
template <typename Extends, typename ForEachNeighbour>
std::vector<char> missing_regions(const std::vector<double>& distance, double coarse, const Extends& extends,
                                  const ForEachNeighbour& for_each_neighbour)
{
  std::vector<char> missing(distance.size(), 0);
  std::vector<std::size_t> stack;
  for(std::size_t i = 0; i < distance.size(); ++i)
    if(distance[i] > coarse) {
      missing[i] = 1;
      stack.push_back(i);
    }
  while(!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    for_each_neighbour(i, [&](std::size_t j) {
      if(!missing[j] && extends(j)) {
        missing[j] = 1;
        stack.push_back(j);
      }
    });
  }
  return missing;
}

// The fine distance `given` (0: `spacings` times `spacing`), and the coarse one.
inline Coverage coverage_of(double given, double spacings, double spacing)
{
  const double fine = given > 0. ? given : spacings * spacing;
  return {fine, (std::max)(fine, least_coverage_distance)};
}

// The images of `points` under the motions of `group` (but the identity) that are missing.
// `coverage_distance` 0: point_coverage_spacings times the median spacing.
inline std::vector<Added_point> completion_of_points(const std::vector<Eigen::Vector3d>& points,
                                                     const std::vector<Eigen::Vector3d>& normals,
                                                     const std::vector<Rigid_motion>& group,
                                                     double coverage_distance, unsigned threads)
{
  const Nearest_point nearest(points);
  const Coverage coverage = coverage_of(coverage_distance, point_coverage_spacings, median_point_spacing(points, nearest));
  const std::vector<std::vector<std::size_t>> neighbours =
    nearest_neighbourhoods(nearest, points.size(), point_neighbours, threads);
  const auto distance_to_input = [&](const Eigen::Vector3d& q) { return std::sqrt(nearest(q).squared_distance); };
  const auto for_each_neighbour = [&](std::size_t i, const auto& f) {
    for(std::size_t j : neighbours[i]) f(j);
  };
  std::vector<Added_point> added;
  std::vector<Eigen::Vector3d> added_points;
  for(std::size_t g = 1; g < group.size(); ++g) {
    report_progress(g - 1, group.size() - 1);
    std::vector<Eigen::Vector3d> images;
    for(const Eigen::Vector3d& p : points) images.push_back(group[g](p));
    const std::vector<double> distance = distances_to_present(images, added_points, distance_to_input, threads);
    const std::vector<char> missing = missing_regions(
      distance, coverage.coarse, [&](std::size_t j) { return distance[j] > coverage.fine; }, for_each_neighbour);
    for(std::size_t i = 0; i < points.size(); ++i)
      if(missing[i])
        added.push_back({images[i], normals.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(group[g].linear * normals[i])});
    for(std::size_t i = added_points.size(); i < added.size(); ++i) added_points.push_back(added[i].point);
  }
  return added;
}

// The added part of a mesh: its own vertices, and faces on them.
struct Added_faces
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<std::size_t> part; // of each point: the number of the motion whose image it is
};

// The images under `motion` of the faces `chosen` (a face's corners reversed under a reflection, so
// that the image keeps the outward orientation), each vertex image made once, appended to `added`.
inline void add_face_images(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::array<std::size_t, 3>>& faces, const std::vector<char>& chosen,
                            const Rigid_motion& motion, std::size_t part, Added_faces& added)
{
  const bool reflects = motion.linear.determinant() < 0.;
  std::vector<std::size_t> image_of(points.size(), no_vertex);
  for(std::size_t f = 0; f < faces.size(); ++f) {
    if(!chosen[f]) continue;
    std::array<std::size_t, 3> image;
    for(int k = 0; k < 3; ++k) {
      std::size_t& v = image_of[faces[f][k]];
      if(v == no_vertex) {
        v = added.points.size();
        added.points.push_back(motion(points[faces[f][k]]));
        added.part.push_back(part);
      }
      image[k] = v;
    }
    if(reflects) std::swap(image[1], image[2]);
    added.faces.push_back(image);
  }
}

// For each face, a function calling `visit` on each face that shares a vertex with it (itself too).
inline auto faces_sharing_a_vertex(const Face_array& faces, const Faces_around_vertices& rings)
{
  return [&faces, &rings](std::size_t f, const auto& visit) {
    for(std::size_t v : faces[f])
      for(std::size_t k = rings.first[v]; k < rings.first[v + 1]; ++k) visit(rings.around[k]);
  };
}

// The images of the faces of a mesh under the motions of `group` (but the identity) that are
// missing, measured at their centroids, to the surface of the mesh and to the centroids of the
// faces added before. `coverage_distance` 0: mesh_coverage_spacings times the median edge length.
inline Added_faces completion_of_mesh(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<std::array<std::size_t, 3>>& faces,
                                      const std::vector<Rigid_motion>& group, double coverage_distance,
                                      unsigned threads)
{
  const Nearest_point nearest(points);
  const Nearby_surface surface(nearest, faces, points.size());
  const Coverage coverage = coverage_of(coverage_distance, mesh_coverage_spacings, median_edge_length(points, faces));
  const auto distance_to_input = [&](const Eigen::Vector3d& q) {
    std::size_t start = Nearby_surface::unknown;
    return (q - surface.closest(q, points, start)).norm();
  };
  const auto for_each_neighbour = faces_sharing_a_vertex(faces, surface.rings());
  Added_faces added;
  std::vector<Eigen::Vector3d> added_centroids;
  for(std::size_t g = 1; g < group.size(); ++g) {
    report_progress(g - 1, group.size() - 1);
    std::vector<Eigen::Vector3d> images;
    for(const auto& f : faces) images.push_back(group[g]((points[f[0]] + points[f[1]] + points[f[2]]) / 3.));
    const std::vector<double> distance = distances_to_present(images, added_centroids, distance_to_input, threads);
    const std::vector<char> missing = missing_regions(
      distance, coverage.coarse, [&](std::size_t j) { return distance[j] > coverage.fine; }, for_each_neighbour);
    add_face_images(points, faces, missing, group[g], g, added);
    for(std::size_t f = 0; f < faces.size(); ++f)
      if(missing[f]) added_centroids.push_back(images[f]);
  }
  return added;
}

// Samples of a triangle, each standing for a quarter of its area (barycentric weights): its
// centroid and the centroids of its three corner quarters in the midpoint subdivision.
constexpr std::array<std::array<double, 3>, 4> quarter_samples{
  {{1. / 3., 1. / 3., 1. / 3.}, {4. / 6., 1. / 6., 1. / 6.}, {1. / 6., 4. / 6., 1. / 6.}, {1. / 6., 1. / 6., 4. / 6.}}};
// A closest point this near (in radii) to a border side or a border vertex lies on the border.
constexpr double on_border_tolerance = 1e-9;
// The added vertices are joined to vertices of the input within this many median edge lengths:
// those of a model cut at its mirror plane are their own images, to the plane's precision.
constexpr double stitch_snap_edges = 0.25;
constexpr char unknown_yet = 2;

inline double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0. ? std::clamp((p - a).dot(ab) / length2, 0., 1.) : 0.;
  return (p - a - t * ab).norm();
}

// The mesh present at a step of the completion up to the borders (the input and the faces added
// so far): the distance of a query to it, and whether a triangle lies over it or beyond its borders.
class Present_surface
{
public:
  explicit Present_surface(Added_faces mesh)
    : mesh_(std::move(mesh)), nearest_(mesh_.points), surface_(nearest_, mesh_.faces, mesh_.points.size()),
      border_(face_border_sides(mesh_.faces)), on_border_(border_vertices(mesh_.faces, border_, mesh_.points.size()))
  {}

  double distance(const Eigen::Vector3d& q) const
  {
    return std::sqrt(surface_.closest_on_face(q, mesh_.points).squared_distance);
  }

  // Whether at least half of the triangle `corners` lies over the surface, within `reach` of it.
  bool covers(const std::array<Eigen::Vector3d, 3>& corners, double reach) const
  {
    std::size_t over = 0;
    for(const auto& w : quarter_samples) over += lies_over(w[0] * corners[0] + w[1] * corners[1] + w[2] * corners[2], reach);
    return 2 * over >= quarter_samples.size();
  }

private:
  // Whether q lies within `reach` of the surface and over it: its closest point is not on a
  // border (q would lie beyond that border).
  bool lies_over(const Eigen::Vector3d& q, double reach) const
  {
    const Nearby_surface::Closest c = surface_.closest_on_face(q, mesh_.points);
    if(c.squared_distance > reach * reach || c.face == mesh_.faces.size()) return false;
    const std::array<std::size_t, 3>& f = mesh_.faces[c.face];
    for(std::size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d &a = mesh_.points[f[k]], &b = mesh_.points[f[(k + 1) % 3]];
      if(on_border_[f[k]] && (c.point - a).norm() <= on_border_tolerance) return false;
      if(border_[c.face][k] && distance_to_segment(c.point, a, b) <= on_border_tolerance) return false;
    }
    return true;
  }

  Added_faces mesh_;
  Nearest_point nearest_;
  Nearby_surface surface_;
  std::vector<std::array<bool, 3>> border_;
  std::vector<char> on_border_;
};

// The input and the faces added so far, as one mesh (the input's part 0).
inline Added_faces joined(const std::vector<Eigen::Vector3d>& points, const Face_array& faces, const Added_faces& added)
{
  Added_faces result{points, faces, std::vector<std::size_t>(points.size(), 0)};
  const std::size_t offset = points.size();
  result.points.insert(result.points.end(), added.points.begin(), added.points.end());
  result.part.insert(result.part.end(), added.part.begin(), added.part.end());
  for(const auto& f : added.faces) result.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return result;
}

// completion_of_mesh() grown up to the borders of what is present (`edge`: the median edge
// length): next to a missing region, the image of a face within the fine distance of the surface
// is added too when most of it lies beyond a border rather than over the surface: the strip
// between a cut and its image. Distances are measured to the surface of the input and of the
// faces added before.
inline Added_faces completion_to_borders(const std::vector<Eigen::Vector3d>& points, const Face_array& faces,
                                         const std::vector<Rigid_motion>& group, double coverage_distance,
                                         double edge, unsigned threads)
{
  const Coverage coverage = coverage_of(coverage_distance, mesh_coverage_spacings, edge);
  const Faces_around_vertices rings(faces, points.size());
  const auto for_each_neighbour = faces_sharing_a_vertex(faces, rings);
  Added_faces added;
  for(std::size_t g = 1; g < group.size(); ++g) {
    report_progress(g - 1, group.size() - 1);
    const Present_surface present(joined(points, faces, added));
    const auto image = [&](std::size_t f) {
      return std::array<Eigen::Vector3d, 3>{group[g](points[faces[f][0]]), group[g](points[faces[f][1]]),
                                            group[g](points[faces[f][2]])};
    };
    std::vector<double> distance(faces.size());
    parallel_for(faces.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
      for(std::size_t f = begin; f < end && parallel_step(); ++f) {
        const std::array<Eigen::Vector3d, 3> c = image(f);
        distance[f] = present.distance((c[0] + c[1] + c[2]) / 3.);
      }
    });
    throw_if_cancelled();
    std::vector<char> beyond(faces.size(), unknown_yet); // whether an image lies beyond a border, once asked
    const auto extends = [&](std::size_t f) {
      if(distance[f] > coverage.fine) return true;
      if(beyond[f] == unknown_yet) beyond[f] = !present.covers(image(f), coverage.fine);
      return beyond[f] == 1;
    };
    add_face_images(points, faces, missing_regions(distance, coverage.coarse, extends, for_each_neighbour), group[g], g,
                    added);
  }
  return added;
}

// The completion of a mesh, and the stitches that join the added faces to the input's borders and
// to each other (vertices numbered as the input's, then the added ones).
struct Stitched_completion
{
  Added_faces added;
  std::vector<Stitch> stitches;
};

inline Stitched_completion stitched_completion_of_mesh(const std::vector<Eigen::Vector3d>& points, const Face_array& faces,
                                                       const std::vector<Rigid_motion>& group,
                                                       double coverage_distance, unsigned threads)
{
  const double edge = median_edge_length(points, faces);
  Stitched_completion result{completion_to_borders(points, faces, group, coverage_distance, edge, threads), {}};
  const Added_faces all = joined(points, faces, result.added);
  result.stitches = border_stitches(all.points, all.faces, all.part, stitch_snap_edges * edge);
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_COMPLETION_H
