// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FUZZY_CLUSTERING_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FUZZY_CLUSTERING_H

// One split of a segment, as Katz and Tal split a mesh: the faces' feature vectors are clustered
// into two fuzzy clusters (area-weighted k-means, seeded k-means++ starts, then fuzzy c-means with
// fuzzifier 2: a face's membership of a cluster falls with its distance to the centre), and a
// graph cut on the dual graph (CGAL::alpha_expansion_graphcut) turns the memberships into labels
// whose boundary is short and follows concave creases. Plain doubles and Eigen throughout.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/Alpha_expansion_MaxFlow_tag.h>
#include <CGAL/boost/graph/alpha_expansion_graphcut.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// k-means++ starts of the 2-means, the best of which is kept: one start can settle on a poor
// local minimum, five rarely all do.
constexpr int clustering_starts = 5;
// A bound on the iterations of k-means and of fuzzy c-means, which converge in far fewer: it only
// guards against a cycle of rounding.
constexpr int max_clustering_iterations = 100;
// Fuzzy c-means stops when its centres (features in [0, 1]) move less than this.
constexpr double center_convergence = 1e-7;
// The least membership of a face in a label, as CGAL's SDF segmentation: every face may take
// every label, at a price.
constexpr double least_membership = 5e-6;
// Added to every data cost of the graph cut: max-flow rejects zero capacities to the source or
// the sink (CGAL's SDF segmentation keeps them above machine epsilon for the same reason).
constexpr double least_label_cost = 1e-12;

// Rows of `x`: the feature vectors; `weights`: the faces' areas.
struct Fuzzy_two_clusters
{
  Eigen::MatrixXd centers;    // 2 x K
  Eigen::MatrixXd membership; // n x 2, rows summing to 1
};

// Area-weighted k-means with k = 2 from a k-means++ start drawn from `random`; returns the
// weighted sum of squared distances to the nearest centre.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double two_means(const Eigen::MatrixXd& x, const std::vector<double>& weights, CGAL::Random& random,
                                                     Eigen::MatrixXd& centers);

// The fuzzy 2-clustering of the rows of `x`: the best of `starts` k-means runs (lowest inertia,
// the first on ties), refined by fuzzy c-means (fuzzifier 2). Deterministic for a seed.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Fuzzy_two_clusters fuzzy_two_clusters(const Eigen::MatrixXd& x, const std::vector<double>& weights,
                                                                          unsigned seed, int starts = clustering_starts);

// Labels 0/1 of the faces of a segment (`faces`; `local`: the position of a face in `faces`, or
// -1) from their memberships (rows in the order of `faces`): the labelling that minimises
//   sum over faces of (A_f / mean A) (-log u_f(label))
//   + lambda sum over cut dual edges of (l_e / mean l) / (1 + d_e / mean d),
// d_e the angular distance of the edge (Katz-Tal); the boundary is thus short and prefers
// concave creases.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> graph_cut_labels(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces,
                                                                              const std::vector<std::size_t>& local,
                                                                              const Eigen::MatrixXd& membership, double lambda);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double two_means(const Eigen::MatrixXd& x, const std::vector<double>& weights, CGAL::Random& random,
                                                     Eigen::MatrixXd& centers)
{
  const Eigen::Index n = x.rows();
  auto draw = [&](const std::vector<double>& w) { // an index with probability proportional to w
    double total = 0.;
    for(double v : w) total += v;
    double r = random.get_double(0., total);
    for(Eigen::Index i = 0; i < n; ++i)
      if((r -= w[std::size_t(i)]) < 0.) return i;
    return n - 1;
  };
  centers.resize(2, x.cols());
  centers.row(0) = x.row(draw(weights));
  std::vector<double> w(static_cast<std::size_t>(n));
  for(Eigen::Index i = 0; i < n; ++i) w[std::size_t(i)] = weights[std::size_t(i)] * (x.row(i) - centers.row(0)).squaredNorm();
  centers.row(1) = x.row(draw(w));
  std::vector<int> label(std::size_t(n), -1);
  double inertia = 0.;
  for(int iteration = 0; iteration < max_clustering_iterations; ++iteration) {
    poll_progress(); // an iteration over a million faces takes a tenth of a second (progress.h)
    bool changed = false;
    inertia = 0.;
    for(Eigen::Index i = 0; i < n; ++i) {
      const double d0 = (x.row(i) - centers.row(0)).squaredNorm(), d1 = (x.row(i) - centers.row(1)).squaredNorm();
      const int l = d1 < d0 ? 1 : 0;
      inertia += weights[std::size_t(i)] * (std::min)(d0, d1);
      if(l != label[std::size_t(i)]) changed = true;
      label[std::size_t(i)] = l;
    }
    if(!changed) break;
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(2, x.cols());
    double mass[2] = {0., 0.};
    for(Eigen::Index i = 0; i < n; ++i) {
      sums.row(label[std::size_t(i)]) += weights[std::size_t(i)] * x.row(i);
      mass[label[std::size_t(i)]] += weights[std::size_t(i)];
    }
    for(int c = 0; c < 2; ++c)
      if(mass[c] > 0.) centers.row(c) = sums.row(c) / mass[c];
  }
  return inertia;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Fuzzy_two_clusters fuzzy_two_clusters(const Eigen::MatrixXd& x, const std::vector<double>& weights,
                                                                          unsigned seed, int starts)
{
  CGAL::Random random(seed);
  Fuzzy_two_clusters result;
  double best = std::numeric_limits<double>::infinity();
  for(int s = 0; s < starts; ++s) {
    Eigen::MatrixXd centers;
    const double inertia = two_means(x, weights, random, centers);
    if(inertia < best) {
      best = inertia;
      result.centers = centers;
    }
  }
  const Eigen::Index n = x.rows();
  result.membership.resize(n, 2);
  for(int iteration = 0; iteration < max_clustering_iterations; ++iteration) {
    poll_progress();
    for(Eigen::Index i = 0; i < n; ++i) {
      const double d0 = (x.row(i) - result.centers.row(0)).squaredNorm(),
                   d1 = (x.row(i) - result.centers.row(1)).squaredNorm();
      // u_c = (1/d_c^2) / sum_k (1/d_k^2), written without dividing by zero
      const double u0 = d0 + d1 > 0. ? d1 / (d0 + d1) : 0.5;
      result.membership(i, 0) = u0;
      result.membership(i, 1) = 1. - u0;
    }
    Eigen::MatrixXd centers = Eigen::MatrixXd::Zero(2, x.cols());
    for(int c = 0; c < 2; ++c) {
      double mass = 0.;
      for(Eigen::Index i = 0; i < n; ++i) {
        const double m = weights[std::size_t(i)] * result.membership(i, c) * result.membership(i, c);
        centers.row(c) += m * x.row(i);
        mass += m;
      }
      centers.row(c) = mass > 0. ? Eigen::RowVectorXd(centers.row(c) / mass) : Eigen::RowVectorXd(result.centers.row(c));
    }
    const double moved = (centers - result.centers).norm();
    result.centers = centers;
    if(moved < center_convergence) break;
  }
  return result;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> graph_cut_labels(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces,
                                                                              const std::vector<std::size_t>& local,
                                                                              const Eigen::MatrixXd& membership, double lambda)
{
  const std::size_t none = std::size_t(-1);
  double mean_area = 0.;
  for(std::size_t f : faces) mean_area += mesh.areas[f];
  mean_area /= double(faces.size());
  std::vector<std::size_t> inner; // the dual edges inside the segment
  double mean_length = 0., mean_distance = 0.;
  for(std::size_t f : faces)
    for(std::size_t e : mesh.face_edges[f]) {
      const Dual_edge& d = mesh.edges[e];
      if(d.first != f || local[d.second] == none) continue; // each inner edge once
      inner.push_back(e);
      mean_length += d.length;
      mean_distance += d.angular_distance;
    }
  if(!inner.empty()) {
    mean_length /= double(inner.size());
    mean_distance /= double(inner.size());
  }
  // Flat arrays, read through the vector interface of alpha_expansion_graphcut() as CGAL's SDF
  // segmentation does: a boost::adjacency_list would allocate per face and per edge.
  std::vector<std::vector<double>> costs(2, std::vector<double>(faces.size()));
  std::vector<std::size_t> labels(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const double scale = mean_area > 0. ? mesh.areas[faces[i]] / mean_area : 1.;
    for(int c = 0; c < 2; ++c)
      costs[std::size_t(c)][i] =
        scale * -std::log((std::max)(membership(Eigen::Index(i), c), least_membership)) + least_label_cost;
    labels[i] = membership(Eigen::Index(i), 1) > membership(Eigen::Index(i), 0) ? 1 : 0;
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<double> weights;
  pairs.reserve(inner.size());
  weights.reserve(inner.size());
  for(std::size_t e : inner) {
    const Dual_edge& d = mesh.edges[e];
    const double length = mean_length > 0. ? d.length / mean_length : 1.;
    const double crease = mean_distance > 0. ? 1. / (1. + d.angular_distance / mean_distance) : 1.;
    pairs.emplace_back(local[d.first], local[d.second]);
    weights.push_back(lambda * length * crease);
  }
  if(lambda > 0. && !inner.empty())
    CGAL::alpha_expansion_graphcut(pairs, weights, costs, labels, CGAL::Alpha_expansion_MaxFlow_tag());
  return labels;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_FUZZY_CLUSTERING_H
