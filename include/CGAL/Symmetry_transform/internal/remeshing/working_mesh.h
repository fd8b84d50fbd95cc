// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H

// The working mesh of symmetric remeshing: an indexed triangle soup in double precision with
// its faces that cross a plane of symmetry split there (thesis, Section 5.1.2, "Proxies Spanning
// Reflection Planes"), its halfedge adjacency, per-face area, centroid and normal, and the
// planes each vertex lies on. The algorithm works on plain arrays for speed; the public layer
// converts from and to the user's mesh and kernel.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A vertex within this fraction of the bounding-box diagonal of a plane lies on it: far above
// the rounding of the split vertices put on the plane (about 1e-16), far below any feature.
constexpr double on_plane_tolerance = 1e-9;

// The reflection of a direction through a plane.
inline Eigen::Vector3d reflect_vector(const Dplane& p, const Eigen::Vector3d& v)
{
  return v - 2. * p.normal.dot(v) * p.normal;
}

// Where the edges that cross a plane meet it: a vertex per crossing edge, on the plane, appended
// to `points` once and shared by the edge's two faces.
class Plane_cut
{
public:
  typedef std::array<std::size_t, 3> Triangle;

  // Vertices at distance at most `tolerance` of the plane count as on it.
  Plane_cut(std::vector<Eigen::Vector3d>& points, const Dplane& plane, double tolerance);

  // Appends the triangles that replace t to `out`, with t's orientation: t itself if no edge
  // crosses the plane; two triangles if one edge does (the opposite vertex on the plane); three
  // if two do (the quadrilateral side cut along its shorter diagonal).
  void split(const Triangle& t, std::vector<Triangle>& out);

private:
  bool crosses(std::size_t a, std::size_t b) const { return side_[a] * side_[b] < 0.; }

  // The vertex where the crossing edge (a, b) meets the plane, made on first use.
  std::size_t vertex_on(std::size_t a, std::size_t b);

  std::vector<Eigen::Vector3d>& points_;
  const Dplane& plane_;
  std::vector<double> side_; // per vertex: signed distance to the plane, 0 on it
  std::unordered_map<std::uint64_t, std::size_t> vertex_of_edge_; // (smaller, larger index) -> its vertex
};

struct Remeshing_mesh
{
  // `points` are relative to the centre of the input's bounding box (the proxies' moments, the
  // cuts and the anchors are sums and differences of positions).
  Local_coordinates frame;
  static constexpr std::size_t none = std::size_t(-1);

  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<std::size_t> origin;   // per face: the index of the input face it comes from
  std::vector<std::size_t> opposite; // per halfedge 3f+i (faces[f][i] -> faces[f][i+1]): `none` on a border
  std::vector<std::size_t> vertex_face_begin, vertex_face; // the faces around each vertex (CSR)
  std::vector<double> area;
  std::vector<Eigen::Vector3d> centroid, normal;
  std::vector<std::uint64_t> vertex_planes; // per vertex: a bit per plane it lies on
  double average_edge_length = 0., diagonal = 0.;
  std::size_t number_of_input_faces = 0;

  std::size_t number_of_faces() const { return faces.size(); }
  static std::size_t face_of(std::size_t h) { return h / 3; }
  static std::size_t next(std::size_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static std::size_t prev(std::size_t h) { return h - h % 3 + (h % 3 + 2) % 3; }
  std::size_t source(std::size_t h) const { return faces[h / 3][h % 3]; }
  std::size_t target(std::size_t h) const { return faces[h / 3][(h % 3 + 1) % 3]; }
  // The face across halfedge h, or `none`.
  std::size_t neighbor(std::size_t h) const { return opposite[h] == none ? none : opposite[h] / 3; }

  // Splits the faces that cross `plane` (see Plane_cut); orientation and `origin` are kept.
  void split_along(const Dplane& plane, double tolerance);

  // The bounding-box diagonal, the faces split along each plane, then adjacency, face geometry
  // and the planes of each vertex.
  void split_along_planes(const std::vector<Dplane>& planes);

  // Adjacency and face geometry from `points` and `faces`.
  void build();

  // The connected pieces of the faces, where faces f and g that share an edge are joined if
  // `joined(f, g)`: the piece of each face, pieces numbered in the order of their first face.
  // `visit(f, piece)` sees each face once, in the order of a depth-first walk from that face.
  template <typename Joined, typename Visit>
  std::vector<std::size_t> connected_pieces(const Joined& joined, const Visit& visit) const
  {
    std::vector<std::size_t> piece(number_of_faces(), none), stack;
    std::size_t count = 0;
    for(std::size_t f = 0; f < number_of_faces(); ++f) {
      if(piece[f] != none) continue;
      piece[f] = count;
      stack.assign(1, f);
      while(!stack.empty()) {
        const std::size_t g = stack.back();
        stack.pop_back();
        visit(g, count);
        for(int h = 0; h < 3; ++h) {
          const std::size_t n = neighbor(3 * g + h);
          if(n != none && piece[n] == none && joined(g, n)) {
            piece[n] = count;
            stack.push_back(n);
          }
        }
      }
      ++count;
    }
    return piece;
  }

private:
  // Opposite halfedges and the faces around each vertex. An edge shared by more than two faces
  // (non-manifold) is treated as a border of each.
  void build_adjacency();
};

// Throws unless `index` gives the descriptors of `range` distinct indices below `count` (CGAL
// only asserts it, in debug builds). On a Surface_mesh with removed elements, the indices of the
// remaining ones have gaps: those are fine.
template <typename Range, typename IndexMap>
void check_index_map(const Range& range, const IndexMap& index, std::size_t count, const char* what)
{
  std::vector<char> seen(count, 0);
  for(const auto& d : range) {
    const std::size_t i = std::size_t(get(index, d));
    if(i >= count || seen[i])
      throw std::invalid_argument(std::string("Symmetry_transform: the ") + what +
                                  " index map does not give distinct indices below the number of elements");
    seen[i] = 1;
  }
}

// The working mesh of `tm`, in coordinates relative to its centre, split along `planes` (in
// those coordinates): its vertices numbered in the order of vertices(tm), through the vertex
// index map (a vector, not a hash map, from index to number); its faces in the order of
// faces(tm), each with the face index of its input face as `origin`.
// Throws on the bad meshes of triangles_of_mesh() and on an invalid index map.
template <typename TriangleMesh, typename NamedParameters>
Remeshing_mesh make_working_mesh(const TriangleMesh& tm, std::vector<Dplane>& planes, const NamedParameters& np)
{
  triangles_of_mesh(tm, np); // the checks of the input
  const auto vpm = vertex_point_map(tm, np);
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
  check_index_map(vertices(tm), vertex_index, num_vertices(tm), "vertex");
  check_index_map(faces(tm), face_index, num_faces(tm), "face");
  poll_progress();
  Remeshing_mesh m;
  std::vector<std::size_t> number(num_vertices(tm), Remeshing_mesh::none);
  for(auto v : vertices(tm)) {
    number[get(vertex_index, v)] = m.points.size();
    m.points.push_back(to_eigen(to_dpoint(get(vpm, v))));
  }
  poll_progress();
  auto number_of = [&](auto v) { return number[get(vertex_index, v)]; };
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    m.faces.push_back({number_of(source(h, tm)), number_of(target(h, tm)), number_of(target(next(h, tm), tm))});
    m.origin.push_back(get(face_index, f));
  }
  m.number_of_input_faces = m.faces.size();
  m.frame.center = Bounding_box(m.points).center();
  for(Eigen::Vector3d& p : m.points) p = m.frame.to_local(p);
  for(Dplane& plane : planes) plane = m.frame.to_local(plane);
  poll_progress();
  m.split_along_planes(planes);
  return m;
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Plane_cut::Plane_cut(std::vector<Eigen::Vector3d>& points, const Dplane& plane, double tolerance)
  : points_(points), plane_(plane), side_(points.size())
{
  for(std::size_t v = 0; v < points.size(); ++v) {
    const double s = plane.signed_distance(points[v]);
    side_[v] = std::abs(s) <= tolerance ? 0. : s;
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Plane_cut::split(const Triangle& t, std::vector<Triangle>& out)
{
  int count = 0;
  for(int i = 0; i < 3; ++i) count += crosses(t[i], t[(i + 1) % 3]) ? 1 : 0;
  if(count == 0) {
    out.push_back(t);
  } else if(count == 1) {
    int i = 0;
    while(!crosses(t[(i + 1) % 3], t[(i + 2) % 3])) ++i;
    const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3], m = vertex_on(b, c);
    out.push_back({a, b, m});
    out.push_back({a, m, c});
  } else { // vertex a alone on its side
    int i = 0;
    while(!(crosses(t[i], t[(i + 1) % 3]) && crosses(t[i], t[(i + 2) % 3]))) ++i;
    const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
    const std::size_t mb = vertex_on(a, b), mc = vertex_on(a, c);
    out.push_back({a, mb, mc});
    if((points_[mb] - points_[c]).squaredNorm() <= (points_[b] - points_[mc]).squaredNorm()) {
      out.push_back({mb, b, c});
      out.push_back({mb, c, mc});
    } else {
      out.push_back({mb, b, mc});
      out.push_back({b, c, mc});
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Plane_cut::vertex_on(std::size_t a, std::size_t b)
{
  if(a > b) std::swap(a, b);
  const std::uint64_t key = (std::uint64_t(a) << 32) | std::uint64_t(b);
  const auto found = vertex_of_edge_.find(key);
  if(found != vertex_of_edge_.end()) return found->second;
  const double t = side_[a] / (side_[a] - side_[b]);
  Eigen::Vector3d p = points_[a] + t * (points_[b] - points_[a]);
  p -= plane_.signed_distance(p) * plane_.normal;
  points_.push_back(p);
  side_.push_back(0.);
  vertex_of_edge_.emplace(key, points_.size() - 1);
  return points_.size() - 1;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Remeshing_mesh::split_along(const Dplane& plane, double tolerance)
{
  Plane_cut cut(points, plane, tolerance);
  std::vector<std::array<std::size_t, 3>> new_faces;
  std::vector<std::size_t> new_origin;
  new_faces.reserve(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f) {
    cut.split(faces[f], new_faces);
    new_origin.resize(new_faces.size(), origin[f]);
  }
  faces.swap(new_faces);
  origin.swap(new_origin);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Remeshing_mesh::split_along_planes(const std::vector<Dplane>& planes)
{
  const Bounding_box box(points);
  diagonal = (box.high - box.low).norm();
  const double on_plane = on_plane_tolerance * diagonal;
  for(const Dplane& plane : planes) {
    poll_progress(); // each step takes a tenth of a second on a million faces (progress.h)
    split_along(plane, on_plane);
  }
  poll_progress();
  build();
  poll_progress();
  vertex_planes.assign(points.size(), 0);
  for(std::size_t v = 0; v < points.size(); ++v)
    for(std::size_t j = 0; j < planes.size(); ++j)
      if(std::abs(planes[j].signed_distance(points[v])) <= on_plane) vertex_planes[v] |= std::uint64_t(1) << j;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Remeshing_mesh::build()
{
  build_adjacency();
  area.resize(faces.size());
  centroid.resize(faces.size());
  normal.resize(faces.size());
  double length = 0.;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Eigen::Vector3d &a = points[faces[f][0]], &b = points[faces[f][1]], &c = points[faces[f][2]];
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    area[f] = 0.5 * cross.norm();
    centroid[f] = (a + b + c) / 3.;
    normal[f] = area[f] > 0. ? Eigen::Vector3d(cross / (2. * area[f])) : Eigen::Vector3d::Zero();
    length += (b - a).norm() + (c - b).norm() + (a - c).norm();
  }
  average_edge_length = length / double(3 * faces.size());
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Remeshing_mesh::build_adjacency()
{
  const std::size_t nh = 3 * faces.size();
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(nh);
  auto key = [](std::size_t a, std::size_t b) { return (std::uint64_t(a) << 32) | std::uint64_t(b); };
  for(std::size_t h = 0; h < nh; ++h) keyed[h] = {key(source(h), target(h)), h};
  std::sort(keyed.begin(), keyed.end());
  poll_progress();
  auto range = [&](std::uint64_t k) {
    return std::equal_range(keyed.begin(), keyed.end(), std::make_pair(k, std::size_t(0)),
                            [](const auto& x, const auto& y) { return x.first < y.first; });
  };
  opposite.assign(nh, none);
  for(std::size_t h = 0; h < nh; ++h) {
    if(h % sequential_items_per_report == 0) poll_progress();
    const auto same = range(key(source(h), target(h))), reverse = range(key(target(h), source(h)));
    if(same.second - same.first == 1 && reverse.second - reverse.first == 1) opposite[h] = reverse.first->second;
  }
  vertex_face_begin.assign(points.size() + 1, 0);
  for(const auto& f : faces)
    for(std::size_t v : f) ++vertex_face_begin[v + 1];
  for(std::size_t v = 0; v < points.size(); ++v) vertex_face_begin[v + 1] += vertex_face_begin[v];
  vertex_face.assign(vertex_face_begin.back(), 0);
  std::vector<std::size_t> fill(vertex_face_begin.begin(), vertex_face_begin.end() - 1);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t v : faces[f]) vertex_face[fill[v]++] = f;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H
