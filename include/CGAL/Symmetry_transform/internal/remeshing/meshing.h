// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESHING_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESHING_H

// The output mesh of symmetric remeshing from the patches (thesis, Section 5.1.2, "Point
// Correspondences" and "Triangulation"), in the steps of CGAL's VSA (extract_mesh):
// - anchors where three or more patch boundaries meet, plus the vertices on a plane of symmetry
//   where a patch boundary crosses the plane (the split vertices of the thesis);
// - boundary chords between anchors, subdivided at their farthest vertex while it lies farther
//   than `subdivision_ratio` (times the mean edge length, or the chord length) from the chord;
// - the anchors of corresponding boundaries completed by each other's mirror images (the mesh
//   vertex nearest the reflected anchor, if it lies on a boundary of the same proxies and not
//   next to another anchor);
// - the triangulation of each patch by multi-source Dijkstra from its anchors (each vertex
//   takes the tag of its nearest anchor, chord vertices that of the nearer chord end): a face
//   whose three vertices have three tags gives a triangle; of triangles with the same directed
//   edge (folded onto each other), the largest is kept;
// - anchor positions: the mean of their projections onto the planes of their patches;
// - anchors matched across each plane (same proxies around, mutually nearest mirror images)
//   and moved to exact mirror positions, vertices matched to themselves onto the plane;
// - the holes left by the removed folds (cycles of output border edges not on a border of the
//   input; flaps, triangles held by their corners only, removed first) filled by the
//   triangulation of least total edge length between the final anchor positions, or, where the
//   cycle has none that makes no edge twice, by a fan from a vertex at its centroid: choices
//   that only depend on lengths, invariant under a reflection, so that the fill of a hole and
//   that of its mirror image are mirror images of each other.

#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

struct Meshing_settings
{
  double subdivision_ratio = 5.;
  bool relative_to_chord = false, with_dihedral_angle = false, optimize_anchor_location = true;
};

struct Remeshing_output
{
  std::vector<std::size_t> anchor_vertices; // working-mesh vertex of each anchor
  std::vector<Eigen::Vector3d> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t matched_anchors = 0; // anchors moved to an exact mirror position
};

class Symmetric_meshing
{
  static constexpr std::size_t none = Remeshing_mesh::none;

public:
  // `nearest_vertex(p)`: the working-mesh vertex nearest to p.
  Symmetric_meshing(const Remeshing_mesh& mesh, const Symmetric_partition& partition, const std::vector<Dplane>& planes,
                    const std::vector<std::uint64_t>& vertex_planes,
                    const std::function<std::size_t(const Eigen::Vector3d&)>& nearest_vertex)
    : m_(mesh), p_(partition), planes_(planes), vertex_planes_(vertex_planes), nearest_vertex_(nearest_vertex),
      label_(partition.labels()), t_(partition.transforms())
  {}

  Remeshing_output run(const Meshing_settings& s)
  {
    anchor_.assign(m_.points.size(), none);
    out_ = Remeshing_output();
    find_anchors();
    find_chords(s);
    add_anchors_to_short_cycles();
    complete_with_mirrors();
    triangulate();
    place_anchors(s.optimize_anchor_location);
    snap_mirrors();
    fill_holes();
    return std::move(out_);
  }

private:
  std::size_t label(std::size_t h) const { return label_[h / 3]; }
  // Whether halfedge h separates its patch from another patch or the outside.
  bool is_boundary(std::size_t h) const
  {
    const std::size_t n = m_.neighbor(h);
    return n == none || label_[n] != label_[h / 3];
  }

  void attach(std::size_t v)
  {
    if(anchor_[v] != none) return;
    anchor_[v] = out_.anchor_vertices.size();
    out_.anchor_vertices.push_back(v);
  }

  // Twice the number of boundary edges at v (a border edge is seen from one face, a patch
  // boundary from two), and the proxies around it.
  std::size_t boundary_count(std::size_t v, std::vector<std::size_t>* proxies = nullptr) const
  {
    std::size_t count = 0;
    for(std::size_t i = m_.vertex_face_begin[v]; i < m_.vertex_face_begin[v + 1]; ++i) {
      const std::size_t f = m_.vertex_face[i];
      if(proxies) proxies->push_back(p_.proxy_of(label_[f]));
      for(int c = 0; c < 3; ++c) {
        const std::size_t h = 3 * f + c;
        if(m_.source(h) != v && m_.target(h) != v) continue;
        if(m_.neighbor(h) == none) count += 2;
        else if(is_boundary(h)) count += 1;
      }
    }
    if(proxies) {
      std::sort(proxies->begin(), proxies->end());
      proxies->erase(std::unique(proxies->begin(), proxies->end()), proxies->end());
    }
    return count;
  }

  void find_anchors()
  {
    for(std::size_t v = 0; v < m_.points.size(); ++v) {
      if(boundary_count(v) >= 6) { attach(v); continue; }
      if(vertex_planes_[v] == 0) continue;
      // On a plane: an anchor where a boundary crosses the plane (boundary edges to both of its
      // sides). The middle of a chord symmetric about the plane lies there, and its tag (the
      // nearer end of the chord) would otherwise be a tie.
      for(std::size_t j = 0; j < planes_.size() && anchor_[v] == none; ++j) {
        if(!((vertex_planes_[v] >> j) & 1u)) continue;
        bool above = false, below = false;
        for(std::size_t i = m_.vertex_face_begin[v]; i < m_.vertex_face_begin[v + 1]; ++i)
          for(int c = 0; c < 3; ++c) {
            const std::size_t h = 3 * m_.vertex_face[i] + c;
            const std::size_t other = m_.source(h) == v ? m_.target(h) : m_.target(h) == v ? m_.source(h) : none;
            if(other == none || !is_boundary(h) || ((vertex_planes_[other] >> j) & 1u)) continue;
            (signed_distance(planes_[j], m_.points[other]) > 0. ? above : below) = true;
          }
        if(above && below) attach(v);
      }
    }
  }

  // The boundary halfedge of the same patch that follows h (a boundary halfedge) on its cycle.
  std::size_t next_boundary(std::size_t h) const
  {
    std::size_t g = Remeshing_mesh::next(h);
    for(std::size_t guard = 0; !is_boundary(g) && guard < 1000000; ++guard) g = Remeshing_mesh::next(m_.opposite[g]);
    return g;
  }

  // The boundary halfedges from h (excluded) to the next anchor; h is moved there.
  std::vector<std::size_t> walk_chord(std::size_t& h) const
  {
    std::vector<std::size_t> chord;
    do {
      h = next_boundary(h);
      chord.push_back(h);
    } while(anchor_[m_.target(h)] == none);
    return chord;
  }

  // Subdivides chord[begin, end) at its farthest vertex while the criterion holds (CGAL's rule).
  void subdivide(const std::vector<std::size_t>& chord, std::size_t begin, std::size_t end, const Meshing_settings& s)
  {
    const std::size_t first = m_.source(chord[begin]), last = m_.target(chord[end - 1]);
    if(first != last && end - begin < 4) return;
    const Eigen::Vector3d &a = m_.points[first], &b = m_.points[last];
    std::size_t farthest = begin;
    double largest = 0.;
    const double length = (b - a).norm();
    bool split = false;
    if(first == last) {
      for(std::size_t i = begin; i + 1 < end; ++i) {
        const double d = (m_.points[m_.target(chord[i])] - a).norm();
        if(d > largest) { largest = d; farthest = i; }
      }
      split = end - begin > 2;
    } else {
      for(std::size_t i = begin; i + 1 < end; ++i) {
        const Eigen::Vector3d x = m_.points[m_.target(chord[i])] - a;
        const double d = length > 0. ? (b - a).cross(x).norm() / length : x.norm();
        if(d > largest) { largest = d; farthest = i; }
      }
      double criterion = largest / (s.relative_to_chord && length > 0. ? length : m_.average_edge_length);
      if(s.with_dihedral_angle && m_.neighbor(chord[begin]) != none)
        criterion *= p_.patch_normal(label(chord[begin])).cross(p_.patch_normal(label_[m_.neighbor(chord[begin])])).norm();
      split = criterion > s.subdivision_ratio;
    }
    if(!split || largest <= 0.) return;
    attach(m_.target(chord[farthest]));
    subdivide(chord, begin, farthest + 1, s);
    subdivide(chord, farthest + 1, end, s);
  }

  void find_chords(const Meshing_settings& s)
  {
    const std::size_t nh = 3 * m_.number_of_faces();
    std::vector<char> candidate(nh, 0);
    for(std::size_t h = 0; h < nh; ++h) candidate[h] = is_boundary(h) ? 1 : 0;
    for(std::size_t start = 0; start < nh; ++start) {
      if(!candidate[start]) continue;
      std::size_t head = start;
      while(anchor_[m_.target(head)] == none) {
        head = next_boundary(head);
        if(head == start) break;
      }
      if(anchor_[m_.target(head)] == none) {
        head = farthest_from_centroid(head);
        attach(m_.target(head));
      }
      cycles_.push_back(head);
      std::size_t h = head;
      do {
        const std::vector<std::size_t> chord = walk_chord(h);
        subdivide(chord, 0, chord.size(), s);
        for(std::size_t c : chord) candidate[c] = 0;
      } while(h != head);
    }
  }

  // A boundary cycle needs three anchors: each one added is the vertex whose distance to the
  // nearest anchor of the cycle is largest. The rule depends on the anchors, not on where the
  // walk around the cycle starts: mirror cycles get mirror anchors.
  void add_anchors_to_short_cycles()
  {
    for(std::size_t head : cycles_) {
      std::vector<std::size_t> anchors, others;
      std::size_t h = head;
      do {
        h = next_boundary(h);
        (anchor_[m_.target(h)] != none ? anchors : others).push_back(m_.target(h));
      } while(h != head);
      while(anchors.size() < 3 && !others.empty()) {
        std::size_t best = 0;
        double largest = -1.;
        for(std::size_t i = 0; i < others.size(); ++i) {
          double nearest = std::numeric_limits<double>::infinity();
          for(std::size_t a : anchors) nearest = (std::min)(nearest, (m_.points[others[i]] - m_.points[a]).norm());
          if(nearest > largest) { largest = nearest; best = i; }
        }
        attach(others[best]);
        anchors.push_back(others[best]);
        others.erase(others.begin() + std::ptrdiff_t(best));
      }
    }
  }

  // The boundary halfedge of the cycle of `head` whose target lies farthest from the cycle's
  // centroid: the first anchor of a cycle that has none, chosen so that mirror cycles get mirror
  // anchors (the first halfedge in index order would not).
  std::size_t farthest_from_centroid(std::size_t head) const
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    std::size_t count = 0, h = head;
    do {
      centroid += m_.points[m_.target(h)];
      ++count;
      h = next_boundary(h);
    } while(h != head);
    centroid /= double(count);
    std::size_t best = head;
    double largest = -1.;
    do {
      const double d = (m_.points[m_.target(h)] - centroid).squaredNorm();
      if(d > largest) { largest = d; best = h; }
      h = next_boundary(h);
    } while(h != head);
    return best;
  }

  // Each anchor's mirror images through the planes become anchors too, where the mesh vertex
  // nearest the image lies within a mean edge length and on a boundary of the same proxies.
  void complete_with_mirrors()
  {
    if(planes_.empty()) return;
    std::vector<std::size_t> proxies, image_proxies;
    for(std::size_t a = 0; a < out_.anchor_vertices.size(); ++a) { // grows while looping
      const std::size_t v = out_.anchor_vertices[a];
      proxies.clear();
      boundary_count(v, &proxies);
      for(const Dplane& plane : planes_) {
        const Eigen::Vector3d image = plane.reflect(m_.points[v]);
        const std::size_t w = nearest_vertex_(image);
        if(w == none || anchor_[w] != none || (m_.points[w] - image).norm() > m_.average_edge_length) continue;
        image_proxies.clear();
        if(boundary_count(w, &image_proxies) >= 2 && image_proxies == proxies && !next_to_anchor(w)) attach(w);
      }
    }
  }

  // Whether a vertex shares an edge with an anchor (anchors that close make slivers and
  // non-manifold fans).
  bool next_to_anchor(std::size_t v) const
  {
    for(std::size_t i = m_.vertex_face_begin[v]; i < m_.vertex_face_begin[v + 1]; ++i)
      for(std::size_t w : m_.faces[m_.vertex_face[i]])
        if(w != v && anchor_[w] != none) return true;
    return false;
  }

  void triangulate()
  {
    const std::size_t nv = m_.points.size(), nf = m_.number_of_faces();
    std::vector<std::size_t> tag(nv, none);
    for(std::size_t a = 0; a < out_.anchor_vertices.size(); ++a) tag[out_.anchor_vertices[a]] = a;
    // Faces of each patch.
    std::vector<std::size_t> begin(label_.empty() ? 1 : *std::max_element(label_.begin(), label_.end()) + 2, 0);
    for(std::size_t f = 0; f < nf; ++f) ++begin[label_[f] + 1];
    for(std::size_t l = 0; l + 1 < begin.size(); ++l) begin[l + 1] += begin[l];
    std::vector<std::size_t> faces_of(nf), fill(begin.begin(), begin.end() - 1);
    for(std::size_t f = 0; f < nf; ++f) faces_of[fill[label_[f]]++] = f;

    std::vector<double> distance(nv, 0.);
    std::vector<std::size_t> stamp(nv, none);
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for(std::size_t l = 0; l + 1 < begin.size(); ++l) {
      if(begin[l] == begin[l + 1]) continue;
      for(std::size_t i = begin[l]; i < begin[l + 1]; ++i)
        for(std::size_t v : m_.faces[faces_of[i]])
          if(stamp[v] != l) {
            stamp[v] = l;
            distance[v] = std::numeric_limits<double>::infinity();
            if(anchor_[v] != none) {
              distance[v] = 0.;
              tag[v] = anchor_[v];
              queue.push({0., v});
            }
          }
      while(!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if(d > distance[v]) continue;
        for(std::size_t i = m_.vertex_face_begin[v]; i < m_.vertex_face_begin[v + 1]; ++i) {
          const std::size_t f = m_.vertex_face[i];
          if(label_[f] != l) continue;
          for(std::size_t w : m_.faces[f]) {
            if(w == v) continue;
            const double dw = d + (m_.points[w] - m_.points[v]).norm();
            if(dw < distance[w]) {
              distance[w] = dw;
              tag[w] = tag[v];
              queue.push({dw, w});
            }
          }
        }
      }
    }
    // Chord vertices: the tag of the nearer chord end along the chord.
    for(std::size_t head : cycles_) {
      std::size_t h = head;
      do {
        const std::vector<std::size_t> chord = walk_chord(h);
        std::vector<double> along(1, 0.);
        for(std::size_t c : chord) along.push_back(along.back() + (m_.points[m_.target(c)] - m_.points[m_.source(c)]).norm());
        const std::size_t left = anchor_[m_.source(chord.front())], right = anchor_[m_.target(chord.back())];
        for(std::size_t i = 0; i + 1 < chord.size(); ++i)
          tag[m_.target(chord[i])] = along[i + 1] < along.back() / 2. ? left : right;
      } while(h != head);
    }
    std::set<std::array<std::size_t, 3>> seen;
    for(std::size_t f = 0; f < nf; ++f) {
      const std::size_t i = tag[m_.faces[f][0]], j = tag[m_.faces[f][1]], k = tag[m_.faces[f][2]];
      if(i == none || j == none || k == none || i == j || j == k || i == k) continue;
      std::array<std::size_t, 3> key = {i, j, k};
      std::sort(key.begin(), key.end());
      if(seen.insert(key).second) out_.triangles.push_back({i, j, k});
    }
    remove_folded_triangles();
  }

  // Two triangles with the same directed edge overlap (one folds onto the other) and make the
  // edge and its ends non-manifold: of each such set, only the largest triangle (area between the
  // anchors' mesh vertices) is kept. The folds are slivers; removing the smaller ones keeps the
  // surface covered best.
  void remove_folded_triangles()
  {
    auto& t = out_.triangles;
    typedef std::pair<std::size_t, std::size_t> Edge;
    std::map<Edge, std::vector<std::size_t>> directed;
    for(std::size_t i = 0; i < t.size(); ++i)
      for(int c = 0; c < 3; ++c) directed[Edge(t[i][c], t[i][(c + 1) % 3])].push_back(i);
    auto area = [&](std::size_t i) {
      const Eigen::Vector3d &a = m_.points[out_.anchor_vertices[t[i][0]]], &b = m_.points[out_.anchor_vertices[t[i][1]]],
                            &c = m_.points[out_.anchor_vertices[t[i][2]]];
      return (b - a).cross(c - a).norm();
    };
    std::vector<char> removed(t.size(), 0);
    for(const auto& entry : directed) {
      std::size_t largest = Remeshing_mesh::none;
      for(std::size_t i : entry.second)
        if(!removed[i] && (largest == Remeshing_mesh::none || area(i) > area(largest))) largest = i;
      for(std::size_t i : entry.second)
        if(i != largest) removed[i] = 1;
    }
    std::vector<std::array<std::size_t, 3>> kept;
    for(std::size_t i = 0; i < t.size(); ++i)
      if(!removed[i]) kept.push_back(t[i]);
    t.swap(kept);
  }

  // Holes left where folded triangles were removed: each cycle of output border edges (read
  // against the orientation of the triangles, split where it passes a vertex twice) whose
  // edges do not all follow a border of the input is filled by the triangulation of least
  // total edge length (dynamic programming over the cycle), between the final anchor
  // positions; triangles that would be degenerate, duplicate an output triangle or reuse an
  // output edge are excluded, and a cycle without such a triangulation gets a fan from a new
  // vertex at its centroid.
  void fill_holes()
  {
    auto& t = out_.triangles;
    if(t.empty()) return;
    typedef std::pair<std::size_t, std::size_t> Edge;
    std::vector<char> on_border(m_.points.size(), 0);
    for(std::size_t h = 0; h < m_.opposite.size(); ++h)
      if(m_.opposite[h] == none) on_border[m_.source(h)] = on_border[m_.target(h)] = 1;
    auto anchor_on_border = [&](std::size_t a) {
      return out_.anchor_vertices[a] != none && on_border[out_.anchor_vertices[a]];
    };
    {
      // A triangle none of whose edges is shared (a flap left by the removed folds, held by its
      // corners only) goes, unless it lies on a border of the input.
      std::map<Edge, std::size_t> count;
      for(const auto& tri : t)
        for(int c = 0; c < 3; ++c) ++count[std::minmax(tri[c], tri[(c + 1) % 3])];
      std::vector<std::array<std::size_t, 3>> kept;
      for(const auto& tri : t) {
        bool flap = true;
        for(int c = 0; c < 3 && flap; ++c) flap = count[std::minmax(tri[c], tri[(c + 1) % 3])] == 1;
        if(flap && !(anchor_on_border(tri[0]) && anchor_on_border(tri[1]) && anchor_on_border(tri[2]))) continue;
        kept.push_back(tri);
      }
      t.swap(kept);
    }
    std::set<Edge> directed;
    std::set<std::array<std::size_t, 3>> keys;
    for(const auto& tri : t) {
      for(int c = 0; c < 3; ++c) directed.insert(Edge(tri[c], tri[(c + 1) % 3]));
      std::array<std::size_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      keys.insert(key);
    }
    // Hole edges: (b, a) for each output edge (a, b) without its reverse.
    std::multimap<std::size_t, std::size_t> hole;
    for(const Edge& e : directed)
      if(!directed.count(Edge(e.second, e.first))) hole.insert({e.second, e.first});
    if(hole.empty()) return;
    auto& x = out_.anchors;
    // Of several hole edges leaving a vertex, the shortest (a geometric choice).
    auto take = [&](std::size_t v) {
      auto range = hole.equal_range(v);
      auto best = range.first;
      for(auto it = range.first; it != range.second; ++it)
        if((x[it->second] - x[v]).norm() < (x[best->second] - x[v]).norm()) best = it;
      const std::size_t w = best->second;
      hole.erase(best);
      return w;
    };
    std::vector<std::vector<std::size_t>> cycles;
    while(!hole.empty()) {
      std::vector<std::size_t> path(1, hole.begin()->first);
      std::map<std::size_t, std::size_t> position{{path.front(), 0}};
      while(hole.count(path.back())) {
        const std::size_t w = take(path.back());
        const auto found = position.find(w);
        if(found == position.end()) {
          position[w] = path.size();
          path.push_back(w);
          continue;
        }
        // A cycle closes at w: cut it off the path.
        cycles.emplace_back(path.begin() + std::ptrdiff_t(found->second), path.end());
        for(std::size_t i = found->second + 1; i < path.size(); ++i) position.erase(path[i]);
        path.resize(found->second + 1);
      }
    }
    for(const std::vector<std::size_t>& cycle : cycles) {
      const std::size_t n = cycle.size();
      if(n < 3 || n > 200) continue;
      bool follows_input_border = true;
      for(std::size_t i = 0; i < n && follows_input_border; ++i)
        follows_input_border = anchor_on_border(cycle[i]) && anchor_on_border(cycle[(i + 1) % n]);
      if(follows_input_border) continue;
      const double infinity = std::numeric_limits<double>::infinity();
      auto length = [&](std::size_t i, std::size_t j) { return (x[cycle[i]] - x[cycle[j]]).norm(); };
      // A triangle (i, k, j) of the cycle, oriented as the cycle, is allowed if it is not
      // degenerate, not an output triangle and its diagonals are no output edges.
      auto allowed = [&](std::size_t i, std::size_t k, std::size_t j) {
        const std::size_t a = cycle[i], b = cycle[k], c = cycle[j];
        if(a == b || b == c || a == c) return false;
        if((x[b] - x[a]).cross(x[c] - x[a]).norm() <= 1e-12 * (x[b] - x[a]).squaredNorm() + 1e-300) return false;
        std::array<std::size_t, 3> key = {a, b, c};
        std::sort(key.begin(), key.end());
        if(keys.count(key)) return false;
        const std::pair<std::size_t, std::size_t> sides[3] = {{i, k}, {k, j}, {j, i}};
        for(const auto& [p, q] : sides) {
          const bool on_cycle = (p + 1) % n == q;
          if(!on_cycle && (directed.count(Edge(cycle[p], cycle[q])) || directed.count(Edge(cycle[q], cycle[p]))))
            return false;
        }
        return true;
      };
      // cost[i][j]: least total length of the diagonals triangulating the cycle from i to j.
      std::vector<std::vector<double>> cost(n, std::vector<double>(n, infinity));
      std::vector<std::vector<std::size_t>> split(n, std::vector<std::size_t>(n, none));
      for(std::size_t i = 0; i + 1 < n; ++i) cost[i][i + 1] = 0.;
      for(std::size_t gap = 2; gap < n; ++gap)
        for(std::size_t i = 0; i + gap < n; ++i) {
          const std::size_t j = i + gap;
          const double diagonal = (i == 0 && j == n - 1) ? 0. : length(i, j);
          for(std::size_t k = i + 1; k < j; ++k) {
            if(cost[i][k] == infinity || cost[k][j] == infinity || !allowed(i, k, j)) continue;
            const double c = cost[i][k] + cost[k][j] + diagonal;
            if(c < cost[i][j]) { cost[i][j] = c; split[i][j] = k; }
          }
        }
      if(cost[0][n - 1] == infinity) {
        // No triangulation of the cycle alone (its diagonals are output edges already): a fan
        // from a new vertex at the centroid of the cycle, the mirror image of that of the
        // mirror cycle.
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for(std::size_t v : cycle) centroid += x[v];
        centroid /= double(n);
        bool flat = false;
        for(std::size_t i = 0; i < n && !flat; ++i) {
          const Eigen::Vector3d &a = x[cycle[i]], &b = x[cycle[(i + 1) % n]];
          flat = (b - a).cross(centroid - a).norm() <= 1e-12 * (b - a).squaredNorm() + 1e-300;
        }
        if(flat) continue;
        const std::size_t c = x.size();
        x.push_back(centroid);
        out_.anchor_vertices.push_back(nearest_vertex_(centroid));
        for(std::size_t i = 0; i < n; ++i) {
          const std::array<std::size_t, 3> tri = {cycle[i], cycle[(i + 1) % n], c};
          t.push_back(tri);
          for(int e = 0; e < 3; ++e) directed.insert(Edge(tri[e], tri[(e + 1) % 3]));
        }
        continue;
      }
      std::vector<std::pair<std::size_t, std::size_t>> stack = {{0, n - 1}};
      while(!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if(j < i + 2) continue;
        const std::size_t k = split[i][j];
        const std::array<std::size_t, 3> tri = {cycle[i], cycle[k], cycle[j]};
        t.push_back(tri);
        std::array<std::size_t, 3> key = tri;
        std::sort(key.begin(), key.end());
        keys.insert(key);
        for(int c = 0; c < 3; ++c) directed.insert(Edge(tri[c], tri[(c + 1) % 3]));
        stack.push_back({i, k});
        stack.push_back({k, j});
      }
    }
  }

  void place_anchors(bool optimize)
  {
    out_.anchors.clear();
    std::vector<std::size_t> labels;
    for(std::size_t v : out_.anchor_vertices) {
      const Eigen::Vector3d& x = m_.points[v];
      labels.clear();
      for(std::size_t i = m_.vertex_face_begin[v]; i < m_.vertex_face_begin[v + 1]; ++i)
        labels.push_back(label_[m_.vertex_face[i]]);
      std::sort(labels.begin(), labels.end());
      labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double weight = 0.;
      for(std::size_t l : labels) {
        const Eigen::Vector3d& n = p_.patch_normal(l);
        const double w = p_.patch_area(l);
        sum += w * (x - n.dot(x - p_.patch_center(l)) * n);
        weight += w;
      }
      out_.anchors.push_back(optimize && weight > 0. ? Eigen::Vector3d(sum / weight) : x);
    }
  }

  // Anchors matched across each plane, moved to exact mirror positions.
  void snap_mirrors()
  {
    if(planes_.empty() || out_.anchor_vertices.empty()) return;
    const std::size_t na = out_.anchor_vertices.size();
    std::map<std::vector<std::size_t>, std::vector<std::size_t>> by_proxies;
    std::vector<std::vector<std::size_t>> proxies(na);
    for(std::size_t a = 0; a < na; ++a) {
      boundary_count(out_.anchor_vertices[a], &proxies[a]);
      by_proxies[proxies[a]].push_back(a);
    }
    const double tolerance = 2. * m_.average_edge_length;
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> pairs(planes_.size());
    std::vector<char> matched(na, 0);
    for(std::size_t j = 0; j < planes_.size(); ++j) {
      auto nearest = [&](std::size_t a) {
        const Eigen::Vector3d image = planes_[j].reflect(m_.points[out_.anchor_vertices[a]]);
        std::size_t best = none;
        double d = tolerance;
        for(std::size_t b : by_proxies[proxies[a]]) {
          const double e = (m_.points[out_.anchor_vertices[b]] - image).norm();
          if(e <= d) { d = e; best = b; }
        }
        return best;
      };
      for(std::size_t a = 0; a < na; ++a) {
        const std::size_t b = nearest(a);
        if(b != none && b >= a && nearest(b) == a) {
          pairs[j].push_back({a, b});
          matched[a] = matched[b] = 1;
        }
      }
    }
    // Alternating projections onto the mirror constraints of each plane.
    for(int round = 0; round < 8; ++round)
      for(std::size_t j = 0; j < planes_.size(); ++j)
        for(const auto& [a, b] : pairs[j]) {
          const Dplane& plane = planes_[j];
          if(a == b) {
            out_.anchors[a] -= signed_distance(plane, out_.anchors[a]) * plane.normal;
          } else {
            const Eigen::Vector3d mean = 0.5 * (out_.anchors[a] + plane.reflect(out_.anchors[b]));
            out_.anchors[a] = mean;
            out_.anchors[b] = plane.reflect(mean);
          }
        }
    out_.matched_anchors = std::size_t(std::count(matched.begin(), matched.end(), 1));
  }

  const Remeshing_mesh& m_;
  const Symmetric_partition& p_;
  const std::vector<Dplane>& planes_;
  const std::vector<std::uint64_t>& vertex_planes_;
  std::function<std::size_t(const Eigen::Vector3d&)> nearest_vertex_;
  const std::vector<std::size_t>& label_;
  const std::size_t t_;
  std::vector<std::size_t> anchor_, cycles_;
  Remeshing_output out_;
};

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESHING_H
