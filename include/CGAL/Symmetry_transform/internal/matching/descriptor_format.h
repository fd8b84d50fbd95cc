// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DESCRIPTOR_FORMAT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DESCRIPTOR_FORMAT_H

// Binary file of a symmetry descriptor, in the frame of checked_binary_stream.h:
//   signature "CGALSDSC", version 1; payload: uint64 resolution n, n^3 floats (PRST bins,
//   k fastest), n^3 floats (GEDT samples, i fastest).
// Several descriptors may follow each other in a stream.

#include <CGAL/Symmetry_transform/internal/common/checked_binary_stream.h>

#include <cstdint>
#include <istream>
#include <ostream>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Descriptors are compared by the thousand at 32^3 (256 KiB each): beyond 1024 (8 GiB for the
// two arrays) none is of use, and the header is corrupt.
constexpr std::uint64_t max_descriptor_file_resolution = 1024;
constexpr Binary_format descriptor_file_format = {{'C', 'G', 'A', 'L', 'S', 'D', 'S', 'C'}, 1, "symmetry descriptor", max_descriptor_file_resolution};

inline void write_descriptor(std::ostream& os, std::size_t resolution, const std::vector<float>& prst,
                             const std::vector<float>& gedt)
{
  Checked_binary_writer out(os, descriptor_file_format);
  const std::uint64_t n = resolution;
  out.write(&n, sizeof(n));
  out.write(prst.data(), sizeof(float) * prst.size());
  out.write(gedt.data(), sizeof(float) * gedt.size());
  out.finish();
}

// Reads the arrays of a descriptor; returns its resolution.
inline std::size_t read_descriptor(std::istream& is, std::vector<float>& prst, std::vector<float>& gedt)
{
  Checked_binary_reader in(is, descriptor_file_format, "Symmetry_descriptor::load: ");
  const std::size_t n = in.read_resolution();
  prst.resize(n * n * n);
  gedt.resize(prst.size());
  in.read(prst.data(), sizeof(float) * prst.size());
  in.read(gedt.data(), sizeof(float) * gedt.size());
  in.finish();
  return n;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DESCRIPTOR_FORMAT_H
