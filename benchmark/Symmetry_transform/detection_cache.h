// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// A detection of principal symmetries (the planes and the transform they came from) kept in a
// folder, so that the experiments that read it (alignment_experiment, viewpoint_experiment)
// compare rules without detecting again: DIR/KEY.planes (text) and DIR/KEY.prst (the transform's
// own format).

#ifndef SYMMETRY_TRANSFORM_DETECTION_CACHE_H
#define SYMMETRY_TRANSFORM_DETECTION_CACHE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>

#include <fstream>
#include <functional>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace detection_cache {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Symmetry_transform::internal::Detection<K> Detection;
namespace ST = CGAL::Symmetry_transform;


inline void save_symmetries(const std::string& file, const std::vector<ST::Principal_symmetry<K>>& symmetries)
{
  std::ofstream out(file);
  out << std::setprecision(17) << symmetries.size() << "\n";
  for(const auto& s : symmetries)
    out << s.plane.a() << " " << s.plane.b() << " " << s.plane.c() << " " << s.plane.d() << " " << s.symmetry << " "
        << s.support << "\n";
  if(!out) throw std::runtime_error("cannot write " + file);
}

inline std::vector<ST::Principal_symmetry<K>> load_symmetries(const std::string& file)
{
  std::ifstream in(file);
  std::size_t count = 0;
  in >> count;
  std::vector<ST::Principal_symmetry<K>> symmetries;
  for(std::size_t i = 0; i < count; ++i) {
    double a, b, c, d, m, s;
    in >> a >> b >> c >> d >> m >> s;
    symmetries.push_back({K::Plane_3(a, b, c, d), m, s});
  }
  if(!in) throw std::runtime_error("cannot read " + file);
  return symmetries;
}

inline bool exists(const std::string& file)
{
  struct stat info;
  return stat(file.c_str(), &info) == 0;
}

// The detection `compute()` gives, or the one cached under `key` in `cache` (if not empty).
inline Detection cached(const std::string& cache, const std::string& key, const std::function<Detection()>& compute)
{
  const std::string planes = cache + "/" + key + ".planes", prst = cache + "/" + key + ".prst";
  if(!cache.empty() && exists(planes) && exists(prst))
    return {load_symmetries(planes), ST::Reflective_symmetry_transform<K>::load(prst)};
  Detection d = compute();
  if(!cache.empty()) {
    save_symmetries(planes, d.symmetries);
    d.prst.save(prst);
  }
  return d;
}

} // namespace detection_cache

#endif // SYMMETRY_TRANSFORM_DETECTION_CACHE_H
