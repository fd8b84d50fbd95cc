// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H

// Binary file of a reflective symmetry transform:
//   8 bytes "CGALPRST", uint32 format version, uint32 byte-order mark 0x01020304,
//   uint64 resolution n, 3 doubles centre, double radius, n^3 doubles (bin values, k fastest),
//   uint64 FNV-1a hash of all preceding bytes after the magic.
// Values are written in the machine's byte order; the mark makes a foreign order an error.

#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

constexpr char prst_file_magic[8] = {'C', 'G', 'A', 'L', 'P', 'R', 'S', 'T'};
constexpr std::uint32_t prst_file_version = 1;
constexpr std::uint32_t prst_byte_order_mark = 0x01020304;

class Fnv1a_hash
{
public:
  void add(const void* data, std::size_t size)
  {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

inline void write_reflective_symmetry(std::ostream& os, const Plane_bins& bins, const std::vector<double>& values)
{
  Fnv1a_hash hash;
  auto put = [&](const void* data, std::size_t size) {
    os.write(static_cast<const char*>(data), std::streamsize(size));
    hash.add(data, size);
  };
  os.write(prst_file_magic, sizeof(prst_file_magic));
  const std::uint64_t n = bins.n;
  put(&prst_file_version, sizeof(prst_file_version));
  put(&prst_byte_order_mark, sizeof(prst_byte_order_mark));
  put(&n, sizeof(n));
  put(bins.center.data(), sizeof(double) * 3);
  put(&bins.radius, sizeof(double));
  put(values.data(), sizeof(double) * values.size());
  const std::uint64_t checksum = hash.value();
  os.write(reinterpret_cast<const char*>(&checksum), sizeof(checksum));
}

inline void read_reflective_symmetry(std::istream& is, Plane_bins& bins, std::vector<double>& values)
{
  const std::string what = "Reflective_symmetry_transform::load: ";
  Fnv1a_hash hash;
  auto get = [&](void* data, std::size_t size) {
    if(!is.read(static_cast<char*>(data), std::streamsize(size)))
      throw std::runtime_error(what + "the file is truncated");
    hash.add(data, size);
  };
  char magic[sizeof(prst_file_magic)];
  if(!is.read(magic, sizeof(magic)) || std::memcmp(magic, prst_file_magic, sizeof(magic)) != 0)
    throw std::runtime_error(what + "not a reflective symmetry transform file (bad signature)");
  std::uint32_t version = 0, mark = 0;
  get(&version, sizeof(version));
  if(version != prst_file_version)
    throw std::runtime_error(what + "unsupported file format version " + std::to_string(version) +
                             " (this library reads version " + std::to_string(prst_file_version) + ")");
  get(&mark, sizeof(mark));
  if(mark != prst_byte_order_mark) throw std::runtime_error(what + "the file was written with another byte order");
  std::uint64_t n = 0;
  get(&n, sizeof(n));
  if(n == 0 || n % 2 != 0 || n > 4096) throw std::runtime_error(what + "corrupt header (resolution " + std::to_string(n) + ")");
  bins.n = std::size_t(n);
  get(bins.center.data(), sizeof(double) * 3);
  get(&bins.radius, sizeof(double));
  for(double c : bins.center)
    if(!std::isfinite(c)) throw std::runtime_error(what + "corrupt header (centre)");
  if(!(bins.radius > 0.) || !std::isfinite(bins.radius)) throw std::runtime_error(what + "corrupt header (radius)");
  values.resize(bins.n * bins.n * bins.n);
  get(values.data(), sizeof(double) * values.size());
  std::uint64_t checksum = 0;
  if(!is.read(reinterpret_cast<char*>(&checksum), sizeof(checksum)))
    throw std::runtime_error(what + "the file is truncated");
  if(checksum != hash.value()) throw std::runtime_error(what + "the file is corrupt (checksum mismatch)");
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H
