// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOUR_RAMPS_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOUR_RAMPS_H

// The colours the examples give to values, as the PLY files they write carry them (the manual's
// figure scripts in doc/Symmetry_transform/ read the same ramps back).

#include <CGAL/IO/Color.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace examples {

// The colour of a value t in [0,1] on a ramp of `count` evenly spaced RGB stops.
template <int count>
CGAL::IO::Color ramp(const double (&stops)[count][3], double t)
{
  t = std::clamp(t, 0., 1.) * (count - 1);
  const int s = std::min(int(t), count - 2);
  auto channel = [&](int c) {
    return (unsigned char)std::lround(stops[s][c] + (t - s) * (stops[s + 1][c] - stops[s][c]));
  };
  return CGAL::IO::Color(channel(0), channel(1), channel(2));
}

// Dark to bright (close to matplotlib's "inferno"): 0 is black, 1 is pale yellow. For measures
// where more is better (symmetry, support, viewpoint score).
inline CGAL::IO::Color dark_to_bright(double t)
{
  static const double stops[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
  return ramp(stops, t);
}

// Dark blue (0) to yellow (1). For errors, where dark is good.
inline CGAL::IO::Color blue_to_yellow(double t)
{
  static const double stops[4][3] = {{20, 30, 110}, {30, 150, 160}, {120, 200, 80}, {250, 230, 40}};
  return ramp(stops, t);
}

// The colour of the square drawn for a plane: a blue that dark_to_bright() never takes.
inline CGAL::IO::Color plane_colour() { return CGAL::IO::Color(64, 160, 255); }

// Distinct colours for the first segments (a qualitative palette), then hues spread by the
// golden ratio.
inline CGAL::IO::Color segment_colour(std::size_t id)
{
  static const unsigned char palette[12][3] = {{230, 159, 0},  {86, 180, 233}, {0, 158, 115},   {240, 228, 66},
                                               {0, 114, 178},  {213, 94, 0},   {204, 121, 167}, {120, 120, 120},
                                               {153, 68, 153}, {136, 204, 238}, {68, 170, 153}, {221, 204, 119}};
  if(id < 12) return CGAL::IO::Color(palette[id][0], palette[id][1], palette[id][2]);
  const double h = std::fmod(0.618033988749895 * double(id), 1.) * 6.;
  const int i = int(h);
  const double f = h - i;
  const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  auto c = [&](int k) { return (unsigned char)std::lround(60. + 170. * rgb[i][k]); };
  return CGAL::IO::Color(c(0), c(1), c(2));
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOUR_RAMPS_H
