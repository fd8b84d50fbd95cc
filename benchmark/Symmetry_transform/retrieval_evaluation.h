// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Retrieval statistics of the Princeton Shape Benchmark (Shilane et al. 2004), written from their
// definitions (the benchmark's psbTable and psbPlot tools were read for the conventions, not
// copied): a classification read from a .cla file, a square matrix of distances, and for every
// query its ranked list of the other models, from which nearest neighbour, first and second
// tier, E-measure, discounted cumulative gain and the precision-recall curve follow.
// Plain C++17, no CGAL: the tests check it on hand-made cases.
//
// The statistics leave the query out of its list (psbTable); the precision-recall curve counts it
// as the first result, relevant, as psbPlot does (its USE_QUERY setting): recall k / C for the
// k-th of the C models of the class, the query being the first.

#ifndef SYMMETRY_TRANSFORM_RETRIEVAL_EVALUATION_H
#define SYMMETRY_TRANSFORM_RETRIEVAL_EVALUATION_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <istream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace retrieval_evaluation {

// The E-measure looks at the first 32 results only: what a user sees on a first page.
constexpr std::size_t e_measure_depth = 32;
// Classes of at most 2 models are left out of every average: one relevant model at most.
constexpr std::size_t smallest_evaluated_class = 3;
// The precision-recall curve is sampled at recall 1/20, 2/20, ..., 1.
constexpr std::size_t recall_levels = 20;
// The name of the benchmark's "miscellaneous" class, never evaluated.
const char* const miscellaneous_class = "-1";

// Models in the order of the .cla file (the order of the matrix's rows), each with its class.
struct Classification
{
  std::vector<std::string> class_names; // the classes that hold models, in file order
  std::vector<int> model_ids;           // of each model
  std::vector<std::size_t> class_of;    // of each model, an index into class_names
};

// Reads a PSB classification: "PSB 1", "<classes> <models>", then per class "<name> <parent>
// <count>" followed by <count> model ids. Classes without models (inner nodes) are dropped.
inline Classification read_classification(std::istream& in)
{
  std::string magic, version;
  std::size_t classes = 0, models = 0;
  if(!(in >> magic >> version >> classes >> models) || magic != "PSB")
    throw std::runtime_error("not a PSB classification file");
  Classification c;
  for(std::size_t k = 0; k < classes; ++k) {
    std::string name, parent;
    std::size_t count = 0;
    if(!(in >> name >> parent >> count)) throw std::runtime_error("truncated classification file");
    if(count > 0) c.class_names.push_back(name);
    for(std::size_t m = 0; m < count; ++m) {
      int id = 0;
      if(!(in >> id)) throw std::runtime_error("truncated classification file (class " + name + ")");
      c.model_ids.push_back(id);
      c.class_of.push_back(c.class_names.size() - 1);
    }
  }
  if(c.model_ids.size() != models) throw std::runtime_error("classification file: model count mismatch");
  return c;
}

// The classification restricted to the models with keep[i] true (classes keep their indices).
inline Classification restricted(const Classification& c, const std::vector<bool>& keep)
{
  Classification r;
  r.class_names = c.class_names;
  for(std::size_t i = 0; i < c.model_ids.size(); ++i)
    if(keep[i]) {
      r.model_ids.push_back(c.model_ids[i]);
      r.class_of.push_back(c.class_of[i]);
    }
  return r;
}

// The five statistics of one query, or their mean over queries; all in [0, 1].
struct Scores
{
  double nearest_neighbour = 0., first_tier = 0., second_tier = 0., e_measure = 0., dcg = 0.;

  Scores& operator+=(const Scores& s)
  {
    nearest_neighbour += s.nearest_neighbour; first_tier += s.first_tier; second_tier += s.second_tier;
    e_measure += s.e_measure; dcg += s.dcg;
    return *this;
  }
  Scores operator/(double d) const { return {nearest_neighbour / d, first_tier / d, second_tier / d, e_measure / d, dcg / d}; }
};

// The other models ranked by increasing distance to the query, equal distances in model order
// (a stable order, so that the statistics do not depend on the sort's implementation).
inline std::vector<std::size_t> retrieval_list(const std::vector<double>& row, std::size_t query)
{
  std::vector<std::size_t> list;
  list.reserve(row.size());
  for(std::size_t j = 0; j < row.size(); ++j)
    if(j != query) list.push_back(j);
  std::stable_sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) { return row[a] < row[b]; });
  return list;
}

// relevant[r]: whether the result at rank r (0-based) is in the query's class.
inline std::vector<bool> relevance(const std::vector<std::size_t>& list, const std::vector<std::size_t>& class_of,
                                   std::size_t query)
{
  std::vector<bool> relevant(list.size());
  for(std::size_t r = 0; r < list.size(); ++r) relevant[r] = class_of[list[r]] == class_of[query];
  return relevant;
}

// Statistics of one query whose class has `others` models besides it (others >= 1):
// NN: the first result is relevant; first (second) tier: the relevant fraction of the others
// found in the first `others` (2 `others`) results; E-measure: the harmonic mean of precision and
// recall over the first 32 results; DCG: sum of 1/log2(rank) over the relevant results (rank 1
// counting 1), divided by its value for a perfect list.
inline Scores query_scores(const std::vector<bool>& relevant, std::size_t others)
{
  auto hits_in_first = [&](std::size_t k) {
    return double(std::count(relevant.begin(), relevant.begin() + std::ptrdiff_t(std::min(k, relevant.size())), true));
  };
  Scores s;
  s.nearest_neighbour = !relevant.empty() && relevant[0] ? 1. : 0.;
  s.first_tier = hits_in_first(others) / double(others);
  s.second_tier = hits_in_first(2 * others) / double(others);
  const double depth = double(std::min(e_measure_depth, relevant.size())), hits = hits_in_first(e_measure_depth);
  const double precision = hits / depth, recall = hits / double(others);
  s.e_measure = hits > 0. ? 2. * precision * recall / (precision + recall) : 0.;
  auto gain_at = [](std::size_t rank) { return rank == 1 ? 1. : 1. / std::log2(double(rank)); }; // rank from 1
  double dcg = 0., ideal = 0.;
  for(std::size_t r = 0; r < relevant.size(); ++r)
    if(relevant[r]) dcg += gain_at(r + 1);
  for(std::size_t r = 1; r <= others; ++r) ideal += gain_at(r);
  s.dcg = dcg / ideal;
  return s;
}

// The precision when the k-th model of the query's class is found, k = 1 .. C: k / its rank, in
// the list that starts with the query itself (precision 1 at rank 1), as psbPlot counts.
inline std::vector<double> precision_at_hits(const std::vector<bool>& relevant)
{
  std::vector<double> p(1, 1.); // the query
  for(std::size_t r = 0; r < relevant.size(); ++r)
    if(relevant[r]) p.push_back(double(p.size() + 1) / double(r + 2));
  return p;
}

// The precision of one query at recall `recall`, linearly interpolated between the recalls k/C
// of its hits (psbPlot's convention: flat above the last).
inline double precision_at_recall(const std::vector<double>& hits, double recall)
{
  const double x = recall * double(hits.size()) - 1.; // the position among the hits, 0-based
  const double lower = std::floor(x);
  auto at = [&](double i) { return hits[std::size_t(std::clamp(i, 0., double(hits.size() - 1)))]; };
  return at(lower) * (1. - (x - lower)) + at(lower + 1.) * (x - lower);
}

// The statistics of a distance matrix: their mean over the queries (micro average, as psbTable
// prints by default), per class, and the mean precision-recall curve.
struct Summary
{
  Scores mean;
  std::size_t queries = 0;
  std::vector<Scores> per_class;           // mean over the class's queries (zero if none)
  std::vector<std::size_t> class_queries;  // number of queries of each class
  std::vector<double> recall, precision;   // recall_levels points
};

// `distances`: n x n, row i the distances from model i. A query counts if its class has at least
// smallest_evaluated_class models and is not the miscellaneous class. At recall level r a query
// of a class of C models counts only if r >= 1/C (psbPlot: below it no precision is defined).
inline Summary evaluate(const std::vector<std::vector<double>>& distances, const Classification& c)
{
  const std::size_t n = c.class_of.size(), classes = c.class_names.size();
  std::vector<std::size_t> size(classes, 0);
  for(std::size_t k : c.class_of) ++size[k];
  Summary s;
  s.per_class.assign(classes, Scores());
  s.class_queries.assign(classes, 0);
  std::vector<double> precision_sum(recall_levels, 0.), precision_count(recall_levels, 0.);
  for(std::size_t q = 0; q < n; ++q) {
    const std::size_t k = c.class_of[q];
    if(size[k] < smallest_evaluated_class || c.class_names[k] == miscellaneous_class) continue;
    const std::vector<bool> relevant = relevance(retrieval_list(distances[q], q), c.class_of, q);
    const Scores scores = query_scores(relevant, size[k] - 1);
    s.mean += scores;
    s.per_class[k] += scores;
    ++s.class_queries[k];
    ++s.queries;
    const std::vector<double> hits = precision_at_hits(relevant);
    for(std::size_t l = 0; l < recall_levels; ++l) {
      const double recall = double(l + 1) / double(recall_levels);
      if(recall * double(hits.size()) < 1.) continue;
      precision_sum[l] += precision_at_recall(hits, recall);
      precision_count[l] += 1.;
    }
  }
  if(s.queries > 0) s.mean = s.mean / double(s.queries);
  for(std::size_t k = 0; k < classes; ++k)
    if(s.class_queries[k] > 0) s.per_class[k] = s.per_class[k] / double(s.class_queries[k]);
  for(std::size_t l = 0; l < recall_levels; ++l) {
    s.recall.push_back(double(l + 1) / double(recall_levels));
    s.precision.push_back(precision_count[l] > 0. ? precision_sum[l] / precision_count[l] : 0.);
  }
  return s;
}

} // namespace retrieval_evaluation

#endif // SYMMETRY_TRANSFORM_RETRIEVAL_EVALUATION_H
