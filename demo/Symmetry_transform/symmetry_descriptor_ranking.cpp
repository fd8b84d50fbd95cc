// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include "command_line_options.h"
#include "input_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

const char* const usage = R"(usage: symmetry_descriptor_ranking [QUERY] [--collection DIR] [--max-meshes N] [--resolution N]
         [--samples N] [--seed S] [--index FILE] [--output FILE]

Shape retrieval by symmetry descriptors: indexes a folder of meshes (each aligned in its
symmetry frame, then described by its PRST and GEDT), ranks them against a query mesh by the
combined distance (PRST distance x GEDT distance) and prints the ranked list.

  QUERY             the query mesh, an OFF, PLY, OBJ or STL file; default: meshes/bull.off of
                    CGAL's sample data, in the folder $CGAL_DATA_DIR
  --collection DIR  the folder whose .off files are ranked, and the query if it lies there
                    (default: the query's folder)
  --max-meshes N    ranks the first N files of the folder in sorted order; 0: all (default 12)
  --resolution N    GEDT samples and PRST bins per axis, even, at least 8 (default 32)
  --samples N       Monte Carlo samples of the PRST (default 200000)
  --seed S          random seed: the same seed, the same descriptors (default 0)
  --index FILE      a file of descriptors, read if present and (re)written when meshes were
                    added to it, so that a collection is indexed once (entries are keyed by
                    path; a file edited since is not noticed) (default: none)
  --output FILE     also writes the ranked list there, as text: rank, distances, file
                    (default: none)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Symmetry_descriptor<K> Descriptor;
namespace ST = CGAL::Symmetry_transform;
namespace fs = std::filesystem;

// The descriptors of an index file, by path, with the settings they were computed with:
// a text header line, then for each mesh a line with its path followed by the binary descriptor.
struct Index
{
  std::string settings; // resolution, samples and seed
  std::map<std::string, Descriptor> descriptors;
  bool modified = false;
};

const char* const index_header = "CGAL symmetry descriptor index, version 1:";

Index read_index(const std::string& filename, const std::string& settings)
{
  Index index{settings, {}, false};
  std::ifstream is(filename, std::ios::binary);
  if(filename.empty() || !is) return index;
  std::string header, count_line;
  std::getline(is, header);
  if(header != index_header + (" " + settings) || !std::getline(is, count_line) || count_line.empty() ||
     count_line.find_first_not_of("0123456789") != std::string::npos) {
    std::cout << "Index " << filename << " was made with other settings or is not an index: it is rebuilt\n";
    return index;
  }
  const std::size_t count = std::stoull(count_line);
  for(std::size_t i = 0; i < count; ++i) {
    std::string path;
    if(!std::getline(is, path)) throw std::runtime_error("index " + filename + " is truncated");
    index.descriptors[path] = Descriptor::load(is);
  }
  std::cout << "Read " << count << " descriptors from " << filename << "\n";
  return index;
}

void write_index(const std::string& filename, const Index& index)
{
  std::ofstream os(filename, std::ios::binary);
  os << index_header << ' ' << index.settings << '\n' << index.descriptors.size() << '\n';
  for(const auto& [path, descriptor] : index.descriptors) {
    os << path << '\n';
    descriptor.save(os);
  }
  if(!os) throw std::runtime_error("cannot write the index " + filename);
  std::cout << "Wrote " << index.descriptors.size() << " descriptors to " << filename << "\n";
}

// The descriptor of the mesh in `filename`, from the index or computed (and added to the
// index); none if the file holds no usable mesh.
template <typename NamedParameters>
std::optional<Descriptor> descriptor_of(const std::string& filename, Index& index, const NamedParameters& np)
{
  const auto found = index.descriptors.find(filename);
  if(found != index.descriptors.end()) return found->second;
  try {
    Mesh mesh = examples::read_triangle_mesh<Mesh>(filename, true);
    // The descriptors are compared in the meshes' coordinates: align each mesh in its symmetry
    // frame (centre of symmetry at the origin, principal symmetry axes along x, y, z) first.
    CGAL::Polygon_mesh_processing::transform(ST::to_canonical(ST::symmetry_frame(mesh, np)), mesh);
    const Descriptor d = ST::symmetry_descriptor(mesh, np);
    index.descriptors[filename] = d;
    index.modified = true;
    return d;
  } catch(const std::exception& e) { // std::invalid_argument from the package, std::runtime_error from reading
    std::cout << "  skipped " << filename << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

// The first `max_meshes` .off files of `collection` in sorted order (all if 0), and the query if
// it lies there and is not among them: it should come first, at distance 0.
std::vector<std::string> collection_files(const std::string& collection, std::size_t max_meshes, const std::string& query)
{
  std::vector<std::string> files;
  for(const fs::directory_entry& entry : fs::directory_iterator(collection))
    if(entry.is_regular_file() && entry.path().extension() == ".off") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if(max_meshes > 0 && files.size() > max_meshes) files.resize(max_meshes);
  const fs::path query_folder = fs::path(query).parent_path().empty() ? "." : fs::path(query).parent_path();
  if(fs::exists(query) && fs::equivalent(query_folder, collection) &&
     std::none_of(files.begin(), files.end(), [&](const std::string& f) { return fs::equivalent(f, query); }))
    files.push_back(query);
  std::cout << "Collection " << collection << ": " << files.size() << " meshes\n";
  return files;
}

// The ranked list, nearest first, by the combined distance (descriptor_distance(), the product
// of the other two, recomputed here from them).
std::string ranked_list(const Descriptor& query, const std::vector<std::pair<std::string, Descriptor>>& described)
{
  struct Match { double distance, prst, gedt; std::string file; };
  std::vector<Match> matches;
  for(const auto& [file, d] : described) {
    const double prst = ST::reflective_symmetry_descriptor_distance(query, d), gedt = ST::gedt_distance(query, d);
    matches.push_back({prst * gedt, prst, gedt, file});
  }
  std::sort(matches.begin(), matches.end(), [](const Match& a, const Match& b) { return a.distance < b.distance; });
  std::ostringstream list;
  list << "# rank  distance  PRST_distance  GEDT_distance  file\n";
  for(std::size_t r = 0; r < matches.size(); ++r)
    list << std::setw(6) << r + 1 << "  " << std::scientific << std::setprecision(3) << matches[r].distance << "  "
         << matches[r].prst << "      " << matches[r].gedt << "      " << fs::path(matches[r].file).filename().string() << "\n";
  return list.str();
}

void write_text(const std::string& file, const std::string& text)
{
  std::ofstream os(file);
  os << text;
  if(!os) throw std::runtime_error("cannot write " + file);
  std::cout << "Wrote the ranked list to " << file << "\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string query = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 32, 8), samples = options.integer("--samples", 200000),
                    seed = options.integer("--seed", 0, 0), max_meshes = options.integer("--max-meshes", 12, 0);
  const std::string parent = fs::path(query).parent_path().string();
  const std::string collection = options.text("--collection", parent.empty() ? "." : parent);
  const std::string index_file = options.text("--index", ""), output = options.text("--output", "");
  options.validate();
  if(resolution % 2 != 0) throw std::invalid_argument("--resolution must be even");
  examples::check_exists(query); // before its folder is listed

  const auto np = CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins per axis
                                    number_of_samples(samples).       // Monte Carlo samples of the PRST
                                    random_seed(unsigned(seed));      // the same seed, the same descriptors
  const std::vector<std::string> files = collection_files(collection, max_meshes, query);
  Index index = read_index(index_file, "resolution " + std::to_string(resolution) + " samples " +
                                         std::to_string(samples) + " seed " + std::to_string(seed));
  CGAL::Real_timer timer;
  timer.start();
  const std::optional<Descriptor> q = descriptor_of(fs::absolute(query).string(), index, np);
  if(!q) throw std::runtime_error("cannot describe the query '" + query + "'");
  std::vector<std::pair<std::string, Descriptor>> described;
  for(const std::string& file : files)
    if(const std::optional<Descriptor> d = descriptor_of(fs::absolute(file).string(), index, np)) described.emplace_back(file, *d);
  if(!index_file.empty() && index.modified) write_index(index_file, index);

  const std::string list = "# query " + query + ", grid " + std::to_string(resolution) + "^3, " +
                           std::to_string(samples) + " Monte Carlo samples\n" + ranked_list(*q, described);
  std::cout << std::setprecision(3) << "Indexed " << described.size() << " meshes and the query in " << timer.time()
            << " s (aligned, grid " << resolution << "^3)\n" << list;
  if(!output.empty()) write_text(output, list);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
