// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Time of detect_principal_symmetries() and its split into stages.
//
// For each mesh, with the default parameters except grid_resolution, each timed alone (wall
// clock, median of --repeats runs, default number_of_threads = hardware_concurrency):
//   - total: detect_principal_symmetries(mesh, np);
//   - GEDT: the Gaussian distance transform with the closest triangles of the voxels of its band
//     (internal::gaussian_distance_transform_of_triangles, as detect computes it, with the tree
//     of the matcher);
//   - PRST: internal::detection_transform(gedt, np), i.e. the Monte Carlo PRST with detect's
//     5e5 samples;
//   - maxima: internal::symmetry_candidates(prst, 0.1, 0.1) (smoothing and candidate extraction);
//   - tree: internal::triangles_of_mesh, the internal::Triangle_matcher (AABB tree, which the
//     GEDT shares) and the internal::Closest_triangle_field (ISP walks with it);
//   - ISP stage: internal::refine_candidates(gedt, prst, surface_samples, matcher, np, &field), which
//     draws the 1e4 samples, extracts the candidates again and refines them, strongest first,
//     until max_number_of_planes (10) are accepted or its cap on candidates is reached; with
//     the number of candidates (all of them, before that cap) and of planes returned.
// Total ~ GEDT + PRST + tree + ISP stage (the maxima are inside the ISP stage).
// Then one ISP refinement (both phases, 1e4 samples) per returned plane P, from P rotated by
// 2 degrees about a random axis orthogonal to its normal through the shape's centre projected
// on P, and shifted by 1 % of the shape radius: min / median / max over the planes of the
// per-plane median time, median number of iterations, and the angle between the result and P.
// Prints Markdown tables on std::cout, progress on std::cerr.
//
// Usage: principal_symmetries_timing [--meshes bull.off,refined_elephant.off] [--resolution 64]
//          [--repeats 3] [--seed 1] [--summary 0|1] [--messy 0|1] [--loop 0] [--stages 1]
// A mesh given as a bare name is looked for in SYMMETRY_TRANSFORM_DATA_DIR/meshes/; a name
// with a '/' is a path; `--meshes all` is every .off file there. --seed sets the random axes of
// the perturbed starting planes.
//
// --summary 1 prints instead one row per mesh: faces, the processor time (std::clock,
// all threads) and wall time of detect_principal_symmetries (median of --repeats), the stages
// (with --stages 1), the candidates refined and the longest single ISP refinement (wall time, as
// verbose(true) prints it, during the ISP stage; during the detection itself with --stages 0),
// then the distribution over the meshes (median, 95th percentile, max) and the slowest ten.
// --messy 1 adds, after each mesh, its hard variants (messy_meshes.h: many components,
// interior faces, slivers, one part finely tessellated). --loop L Loop-subdivides each mesh L
// times first (bunny00.off with --loop 2: 1.2M faces). --verbose 1 passes on what verbose(true)
// printed during the refinements. With --stages 0 only the detection runs,
// so that /usr/bin/time -v reports the detection's peak memory (plus the mesh's).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Random.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "benchmark_utilities.h"
#include "messy_meshes.h"

namespace {

using benchmark_utilities::split;
using benchmark_utilities::median;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace STI = CGAL::Symmetry_transform::internal;

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

// Median wall time in seconds of `repeats` calls of f.
template <typename F>
double median_time(unsigned repeats, F f)
{
  std::vector<double> times;
  for(unsigned r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(times);
}

// Median processor time (all threads) and wall time in seconds of `repeats` calls of f.
template <typename F>
std::pair<double, double> median_cpu_and_wall(unsigned repeats, F f)
{
  std::vector<double> cpu, wall;
  for(unsigned r = 0; r < repeats; ++r) {
    const std::clock_t c0 = std::clock();
    const auto start = std::chrono::steady_clock::now();
    f();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return {median(cpu), median(wall)};
}

// Whether the captured output of verbose(true) goes on to std::cerr (--verbose 1).
bool echo_verbose = false;

// Calls f with std::cerr captured; returns the longest ISP time that verbose(true) printed
// ("candidate ... ISP <seconds> s ...") and the number of such lines.
template <typename F>
std::pair<double, std::size_t> longest_refinement(F f)
{
  std::ostringstream captured;
  std::streambuf* const previous = std::cerr.rdbuf(captured.rdbuf());
  f();
  std::cerr.rdbuf(previous);
  if(echo_verbose) std::cerr << captured.str();
  std::istringstream lines(captured.str());
  double longest = 0.;
  std::size_t count = 0;
  for(std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find(": ISP ");
    if(line.find("candidate") == std::string::npos || at == std::string::npos) continue;
    longest = (std::max)(longest, std::atof(line.c_str() + at + 6));
    ++count;
  }
  return {longest, count};
}

double angle_degrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::acos((std::min)(1., std::abs(a.normalized().dot(b.normalized())))) * 180. / CGAL_PI;
}

const char* const usage_options = " [--meshes bull.off,refined_elephant.off|all] [--resolution 64] [--repeats 3] [--seed 1]"
                                  " [--summary 0|1] [--messy 0|1] [--loop 0] [--stages 0|1] [--verbose 0|1]\n";

[[noreturn]] void fail(const char* program, const std::string& message)
{
  benchmark_utilities::fail_with_usage(program, usage_options, message);
}

unsigned natural(const char* program, const std::string& option, const std::string& value, bool zero_allowed)
{
  return benchmark_utilities::natural_option(program, usage_options, option, value, zero_allowed);
}

struct Options
{
  std::vector<std::string> meshes = {"bull.off", "refined_elephant.off"};
  unsigned resolution = 64, repeats = 3, seed = 1, loop = 0;
  bool summary = false, messy = false, stages = true;
};

Options parse(int argc, char** argv)
{
  Options o;
  const std::vector<std::string> known = {"--meshes", "--resolution", "--repeats", "--seed",
                                          "--summary", "--messy", "--loop", "--stages", "--verbose"};
  for(int a = 1; a < argc; a += 2) {
    const std::string option = argv[a];
    if(std::find(known.begin(), known.end(), option) == known.end()) fail(argv[0], "unknown option '" + option + "'");
    if(a + 1 >= argc) fail(argv[0], option + " needs a value");
    const std::string value = argv[a + 1];
    if(option == "--meshes") o.meshes = value == "all" ? benchmark_utilities::all_sample_meshes() : split(value);
    else if(option == "--resolution") o.resolution = natural(argv[0], option, value, false);
    else if(option == "--repeats") o.repeats = natural(argv[0], option, value, false);
    else if(option == "--seed") o.seed = natural(argv[0], option, value, false);
    else if(option == "--loop") o.loop = natural(argv[0], option, value, true);
    else if(option == "--summary") o.summary = natural(argv[0], option, value, true) != 0;
    else if(option == "--messy") o.messy = natural(argv[0], option, value, true) != 0;
    else if(option == "--verbose") echo_verbose = natural(argv[0], option, value, true) != 0;
    else o.stages = natural(argv[0], option, value, true) != 0;
  }
  if(o.meshes.empty()) fail(argv[0], "--meshes names no mesh");
  return o;
}

// The mesh, triangulated and Loop-subdivided `loop` times; nullopt if unreadable.
std::optional<Mesh> read_mesh(const std::string& name, unsigned loop)
{
  const std::string path = mesh_path(name);
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << path << " (run scripts/setup.sh)\n";
    return std::nullopt;
  }
  if(!CGAL::is_triangle_mesh(mesh) && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh)) {
    std::cerr << "cannot triangulate " << path << "\n";
    return std::nullopt;
  }
  if(loop > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(loop));
  return mesh;
}

// The stages of a detection, each timed alone (see the head of this file).
struct Stage_times
{
  double gedt = 0., prst = 0., maxima = 0., tree = 0., isp = 0.;
  std::size_t candidates = 0;
  double longest_refinement = 0.; // wall seconds, of one candidate in the ISP stage
  std::size_t refined = 0;        // candidates refined in the ISP stage
};

// The stages; the stage objects go to the holders, for the refinements of the per-plane table.
struct Stage_objects
{
  std::optional<ST::Voxel_grid<K>> gedt; // no default constructors
  std::optional<ST::Reflective_symmetry_transform<K>> prst;
  std::vector<STI::Dtriangle> triangles;
  std::optional<STI::Triangle_matcher> matcher; // its tree points into `triangles`
  // And so does the field; a pointer, since g++ 12 warns that the vector of an optional field may be
  // used uninitialised (-Wmaybe-uninitialized, a false positive).
  std::unique_ptr<STI::Closest_triangle_field> field;
  std::vector<ST::Principal_symmetry<K>> planes;
};

template <typename NP>
Stage_times time_stages(const Mesh& mesh, const NP& np, unsigned repeats, Stage_objects& o)
{
  Stage_times t;
  std::vector<std::int32_t> closest_triangles;
  const std::vector<STI::Dtriangle> mesh_triangles = STI::triangles_of_mesh(mesh, CGAL::parameters::default_values());
  const STI::Triangle_matcher gedt_matcher(mesh_triangles); // the tree the detection shares with the GEDT
  const STI::Shape_frame frame = STI::frame_of_triangles(mesh_triangles);
  const STI::Grid_settings grid = STI::grid_settings(STI::grid_options(np), frame.radius);
  t.gedt = median_time(repeats, [&] {
    o.gedt.emplace(STI::gaussian_distance_transform_of_triangles<K>(mesh_triangles, gedt_matcher.tree(), frame, grid,
                                                                    &closest_triangles));
  });
  t.prst = median_time(repeats, [&] { o.prst.emplace(STI::detection_transform(*o.gedt, np)); });
  t.maxima = median_time(repeats, [&] { t.candidates = STI::symmetry_candidates(*o.prst, 0.1, 0.1).size(); });
  t.tree = median_time(repeats, [&] {
    o.field.reset();
    o.matcher.reset();
    o.triangles = STI::triangles_of_mesh(mesh, CGAL::parameters::default_values());
    o.matcher.emplace(o.triangles);
  });
  const ST::Voxel_grid<K>& gedt = *o.gedt;
  t.tree += median_time(repeats, [&] {
    o.field.reset();
    o.field = std::make_unique<STI::Closest_triangle_field>(o.triangles, *o.matcher, closest_triangles, gedt.origin(),
                                                            gedt.voxel_size(), gedt.resolution());
  });
  t.isp = median_time(repeats, [&] {
    std::tie(t.longest_refinement, t.refined) = longest_refinement([&] {
      o.planes = STI::refine_candidates(gedt, *o.prst, STI::surface_samples(o.triangles, np), *o.matcher,
                                        np.verbose(true), o.field.get());
    });
  });
  return t;
}

// One ISP refinement per returned plane, from a perturbed start: a row of the second table.
template <typename NP>
std::string perturbed_refinements_row(const std::string& name, const NP& np, unsigned repeats, unsigned seed,
                                      const Stage_objects& o)
{
  const ST::Voxel_grid<K>& gedt = *o.gedt;
  const std::vector<Eigen::Vector3d> samples = STI::surface_samples(o.triangles, np);
  const STI::Isp_settings settings = STI::isp_settings(np, gedt);
  const Eigen::Vector3d center(gedt.center().x(), gedt.center().y(), gedt.center().z());
  CGAL::Random random(seed);
  std::vector<double> times, iterations, angles;
  for(const ST::Principal_symmetry<K>& p : o.planes) {
    const STI::Dplane P = STI::to_dplane(p.plane);
    Eigen::Vector3d axis;
    do {
      axis = Eigen::Vector3d(random.get_double(-1., 1.), random.get_double(-1., 1.), random.get_double(-1., 1.));
      axis -= axis.dot(P.normal) * P.normal;
    } while(axis.norm() < 1e-3);
    axis.normalize();
    const double a = 2. * CGAL_PI / 180.;
    const Eigen::Vector3d pivot = center - (P.normal.dot(center) - P.offset) * P.normal; // centre projected on P
    const Eigen::Vector3d n = std::cos(a) * P.normal + std::sin(a) * axis.cross(P.normal);
    const K::Plane_3 start(n.x(), n.y(), n.z(), -(n.dot(pivot) + 0.01 * gedt.radius()));
    STI::Dplane found = P;
    unsigned steps = 0;
    times.push_back(median_time(repeats, [&] {
      const STI::Isp_result result = STI::iterative_symmetric_points(samples, STI::to_dplane(start), *o.matcher, settings,
                                                                     STI::Isp_phase::BOTH, {}, o.field.get());
      found = result.plane;
      steps = result.iterations;
    }));
    iterations.push_back(double(steps));
    angles.push_back(angle_degrees(found.normal, P.normal));
  }
  std::string row = "| " + name + " | " + std::to_string(o.planes.size()) + " | " + std::to_string(samples.size()) + " | ";
  if(o.planes.empty()) return row + "- | - | - | - | - | - |\n";
  return row + format("%.1f", 1000. * *std::min_element(times.begin(), times.end())) + " | " +
         format("%.1f", 1000. * median(times)) + " | " +
         format("%.1f", 1000. * *std::max_element(times.begin(), times.end())) + " | " +
         format("%.1f", median(iterations)) + " | " + format("%.3f", median(angles)) + " | " +
         format("%.3f", *std::max_element(angles.begin(), angles.end())) + " |\n";
}

// The per-stage tables of one mesh (the default mode).
template <typename NP>
void stage_tables(const std::string& name, const Mesh& mesh, const NP& np, const Options& options, std::string& isp_table)
{
  std::cerr << name << ": detection..." << std::endl;
  const double total = median_time(options.repeats, [&] { ST::detect_principal_symmetries(mesh, np); });
  std::cerr << name << ": stages..." << std::endl;
  Stage_objects o;
  const Stage_times t = time_stages(mesh, np, options.repeats, o);
  std::cout << "| " << name << " | " << num_faces(mesh) << " | " << format("%.3f", total) << " | "
            << format("%.3f", t.gedt) << " | " << format("%.3f", t.prst) << " | " << format("%.3f", t.maxima) << " | "
            << format("%.3f", t.tree) << " | " << format("%.3f", t.isp) << " | " << t.candidates << " | "
            << o.planes.size() << " | "
            << (o.planes.empty() ? std::string("-") : format("%.0f", 1000. * t.isp / double(o.planes.size())))
            << " |\n"
            << std::flush;
  std::cerr << name << ": one ISP per plane..." << std::endl;
  isp_table += perturbed_refinements_row(name, np, options.repeats, options.seed, o);
}

struct Summary_row
{
  std::string name;
  double cpu, wall, longest_refinement;
};

// One row of the summary (--summary 1).
template <typename NP>
Summary_row summary_row(const std::string& name, const Mesh& mesh, const NP& np, const Options& options)
{
  std::cerr << name << " (" << num_faces(mesh) << " faces)..." << std::endl;
  Summary_row row{name, 0., 0., 0.};
  std::size_t planes = 0, refined = 0;
  std::pair<double, std::size_t> longest{0., 0};
  std::vector<ST::Principal_symmetry<K>> found;
  std::tie(row.cpu, row.wall) = median_cpu_and_wall(options.repeats, [&] {
    if(options.stages) found = ST::detect_principal_symmetries(mesh, np);
    else longest = longest_refinement([&] { found = ST::detect_principal_symmetries(mesh, np.verbose(true)); });
  });
  planes = found.size();
  if(echo_verbose)
    for(const ST::Principal_symmetry<K>& p : found)
      std::fprintf(stderr, "plane %.17g %.17g %.17g %.17g symmetry %.17g support %.17g\n", p.plane.a(), p.plane.b(),
                   p.plane.c(), p.plane.d(), p.symmetry, p.support);
  std::tie(row.longest_refinement, refined) = longest;
  std::cout << "| " << name << " | " << num_faces(mesh) << " | " << format("%.3f", row.cpu) << " | "
            << format("%.3f", row.wall) << " | ";
  if(options.stages) {
    Stage_objects o;
    const Stage_times t = time_stages(mesh, np, 1, o);
    row.longest_refinement = t.longest_refinement;
    refined = t.refined;
    std::cout << format("%.3f", t.gedt) << " | " << format("%.3f", t.prst) << " | " << format("%.3f", t.tree) << " | "
              << format("%.3f", t.isp) << " | ";
  }
  std::cout << refined << " | " << format("%.0f", 1000. * row.longest_refinement) << " | " << planes << " |\n"
            << std::flush;
  return row;
}

double percentile(std::vector<double> v, double p)
{
  std::sort(v.begin(), v.end());
  return v[std::size_t(std::lround(p * double(v.size() - 1)))];
}

void print_distribution(std::vector<Summary_row> rows)
{
  if(rows.empty()) return;
  std::cout << "\n| over " << rows.size() << " meshes | median | 95th percentile | max |\n|---|---:|---:|---:|\n";
  const std::pair<const char*, double Summary_row::*> columns[] = {
    {"processor time (s)", &Summary_row::cpu}, {"wall time (s)", &Summary_row::wall},
    {"longest refinement (ms)", &Summary_row::longest_refinement}};
  for(const auto& [label, member] : columns) {
    std::vector<double> v;
    for(const Summary_row& r : rows) v.push_back(r.*member);
    const double scale = member == &Summary_row::longest_refinement ? 1000. : 1.;
    std::cout << "| " << label << " | " << format("%.3f", scale * median(v)) << " | "
              << format("%.3f", scale * percentile(v, 0.95)) << " | "
              << format("%.3f", scale * *std::max_element(v.begin(), v.end())) << " |\n";
  }
  std::sort(rows.begin(), rows.end(), [](const Summary_row& a, const Summary_row& b) { return a.cpu > b.cpu; });
  std::cout << "\nSlowest (processor time):";
  for(std::size_t i = 0; i < (std::min)(std::size_t(10), rows.size()); ++i)
    std::cout << (i ? ", " : " ") << rows[i].name << " " << format("%.2f", rows[i].cpu) << " s";
  std::cout << "\n";
}

} // namespace

int main(int argc, char** argv)
{
  const Options options = parse(argc, argv);
  std::string command = argv[0];
  for(int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];
  std::cout << "Command: `" << command << "`; hardware_concurrency " << std::thread::hardware_concurrency() << "; grid "
            << options.resolution << "^3, other parameters default; times: median of " << options.repeats << " runs.\n\n";
  if(options.summary)
    std::cout << "| mesh | faces | detection, processor (s) | detection, wall (s) | "
              << (options.stages ? "GEDT (s) | PRST 5e5 (s) | tree (s) | ISP stage (s) | " : "")
              << "candidates refined | longest refinement (ms) | planes |\n|---|---:|---:|---:|"
              << (options.stages ? "---:|---:|---:|---:|" : "") << "---:|---:|---:|\n";
  else
    std::cout << "| mesh | faces | total (s) | GEDT (s) | PRST 5e5 (s) | maxima (s) | tree (s) | ISP stage (s) "
                 "| candidates | planes | ISP stage / plane (ms) |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::string isp_table;
  std::vector<Summary_row> rows;
  const auto np = CGAL::parameters::grid_resolution(options.resolution);
  for(const std::string& name : options.meshes) {
    std::optional<Mesh> mesh = read_mesh(name, options.loop);
    if(!mesh) {
      if(options.summary) continue; // a file of the collection that is not a surface
      return 1;
    }
    std::vector<std::pair<std::string, Mesh>> shapes;
    shapes.emplace_back(name, std::move(*mesh));
    if(options.messy)
      for(auto& [variant, messy] : messy_meshes::messy_variants(shapes.front().second))
        shapes.emplace_back(name + " " + variant, std::move(messy));
    for(const auto& [shape_name, shape] : shapes) {
      if(options.summary) rows.push_back(summary_row(shape_name, shape, np, options));
      else stage_tables(shape_name, shape, np, options, isp_table);
    }
  }
  if(options.summary) {
    print_distribution(rows);
    return 0;
  }
  std::cout << "\nOne ISP refinement (both phases) per returned plane P, from P rotated by 2 degrees and shifted by "
               "1 % of the radius (seed "
            << options.seed << "); time: per plane the median of " << options.repeats
            << " runs, then min / median / max over the planes.\n\n"
            << "| mesh | planes | samples | min (ms) | median (ms) | max (ms) | median iterations "
               "| angle to P, median (deg) | angle to P, max (deg) |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
            << isp_table;
  return 0;
}
