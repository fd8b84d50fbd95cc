// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H

// Binary file of a reflective symmetry transform, in the frame of checked_binary_stream.h:
//   signature "CGALPRST", version 1; payload: uint64 resolution n, 3 doubles centre, double
//   radius, n^3 doubles (bin values, k fastest).

#include <CGAL/Symmetry_transform/internal/common/checked_binary_stream.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>

#include <cmath>
#include <cstdint>
#include <istream>
#include <ostream>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The resolution of a PRST is that of its grid: beyond 4096 (4096^3 doubles, 512 GiB) no machine
// wrote it, and the header is corrupt.
constexpr std::uint64_t max_prst_file_resolution = 4096;
constexpr Binary_format prst_file_format = {{'C', 'G', 'A', 'L', 'P', 'R', 'S', 'T'}, 1, "reflective symmetry transform", max_prst_file_resolution};

inline void write_reflective_symmetry(std::ostream& os, const Plane_bins& bins, const std::vector<double>& values)
{
  Checked_binary_writer out(os, prst_file_format);
  const std::uint64_t n = bins.n;
  out.write(&n, sizeof(n));
  out.write(bins.center.data(), sizeof(double) * 3);
  out.write(&bins.radius, sizeof(double));
  out.write(values.data(), sizeof(double) * values.size());
  out.finish();
}

inline void read_reflective_symmetry(std::istream& is, Plane_bins& bins, std::vector<double>& values)
{
  Checked_binary_reader in(is, prst_file_format, "Reflective_symmetry_transform::load: ");
  bins.n = in.read_resolution();
  in.read(bins.center.data(), sizeof(double) * 3);
  in.read(&bins.radius, sizeof(double));
  for(double c : bins.center)
    if(!std::isfinite(c)) in.fail("corrupt header (centre)");
  if(!(bins.radius > 0.) || !std::isfinite(bins.radius)) in.fail("corrupt header (radius)");
  values.resize(bins.n * bins.n * bins.n);
  in.read(values.data(), sizeof(double) * values.size());
  in.finish();
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_FILE_FORMAT_H
