// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SEEDING_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SEEDING_H

// The initial proxies of the symmetric partition, as CGAL's VSA (initialize_seeds): one proxy
// per connected component, then random, incremental (one proxy at the worst face at a time) or
// hierarchical (the number of proxies doubled at a time, shared by error) seeding, with
// `number_of_relaxations` Lloyd iterations after each step.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// One proxy per connected component of the mesh, fitted to it.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void bootstrap(Symmetric_partition& partition);

// CGAL's error diffusion: `count` new proxies, shared among the proxies in proportion to their
// error (to their size if all errors are zero), each placed at faces spread over its region.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t add_proxies_by_error(Symmetric_partition& partition, std::size_t count);

// The number of proxies doubled (up to `max_proxies`) while the error drop exceeds `min_drop`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_hierarchical(Symmetric_partition& partition, std::size_t max_proxies, double min_drop);

// A proxy at the worst face at a time, while the error drop exceeds `min_drop`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_incremental(Symmetric_partition& partition, std::size_t max_proxies, double min_drop);

// Proxies at distinct random faces (`random_seed`), up to `max_proxies`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_random(Symmetric_partition& partition, std::size_t max_proxies);

// The seeding of the settings, with CGAL's rules for `max_number_of_proxies` and
// `min_error_drop`: a maximum under a third of the faces is kept, with the error drop if one in
// (0, 1) is given; otherwise the maximum is a third of the faces, and the error drop the given
// one or `defaults::min_error_drop`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_proxies(Symmetric_partition& partition);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void bootstrap(Symmetric_partition& partition)
{
  std::vector<std::size_t> first_faces;
  const std::vector<std::size_t> component = partition.mesh().connected_pieces(
    [](std::size_t, std::size_t) { return true; },
    [&first_faces](std::size_t f, std::size_t c) {
      if(c == first_faces.size()) first_faces.push_back(f);
    });
  partition.reset_to_pieces(component, first_faces);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t add_proxies_by_error(Symmetric_partition& partition, std::size_t count)
{
  const std::size_t np = partition.proxies().size(), nf = partition.mesh().number_of_faces();
  std::vector<std::vector<std::size_t>> region(np);
  for(std::size_t f = 0; f < nf; ++f) region[partition.proxy_of(partition.labels()[f])].push_back(f);
  std::vector<double> weight(np);
  double sum = 0.;
  for(std::size_t p = 0; p < np; ++p) sum += weight[p] = partition.proxies()[p].error;
  if(!(sum > 0.)) {
    sum = 0.;
    for(std::size_t p = 0; p < np; ++p) sum += weight[p] = double(region[p].size());
  }
  std::vector<std::size_t> order(np);
  for(std::size_t p = 0; p < np; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weight[a] < weight[b]; });
  const double unit = sum / double(count);
  double residual = 0.;
  std::size_t added = 0;
  for(std::size_t p : order) {
    const double share = (residual + weight[p]) / unit;
    const double rounded = std::floor(share + 0.5);
    residual = (share - rounded) * unit;
    std::size_t n = (std::min)(std::size_t((std::max)(0., rounded)), region[p].size() - 1);
    for(std::size_t q = 0; q < n; ++q) {
      const std::size_t at = std::size_t((double(q) + 0.5) * double(region[p].size()) / double(n));
      std::size_t f = region[p][at];
      if(f == partition.proxies()[p].seed) f = region[p][(at + 1) % region[p].size()];
      partition.add_proxy_at(f);
      ++added;
    }
  }
  return added;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_hierarchical(Symmetric_partition& partition, std::size_t max_proxies, double min_drop)
{
  const double initial = partition.total_error();
  double drop = !(min_drop > 0.) ? 1. : 2. * min_drop;
  while(partition.proxies().size() < max_proxies && drop > min_drop) {
    const std::size_t target = (std::min)(2 * partition.proxies().size(), max_proxies);
    if(add_proxies_by_error(partition, target - partition.proxies().size()) == 0) break;
    const double e = partition.run_iterations(partition.settings().number_of_relaxations);
    drop = initial > 0. ? e / initial : 0.;
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_incremental(Symmetric_partition& partition, std::size_t max_proxies, double min_drop)
{
  const double initial = partition.total_error();
  double drop = !(min_drop > 0.) ? 1. : 2. * min_drop;
  while(partition.proxies().size() < max_proxies && drop > min_drop) {
    const std::size_t f = partition.worst_face();
    if(f == Symmetric_partition::none) break;
    partition.add_proxy_at(f);
    const double e = partition.run_iterations(partition.settings().number_of_relaxations);
    drop = initial > 0. ? e / initial : 0.;
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_random(Symmetric_partition& partition, std::size_t max_proxies)
{
  CGAL::Random random(partition.settings().random_seed);
  const std::size_t nf = partition.mesh().number_of_faces();
  std::vector<char> taken(nf, 0);
  for(const Symmetric_partition::Proxy& p : partition.proxies()) taken[p.seed] = 1;
  while(partition.proxies().size() < max_proxies) {
    const std::size_t f = std::size_t(random.get_int(0, int(nf)));
    if(taken[f]) continue;
    taken[f] = 1;
    partition.add_proxy_at(f);
  }
  partition.run_iterations(partition.settings().number_of_relaxations);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void seed_proxies(Symmetric_partition& partition)
{
  const Remeshing_settings& settings = partition.settings();
  std::size_t max_proxies = settings.max_number_of_proxies;
  double min_drop = settings.min_error_drop;
  const bool drop_given = min_drop < 1. && min_drop > 0.;
  const std::size_t most = partition.mesh().number_of_faces() / defaults::faces_per_proxy;
  if(max_proxies < most && max_proxies > 0) {
    if(!drop_given) min_drop = -1.; // not used
  } else {
    max_proxies = most;
    if(!drop_given) min_drop = defaults::min_error_drop;
  }
  bootstrap(partition);
  if(partition.proxies().size() >= max_proxies) return;
  if(settings.seeding == Seeding::random) seed_random(partition, max_proxies);
  else if(settings.seeding == Seeding::incremental) seed_incremental(partition, max_proxies, min_drop);
  else seed_hierarchical(partition, max_proxies, min_drop);
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SEEDING_H
