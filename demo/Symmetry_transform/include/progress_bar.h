// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_PROGRESS_BAR_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_PROGRESS_BAR_H

// A progress bar on std::cerr for CGAL's `callback` named parameter (std::function<bool(double)>,
// called with the progress in [0, 1]; returning false would cancel the work). It is drawn only
// when std::cerr is a terminal, redrawn in place: the outputs of runs into files or pipes (those
// the tests check) stay the same.

#include <unistd.h>

#include <cstdio>
#include <functional>
#include <iostream>
#include <string>

namespace examples {

// Characters of the bar at 100 %.
constexpr int progress_bar_width = 40;

// A callback drawing "label [#####.....]  45 %", or an empty function (no callback: no cost)
// when std::cerr is not a terminal.
inline std::function<bool(double)> progress_bar(const std::string& label)
{
  if(!isatty(fileno(stderr))) return {};
  return [label, shown = -1](double progress) mutable {
    const int percent = int(100. * progress);
    if(percent == shown) return true; // redraw only when the number changes
    shown = percent;
    const int filled = int(progress * progress_bar_width);
    std::cerr << '\r' << label << " [" << std::string(std::size_t(filled), '#')
              << std::string(std::size_t(progress_bar_width - filled), '.') << "] " << percent << " %"
              << (progress >= 1. ? "\n" : "") << std::flush;
    return true; // never cancels
  };
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_PROGRESS_BAR_H
