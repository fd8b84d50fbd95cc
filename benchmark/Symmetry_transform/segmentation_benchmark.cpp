// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Segmentation on the Princeton Segmentation Benchmark (Chen, Golovinskiy and Funkhouser 2009):
// 380 meshes of 19 categories (ids 1-260 and 281-400; the Spring category, 261-280, is left out
// as in the benchmark), each with several human segmentations. Every mesh is segmented by
// segment_by_symmetry (thesis, section 5.2) and by CGAL's SDF segmentation (sdf_values, then
// segmentation_from_sdf_values), and each result is compared with every human segmentation of
// the mesh by Cut Discrepancy, Hamming distance (and its Rm, Rf parts), Rand Index and the
// Global/Local Consistency Errors (segmentation_evaluation.h); the human segmentations are also
// compared with each other (the benchmark's "Human" row). Means per mesh, then per category and
// over all meshes, as the benchmark's scripts average them.
//
// The number of segments, for the methods that take one, follows the benchmark's protocol for
// such algorithms: by default "ByModel", the mode of the numbers of segments of the mesh's human
// segmentations (parameters/nSeg-ByModel.txt; ByCategory and ByDataset are the other choices).
// segment_by_symmetry gets it as max_number_of_segments, with a depth of ceil(log2 k) + 1;
// segmentation_from_sdf_values gets it as its number of clusters ("SDF k"; it returns one segment
// per connected part of a cluster, often more than k), and runs with its default 5 clusters as
// well ("SDF 5", how the benchmark ran the shape-diameter method: with its own choice).
//
// The segmentations are saved in the cache folder (the benchmark's .seg format: one label per
// face), so that an interrupted run resumes; the evaluation is redone each run.
//
// usage: segmentation_benchmark --data DIR --cache DIR [--output DIR] [--count ByModel]
//          [--models 1-20,41] [--resolution N] [--jobs J] [--no-human] [--no-sdf]
//          [--partial-symmetry-fraction P] [--smallest-part-fraction Q] [--sdf-feature] [--variant NAME]
//          [--ply DIR]
//   --data: the benchmark's folder, with off/, seg/Benchmark/ and parameters/ (RESULTS.md)
//   --partial-symmetry-fraction, --smallest-part-fraction: segment_by_symmetry's named parameters
//              of the same names (default: the library's, 0.1 and 0.05)
//   --sdf-feature: segment_by_symmetry clusters CGAL's shape diameter function (sdf_values) with
//              the planes' supports (named parameter face_feature_map); its time counts
//   --variant: a name for the library's segment_by_symmetry as built (a prototype, say): its
//              segmentations get their own cache folder
//   --ply: also writes every segmentation of the models run as a PLY file coloured by segment
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include "benchmark_utilities.h"
#include "segmentation_evaluation.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace SE = segmentation_evaluation;
namespace fs = std::filesystem;

const char* const categories[] = {"Human",   "Cup",    "Glasses", "Airplane", "Ant",       "Chair", "Octopus",
                                  "Table",   "Teddy",  "Hand",    "Plier",    "Fish",      "Bird",  "Spring",
                                  "Armadillo", "Bust", "Mech",    "Bearing",  "Vase",      "FourLeg"};
constexpr int models_per_category = 20;
constexpr int spring = 13; // the category left out of the benchmark's study
// The methods evaluated against the human segmentations; "Human" compares those with each other.
const char* const methods[] = {"Human", "Symmetry", "SDF k", "SDF 5"};
constexpr std::size_t number_of_methods = 4;
constexpr std::size_t sdf_default_clusters = 5; // segmentation_from_sdf_values' default

int category_of(int id) { return (id - 1) / models_per_category; }

struct Options
{
  fs::path data, cache, output = ".", ply;
  std::string count = "ByModel";
  std::string variant;     // a name for a variant of segment_by_symmetry (its own cache folder)
  double partial_fraction = -1., part_fraction = -1.; // segment_by_symmetry's, if >= 0
  bool run_sdf = true;     // false: segment_by_symmetry only (the SDF rows are left empty)
  bool sdf_feature = false; // segment_by_symmetry gets CGAL's SDF values as its face_feature_map
  std::vector<int> models;
  int resolution = 32; // segment_by_symmetry's default
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  bool human = true;
};

// "1-20,41" -> 1 .. 20, 41; the Spring category is dropped.
std::vector<int> model_list(const std::string& text)
{
  std::vector<int> ids;
  for(const std::string& item : benchmark_utilities::split(text)) {
    const std::size_t dash = item.find('-');
    const int first = std::stoi(item.substr(0, dash)), last = dash == std::string::npos ? first : std::stoi(item.substr(dash + 1));
    for(int id = first; id <= last; ++id)
      if(id >= 1 && id <= 400 && category_of(id) != spring) ids.push_back(id);
  }
  return ids;
}

Options parse(int argc, char** argv)
{
  Options o;
  o.models = model_list("1-400");
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--no-human") { o.human = false; continue; }
    if(arg == "--no-sdf") { o.run_sdf = false; continue; }
    if(arg == "--sdf-feature") { o.sdf_feature = true; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--data") o.data = value;
    else if(arg == "--cache") o.cache = value;
    else if(arg == "--output") o.output = value;
    else if(arg == "--ply") o.ply = value;
    else if(arg == "--count") o.count = value;
    else if(arg == "--variant") o.variant = value;
    else if(arg == "--partial-symmetry-fraction") o.partial_fraction = std::stod(value);
    else if(arg == "--smallest-part-fraction") o.part_fraction = std::stod(value);
    else if(arg == "--models") o.models = model_list(value);
    else if(arg == "--resolution") o.resolution = std::stoi(value);
    else if(arg == "--jobs") o.jobs = unsigned(std::max(1, std::stoi(value)));
    else throw std::invalid_argument("unknown option " + arg);
  }
  if(o.data.empty() || o.cache.empty()) throw std::invalid_argument("usage: segmentation_benchmark --data DIR --cache DIR [options]");
  if(o.count != "ByModel" && o.count != "ByCategory" && o.count != "ByDataset")
    throw std::invalid_argument("--count: ByModel, ByCategory or ByDataset");
  return o;
}

// The benchmark's number of segments of each model (line i of parameters/nSeg-<mode>.txt, model i).
std::vector<std::size_t> segment_counts(const Options& o)
{
  std::ifstream in(o.data / "parameters" / ("nSeg-" + o.count + ".txt"));
  if(!in) throw std::runtime_error("cannot read the benchmark's parameters/nSeg-" + o.count + ".txt");
  std::vector<std::size_t> counts(1, 0); // from id 1
  for(std::string line; std::getline(in, line);) counts.push_back(std::size_t(std::atol(line.c_str())));
  return counts;
}

// A mesh of the benchmark with its faces in file order (the order of the .seg labels).
struct Benchmark_mesh
{
  std::vector<SE::Point> points;
  std::vector<SE::Triangle> triangles;
  Mesh mesh; // face i is Mesh::Face_index(i)
};

Benchmark_mesh read_mesh(const fs::path& file)
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(file.string(), points, polygons) || polygons.empty())
    throw std::runtime_error("cannot read " + file.string());
  Benchmark_mesh m;
  for(const K::Point_3& p : points) {
    m.points.push_back({p.x(), p.y(), p.z()});
    m.mesh.add_vertex(p);
  }
  for(const auto& polygon : polygons) {
    if(polygon.size() != 3) throw std::runtime_error(file.string() + ": a face is not a triangle");
    m.triangles.push_back({polygon[0], polygon[1], polygon[2]});
    if(m.mesh.add_face(Mesh::Vertex_index(polygon[0]), Mesh::Vertex_index(polygon[1]), Mesh::Vertex_index(polygon[2])) ==
       Mesh::null_face())
      throw std::runtime_error(file.string() + ": not a manifold mesh in file order");
  }
  return m;
}

typedef std::vector<std::size_t> Labels;

Labels read_labels(const fs::path& file, std::size_t faces)
{
  std::ifstream in(file);
  Labels labels;
  for(std::size_t l; labels.size() < faces && in >> l;) labels.push_back(l);
  if(labels.size() != faces) throw std::runtime_error(file.string() + ": not one label per face");
  return labels;
}

void write_labels(const fs::path& file, const Labels& labels, double seconds, const std::string& leaves)
{
  const fs::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary);
    for(std::size_t l : labels) out << l << '\n';
  }
  std::ofstream(file.string() + ".seconds") << seconds << '\n';
  if(!leaves.empty()) std::ofstream(file.string() + ".leaves") << leaves << '\n';
  fs::rename(temporary, file);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The labels of a face property map, in face order.
template <typename Map>
Labels labels_of(const Mesh& mesh, const Map& map)
{
  Labels labels;
  for(Mesh::Face_index f : faces(mesh)) labels.push_back(std::size_t(get(map, f)));
  return labels;
}

// One segmentation of a method, with its time; computed, or read back from the cache.
struct Segmentation
{
  Labels labels;
  double seconds = 0.;
  std::string leaves; // segment_by_symmetry: why each leaf of its tree was not split
};

// "NO_PARTIAL_SYMMETRY 2 TOO_SMALL 1 ...": the number of leaves of each status.
std::string leaf_statuses(const ST::Segmentation_tree<K>& tree)
{
  const char* const names[] = {"SPLIT", "DEPTH_LIMIT", "COUNT_LIMIT", "NO_PARTIAL_SYMMETRY", "NOT_SEPARABLE", "TOO_SMALL"};
  std::map<std::string, int> count;
  for(const auto& segment : tree.segments)
    if(segment.children.empty()) ++count[names[int(segment.status)]];
  std::ostringstream text;
  for(const auto& [name, n] : count) text << name << ' ' << n << ' ';
  return text.str();
}

Segmentation segment_by_symmetry(const Options& o, Benchmark_mesh& m, std::size_t k)
{
  auto segment = m.mesh.add_property_map<Mesh::Face_index, std::size_t>("f:symmetry", 0).first;
  const std::size_t depth = std::size_t(std::ceil(std::log2(double(std::max<std::size_t>(k, 2))))) + 1;
  ST::Segmentation_tree<K> tree;
  // The library's defaults where the options are not given (the same results as leaving them out).
  const double p = o.partial_fraction >= 0. ? o.partial_fraction : ST::internal::defaults::partial_symmetry_fraction;
  const double q = o.part_fraction >= 0. ? o.part_fraction : ST::internal::defaults::smallest_part_fraction;
  const auto np = CGAL::parameters::grid_resolution(o.resolution).number_of_threads(1u).max_number_of_segments(k)
                    .max_segmentation_depth(depth).segmentation_tree(std::ref(tree))
                    .partial_symmetry_fraction(p).smallest_part_fraction(q);
  const auto start = std::chrono::steady_clock::now();
  if(o.sdf_feature) { // the SDF values' time counts
    auto sdf = m.mesh.add_property_map<Mesh::Face_index, double>("f:sdf_feature", 0.).first;
    CGAL::sdf_values(m.mesh, sdf);
    ST::segment_by_symmetry(m.mesh, segment, np.face_feature_map(sdf));
    m.mesh.remove_property_map(sdf);
  } else
    ST::segment_by_symmetry(m.mesh, segment, np);
  Segmentation s{labels_of(m.mesh, segment), seconds_since(start), leaf_statuses(tree)};
  m.mesh.remove_property_map(segment);
  return s;
}

// CGAL's SDF segmentation with k clusters and with its default 5, from one computation of the
// SDF values (whose time counts in both).
std::array<Segmentation, 2> segment_by_sdf(Benchmark_mesh& m, std::size_t k)
{
  auto sdf = m.mesh.add_property_map<Mesh::Face_index, double>("f:sdf", 0.).first;
  auto segment = m.mesh.add_property_map<Mesh::Face_index, std::size_t>("f:sdf_segment", 0).first;
  auto start = std::chrono::steady_clock::now();
  CGAL::sdf_values(m.mesh, sdf);
  const double values = seconds_since(start);
  std::array<Segmentation, 2> result;
  const std::size_t clusters[2] = {k, sdf_default_clusters};
  for(int c = 0; c < 2; ++c) {
    start = std::chrono::steady_clock::now();
    CGAL::segmentation_from_sdf_values(m.mesh, sdf, segment, clusters[c]);
    result[std::size_t(c)] = {labels_of(m.mesh, segment), values + seconds_since(start), std::string()};
  }
  m.mesh.remove_property_map(sdf);
  m.mesh.remove_property_map(segment);
  return result;
}

fs::path cache_folder(const Options& o, std::size_t method)
{
  std::ostringstream symmetry;
  symmetry << "symmetry-" << o.count << "-n" << o.resolution;
  if(o.partial_fraction >= 0.) symmetry << "-p" << o.partial_fraction;
  if(o.part_fraction >= 0.) symmetry << "-q" << o.part_fraction;
  if(o.sdf_feature) symmetry << "-sdf";
  if(!o.variant.empty()) symmetry << "-" << o.variant;
  const std::string name[] = {"", symmetry.str(), "sdf-" + o.count, "sdf-5"};
  return o.cache / name[method];
}

// The segmentations of methods 1 .. 3 of one model, from the cache or computed (and cached).
std::array<Segmentation, number_of_methods> segmentations(const Options& o, int id, Benchmark_mesh& m, std::size_t k)
{
  std::array<Segmentation, number_of_methods> s;
  std::array<bool, number_of_methods> found{};
  for(std::size_t method = 1; method < number_of_methods; ++method) {
    const fs::path file = cache_folder(o, method) / (std::to_string(id) + ".seg");
    if(!fs::exists(file)) continue;
    s[method].labels = read_labels(file, m.triangles.size());
    std::ifstream(file.string() + ".seconds") >> s[method].seconds;
    std::getline(std::ifstream(file.string() + ".leaves"), s[method].leaves);
    found[method] = true;
  }
  if(!found[1]) s[1] = segment_by_symmetry(o, m, k);
  if(o.run_sdf && (!found[2] || !found[3])) {
    const std::array<Segmentation, 2> sdf = segment_by_sdf(m, k);
    s[2] = sdf[0];
    s[3] = sdf[1];
  }
  for(std::size_t method = 1; method < number_of_methods; ++method)
    if(!found[method] && !s[method].labels.empty())
      write_labels(cache_folder(o, method) / (std::to_string(id) + ".seg"), s[method].labels, s[method].seconds, s[method].leaves);
  return s;
}

// The mean of the metrics over the comparisons of one model (or over models).
struct Mean_scores
{
  double cd = 0., hd = 0., rm = 0., rf = 0., ri = 0., gce = 0., lce = 0., gce_faces = 0., lce_faces = 0.;
  double segments = 0., seconds = 0.;
  std::size_t count = 0, cd_count = 0; // comparisons (or models), those with a defined CD

  void add(const SE::Scores& s)
  {
    if(s.cut_discrepancy) { cd += *s.cut_discrepancy; ++cd_count; }
    hd += s.hamming.distance; rm += s.hamming.missing; rf += s.hamming.false_alarm; ri += s.rand_index_error;
    gce += s.consistency.gce; lce += s.consistency.lce; gce_faces += s.consistency.gce_faces; lce_faces += s.consistency.lce_faces;
    ++count;
  }
  void add(const Mean_scores& m) // a model's means, as one item
  {
    if(m.cd_count > 0) { cd += m.cd; ++cd_count; }
    hd += m.hd; rm += m.rm; rf += m.rf; ri += m.ri; gce += m.gce; lce += m.lce;
    gce_faces += m.gce_faces; lce_faces += m.lce_faces; segments += m.segments; seconds += m.seconds;
    ++count;
  }
  Mean_scores mean() const
  {
    Mean_scores m = *this;
    const double n = double(std::max<std::size_t>(count, 1));
    if(cd_count > 0) m.cd /= double(cd_count);
    for(double* x : {&m.hd, &m.rm, &m.rf, &m.ri, &m.gce, &m.lce, &m.gce_faces, &m.lce_faces, &m.segments, &m.seconds}) *x /= n;
    return m;
  }
};

std::size_t number_of_segments(Labels labels) { return SE::renumber(labels); }

// A mesh with its faces coloured by segment (ASCII PLY, any viewer): <id>-<method>.ply.
void write_ply(const fs::path& file, const Benchmark_mesh& m, const Labels& labels)
{
  static const unsigned char palette[][3] = {{228, 26, 28},   {55, 126, 184}, {77, 175, 74},  {152, 78, 163},
                                             {255, 127, 0},   {255, 255, 51}, {166, 86, 40},  {247, 129, 191},
                                             {153, 153, 153}, {102, 194, 165}, {141, 160, 203}, {231, 138, 195}};
  constexpr std::size_t colours = sizeof(palette) / sizeof(palette[0]);
  std::ofstream out(file);
  out << "ply\nformat ascii 1.0\nelement vertex " << m.points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for(const SE::Point& p : m.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(std::size_t f = 0; f < m.triangles.size(); ++f) {
    const unsigned char* c = palette[labels[f] % colours];
    out << "3 " << m.triangles[f][0] << ' ' << m.triangles[f][1] << ' ' << m.triangles[f][2] << ' ' << int(c[0]) << ' '
        << int(c[1]) << ' ' << int(c[2]) << '\n';
  }
}

void write_ply(const Options& o, int id, const Benchmark_mesh& m, const std::array<Segmentation, number_of_methods>& s)
{
  const char* const names[] = {"", "symmetry", "sdf-k", "sdf-5"};
  fs::create_directories(o.ply);
  for(std::size_t method = 1; method < number_of_methods; ++method) {
    if(s[method].labels.empty()) continue;
    Labels labels = s[method].labels;
    SE::renumber(labels); // colours in order of first appearance
    write_ply(o.ply / (std::to_string(id) + "-" + names[method] + ".ply"), m, labels);
  }
}

// What the evaluation of one model gives: per method, its means over the human segmentations.
struct Model_result
{
  int id = 0;
  std::size_t k = 0, humans = 0;
  std::array<Mean_scores, number_of_methods> scores;
  std::string leaves; // of segment_by_symmetry's tree
  std::string error;  // not evaluated, and why
};

Model_result evaluate_model(const Options& o, int id, std::size_t k)
{
  Model_result r;
  r.id = id;
  r.k = k;
  Benchmark_mesh m = read_mesh(o.data / "off" / (std::to_string(id) + ".off"));
  const SE::Mesh_data data = SE::mesh_data(m.points, m.triangles);
  std::vector<Labels> humans;
  const fs::path folder = o.data / "seg" / "Benchmark" / std::to_string(id);
  for(std::size_t j = 0; fs::exists(folder / (std::to_string(id) + "_" + std::to_string(j) + ".seg")); ++j)
    humans.push_back(read_labels(folder / (std::to_string(id) + "_" + std::to_string(j) + ".seg"), m.triangles.size()));
  if(humans.empty()) throw std::runtime_error("no human segmentation in " + folder.string());
  r.humans = humans.size();
  const std::array<Segmentation, number_of_methods> s = segmentations(o, id, m, k);
  r.leaves = s[1].leaves;
  for(std::size_t method = 1; method < number_of_methods; ++method) {
    if(s[method].labels.empty()) continue; // not run
    Mean_scores sum;
    for(const Labels& h : humans) sum.add(SE::compare(data, s[method].labels, h));
    r.scores[method] = sum.mean();
    r.scores[method].segments = double(number_of_segments(s[method].labels));
    r.scores[method].seconds = s[method].seconds;
  }
  Mean_scores human; // every pair of human segmentations, as groupSegEval
  for(std::size_t i = 0; o.human && i < humans.size(); ++i)
    for(std::size_t j = i + 1; j < humans.size(); ++j) human.add(SE::compare(data, humans[i], humans[j]));
  r.scores[0] = human.mean();
  for(const Labels& h : humans) r.scores[0].segments += double(number_of_segments(h)) / double(humans.size());
  if(!o.ply.empty()) write_ply(o, id, m, s);
  return r;
}

// Evaluates every model, `jobs` at a time, with a progress line on stderr; a model that fails is
// kept with its error.
std::vector<Model_result> run(const Options& o)
{
  const std::vector<std::size_t> counts = segment_counts(o);
  for(std::size_t method = 1; method < number_of_methods; ++method) fs::create_directories(cache_folder(o, method));
  std::vector<Model_result> results(o.models.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const auto start = std::chrono::steady_clock::now();
  auto work = [&] {
    for(std::size_t i; (i = next++) < o.models.size();) {
      const int id = o.models[i];
      try {
        results[i] = evaluate_model(o, id, counts.at(std::size_t(id)));
      } catch(const std::exception& e) {
        results[i].id = id;
        results[i].error = e.what();
      }
      const std::size_t finished = ++done;
      std::lock_guard<std::mutex> lock(print);
      if((finished * 50) / o.models.size() == ((finished - 1) * 50) / o.models.size()) continue;
      const double elapsed = seconds_since(start);
      std::cerr << "[segmentation] " << finished << "/" << o.models.size() << " meshes, " << std::fixed << std::setprecision(1)
                << elapsed << " s, about " << elapsed / double(finished) * double(o.models.size() - finished) << " s left\n";
    }
  };
  std::vector<std::thread> workers;
  for(unsigned t = 0; t < o.jobs; ++t) workers.emplace_back(work);
  for(std::thread& t : workers) t.join();
  return results;
}

void write_model_csv(const Options& o, const std::vector<Model_result>& results)
{
  std::ofstream csv(o.output / "segmentation_per_model.csv");
  csv << "model,category,method,k,humans,segments,seconds,cd,cd_comparisons,hd,rm,rf,ri_error,gce,lce,gce_faces,lce_faces,leaves,error\n";
  for(const Model_result& r : results)
    for(std::size_t method = 0; method < number_of_methods; ++method) {
      const Mean_scores& m = r.scores[method];
      csv << r.id << ',' << categories[category_of(r.id)] << ',' << methods[method] << ',' << r.k << ',' << r.humans << ','
          << m.segments << ',' << m.seconds << ',' << (m.cd_count > 0 ? std::to_string(m.cd) : "") << ',' << m.cd_count << ',' << m.hd << ',' << m.rm << ',' << m.rf
          << ',' << m.ri << ',' << m.gce << ',' << m.lce << ',' << m.gce_faces << ',' << m.lce_faces << ",\""
          << (method == 1 ? r.leaves : "") << "\",\"" << r.error << "\"\n";
    }
}

// Per category (index 0 .. 19) and over all models (index 20): the mean of the models' means.
std::vector<std::array<Mean_scores, number_of_methods>> aggregate(const std::vector<Model_result>& results)
{
  constexpr std::size_t all = 20;
  std::vector<std::array<Mean_scores, number_of_methods>> sums(all + 1);
  for(const Model_result& r : results) {
    if(!r.error.empty()) continue;
    for(std::size_t method = 0; method < number_of_methods; ++method) {
      if(r.scores[method].count == 0) continue; // not run
      sums[std::size_t(category_of(r.id))][method].add(r.scores[method]);
      sums[all][method].add(r.scores[method]);
    }
  }
  for(auto& row : sums)
    for(Mean_scores& m : row) m = m.mean();
  return sums;
}

void print_tables(const Options& o, const std::vector<std::array<Mean_scores, number_of_methods>>& a)
{
  std::ofstream csv(o.output / "segmentation_per_category.csv");
  csv << "category,method,models,segments,seconds,cd,hd,rm,rf,ri_error,gce,lce,gce_faces,lce_faces\n";
  std::cout << std::fixed << std::setprecision(3);
  for(std::size_t method = 0; method < number_of_methods; ++method) {
    if(a.back()[method].count == 0) continue; // not run
    std::cout << "\n" << methods[method] << " (means over the meshes of the means over their human segmentations)\n\n"
              << "| category | meshes | segments | seconds | CD | HD | Rm | Rf | 1 - RI | GCE | LCE |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for(std::size_t c = 0; c < a.size(); ++c) {
      const Mean_scores& m = a[c][method];
      if(m.count == 0) continue;
      const std::string name = c + 1 == a.size() ? "**all**" : categories[c];
      std::ostringstream cd; // undefined when no mesh has a comparison with cuts on both sides
      if(m.cd_count > 0) cd << std::fixed << std::setprecision(3) << m.cd; else cd << "n/a";
      std::cout << "| " << name << " | " << m.count << " | " << std::setprecision(1) << m.segments << " | "
                << std::setprecision(2) << m.seconds << " | " << std::setprecision(3) << cd.str() << " | " << m.hd << " | " << m.rm
                << " | " << m.rf << " | " << m.ri << " | " << m.gce << " | " << m.lce << " |\n";
      csv << name << ',' << methods[method] << ',' << m.count << ',' << m.segments << ',' << m.seconds << ',' << cd.str() << ','
          << m.hd << ',' << m.rm << ',' << m.rf << ',' << m.ri << ',' << m.gce << ',' << m.lce << ',' << m.gce_faces << ','
          << m.lce_faces << '\n';
    }
  }
}

// 1 - RI side by side, and where ours is at most SDF's ("-": not run).
void print_comparison(const std::vector<std::array<Mean_scores, number_of_methods>>& a)
{
  std::cout << "\n1 - Rand Index by category\n\n| category | Human | Symmetry | SDF k | SDF 5 | Symmetry <= SDF k | Symmetry <= SDF 5 |\n"
            << "|---|---:|---:|---:|---:|:---:|:---:|\n";
  for(std::size_t c = 0; c < a.size(); ++c) {
    if(a[c][1].count == 0) continue;
    auto value = [&](std::size_t method) {
      std::ostringstream text;
      if(a[c][method].count > 0) text << std::fixed << std::setprecision(3) << a[c][method].ri; else text << "-";
      return text.str();
    };
    auto at_most = [&](std::size_t method) {
      return a[c][method].count == 0 ? "-" : a[c][1].ri <= a[c][method].ri ? "yes" : "no";
    };
    std::cout << "| " << (c + 1 == a.size() ? "**all**" : categories[c]) << " | " << value(0) << " | " << value(1) << " | "
              << value(2) << " | " << value(3) << " | " << at_most(2) << " | " << at_most(3) << " |\n";
  }
}

} // namespace

int main(int argc, char** argv)
try {
  const Options o = parse(argc, argv);
  fs::create_directories(o.output);
  std::cout << "Princeton Segmentation Benchmark (" << o.data.string() << "): " << o.models.size() << " meshes; number of segments "
            << o.count << "; segment_by_symmetry at " << o.resolution << "^3";
  if(o.partial_fraction >= 0.) std::cout << ", partial_symmetry_fraction " << o.partial_fraction;
  if(o.part_fraction >= 0.) std::cout << ", smallest_part_fraction " << o.part_fraction;
  std::cout << " (cache " << cache_folder(o, 1).filename().string() << "); " << o.jobs << " meshes at a time\n";
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Model_result> results = run(o);
  std::size_t failed = 0;
  for(const Model_result& r : results)
    if(!r.error.empty()) {
      std::cout << "  mesh " << r.id << " not evaluated: " << r.error << "\n";
      ++failed;
    }
  std::cout << results.size() - failed << " of " << results.size() << " meshes evaluated in " << std::setprecision(1)
            << std::fixed << seconds_since(start) << " s (segmentations taken from the cache are not recomputed)\n";
  write_model_csv(o, results);
  const auto a = aggregate(results);
  print_tables(o, a);
  print_comparison(a);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
