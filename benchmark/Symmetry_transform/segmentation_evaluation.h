// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The four metrics of the Princeton Segmentation Benchmark (Chen, Golovinskiy and Funkhouser
// 2009), comparing a segmentation (one label per face) with a reference segmentation of the same
// mesh, written from their definitions (the benchmark's segEval was read for the conventions,
// not copied):
// - Cut Discrepancy (CD): the mean geodesic distance from the vertices on the cuts of one
//   segmentation to the cuts of the other, both ways, over the mesh's average radius;
// - Hamming distance (HD): the area left over by the best-matching segments, Rm from the
//   reference's side (missing), Rf from the evaluated side (false alarms), HD their mean;
// - Rand Index: the fraction of face pairs on which the two disagree (same segment or not), the
//   complement 1 - RI being what the benchmark reports;
// - Global and Local Consistency Errors (GCE, LCE; Martin et al. 2001): the refinement error of
//   each face's segment, globally one-directional, locally the smaller direction per face.
// Labels need not be contiguous. Plain C++17, no CGAL: the tests check it on hand-made cases.

#ifndef SYMMETRY_TRANSFORM_SEGMENTATION_EVALUATION_H
#define SYMMETRY_TRANSFORM_SEGMENTATION_EVALUATION_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <utility>
#include <vector>

namespace segmentation_evaluation {

typedef std::array<double, 3> Point;
typedef std::array<std::size_t, 3> Triangle;

// What the metrics need of a mesh, computed once per mesh: face areas, the edges between two
// faces, the vertex graph weighted by edge lengths (geodesics for CD) and the average radius.
struct Mesh_data
{
  std::vector<double> areas;                                    // of each face
  std::vector<std::pair<std::size_t, std::size_t>> edge_faces;   // the two faces of each inner edge
  std::vector<std::pair<std::size_t, std::size_t>> edge_vertices; // its two vertices
  std::vector<std::vector<std::pair<std::size_t, double>>> neighbours; // of each vertex, with the length
  double average_radius = 0.; // area-weighted mean distance from the face centroids to their area-weighted centroid

  std::size_t number_of_faces() const { return areas.size(); }
};

inline double distance(const Point& a, const Point& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

inline double triangle_area(const Point& a, const Point& b, const Point& c)
{
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// The area-weighted mean distance of the face centroids to their area-weighted centroid (the
// scale that CD is divided by: a segmentation's score does not depend on the mesh's size).
inline double average_radius(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                             const std::vector<double>& areas)
{
  std::vector<Point> centroids(triangles.size());
  Point center{0., 0., 0.};
  double total = 0.;
  for(std::size_t f = 0; f < triangles.size(); ++f) {
    for(int i = 0; i < 3; ++i)
      centroids[f][i] = (points[triangles[f][0]][i] + points[triangles[f][1]][i] + points[triangles[f][2]][i]) / 3.;
    for(int i = 0; i < 3; ++i) center[i] += areas[f] * centroids[f][i];
    total += areas[f];
  }
  if(!(total > 0.)) return 0.;
  for(double& x : center) x /= total;
  double sum = 0.;
  for(std::size_t f = 0; f < triangles.size(); ++f) sum += areas[f] * distance(centroids[f], center);
  return sum / total;
}

inline Mesh_data mesh_data(const std::vector<Point>& points, const std::vector<Triangle>& triangles)
{
  Mesh_data m;
  m.areas.resize(triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f)
    m.areas[f] = triangle_area(points[triangles[f][0]], points[triangles[f][1]], points[triangles[f][2]]);
  // Faces of each undirected edge; an edge of two faces is an inner edge (a possible cut).
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> faces_of_edge;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = triangles[f][i], b = triangles[f][(i + 1) % 3];
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  m.neighbours.resize(points.size());
  for(const auto& [edge, faces] : faces_of_edge) {
    const double length = distance(points[edge.first], points[edge.second]);
    m.neighbours[edge.first].push_back({edge.second, length});
    m.neighbours[edge.second].push_back({edge.first, length});
    if(faces.size() == 2) {
      m.edge_faces.push_back({faces[0], faces[1]});
      m.edge_vertices.push_back(edge);
    }
  }
  m.average_radius = average_radius(points, triangles, m.areas);
  return m;
}

// Labels renumbered 0 .. k-1 in order of first appearance; returns k.
inline std::size_t renumber(std::vector<std::size_t>& labels)
{
  std::map<std::size_t, std::size_t> index;
  for(std::size_t& l : labels) l = index.emplace(l, index.size()).first->second;
  return index.size();
}

// The overlap of two segmentations: faces and area of each pair of segments, and of each segment.
struct Overlap
{
  std::size_t rows = 0, columns = 0; // segments of the evaluated and of the reference segmentation
  std::vector<double> count, area;   // rows x columns, row-major
  std::vector<double> row_count, row_area, column_count, column_area;
  double faces = 0., total_area = 0.;
};

inline Overlap overlap(const Mesh_data& m, std::vector<std::size_t> evaluated, std::vector<std::size_t> reference)
{
  Overlap o;
  o.rows = renumber(evaluated);
  o.columns = renumber(reference);
  o.count.assign(o.rows * o.columns, 0.);
  o.area.assign(o.rows * o.columns, 0.);
  o.row_count.assign(o.rows, 0.);
  o.row_area.assign(o.rows, 0.);
  o.column_count.assign(o.columns, 0.);
  o.column_area.assign(o.columns, 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const std::size_t i = evaluated[f], j = reference[f];
    o.count[i * o.columns + j] += 1.;
    o.area[i * o.columns + j] += m.areas[f];
    o.row_count[i] += 1.;
    o.row_area[i] += m.areas[f];
    o.column_count[j] += 1.;
    o.column_area[j] += m.areas[f];
    o.faces += 1.;
    o.total_area += m.areas[f];
  }
  return o;
}

// 1 - RI: the fraction of the pairs of faces that one segmentation puts in the same segment and
// the other not, from the sums of C(n, 2) over the segments and over their intersections.
inline double rand_index_error(const Overlap& o)
{
  auto pairs = [](double n) { return n * (n - 1.) / 2.; };
  double disagreements = 0.;
  for(double n : o.row_count) disagreements += pairs(n);
  for(double n : o.column_count) disagreements += pairs(n);
  for(double n : o.count) disagreements -= 2. * pairs(n);
  return o.faces > 1. ? disagreements / pairs(o.faces) : 0.;
}

struct Hamming
{
  double distance = 0., missing = 0., false_alarm = 0.; // HD, Rm, Rf
};

// Each reference segment is matched to the evaluated segment that overlaps it most; the area
// outside those matches, over the total area, is Rm. Rf swaps the roles. HD = (Rm + Rf) / 2.
inline Hamming hamming_distance(const Overlap& o)
{
  double matched_reference = 0., matched_evaluated = 0.;
  for(std::size_t j = 0; j < o.columns; ++j) {
    double best = 0.;
    for(std::size_t i = 0; i < o.rows; ++i) best = std::max(best, o.area[i * o.columns + j]);
    matched_reference += best;
  }
  for(std::size_t i = 0; i < o.rows; ++i)
    matched_evaluated += *std::max_element(o.area.begin() + std::ptrdiff_t(i * o.columns),
                                           o.area.begin() + std::ptrdiff_t((i + 1) * o.columns));
  Hamming h;
  // max(0, .): the sums of the same areas in another order may differ by a rounding error.
  h.missing = std::max(0., o.total_area - matched_reference) / o.total_area;
  h.false_alarm = std::max(0., o.total_area - matched_evaluated) / o.total_area;
  h.distance = 0.5 * (h.missing + h.false_alarm);
  return h;
}

struct Consistency
{
  double gce = 0., lce = 0.;             // refinement errors measured by area (the benchmark's plots)
  double gce_faces = 0., lce_faces = 0.; // measured by face counts
};

// For a face f in segment i of one segmentation and j of the other, E(i, j) = 1 - |i n j| / |i|
// is how much of f's segment the other one leaves out: 0 if i refines j. GCE: the smaller of the
// two one-directional sums over the faces, over the number of faces; LCE: the smaller direction
// face by face. |.| measures area (the benchmark's GCE and LCE) or face counts; each face
// counts once in the sums either way, as in segEval.
inline Consistency consistency_errors(const Overlap& o)
{
  double forward = 0., backward = 0., local = 0., forward_f = 0., backward_f = 0., local_f = 0.;
  for(std::size_t i = 0; i < o.rows; ++i)
    for(std::size_t j = 0; j < o.columns; ++j) {
      const double n = o.count[i * o.columns + j];
      if(n == 0.) continue;
      const double a = o.area[i * o.columns + j];
      const double e12 = 1. - a / o.row_area[i], e21 = 1. - a / o.column_area[j];
      const double f12 = 1. - n / o.row_count[i], f21 = 1. - n / o.column_count[j];
      forward += n * e12; backward += n * e21; local += n * std::min(e12, e21);
      forward_f += n * f12; backward_f += n * f21; local_f += n * std::min(f12, f21);
    }
  Consistency c;
  c.gce = std::min(forward, backward) / o.faces;
  c.lce = local / o.faces;
  c.gce_faces = std::min(forward_f, backward_f) / o.faces;
  c.lce_faces = local_f / o.faces;
  return c;
}

// The vertices on the cuts of a segmentation: those of the inner edges between two segments.
inline std::vector<std::size_t> cut_vertices(const Mesh_data& m, const std::vector<std::size_t>& labels)
{
  std::vector<bool> on_cut(m.neighbours.size(), false);
  for(std::size_t e = 0; e < m.edge_faces.size(); ++e)
    if(labels[m.edge_faces[e].first] != labels[m.edge_faces[e].second])
      on_cut[m.edge_vertices[e].first] = on_cut[m.edge_vertices[e].second] = true;
  std::vector<std::size_t> result;
  for(std::size_t v = 0; v < on_cut.size(); ++v)
    if(on_cut[v]) result.push_back(v);
  return result;
}

// Shortest distances along the mesh's edges from the nearest source (Dijkstra); infinity where
// no source is reachable (another connected component).
inline std::vector<double> edge_distances(const Mesh_data& m, const std::vector<std::size_t>& sources)
{
  std::vector<double> d(m.neighbours.size(), std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for(std::size_t s : sources) {
    d[s] = 0.;
    queue.push({0., s});
  }
  while(!queue.empty()) {
    const auto [dv, v] = queue.top();
    queue.pop();
    if(dv > d[v]) continue;
    for(const auto& [w, length] : m.neighbours[v])
      if(dv + length < d[w]) {
        d[w] = dv + length;
        queue.push({d[w], w});
      }
  }
  return d;
}

// CD: the mean, over the cut vertices of both segmentations, of the geodesic distance to the
// other's cuts, over the average radius. Undefined (none) when either has no cut, as in segEval,
// whose score then counts in no mean. A cut vertex from which no cut of the other is reachable
// (another connected component) is left out of the mean.
inline std::optional<double> cut_discrepancy(const Mesh_data& m, const std::vector<std::size_t>& evaluated,
                                             const std::vector<std::size_t>& reference)
{
  const std::vector<std::size_t> cuts[2] = {cut_vertices(m, evaluated), cut_vertices(m, reference)};
  if(cuts[0].empty() || cuts[1].empty() || !(m.average_radius > 0.)) return std::nullopt;
  double sum = 0., count = 0.;
  for(int side = 0; side < 2; ++side) {
    const std::vector<double> d = edge_distances(m, cuts[1 - side]);
    for(std::size_t v : cuts[side])
      if(std::isfinite(d[v])) {
        sum += d[v];
        count += 1.;
      }
  }
  if(count == 0.) return std::nullopt;
  return sum / count / m.average_radius;
}

// All the metrics of one comparison.
struct Scores
{
  std::optional<double> cut_discrepancy;
  Hamming hamming;
  double rand_index_error = 0.;
  Consistency consistency;
};

inline Scores compare(const Mesh_data& m, const std::vector<std::size_t>& evaluated, const std::vector<std::size_t>& reference)
{
  const Overlap o = overlap(m, evaluated, reference);
  Scores s;
  s.cut_discrepancy = cut_discrepancy(m, evaluated, reference);
  s.hamming = hamming_distance(o);
  s.rand_index_error = rand_index_error(o);
  s.consistency = consistency_errors(o);
  return s;
}

} // namespace segmentation_evaluation

#endif // SYMMETRY_TRANSFORM_SEGMENTATION_EVALUATION_H
