// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Retrieval on the Princeton Shape Benchmark (thesis, section 4.2.4): every model of a PSB
// classification (by default the test set, 907 models in 92 classes) is aligned automatically,
// by its symmetry frame (symmetry_frame) and, separately, by its PCA frame (pca_frame), moved by
// to_canonical(frame), and described by symmetry_descriptor (PRST and GEDT, 32^3). Every model is
// then a query against all the others, ranked by the PRST distance, the GEDT distance and their
// product; the program prints nearest neighbour, first tier, second tier, E-measure and DCG
// (retrieval_evaluation.h) and writes the precision-recall curves, per-class statistics and the
// status of every model as CSV files.
//
// The collection is indexed once: each descriptor is saved in the cache folder and reused by
// later runs with the same settings (a progress line shows done/total, rate and time left). A
// mesh is read as a polygon soup, repaired (psb_models.h: repair_polygon_soup,
// orient_polygon_soup), turned into a mesh and triangulated; a model that cannot be read or
// described is listed with the reason, never dropped silently, and the statistics are computed
// over the models described in both frames (the classes keep the others' absence in their sizes).
//
// usage: retrieval_benchmark --data DIR --cache DIR [--output DIR] [--classification FILE]
//          [--frames symmetry,pca] [--resolution N] [--samples N] [--frame-resolution N]
//          [--jobs J] [--limit N] [--matrices DIR] [--pose-search] [--held-out-exponent]
//          [--prst-values LIST]
//   --data: the PSB folder, holding db/<id/100>/m<id>/m<id>.off (RESULTS.md says how to get it)
//   --classification: default DATA/classification/test.cla
//   --jobs: models described at once, each on one thread (default: the number of cores)
//   --limit: the first N models of the classification only (a quick check)
//   --matrices: also write each distance matrix in the PSB binary format (n x n float) and the
//               classification of the models evaluated, for psbTable
//   --pose-search: compare each pair in the 16 poses that flip the axes or swap the first two,
//               keeping the smallest distance (the alignment's sign and order ambiguities)
//   --held-out-exponent: also the product PRST^a x GEDT, a chosen on one half of the models
//               (alternate models of each class) and evaluated on the other, both ways
//   --prst-values: also the PRST and product rows with the PRST bins read otherwise, a comma-
//               separated list of sm, thesis, D^P, standardised, rank (prst_values_of)
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include "benchmark_utilities.h"
#include "psb_models.h"
#include "retrieval_evaluation.h"

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
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Symmetry_descriptor<K> Descriptor;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace RE = retrieval_evaluation;
namespace fs = std::filesystem;

struct Options
{
  fs::path data, cache, output = ".", classification, matrices;
  std::vector<std::string> frames = {"symmetry", "pca"};
  int resolution = 32;            // the thesis's 32^3 PRST (32,768 floats)
  std::size_t samples = 2000000;  // symmetry_descriptor's default
  int frame_resolution = 64;      // symmetry_frame's default
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::size_t limit = 0;          // 0: all
  bool pose_search = false;       // distances minimised over 16 axis flips and swaps
  bool held_out_exponent = false; // PRST^a x GEDT, a chosen on a held-out half
  std::vector<std::string> prst_values; // other readings of the PRST bins compared (prst_values_of)
};

Options parse(int argc, char** argv)
{
  Options o;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--pose-search") { o.pose_search = true; continue; }
    if(arg == "--held-out-exponent") { o.held_out_exponent = true; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--data") o.data = value;
    else if(arg == "--cache") o.cache = value;
    else if(arg == "--output") o.output = value;
    else if(arg == "--classification") o.classification = value;
    else if(arg == "--matrices") o.matrices = value;
    else if(arg == "--frames") o.frames = benchmark_utilities::split(value);
    else if(arg == "--resolution") o.resolution = std::stoi(value);
    else if(arg == "--samples") o.samples = std::stoul(value);
    else if(arg == "--frame-resolution") o.frame_resolution = std::stoi(value);
    else if(arg == "--jobs") o.jobs = unsigned(std::max(1, std::stoi(value)));
    else if(arg == "--limit") o.limit = std::stoul(value);
    else if(arg == "--prst-values") o.prst_values = benchmark_utilities::split(value);
    else throw std::invalid_argument("unknown option " + arg);
  }
  if(o.data.empty() || o.cache.empty()) throw std::invalid_argument("usage: retrieval_benchmark --data DIR --cache DIR [options]");
  for(const std::string& f : o.frames)
    if(f != "symmetry" && f != "pca") throw std::invalid_argument("--frames: symmetry and/or pca, not " + f);
  if(o.classification.empty()) o.classification = o.data / "classification" / "test.cla";
  return o;
}

// The cache folder of a frame: its name holds every setting a descriptor depends on.
fs::path cache_folder(const Options& o, const std::string& frame)
{
  std::ostringstream name;
  name << frame << "-n" << o.resolution << "-s" << o.samples;
  if(frame == "symmetry") name << "-f" << o.frame_resolution;
  return o.cache / name.str();
}

void write_text(const fs::path& file, const std::string& text)
{
  const fs::path temporary = file.string() + ".tmp";
  std::ofstream(temporary) << text << '\n';
  fs::rename(temporary, file);
}

std::string read_text(const fs::path& file)
{
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// What became of one model in one frame.
struct Model_result
{
  bool described = false;
  std::string note; // the repair done, or why it failed
  double seconds = 0.;
  bool from_cache = false;
};

// Reads, repairs, aligns and describes one model; the descriptor is saved in `folder`.
Model_result describe(const Options& o, const std::string& frame, int id, const fs::path& folder)
{
  Model_result r;
  const auto start = std::chrono::steady_clock::now();
  const fs::path path = psb_models::model_path(o.data, id);
  const std::string stem = "m" + std::to_string(id);
  try {
    Mesh mesh;
    if(!fs::exists(path)) throw std::runtime_error("file missing: " + path.string());
    r.note = psb_models::read_triangle_mesh(path.string(), mesh);
    const auto threads = CGAL::parameters::number_of_threads(1u);
    const ST::Symmetry_frame<K> f = frame == "symmetry"
      ? ST::symmetry_frame(mesh, CGAL::parameters::grid_resolution(o.frame_resolution).number_of_threads(1u))
      : ST::pca_frame(mesh);
    PMP::transform(ST::to_canonical(f), mesh);
    const Descriptor d = ST::symmetry_descriptor(mesh, threads.grid_resolution(o.resolution).number_of_samples(o.samples));
    const fs::path temporary = folder / (stem + ".desc.tmp");
    d.save(temporary.string());
    fs::rename(temporary, folder / (stem + ".desc"));
    if(!r.note.empty()) write_text(folder / (stem + ".note"), r.note);
    r.described = true;
  } catch(const std::exception& e) {
    r.note = std::string("FAILED: ") + e.what();
    write_text(folder / (stem + ".failed"), r.note);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// The result of a model already in the cache, if any (a corrupt descriptor is recomputed).
bool cached(const fs::path& folder, int id, Model_result& r, Descriptor* d)
{
  const std::string stem = "m" + std::to_string(id);
  r.from_cache = true;
  if(fs::exists(folder / (stem + ".failed"))) {
    r.note = read_text(folder / (stem + ".failed"));
    return true;
  }
  if(!fs::exists(folder / (stem + ".desc"))) return false;
  try {
    if(d) *d = Descriptor::load((folder / (stem + ".desc")).string());
  } catch(const std::exception&) {
    return false;
  }
  if(fs::exists(folder / (stem + ".note"))) r.note = read_text(folder / (stem + ".note"));
  r.described = true;
  return true;
}

std::string duration(double seconds)
{
  std::ostringstream s;
  const long t = long(seconds + 0.5);
  if(t >= 3600) s << t / 3600 << " h " << std::setw(2) << std::setfill('0') << (t % 3600) / 60 << " min";
  else if(t >= 60) s << t / 60 << " min " << std::setw(2) << std::setfill('0') << t % 60 << " s";
  else s << t << " s";
  return s.str();
}

// Describes every model not in the cache, `jobs` at a time, with a progress line on stderr.
std::vector<Model_result> index_collection(const Options& o, const std::string& frame, const std::vector<int>& ids)
{
  const fs::path folder = cache_folder(o, frame);
  fs::create_directories(folder);
  std::vector<Model_result> results(ids.size());
  std::vector<std::size_t> todo;
  for(std::size_t i = 0; i < ids.size(); ++i)
    if(!cached(folder, ids[i], results[i], nullptr)) todo.push_back(i);
  std::cerr << "[" << frame << "] " << ids.size() - todo.size() << " of " << ids.size() << " models in the cache "
            << folder << ", " << todo.size() << " to describe\n";
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const bool terminal = isatty(fileno(stderr));
  const auto start = std::chrono::steady_clock::now();
  auto work = [&] {
    for(std::size_t k; (k = next++) < todo.size();) {
      const std::size_t i = todo[k];
      results[i] = describe(o, frame, ids[i], folder);
      const std::size_t finished = ++done;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double rate = double(finished) / elapsed;
      std::lock_guard<std::mutex> lock(print);
      // On a terminal one line rewritten in place; in a log file a line per 2 % of the work.
      if(!terminal && (finished * 50) / todo.size() == ((finished - 1) * 50) / todo.size()) continue;
      std::cerr << (terminal ? "\r[" : "[") << frame << "] " << ids.size() - todo.size() + finished << "/" << ids.size()
                << " models, " << std::fixed << std::setprecision(2) << rate << " models/s, "
                << duration(double(todo.size() - finished) / rate) << " left   " << (terminal ? "" : "\n") << std::flush;
    }
  };
  std::vector<std::thread> workers;
  for(unsigned t = 0; t < o.jobs; ++t) workers.emplace_back(work);
  for(std::thread& t : workers) t.join();
  if(!todo.empty())
    std::cerr << "\n[" << frame << "] described " << todo.size() << " models in "
              << duration(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()) << "\n";
  return results;
}

// The three distances of every pair of models, rows shared among `jobs` threads.
struct Distance_matrices
{
  std::vector<std::vector<double>> prst, gedt, product;
};

Distance_matrices distance_matrices(const std::vector<Descriptor>& d, unsigned jobs)
{
  const std::size_t n = d.size();
  Distance_matrices m;
  m.prst.assign(n, std::vector<double>(n, 0.));
  m.gedt = m.prst;
  m.product = m.prst;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for(std::size_t i; (i = next++) < n;)
      for(std::size_t j = i + 1; j < n; ++j) {
        m.prst[i][j] = m.prst[j][i] = ST::reflective_symmetry_descriptor_distance(d[i], d[j]);
        m.gedt[i][j] = m.gedt[j][i] = ST::gedt_distance(d[i], d[j]);
        m.product[i][j] = m.product[j][i] = m.prst[i][j] * m.gedt[i][j];
      }
  };
  std::vector<std::thread> workers;
  for(unsigned t = 0; t < jobs; ++t) workers.emplace_back(work);
  for(std::thread& t : workers) t.join();
  return m;
}

// Pose search: the distances minimised over the 16 rigid motions about the centre of mass that
// swap the first two axes and/or flip any of the three (the symmetries of a square prism around
// the third axis). They map the GEDT samples and the PRST bins onto each other exactly (bins and
// samples as documented in Voxel_grid and Reflective_symmetry_transform), so the search costs
// 16 comparisons and no resampling. It resolves the alignment's ambiguities of sign and of the
// order of the first two axes, not a swap involving the third (the pole of the PRST's bins).
constexpr int number_of_poses = 16; // bit 0, 1, 2: flip x, y, z; bit 3: swap x and y

// For each sample of the moved GEDT, the sample of the original it takes (sample (i, j, k) at
// (k n + j) n + i, offsets (i + 1/2 - n/2, ...) from the centre): the original at g^-1 of it.
std::vector<std::size_t> gedt_source(std::size_t n, int pose)
{
  std::vector<std::size_t> source(n * n * n);
  auto flip = [&](std::size_t x, int bit) { return pose & (1 << bit) ? n - 1 - x : x; };
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t fi = flip(i, 0), fj = flip(j, 1), fk = flip(k, 2);
        const std::size_t si = pose & 8 ? fj : fi, sj = pose & 8 ? fi : fj;
        source[(k * n + j) * n + i] = (fk * n + sj) * n + si;
      }
  return source;
}

// The same for the PRST bins (i, j, k) of (theta, phi, r), at (i n + j) n + k: the plane of
// normal m and offset r takes the value of the plane (g^-1 m, r). On the bin centres, flipping x
// maps phi to pi - phi, y to -phi, z to (phi + pi, -r) (the normal turned back up), and the swap
// maps phi to pi/2 - phi: index maps, n being a multiple of 4.
std::vector<std::size_t> prst_source(std::size_t n, int pose)
{
  std::vector<std::size_t> source(n * n * n);
  auto wrap = [&](long j) { return std::size_t(((j % long(n)) + long(n)) % long(n)); };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t k = 0; k < n; ++k) {
        long phi = long(j);
        std::size_t r = k;
        if(pose & 1) phi = long(n / 2) - 1 - phi;
        if(pose & 2) phi = long(n) - 1 - phi;
        if(pose & 4) { phi += long(n / 2); r = n - 1 - r; }
        if(pose & 8) phi = long(n / 4) - 1 - phi;
        source[(i * n + j) * n + k] = (i * n + wrap(phi)) * n + r;
      }
  return source;
}

// The two parts of a descriptor as plain arrays, possibly moved by a pose.
struct Descriptor_arrays
{
  std::vector<float> prst, gedt;
};

std::vector<Descriptor_arrays> moved(const std::vector<Descriptor>& d, int pose)
{
  const std::size_t n = d.front().resolution();
  const std::vector<std::size_t> ps = prst_source(n, pose), gs = gedt_source(n, pose);
  std::vector<Descriptor_arrays> result(d.size());
  for(std::size_t m = 0; m < d.size(); ++m) {
    const std::vector<float>&p = d[m].compared_symmetry_values(), &g = d[m].gedt_values();
    result[m].prst.resize(p.size());
    result[m].gedt.resize(g.size());
    for(std::size_t x = 0; x < p.size(); ++x) result[m].prst[x] = p[ps[x]];
    for(std::size_t x = 0; x < g.size(); ++x) result[m].gedt[x] = g[gs[x]];
  }
  return result;
}

// The two distances of symmetry_descriptor.h, from their documented formulas: the RMS difference
// of the PRST's compared values (D^(1/4)) weighted by sqrt(sin theta) per theta row, the GEDT's L2.
std::pair<double, double> distances(const Descriptor_arrays& a, const Descriptor_arrays& b, const std::vector<double>& row_weight)
{
  const std::size_t n = row_weight.size(), row = n * n;
  double prst = 0., weights = 0., gedt = 0.;
  for(std::size_t i = 0; i < n; ++i) {
    float sum = 0.f, g = 0.f;
    for(std::size_t x = i * row; x < (i + 1) * row; ++x) {
      const float d = a.prst[x] - b.prst[x], e = a.gedt[x] - b.gedt[x];
      sum += d * d;
      g += e * e;
    }
    prst += row_weight[i] * double(sum);
    weights += row_weight[i] * double(row);
    gedt += double(g);
  }
  return {std::sqrt(prst / weights), std::sqrt(gedt)};
}

// The distance matrices minimised over the poses (the product minimised as a product: one pose
// for both parts). Pose 0 is the identity: its distances are checked against the library's.
Distance_matrices pose_searched_matrices(const std::vector<Descriptor>& d, const Distance_matrices& plain, unsigned jobs)
{
  const std::size_t n = d.size();
  const std::vector<double>& row_weight = d.front().row_weights();
  const std::vector<Descriptor_arrays> fixed = moved(d, 0);
  Distance_matrices m = plain;
  double largest_difference = 0.;
  for(int pose = 0; pose < number_of_poses; ++pose) {
    const std::vector<Descriptor_arrays> other = pose == 0 ? fixed : moved(d, pose);
    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    auto work = [&] {
      for(std::size_t i; (i = next++) < n;)
        for(std::size_t j = i + 1; j < n; ++j) {
          const auto [p, g] = distances(fixed[i], other[j], row_weight);
          if(pose == 0) {
            const double e = std::max(std::abs(p - plain.prst[i][j]), std::abs(g - plain.gedt[i][j]));
            std::lock_guard<std::mutex> lock(mutex);
            largest_difference = std::max(largest_difference, e);
          }
          m.prst[i][j] = m.prst[j][i] = std::min(m.prst[i][j], p);
          m.gedt[i][j] = m.gedt[j][i] = std::min(m.gedt[i][j], g);
          m.product[i][j] = m.product[j][i] = std::min(m.product[i][j], p * g);
        }
    };
    std::vector<std::thread> workers;
    for(unsigned t = 0; t < jobs; ++t) workers.emplace_back(work);
    for(std::thread& t : workers) t.join();
  }
  std::cerr << "pose search: largest difference to the library's distances at the identity " << largest_difference << "\n";
  return m;
}

// Other readings of a PRST bin's symmetry measure SM than the library's D^(1/4), D the
// normalised symmetry distance sqrt((1 - SM)/2) (reflective_symmetry_descriptor_distance):
// "sm": SM itself (the library's comparison until 2026-12-03);
// "thesis": the transform's value sqrt((1 + SM)/2) (thesis, equation 3.1.1);
// "D^P": D raised to the power P (the library's is D^0.25);
// "standardised": SM less its mean over the bins, over its standard deviation (the pattern of
//   the symmetries, not their overall level);
// "rank": the fraction of the shape's bins below SM (the pattern, invariant to any monotone map).
std::vector<float> prst_values_of(const Descriptor& d, const std::string& reading)
{
  std::vector<float> v = d.reflective_symmetry_values();
  if(reading == "sm") return v;
  if(reading == "thesis") {
    for(float& x : v) x = std::sqrt(std::max(0.f, (1.f + x) / 2.f));
  } else if(reading.rfind("D^", 0) == 0) {
    v = ST::internal::compared_symmetry_values(v, std::stod(reading.substr(2)));
  } else if(reading == "standardised") {
    double sum = 0., squares = 0.;
    for(float x : v) { sum += x; squares += double(x) * x; }
    const double mean = sum / double(v.size()), deviation = std::sqrt(std::max(1e-12, squares / double(v.size()) - mean * mean));
    for(float& x : v) x = float((x - mean) / deviation);
  } else if(reading == "rank") {
    std::vector<std::size_t> order(v.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    for(std::size_t r = 0; r < order.size(); ++r) v[order[r]] = float(double(r) / double(order.size()));
  } else
    throw std::invalid_argument("--prst-values: sm, thesis, D^P, standardised or rank, not " + reading);
  return v;
}

// The PRST and product matrices with the PRST bins read as `reading` (the GEDT's unchanged).
Distance_matrices matrices_with_prst_values(const std::vector<Descriptor>& d, const Distance_matrices& plain,
                                           const std::string& reading, unsigned jobs)
{
  const std::size_t n = d.size();
  const std::vector<double>& row_weight = d.front().row_weights();
  std::vector<Descriptor_arrays> a(n);
  for(std::size_t m = 0; m < n; ++m) {
    a[m].prst = prst_values_of(d[m], reading);
    a[m].gedt = d[m].gedt_values();
  }
  Distance_matrices m = plain;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for(std::size_t i; (i = next++) < n;)
      for(std::size_t j = i + 1; j < n; ++j) {
        const double p = distances(a[i], a[j], row_weight).first;
        m.prst[i][j] = m.prst[j][i] = p;
        m.product[i][j] = m.product[j][i] = p * plain.gedt[i][j];
      }
  };
  std::vector<std::thread> workers;
  for(unsigned t = 0; t < jobs; ++t) workers.emplace_back(work);
  for(std::thread& t : workers) t.join();
  return m;
}

// The exponents a of PRST^a x GEDT tried on the tuning half: 0 is the GEDT alone, 1 the product.
constexpr double exponent_step = 0.125;
constexpr int exponent_steps = 24; // up to 3

// The two halves of a classification: the models at even and at odd positions of their class.
std::array<std::vector<bool>, 2> class_halves(const RE::Classification& c)
{
  std::array<std::vector<bool>, 2> half{std::vector<bool>(c.class_of.size()), std::vector<bool>(c.class_of.size())};
  std::vector<std::size_t> seen(c.class_names.size(), 0);
  for(std::size_t i = 0; i < c.class_of.size(); ++i) {
    const bool odd = seen[c.class_of[i]]++ % 2 == 1;
    half[odd][i] = true;
  }
  return half;
}

// PRST^a x GEDT between the models of `keep`.
std::vector<std::vector<double>> weighted_product(const Distance_matrices& m, const std::vector<bool>& keep, double a)
{
  std::vector<std::size_t> index;
  for(std::size_t i = 0; i < keep.size(); ++i)
    if(keep[i]) index.push_back(i);
  std::vector<std::vector<double>> result(index.size(), std::vector<double>(index.size(), 0.));
  for(std::size_t i = 0; i < index.size(); ++i)
    for(std::size_t j = 0; j < index.size(); ++j)
      result[i][j] = std::pow(m.prst[index[i]][index[j]], a) * m.gedt[index[i]][index[j]];
  return result;
}

// The exponent that maximises the mean of NN and DCG on the models of `tuning`.
double best_exponent(const Distance_matrices& m, const RE::Classification& c, const std::vector<bool>& tuning)
{
  const RE::Classification half = RE::restricted(c, tuning);
  double best = 0., best_score = -1.;
  for(int step = 0; step <= exponent_steps; ++step) {
    const double a = step * exponent_step;
    const RE::Summary s = RE::evaluate(weighted_product(m, tuning, a), half);
    const double score = s.mean.nearest_neighbour + s.mean.dcg;
    if(score > best_score) { best_score = score; best = a; }
  }
  return best;
}

// Two-fold: the exponent chosen on each half, the GEDT, the product and PRST^a x GEDT evaluated on
// the other half (a table row each).
void print_held_out_exponent(const std::string& name, const Distance_matrices& m, const RE::Classification& c)
{
  const std::array<std::vector<bool>, 2> half = class_halves(c);
  for(int fold = 0; fold < 2; ++fold) {
    const double a = best_exponent(m, c, half[fold]);
    const std::vector<bool>& test = half[1 - fold];
    const RE::Classification tested = RE::restricted(c, test);
    const std::pair<std::string, double> rows[] = {{"GEDT", 0.}, {"PRST x GEDT", 1.}, {"PRST^a x GEDT", a}};
    for(const auto& [row, exponent] : rows) {
      const RE::Summary s = RE::evaluate(weighted_product(m, test, exponent), tested);
      std::cout << std::fixed << std::setprecision(1) << "| " << name << ", half " << 2 - fold << " (a = "
                << std::setprecision(3) << a << " from half " << fold + 1 << ") | " << row << " | " << std::setprecision(1)
                << 100. * s.mean.nearest_neighbour << " | " << 100. * s.mean.first_tier << " | " << 100. * s.mean.second_tier
                << " | " << 100. * s.mean.e_measure << " | " << 100. * s.mean.dcg << " |\n";
    }
  }
}

// A distance matrix in the PSB binary format: n x n floats, row by row.
void write_matrix(const fs::path& file, const std::vector<std::vector<double>>& m)
{
  std::ofstream out(file, std::ios::binary);
  for(const auto& row : m)
    for(double x : row) {
      const float f = float(x);
      out.write(reinterpret_cast<const char*>(&f), sizeof(f));
    }
}

// The classification of the models evaluated, in the PSB format, for psbTable.
void write_classification(const fs::path& file, const RE::Classification& c)
{
  std::ofstream out(file);
  out << "PSB 1\n" << c.class_names.size() << ' ' << c.model_ids.size() << "\n";
  for(std::size_t k = 0; k < c.class_names.size(); ++k) {
    std::vector<int> ids;
    for(std::size_t i = 0; i < c.model_ids.size(); ++i)
      if(c.class_of[i] == k) ids.push_back(c.model_ids[i]);
    out << "\n" << c.class_names[k] << " 0 " << ids.size() << "\n";
    for(int id : ids) out << id << "\n";
  }
}

// Lists the models not described (all frames) and the repaired ones (CSV), and returns which
// models are described in every frame.
std::vector<bool> report_models(const Options& o, const RE::Classification& c, const std::vector<std::vector<Model_result>>& r)
{
  std::ofstream csv(o.output / "retrieval_models.csv");
  csv << "model,class,frame,status,seconds,note\n";
  std::vector<bool> keep(c.model_ids.size(), true);
  std::size_t repaired = 0;
  for(std::size_t i = 0; i < c.model_ids.size(); ++i) {
    bool noted = false;
    for(std::size_t f = 0; f < o.frames.size(); ++f) {
      const Model_result& m = r[f][i];
      csv << c.model_ids[i] << ',' << c.class_names[c.class_of[i]] << ',' << o.frames[f] << ','
          << (m.described ? "described" : "failed") << ',' << (m.from_cache ? "" : std::to_string(m.seconds)) << ",\""
          << m.note << "\"\n";
      if(!m.described) {
        keep[i] = false;
        std::cout << "  model " << c.model_ids[i] << " (" << c.class_names[c.class_of[i]] << "), " << o.frames[f]
                  << " frame: " << m.note << "\n";
      }
      noted = noted || (m.described && !m.note.empty());
    }
    repaired += noted;
  }
  const std::size_t kept = std::size_t(std::count(keep.begin(), keep.end(), true));
  std::cout << kept << " of " << c.model_ids.size() << " models described in every frame and evaluated; "
            << c.model_ids.size() - kept << " not (listed above); " << repaired
            << " read with repairs (retrieval_models.csv)\n";
  return keep;
}

// Evaluates the three distances of one frame: a table row each, and the CSV files.
void evaluate_frame(const Options& o, const std::string& frame, const RE::Classification& c, std::ofstream& summary,
                    std::ofstream& curves, std::ofstream& classes)
{
  std::vector<Descriptor> d(c.model_ids.size());
  const fs::path folder = cache_folder(o, frame);
  for(std::size_t i = 0; i < d.size(); ++i)
    d[i] = Descriptor::load((folder / ("m" + std::to_string(c.model_ids[i]) + ".desc")).string());
  const auto start = std::chrono::steady_clock::now();
  const Distance_matrices plain = distance_matrices(d, o.jobs);
  const Distance_matrices searched = o.pose_search ? pose_searched_matrices(d, plain, o.jobs) : Distance_matrices();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<std::pair<std::string, const std::vector<std::vector<double>>*>> matrices = {
    {"PRST", &plain.prst}, {"GEDT", &plain.gedt}, {"PRST x GEDT", &plain.product}};
  if(o.pose_search)
    for(const auto& [name, matrix] : {std::make_pair("PRST", &searched.prst), std::make_pair("GEDT", &searched.gedt),
                                      std::make_pair("PRST x GEDT", &searched.product)})
      matrices.push_back({std::string(name) + " pose search", matrix});
  std::vector<Distance_matrices> readings;
  readings.reserve(o.prst_values.size());
  for(const std::string& reading : o.prst_values) {
    readings.push_back(matrices_with_prst_values(d, plain, reading, o.jobs));
    matrices.push_back({"PRST (" + reading + ")", &readings.back().prst});
    matrices.push_back({"PRST (" + reading + ") x GEDT", &readings.back().product});
  }
  for(const auto& [name, matrix] : matrices) {
    const RE::Summary s = RE::evaluate(*matrix, c);
    std::cout << std::fixed << std::setprecision(1) << "| " << frame << " | " << name << " | " << 100. * s.mean.nearest_neighbour
              << " | " << 100. * s.mean.first_tier << " | " << 100. * s.mean.second_tier << " | " << 100. * s.mean.e_measure
              << " | " << 100. * s.mean.dcg << " |\n";
    summary << frame << ',' << name << ',' << s.queries << ',' << s.mean.nearest_neighbour << ',' << s.mean.first_tier
            << ',' << s.mean.second_tier << ',' << s.mean.e_measure << ',' << s.mean.dcg << '\n';
    for(std::size_t l = 0; l < s.recall.size(); ++l) curves << frame << ',' << name << ',' << s.recall[l] << ',' << s.precision[l] << '\n';
    for(std::size_t k = 0; k < c.class_names.size(); ++k)
      classes << frame << ',' << name << ',' << c.class_names[k] << ',' << s.class_queries[k] << ',' << s.per_class[k].nearest_neighbour
              << ',' << s.per_class[k].first_tier << ',' << s.per_class[k].second_tier << ',' << s.per_class[k].e_measure << ','
              << s.per_class[k].dcg << '\n';
    if(!o.matrices.empty()) {
      std::string file = frame + "-" + name + ".matrix";
      std::replace(file.begin(), file.end(), ' ', '_');
      write_matrix(o.matrices / file, *matrix);
    }
  }
  std::cerr << "[" << frame << "] " << d.size() * (d.size() - 1) / 2 << " pairs compared in " << std::setprecision(2)
            << seconds << " s\n";
  if(o.held_out_exponent) {
    std::cout << "\nPRST^a x GEDT, a chosen on one half of the models (alternate models of each class, NN + DCG "
                 "maximised), evaluated on the other half\n\n| alignment, half | distance | NN | FT | ST | E | DCG |\n"
                 "|---|---|---:|---:|---:|---:|---:|\n";
    print_held_out_exponent(frame, plain, c);
    if(o.pose_search) print_held_out_exponent(frame + " pose search", searched, c);
  }
}

void report(const Options& o, const RE::Classification& all, const std::vector<std::vector<Model_result>>& results)
{
  fs::create_directories(o.output);
  const RE::Classification c = RE::restricted(all, report_models(o, all, results));
  if(!o.matrices.empty()) {
    fs::create_directories(o.matrices);
    write_classification(o.matrices / "evaluated.cla", c);
  }
  std::ofstream summary(o.output / "retrieval_summary.csv"), curves(o.output / "retrieval_precision_recall.csv"),
    classes(o.output / "retrieval_per_class.csv");
  summary << "frame,distance,queries,nn,first_tier,second_tier,e_measure,dcg\n";
  curves << "frame,distance,recall,precision\n";
  classes << "frame,distance,class,queries,nn,first_tier,second_tier,e_measure,dcg\n";
  summary << std::setprecision(6);
  curves << std::setprecision(6);
  classes << std::setprecision(6);
  std::cout << "\nStatistics in %, micro-averaged over the queries (psbTable's default)\n\n"
            << "| alignment | distance | NN | FT | ST | E | DCG |\n|---|---|---:|---:|---:|---:|---:|\n";
  for(const std::string& frame : o.frames) evaluate_frame(o, frame, c, summary, curves, classes);
}

} // namespace

int main(int argc, char** argv)
try {
  const Options o = parse(argc, argv);
  std::ifstream cla(o.classification);
  if(!cla) throw std::runtime_error("cannot open " + o.classification.string());
  RE::Classification c = RE::read_classification(cla);
  if(o.limit > 0 && o.limit < c.model_ids.size()) c = RE::restricted(c, [&] {
      std::vector<bool> keep(c.model_ids.size(), false);
      std::fill(keep.begin(), keep.begin() + std::ptrdiff_t(o.limit), true);
      return keep;
    }());
  std::cout << "Princeton Shape Benchmark: " << c.model_ids.size() << " models, " << c.class_names.size()
            << " classes (" << o.classification.string() << ")\n";
  std::vector<std::vector<Model_result>> results;
  for(const std::string& frame : o.frames) results.push_back(index_collection(o, frame, c.model_ids));
  report(o, c, results);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
