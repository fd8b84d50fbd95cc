// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The statistics of the public benchmarks (benchmark/Symmetry_transform/retrieval_evaluation.h
// and segmentation_evaluation.h) on hand-made cases whose values are worked out by hand.

#include "../../benchmark/Symmetry_transform/retrieval_evaluation.h"
#include "../../benchmark/Symmetry_transform/segmentation_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace {

namespace RE = retrieval_evaluation;
namespace SE = segmentation_evaluation;

// A 2 x 1 rectangle in the plane z = 0 cut into four right triangles of area 1/2:
// faces 0 (b0 b1 t0), 1 (b1 t1 t0), 2 (b1 b2 t1), 3 (b2 t2 t1); b = y 0, t = y 1.
SE::Mesh_data strip()
{
  const std::vector<SE::Point> points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  const std::vector<SE::Triangle> triangles = {{0, 1, 3}, {1, 4, 3}, {1, 2, 4}, {2, 5, 4}};
  return SE::mesh_data(points, triangles);
}

const std::vector<std::size_t> one_segment = {0, 0, 0, 0};
const std::vector<std::size_t> halves = {0, 0, 1, 1};    // cut along b1 t1
const std::vector<std::size_t> first_apart = {0, 1, 1, 1}; // cut along b1 t0

TEST(SegmentationEvaluation, IdenticalSegmentationsScoreZeroWhateverTheLabels)
{
  const SE::Scores s = SE::compare(strip(), halves, {7, 7, 3, 3});
  EXPECT_DOUBLE_EQ(s.rand_index_error, 0.);
  EXPECT_DOUBLE_EQ(s.hamming.distance, 0.);
  EXPECT_DOUBLE_EQ(s.consistency.gce, 0.);
  EXPECT_DOUBLE_EQ(s.consistency.lce, 0.);
  ASSERT_TRUE(s.cut_discrepancy.has_value());
  EXPECT_DOUBLE_EQ(*s.cut_discrepancy, 0.);
}

TEST(SegmentationEvaluation, OneSegmentAgainstTwoHalvesByHand)
{
  const SE::Scores s = SE::compare(strip(), one_segment, halves);
  // 6 pairs of faces; the halves separate 4 of them, one segment none.
  EXPECT_DOUBLE_EQ(s.rand_index_error, 4. / 6.);
  // Each half lies in the single segment (Rm = 0); the single segment's best half leaves 1 of 2.
  EXPECT_DOUBLE_EQ(s.hamming.missing, 0.);
  EXPECT_DOUBLE_EQ(s.hamming.false_alarm, 0.5);
  EXPECT_DOUBLE_EQ(s.hamming.distance, 0.25);
  // The halves refine the single segment: no consistency error.
  EXPECT_DOUBLE_EQ(s.consistency.gce, 0.);
  EXPECT_DOUBLE_EQ(s.consistency.lce, 0.);
  // No cut on one side: CD is undefined.
  EXPECT_FALSE(s.cut_discrepancy.has_value());
}

TEST(SegmentationEvaluation, TwoDifferentSplitsByHand)
{
  const SE::Scores s = SE::compare(strip(), halves, first_apart);
  // Same-segment pairs: halves {01, 23}, first_apart {12, 13, 23}; they disagree on 01, 12, 13.
  EXPECT_DOUBLE_EQ(s.rand_index_error, 3. / 6.);
  // Face by face, halves w.r.t. first_apart: 1/2, 1/2, 0, 0 (sum 1); the converse: 0, 2/3, 1/3,
  // 1/3 (sum 4/3). GCE = min(1, 4/3) / 4; LCE = (0 + 1/2 + 0 + 0) / 4. Equal areas: the face-count
  // variants agree.
  EXPECT_DOUBLE_EQ(s.consistency.gce, 0.25);
  EXPECT_DOUBLE_EQ(s.consistency.lce, 0.125);
  EXPECT_DOUBLE_EQ(s.consistency.gce_faces, 0.25);
  EXPECT_DOUBLE_EQ(s.consistency.lce_faces, 0.125);
  // Reference {0} matches halves' first segment (1/2), {1,2,3} its second (1): Rm = 1/2 / 2.
  // Halves' {0,1} matches {0} or {1,2,3} (1/2), {2,3} matches {1,2,3} (1): Rf = 1/2 / 2.
  EXPECT_DOUBLE_EQ(s.hamming.missing, 0.25);
  EXPECT_DOUBLE_EQ(s.hamming.false_alarm, 0.25);
  // Cuts {b1, t1} and {b1, t0}: b1 is on both, t1 and t0 are one edge of length 1 from the other
  // cut: mean 2/4, over the average radius (sqrt(17) + sqrt(5)) / 12 of the four centroids.
  ASSERT_TRUE(s.cut_discrepancy.has_value());
  EXPECT_NEAR(*s.cut_discrepancy, 0.5 / ((std::sqrt(17.) + std::sqrt(5.)) / 12.), 1e-12);
}

TEST(SegmentationEvaluation, AreaWeighsTheHammingDistance)
{
  // The same strip with its right half stretched to x in [1, 3]: faces 2 and 3 of area 1.
  const std::vector<SE::Point> points = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 1, 0}};
  const std::vector<SE::Triangle> triangles = {{0, 1, 3}, {1, 4, 3}, {1, 2, 4}, {2, 5, 4}};
  const SE::Scores s = SE::compare(SE::mesh_data(points, triangles), one_segment, halves);
  EXPECT_DOUBLE_EQ(s.hamming.false_alarm, 1. / 3.); // the best half covers 2 of the area 3
  EXPECT_DOUBLE_EQ(s.rand_index_error, 4. / 6.);    // face counts, not areas
}

// Six models in two classes of three: A = {0, 1, 2}, B = {3, 4, 5}.
RE::Classification two_classes()
{
  std::istringstream cla("PSB 1\n3 6\nroot 0 0\nA root 3\n10\n11\n12\nB root 3\n13\n14\n15\n");
  return RE::read_classification(cla);
}

TEST(RetrievalEvaluation, ReadsAClassification)
{
  const RE::Classification c = two_classes();
  ASSERT_EQ(c.class_names.size(), 2u); // the empty root is dropped
  EXPECT_EQ(c.model_ids, (std::vector<int>{10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(c.class_of, (std::vector<std::size_t>{0, 0, 0, 1, 1, 1}));
}

TEST(RetrievalEvaluation, OneQueryByHand)
{
  // Four models, classes {0, 1} and {2, 3}; query 0 ranks 2, 1, 3 (distances 0.3, 0.1, 0.5).
  const std::vector<double> row = {0., 0.3, 0.1, 0.5};
  const std::vector<std::size_t> class_of = {0, 0, 1, 1};
  const std::vector<std::size_t> list = RE::retrieval_list(row, 0);
  EXPECT_EQ(list, (std::vector<std::size_t>{2, 1, 3}));
  const RE::Scores s = RE::query_scores(RE::relevance(list, class_of, 0), 1);
  EXPECT_DOUBLE_EQ(s.nearest_neighbour, 0.);
  EXPECT_DOUBLE_EQ(s.first_tier, 0.);
  EXPECT_DOUBLE_EQ(s.second_tier, 1.);
  EXPECT_DOUBLE_EQ(s.dcg, 1. / std::log2(2.)); // the hit at rank 2 over the perfect 1
  EXPECT_DOUBLE_EQ(s.e_measure, 2. * (1. / 3.) * 1. / (1. / 3. + 1.)); // P = 1/3, R = 1
}

TEST(RetrievalEvaluation, TiesRankInModelOrder)
{
  EXPECT_EQ(RE::retrieval_list({0., 1., 1., 0.5}, 0), (std::vector<std::size_t>{3, 1, 2}));
}

TEST(RetrievalEvaluation, MatrixByHand)
{
  // Query 0 ranks 1 (A), 3 (B), 2 (A), 4, 5; every other query finds its class first.
  std::vector<std::vector<double>> d(6, std::vector<double>(6, 1.));
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
      d[i][j] = i == j ? 0. : (i / 3 == j / 3 ? 0.1 : 0.9);
  d[0] = {0., 0.1, 0.3, 0.2, 0.4, 0.5};
  const RE::Summary s = RE::evaluate(d, two_classes());
  EXPECT_EQ(s.queries, 6u);
  // Query 0: NN 1, FT 1/2, ST 1, E with 2 hits in 5 (P 2/5, R 1), DCG (1 + 1/log2 3) / 2.
  const double e0 = 2. * 0.4 / 1.4, dcg0 = (1. + 1. / std::log2(3.)) / 2.;
  EXPECT_DOUBLE_EQ(s.per_class[0].first_tier, (0.5 + 1. + 1.) / 3.);
  EXPECT_DOUBLE_EQ(s.mean.nearest_neighbour, 1.);
  EXPECT_DOUBLE_EQ(s.mean.first_tier, (0.5 + 5.) / 6.);
  EXPECT_DOUBLE_EQ(s.mean.second_tier, 1.);
  EXPECT_DOUBLE_EQ(s.mean.dcg, (dcg0 + 5.) / 6.);
  // Perfect queries: 2 hits in 5 as well, E = e0 for all.
  EXPECT_DOUBLE_EQ(s.mean.e_measure, e0);
  // The precision-recall curve counts the query as its first result (psbPlot): query 0 finds its
  // class at ranks 1 (itself), 2 and 4 (precision 1, 1, 3/4), the others at 1, 2, 3. Recall 1/20
  // .. 6/20 are below 1/3: no point there. At 3/4 query 0 interpolates a quarter of the way from
  // 1 to 3/4.
  ASSERT_EQ(s.precision.size(), RE::recall_levels);
  EXPECT_DOUBLE_EQ(s.precision[5], 0.);                      // recall 0.30
  EXPECT_DOUBLE_EQ(s.precision[6], 1.);                      // recall 0.35
  EXPECT_DOUBLE_EQ(s.precision[14], (0.9375 + 5.) / 6.);     // recall 0.75
  EXPECT_DOUBLE_EQ(s.precision[19], (0.75 + 5.) / 6.);       // recall 1
}

TEST(RetrievalEvaluation, SmallClassesAreLeftOut)
{
  std::istringstream cla("PSB 1\n2 5\nA 0 3\n1\n2\n3\nB 0 2\n4\n5\n");
  std::vector<std::vector<double>> d(5, std::vector<double>(5, 1.));
  EXPECT_EQ(RE::evaluate(d, RE::read_classification(cla)).queries, 3u);
}

} // namespace
