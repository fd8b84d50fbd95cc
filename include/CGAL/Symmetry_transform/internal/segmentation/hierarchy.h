// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_HIERARCHY_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_HIERARCHY_H

// The segmentation tree of segment_by_symmetry(), grown level by level: the connected components
// of the mesh are its roots; at each level the segments that may be split are examined, largest
// first, within the depth and segment-count limits; the leaves get the segment ids.

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>
#include <CGAL/Symmetry_transform/internal/segmentation/face_feature.h>
#include <CGAL/Symmetry_transform/internal/segmentation/settings.h>
#include <CGAL/Symmetry_transform/internal/segmentation/split.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The tree under construction. Segment is Symmetry_segment<GT> (symmetry_segmentation.h), a
// template parameter so that this header need not include the public one.
template <typename GT, typename Segment>
class Segmentation_hierarchy
{
  typedef decltype(Segment::status) Status; // Segment_status

public:
  Segmentation_hierarchy(const Segmentation_mesh& mesh, const Segmentation_settings& settings)
    : mesh_(mesh), settings_(settings),
      total_area_(std::accumulate(mesh.areas.begin(), mesh.areas.end(), 0.))
  {
    add_roots();
  }

  // Splits the segments level by level, until no segment of the last level is split.
  void grow()
  {
    std::vector<std::size_t> active(segments_.size());
    std::iota(active.begin(), active.end(), std::size_t(0));
    for(std::size_t level = 0; !active.empty(); ++level) {
      // Deeper levels examine smaller segments on coarser grids: each is given a share of the
      // progress segmentation_level_share times that of the level above.
      const double done = 1. - std::pow(progress_shares::segmentation_level_share, double(level));
      Progress_stage stage(done, done + (1. - done) * (1. - progress_shares::segmentation_level_share));
      active = split_level(level, active);
    }
  }

  // Numbers the leaves, parents first, and writes the id of each face's leaf; returns their number.
  template <typename TriangleMesh, typename FaceIndexMap, typename SegmentIdMap>
  std::size_t write_segment_ids(const TriangleMesh& tm, const FaceIndexMap& face_index, SegmentIdMap segment_id_map)
  {
    std::vector<std::size_t> id_of_face(mesh_.number_of_faces(), Segment::none);
    std::size_t number_of_segments = 0;
    for(std::size_t s = 0; s < segments_.size(); ++s) {
      if(!segments_[s].children.empty()) continue;
      segments_[s].segment_id = number_of_segments++;
      for(std::size_t f : faces_of_[s]) id_of_face[f] = segments_[s].segment_id;
    }
    for(auto f : faces(tm)) put(segment_id_map, f, id_of_face[std::size_t(get(face_index, f))]);
    return number_of_segments;
  }

  std::vector<Segment>& segments() { return segments_; }

private:
  void add_segment(std::vector<std::size_t> faces, std::size_t parent)
  {
    Segment s;
    s.parent = parent;
    s.level = parent == Segment::none ? 0 : segments_[parent].level + 1;
    s.number_of_faces = faces.size();
    for(std::size_t f : faces) s.area += mesh_.areas[f];
    if(parent != Segment::none) segments_[parent].children.push_back(segments_.size());
    segments_.push_back(s);
    faces_of_.push_back(std::move(faces));
  }

  // The connected components of the mesh, each a leaf, and the radius of the largest.
  void add_roots()
  {
    const std::size_t n = mesh_.number_of_faces();
    std::vector<std::size_t> all(n), identity(n), region(n, 0);
    std::iota(all.begin(), all.end(), std::size_t(0));
    std::iota(identity.begin(), identity.end(), std::size_t(0));
    for(auto& component : connected_parts(mesh_, all, identity, region)) add_segment(std::move(component), Segment::none);
    for(std::size_t s = 0; s < segments_.size(); ++s) root_radius_ = (std::max)(root_radius_, radius_of(mesh_, faces_of_[s]));
    leaves_ = segments_.size();
  }

  // The segments of `active` that may be split, largest first; the others get their status.
  std::vector<std::size_t> examined_segments(std::size_t level, const std::vector<std::size_t>& active)
  {
    std::vector<std::size_t> examined;
    for(std::size_t s : active) {
      if(level >= settings_.max_depth) segments_[s].status = Status::DEPTH_LIMIT;
      else if(segments_[s].area < least_examined_area_fraction * total_area_ ||
              segments_[s].number_of_faces < least_examined_faces)
        segments_[s].status = Status::TOO_SMALL;
      else examined.push_back(s);
    }
    // Largest first: when the segment count runs out, the largest segments are the ones split.
    std::stable_sort(examined.begin(), examined.end(),
                     [&](std::size_t a, std::size_t b) { return segments_[a].area > segments_[b].area; });
    return examined;
  }

  // Splits the segments of one level; returns their children. With a count limit, segments are
  // examined a few at a time (one per thread), so that no detection runs for a segment that the
  // limit would leave whole.
  std::vector<std::size_t> split_level(std::size_t level, const std::vector<std::size_t>& active)
  {
    const std::vector<std::size_t> examined = examined_segments(level, active);
    const std::size_t batch = settings_.max_segments == no_segment_limit ? examined.size() : std::size_t(settings_.threads);
    std::vector<std::size_t> next;
    for(std::size_t first = 0; first < examined.size(); first += batch) {
      const std::vector<std::size_t> some(examined.begin() + std::ptrdiff_t(first),
                                          examined.begin() + std::ptrdiff_t((std::min)(first + batch, examined.size())));
      if(leaves_ >= settings_.max_segments) {
        for(std::size_t s : some) segments_[s].status = Status::COUNT_LIMIT;
        continue;
      }
      report_progress(first, examined.size());
      const std::vector<Split> splits = split_segments(mesh_, faces_of_, some, settings_, total_area_, root_radius_);
      for(std::size_t k = 0; k < some.size(); ++k) apply_split(some[k], splits[k], level, next);
    }
    return next;
  }

  // Records the split of segment s, and adds its children to the tree and to `next` if it is split.
  void apply_split(std::size_t s, const Split& split, std::size_t level, std::vector<std::size_t>& next)
  {
    for(const auto& p : split.planes) // to_dplane renormalises the normal
      segments_[s].planes.push_back({to_plane<GT>(to_dplane(p.plane)), p.symmetry, p.support});
    segments_[s].reflected_fractions = split.reflected_fractions;
    if(settings_.verbose) print(s, level, split);
    if(split.parts.size() < 2) {
      segments_[s].status = !split.partial_symmetry ? Status::NO_PARTIAL_SYMMETRY : Status::NOT_SEPARABLE;
      return;
    }
    if(leaves_ >= settings_.max_segments) {
      segments_[s].status = Status::COUNT_LIMIT;
      return;
    }
    std::vector<std::vector<std::size_t>> parts = merge_down_to(mesh_, split.parts, settings_.max_segments - leaves_ + 1);
    segments_[s].status = Status::SPLIT;
    leaves_ += parts.size() - 1;
    for(auto& part : parts) {
      add_segment(std::move(part), s);
      next.push_back(segments_.size() - 1);
    }
  }

  void print(std::size_t s, std::size_t level, const Split& split) const
  {
    std::cerr << "segment " << s << " (level " << level << ", " << segments_[s].number_of_faces << " faces): "
              << split.planes.size() << " planes, " << split.parts.size() << " parts, " << split.seconds
              << " s (detection " << split.detection_seconds << " s, features " << split.feature_seconds
              << " s, clustering and graph cut " << split.seconds - split.detection_seconds - split.feature_seconds
              << " s)\n";
  }

  const Segmentation_mesh& mesh_;
  const Segmentation_settings& settings_;
  const double total_area_;
  double root_radius_ = 0.; // of the largest component
  std::vector<Segment> segments_;
  std::vector<std::vector<std::size_t>> faces_of_; // of each segment
  std::size_t leaves_ = 0; // the number of leaves of the tree
};

// The segmentation of `tm`, its faces numbered 0 to n - 1 by `face_index`: writes the segment
// ids, moves the tree into `segments` and returns the number of segments. `np`: for the
// face_feature_map.
template <typename GT, typename Segment, typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap,
          typename SegmentIdMap, typename NamedParameters>
std::size_t segment_mesh(const TriangleMesh& tm, const VertexPointMap& vpm, const FaceIndexMap& face_index,
                         SegmentIdMap segment_id_map, const Segmentation_settings& settings,
                         std::vector<Segment>& segments, const NamedParameters& np)
{
  Progress_stage stage(0., progress_shares::segmentation_preparation);
  Segmentation_mesh mesh = segmentation_mesh(tm, vpm, face_index);
  mesh.face_features = face_feature_values(tm, face_index, np);
  Segmentation_hierarchy<GT, Segment> hierarchy(mesh, settings);
  stage.move_to(progress_shares::segmentation_preparation, 1.);
  hierarchy.grow();
  throw_if_cancelled(); // nothing is written for a cancelled segmentation
  const std::size_t number_of_segments = hierarchy.write_segment_ids(tm, face_index, segment_id_map);
  segments = std::move(hierarchy.segments());
  return number_of_segments;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_HIERARCHY_H
