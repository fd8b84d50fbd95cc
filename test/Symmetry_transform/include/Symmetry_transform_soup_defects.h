// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Defects of a triangle soup (triangles as index triples): border edges (an undirected edge of
// one triangle only) and non-manifold vertices (whose triangles do not form one fan: their link
// is not a single path or cycle). For the remeshing test and the comparison with CGAL's VSA
// (benchmark/Symmetry_transform/remeshing_comparison.cpp); it needs no GoogleTest.

#ifndef CGAL_SYMMETRY_TRANSFORM_TEST_SOUP_DEFECTS_H
#define CGAL_SYMMETRY_TRANSFORM_TEST_SOUP_DEFECTS_H

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace st_test {

struct Manifold_defects
{
  std::size_t border_edges = 0, non_manifold_vertices = 0;
};

// Whether the link of a vertex (the edge opposite to it in each of its triangles) is one path or
// one cycle: no link vertex of degree above 2, and all connected.
inline bool is_single_fan(const std::vector<std::pair<std::size_t, std::size_t>>& link)
{
  std::map<std::size_t, std::vector<std::size_t>> adjacent;
  for(const auto& [a, b] : link) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  if(std::any_of(adjacent.begin(), adjacent.end(), [](const auto& a) { return a.second.size() > 2; })) return false;
  std::set<std::size_t> reached = {adjacent.begin()->first};
  std::vector<std::size_t> stack = {adjacent.begin()->first};
  while(!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    for(std::size_t w : adjacent[v])
      if(reached.insert(w).second) stack.push_back(w);
  }
  return reached.size() == adjacent.size();
}

template <typename Triangle>
Manifold_defects soup_defects(std::size_t number_of_points, const std::vector<Triangle>& triangles)
{
  Manifold_defects d;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edges;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> link(number_of_points);
  for(const Triangle& t : triangles)
    for(int i = 0; i < 3; ++i) {
      ++edges[std::minmax<std::size_t>(t[i], t[(i + 1) % 3])];
      link[t[i]].push_back({t[(i + 1) % 3], t[(i + 2) % 3]});
    }
  for(const auto& e : edges) d.border_edges += e.second == 1 ? 1 : 0;
  for(const auto& l : link)
    if(!l.empty() && !is_single_fan(l)) ++d.non_manifold_vertices;
  return d;
}

} // namespace st_test

#endif // CGAL_SYMMETRY_TRANSFORM_TEST_SOUP_DEFECTS_H
