// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Writes the seed corpus of fuzz_soups_and_points at test time (never committed): for every entry
// point, a cube soup in integer coordinates on a grid of 8, a box's 26 lattice points with their
// normals as raw doubles on a grid of 16 with two threads, and the cube again far from the origin
// with a callback that cancels (the layout in fuzz_input.h).
//
// usage: make_fuzz_seeds DIRECTORY (emptied first: each run of the fuzzer starts from the seeds)

#include "fuzz_input.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace st_fuzz;
typedef std::array<int, 3> Lattice_point;

// A shape on the integer lattice of fuzz_input.h: coordinates in [-8, 7].
struct Shape
{
  std::vector<Lattice_point> points, normals;
  std::vector<std::array<std::uint8_t, 3>> triangles;
};

Shape cube()
{
  Shape s;
  for(int i = 0; i < 8; ++i) {
    s.points.push_back({i & 1 ? 4 : -4, i & 2 ? 4 : -4, i & 4 ? 4 : -4});
    s.normals.push_back({i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1});
  }
  s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return s;
}

// The 3 x 3 x 3 lattice of the box [-4, 4] x [-2, 2] x [-1, 1] but its centre, normals outwards.
Shape box_lattice()
{
  Shape s;
  for(int i = -1; i <= 1; ++i)
    for(int j = -1; j <= 1; ++j)
      for(int k = -1; k <= 1; ++k)
        if(i != 0 || j != 0 || k != 0) {
          s.points.push_back({4 * i, 2 * j, k});
          s.normals.push_back({i, j, k});
        }
  return s;
}

void put_double(std::vector<std::uint8_t>& bytes, double x)
{
  std::uint8_t b[8];
  std::memcpy(b, &x, sizeof x);
  bytes.insert(bytes.end(), b, b + 8);
}

void put_triples(std::vector<std::uint8_t>& bytes, const std::vector<Lattice_point>& triples, bool raw)
{
  for(const Lattice_point& t : triples)
    for(int c : t) {
      if(raw)
        put_double(bytes, double(c));
      else
        bytes.push_back(std::uint8_t(std::int8_t(16 * c)));
    }
}

std::vector<std::uint8_t> encode(Entry_point entry, std::uint8_t options, std::uint8_t placement, const Shape& s)
{
  const std::uint8_t counts = 2 | (2 << 2) | (2 << 4) | (2 << 6);  // 2000, 100, 3 iterations, 4 planes
  const std::uint8_t width_seed = 0 | (2 << 2) | (1 << 4);          // the first width, 100 points, seed 1
  std::vector<std::uint8_t> bytes = {std::uint8_t(entry), options, counts, width_seed, 2,
                                     std::uint8_t(s.points.size()), placement};
  const bool raw = options & option::raw_doubles;
  put_triples(bytes, s.points, raw);
  put_triples(bytes, s.normals, raw);
  for(int c : {1, 0, 0, 0}) bytes.push_back(std::uint8_t(c));  // the plane x = 0
  for(const auto& t : s.triangles) bytes.insert(bytes.end(), t.begin(), t.end());
  return bytes;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: make_fuzz_seeds DIRECTORY\n";
    return 1;
  }
  const std::string dir = argv[1];
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  int written = 0;
  for(int e = 0; e < NUMBER_OF_ENTRY_POINTS; ++e) {
    const Entry_point entry = Entry_point(e);
    const std::vector<std::vector<std::uint8_t>> seeds = {
      encode(entry, 0, 0, cube()),
      encode(entry, option::grid_16 | option::two_threads | option::raw_doubles, 0, box_lattice()),
      encode(entry, option::cancel | (1 << 4), 4 << 3, cube())};  // offset 1e3, BOUNDED_WEIGHT
    for(std::size_t i = 0; i < seeds.size(); ++i) {
      const std::string name = dir + "/seed_" + std::to_string(e) + "_" + std::to_string(i);
      std::ofstream out(name, std::ios::binary);
      out.write(reinterpret_cast<const char*>(seeds[i].data()), std::streamsize(seeds[i].size()));
      if(!out) {
        std::cerr << "make_fuzz_seeds: cannot write " << name << "\n";
        return 1;
      }
      ++written;
    }
  }
  std::cout << written << " seeds written into " << dir << "\n";
  return 0;
}
