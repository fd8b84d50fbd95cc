// Shape retrieval by symmetry descriptors: indexes a folder of meshes (each aligned in its
// symmetry frame, then described by its PRST and GEDT), ranks them against a query mesh by the
// combined distance (PRST distance x GEDT distance) and prints the ranked list.
//
// usage: symmetry_descriptor_ranking [query.off|.ply|.obj|.stl] [--collection DIR]
//          [--max-meshes N] [--resolution N] [--samples N] [--seed S] [--index FILE] [--output FILE]
// --collection: the folder whose .off files are ranked (default: the query's folder), the first
//   N (--max-meshes, default 12; 0 = all) in sorted order, and the query if it lies there;
// --index: a file of descriptors, read if present and (re)written when meshes were added to it,
//   so that a collection is indexed once (entries are keyed by path; a file edited since is not noticed);
// --output: the ranked list, as text (rank, distances, file).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include <algorithm>
#include <chrono>
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
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Symmetry_descriptor<K> Descriptor;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

std::size_t integer(const std::string& option, const std::string& text, std::size_t minimum = 1)
{
  if(text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos ||
     std::stoull(text) < minimum)
    throw std::invalid_argument(option + " expects an integer >= " + std::to_string(minimum) +
                                ", not '" + text + "'");
  return std::size_t(std::stoull(text));
}

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
  if(header != index_header + (" " + settings) || !std::getline(is, count_line)) {
    std::cout << "Index " << filename << " was made with other settings or is not an index: it is rebuilt\n";
    return index;
  }
  const std::size_t count = integer("the index's count", count_line, 0);
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
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cout << "  skipped " << filename << ": not a readable polygon mesh\n";
    return std::nullopt;
  }
  if(!CGAL::is_triangle_mesh(mesh) && !PMP::triangulate_faces(mesh)) {
    std::cout << "  skipped " << filename << ": some faces could not be triangulated\n";
    return std::nullopt;
  }
  try {
    // The descriptors are compared in the meshes' coordinates: align each mesh in its symmetry
    // frame (centre of symmetry at the origin, principal symmetry axes along x, y, z) first.
    PMP::transform(ST::to_canonical(ST::symmetry_frame(mesh, np)), mesh);
    const Descriptor d = ST::symmetry_descriptor(mesh, np);
    index.descriptors[filename] = d;
    index.modified = true;
    return d;
  } catch(const std::invalid_argument& e) {
    std::cout << "  skipped " << filename << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

int main(int argc, char** argv)
try {
  std::string query, collection, index_file, output;
  std::size_t resolution = 32, samples = 200000, seed = 0, max_meshes = 12;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { query = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value, 8);
    else if(arg == "--samples") samples = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--max-meshes") max_meshes = integer(arg, value, 0);
    else if(arg == "--collection") collection = value;
    else if(arg == "--index") index_file = value;
    else if(arg == "--output") output = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(resolution % 2 != 0) throw std::invalid_argument("--resolution must be even");
  if(query.empty()) query = CGAL::data_file_path("meshes/bull.off");
  if(collection.empty()) collection = fs::path(query).parent_path().string();
  if(collection.empty()) collection = ".";

  // The meshes: the first max_meshes .off files of the folder, in sorted order.
  std::vector<std::string> files;
  for(const fs::directory_entry& entry : fs::directory_iterator(collection))
    if(entry.is_regular_file() && entry.path().extension() == ".off") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if(max_meshes > 0 && files.size() > max_meshes) files.resize(max_meshes);
  // The query itself, if in the folder, is ranked too: it should come first, at distance 0.
  const fs::path query_folder = fs::path(query).parent_path().empty() ? "." : fs::path(query).parent_path();
  const bool query_in_folder = fs::exists(query) && fs::equivalent(query_folder, collection);
  if(query_in_folder &&
     std::none_of(files.begin(), files.end(), [&](const std::string& f) { return fs::equivalent(f, query); }))
    files.push_back(query);
  std::cout << "Collection " << collection << ": " << files.size() << " meshes\n";

  // Symmetry frames and descriptors on resolution^3 grids, with `samples` Monte Carlo samples.
  const auto np = CGAL::parameters::grid_resolution(int(resolution)).number_of_samples(samples).random_seed(unsigned(seed));
  Index index = read_index(index_file, "resolution " + std::to_string(resolution) + " samples " +
                                         std::to_string(samples) + " seed " + std::to_string(seed));
  const auto start = std::chrono::steady_clock::now();
  const std::optional<Descriptor> q = descriptor_of(fs::absolute(query).string(), index, np);
  if(!q) {
    std::cerr << "Cannot describe the query '" << query << "' (with no argument, set CGAL_DATA_DIR to the "
              << "directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<std::pair<std::string, Descriptor>> described;
  for(const std::string& file : files) {
    const std::optional<Descriptor> d = descriptor_of(fs::absolute(file).string(), index, np);
    if(d) described.emplace_back(file, *d);
  }
  const double indexing = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(!index_file.empty() && index.modified) write_index(index_file, index);

  // Ranking by the combined distance, nearest first.
  struct Match { double distance, prst, gedt; std::string file; };
  const auto ranking_start = std::chrono::steady_clock::now();
  std::vector<Match> matches;
  for(const auto& [file, d] : described) {
    const double prst = ST::reflective_symmetry_descriptor_distance(*q, d), gedt = ST::gedt_distance(*q, d);
    matches.push_back({prst * gedt, prst, gedt, file}); // prst * gedt is descriptor_distance(*q, d)
  }
  std::sort(matches.begin(), matches.end(), [](const Match& a, const Match& b) { return a.distance < b.distance; });
  const double ranking = std::chrono::duration<double>(std::chrono::steady_clock::now() - ranking_start).count();

  std::ostringstream list;
  list << "# query " << query << ", grid " << resolution << "^3, " << samples << " Monte Carlo samples\n"
       << "# rank  distance  PRST_distance  GEDT_distance  file\n";
  for(std::size_t r = 0; r < matches.size(); ++r)
    list << std::setw(6) << r + 1 << "  " << std::scientific << std::setprecision(3) << matches[r].distance << "  "
         << matches[r].prst << "      " << matches[r].gedt << "      " << fs::path(matches[r].file).filename().string() << "\n";
  std::cout << std::setprecision(3) << "Indexed " << described.size() << " meshes and the query in " << indexing
            << " s (aligned, grid " << resolution << "^3); ranked them in " << ranking * 1e3 << " ms\n"
            << list.str();
  if(!output.empty()) {
    std::ofstream os(output);
    os << list.str();
    if(!os) throw std::runtime_error("cannot write " + output);
    std::cout << "Wrote the ranked list to " << output << "\n";
  }
  return EXIT_SUCCESS;
} catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
