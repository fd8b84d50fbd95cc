// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Every algorithm of the package on a mesh of about 1.2 million faces, side by side with CGAL's
// Variational Shape Approximation and SDF segmentation on the same mesh. The mesh is
// built in code: bunny00.off (75,408 faces) refined by --levels rounds of Loop subdivision, each
// of which multiplies the face count by 4 (two rounds: 1,206,528 faces).
//
// Each algorithm runs in its own child process (fork), so that each peak resident memory is its
// own: the child resets the kernel's high-water mark (/proc/self/clear_refs), runs, and reports
// its wall-clock time, its process CPU time (all threads, user + system), its resident memory at
// the start (the mesh, shared with the parent) and its peak. The children run one after the
// other, in one run of the program, in the order of the table; with --repeats R, R rounds of all
// of them alternate and each figure is the median.
// - detection: detect_principal_symmetries() with the defaults; its planes (the strongest
//   --planes of them) are given to symmetric remeshing, as remeshing_comparison.cpp does;
// - PRST, PST: reflective_symmetry_transform() and point_symmetry_transform(), defaults;
// - alignment: symmetry_frame(), defaults;
// - symmetric remeshing: symmetric_approximate_triangle_mesh() with the defaults (min_error_drop
//   0.1, as CGAL's VSA) and with max_number_of_proxies(K), next to CGAL's approximate_triangle_mesh
//   with its defaults and with K proxies (remeshing_comparison.cpp's settings otherwise);
// - segmentation: segment_by_symmetry() with the defaults, next to CGAL::sdf_values() +
//   CGAL::segmentation_from_sdf_values() with theirs (segmentation_comparison.cpp's settings).
// With --only NAME, the program runs that algorithm alone, in its own process, without a child
// (for profilers); remeshing then detects its planes first.
//
// usage: million_faces_benchmark [--mesh bunny00.off] [--levels 2] [--proxies K] [--planes P]
//          [--repeats R] [--timeout S] [--only NAME]
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <boost/property_map/property_map.hpp>

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::median;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace VSA = CGAL::Surface_mesh_approximation;

struct Options
{
  std::string mesh = "bunny00.off";
  unsigned levels = 2;
  std::size_t proxies = 100; // the middle count of remeshing_comparison.cpp
  std::size_t planes = 1;    // as remeshing_comparison.cpp: the strongest plane
  std::size_t repeats = 1;
  unsigned timeout = 1800; // seconds before a child is stopped (SIGALRM)
  std::string only;
};

// What one run of one algorithm measured; `info` describes its result, `planes` are detection's.
struct Measure
{
  double wall = 0., cpu = 0., start_mib = 0., peak_mib = 0.;
  std::string info;
  std::vector<double> planes; // a, b, c, d of each plane
  std::string failure;        // why the child did not report, if it did not
};

double process_cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// A field of /proc/self/status in MiB (VmRSS: resident now; VmHWM: the peak since the last reset).
double status_mib(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.compare(0, field.size() + 1, field + ":") == 0) return std::stod(line.substr(field.size() + 1)) / 1024.;
  return 0.;
}

// Sets the peak resident memory back to the current one (Linux >= 4.0), so that a forked child's
// peak is its own and not the parent's.
void reset_peak_memory()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

std::vector<K::Plane_3> planes_of(const std::vector<double>& abcd, std::size_t kept)
{
  std::vector<K::Plane_3> planes;
  for(std::size_t i = 0; i + 3 < abcd.size() && planes.size() < kept; i += 4)
    planes.emplace_back(abcd[i], abcd[i + 1], abcd[i + 2], abcd[i + 3]);
  return planes;
}

typedef std::function<std::string(const Mesh&, const std::vector<K::Plane_3>&, std::vector<double>&)> Algorithm;

std::string counts(std::size_t proxies, std::size_t anchors, std::size_t triangles)
{
  return std::to_string(proxies) + " proxies, " + std::to_string(anchors) + " vertices, " + std::to_string(triangles) +
         " triangles";
}

std::string symmetric_remeshing(const Mesh& mesh, const std::vector<K::Plane_3>& planes, std::size_t k)
{
  std::vector<K::Plane_3> proxies;
  std::vector<K::Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  const auto np = CGAL::parameters::proxies(std::back_inserter(proxies))
                    .anchors(std::back_inserter(anchors))
                    .triangles(std::back_inserter(triangles));
  if(k == 0) ST::symmetric_approximate_triangle_mesh(mesh, planes, np);
  else ST::symmetric_approximate_triangle_mesh(mesh, planes, np.max_number_of_proxies(k));
  return counts(proxies.size(), anchors.size(), triangles.size());
}

std::string cgal_vsa(const Mesh& mesh, std::size_t k)
{
  std::vector<K::Vector_3> proxies; // L21 proxies: normals
  std::vector<K::Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  const auto np = CGAL::parameters::proxies(std::back_inserter(proxies))
                    .anchors(std::back_inserter(anchors))
                    .triangles(std::back_inserter(triangles));
  if(k == 0) VSA::approximate_triangle_mesh(mesh, np);
  else VSA::approximate_triangle_mesh(mesh, np.max_number_of_proxies(k));
  return counts(proxies.size(), anchors.size(), triangles.size());
}

// The algorithms, in the order of the table; the names are those of --only.
std::vector<std::pair<std::string, Algorithm>> algorithms(const Options& o)
{
  typedef std::vector<K::Plane_3> Planes;
  typedef std::vector<double> Out;
  const std::string k = std::to_string(o.proxies);
  return {
    {"detection", [](const Mesh& m, const Planes&, Out& abcd) {
       const auto symmetries = ST::detect_principal_symmetries(m);
       for(const auto& s : symmetries) abcd.insert(abcd.end(), {s.plane.a(), s.plane.b(), s.plane.c(), s.plane.d()});
       return std::to_string(symmetries.size()) + " planes";
     }},
    {"prst", [](const Mesh& m, const Planes&, Out&) {
       return std::to_string(ST::reflective_symmetry_transform(m).resolution()) + " bins per axis";
     }},
    {"pst", [](const Mesh& m, const Planes&, Out&) {
       const auto center = ST::point_symmetry_transform(m).center_of_symmetry();
       std::ostringstream s;
       s << "centre " << center;
       return s.str();
     }},
    {"alignment", [](const Mesh& m, const Planes&, Out&) {
       std::ostringstream s;
       s << "first axis " << ST::symmetry_frame(m).axes[0];
       return s.str();
     }},
    {"remeshing", [](const Mesh& m, const Planes& p, Out&) { return symmetric_remeshing(m, p, 0); }},
    {"vsa", [](const Mesh& m, const Planes&, Out&) { return cgal_vsa(m, 0); }},
    {"remeshing-" + k, [&o](const Mesh& m, const Planes& p, Out&) { return symmetric_remeshing(m, p, o.proxies); }},
    {"vsa-" + k, [&o](const Mesh& m, const Planes&, Out&) { return cgal_vsa(m, o.proxies); }},
    {"segmentation", [](const Mesh& m, const Planes&, Out&) {
       std::vector<std::size_t> ids(num_faces(m));
       const auto segment = boost::make_iterator_property_map(ids.begin(), get(boost::face_index, m));
       return std::to_string(ST::segment_by_symmetry(m, segment)) + " segments";
     }},
    {"sdf", [](const Mesh& m, const Planes&, Out&) {
       std::vector<std::size_t> ids(num_faces(m));
       std::vector<double> values(num_faces(m));
       const auto segment = boost::make_iterator_property_map(ids.begin(), get(boost::face_index, m));
       const auto sdf = boost::make_iterator_property_map(values.begin(), get(boost::face_index, m));
       CGAL::sdf_values(m, sdf);
       return std::to_string(CGAL::segmentation_from_sdf_values(m, sdf, segment)) + " segments";
     }},
  };
}

Measure measured(const Algorithm& algorithm, const Mesh& mesh, const std::vector<K::Plane_3>& planes)
{
  Measure m;
  reset_peak_memory();
  m.start_mib = status_mib("VmRSS");
  const double cpu = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  m.info = algorithm(mesh, planes, m.planes);
  m.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.cpu = process_cpu_seconds() - cpu;
  m.peak_mib = status_mib("VmHWM");
  return m;
}

// The measure as one line of text through the pipe: wall cpu start peak count planes... | info.
std::string serialized(const Measure& m)
{
  std::ostringstream s;
  s << std::setprecision(17) << m.wall << ' ' << m.cpu << ' ' << m.start_mib << ' ' << m.peak_mib << ' '
    << m.planes.size();
  for(double x : m.planes) s << ' ' << x;
  s << " | " << m.info << '\n';
  return s.str();
}

Measure deserialized(const std::string& line)
{
  Measure m;
  std::istringstream s(line);
  std::size_t n = 0;
  s >> m.wall >> m.cpu >> m.start_mib >> m.peak_mib >> n;
  m.planes.resize(n);
  for(double& x : m.planes) s >> x;
  const std::size_t bar = line.find(" | ");
  if(!s || bar == std::string::npos) m.failure = "no report";
  else m.info = line.substr(bar + 3);
  return m;
}

// Runs the algorithm in a forked child, which reports through a pipe; a child killed (time-out,
// out of memory) or failing leaves the reason in `failure`.
Measure measured_in_child(const Algorithm& algorithm, const Mesh& mesh, const std::vector<K::Plane_3>& planes,
                          unsigned timeout)
{
  int fd[2];
  if(pipe(fd) != 0) throw std::runtime_error("pipe failed");
  std::cout << std::flush;
  const pid_t child = fork();
  if(child < 0) throw std::runtime_error("fork failed");
  if(child == 0) {
    close(fd[0]);
    alarm(timeout);
    std::string line;
    try {
      line = serialized(measured(algorithm, mesh, planes));
    } catch(const std::exception& e) {
      line = "error: " + std::string(e.what()) + "\n";
    }
    if(write(fd[1], line.data(), line.size()) != ssize_t(line.size())) _exit(2);
    _exit(0);
  }
  close(fd[1]);
  std::string text;
  char buffer[4096];
  for(ssize_t n; (n = read(fd[0], buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
  close(fd[0]);
  int status = 0;
  waitpid(child, &status, 0);
  Measure m = deserialized(text);
  if(WIFSIGNALED(status))
    m.failure = WTERMSIG(status) == SIGALRM ? "stopped after " + std::to_string(timeout) + " s"
                                            : "killed by signal " + std::to_string(WTERMSIG(status));
  else if(text.compare(0, 6, "error:") == 0) m.failure = text.substr(0, text.size() - 1);
  return m;
}

Options options_of(int argc, char** argv)
{
  Options o;
  for(const auto& [name, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(name == "--mesh") o.mesh = value;
    else if(name == "--levels") o.levels = unsigned(std::stoul(value));
    else if(name == "--proxies") o.proxies = std::stoul(value);
    else if(name == "--planes") o.planes = std::stoul(value);
    else if(name == "--repeats") o.repeats = std::max<std::size_t>(1, std::stoul(value));
    else if(name == "--timeout") o.timeout = unsigned(std::stoul(value));
    else if(name == "--only") o.only = value;
    else throw std::invalid_argument("unknown option: " + name);
  }
  if(o.proxies == 0) throw std::invalid_argument("--proxies must be positive");
  return o;
}

Mesh subdivided_mesh(const Options& o)
{
  Mesh mesh;
  const std::string path = mesh_path(o.mesh);
  if(!PMP::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) throw std::runtime_error("cannot read " + path);
  if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
  const std::size_t input_faces = num_faces(mesh);
  const auto start = std::chrono::steady_clock::now();
  if(o.levels > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(o.levels));
  std::cerr << o.mesh << ": " << input_faces << " faces, " << num_faces(mesh) << " after " << o.levels
            << " Loop subdivision(s) ("
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
  return mesh;
}

// --only NAME: the algorithm alone, in this process (remeshing detects its planes first).
int run_only(const Options& o, const Mesh& mesh)
{
  const auto all = algorithms(o);
  for(const auto& [name, algorithm] : all)
    if(name == o.only) {
      std::vector<double> abcd;
      if(name.compare(0, 9, "remeshing") == 0) all.front().second(mesh, {}, abcd);
      const Measure m = measured(algorithm, mesh, planes_of(abcd, o.planes));
      std::cout << name << ": " << m.wall << " s wall, " << m.cpu << " s CPU, peak " << m.peak_mib << " MiB ("
                << m.start_mib << " at the start); " << m.info << std::endl;
      return EXIT_SUCCESS;
    }
  throw std::invalid_argument("unknown algorithm: " + o.only);
}

std::string cell(const std::vector<Measure>& runs, double Measure::*field, int digits)
{
  std::vector<double> v;
  for(const Measure& m : runs)
    if(m.failure.empty()) v.push_back(m.*field);
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits);
  if(v.empty()) s << "-";
  else s << median(v);
  return s.str();
}

double median_wall(const std::vector<Measure>& runs)
{
  std::vector<double> v;
  for(const Measure& m : runs)
    if(m.failure.empty()) v.push_back(m.wall);
  return v.empty() ? 0. : median(v);
}

void print_table(const Options& o, const Mesh& mesh, const std::vector<std::pair<std::string, Algorithm>>& all,
                 const std::map<std::string, std::vector<Measure>>& runs)
{
  std::cout << "\n" << o.mesh << " after " << o.levels << " Loop subdivision(s): " << num_faces(mesh) << " faces, "
            << num_vertices(mesh) << " vertices; " << o.repeats << " round(s), medians; memory in MiB (peak: the "
            << "child's resident peak, mesh included; own: peak - resident at the start)\n\n"
            << "| algorithm | wall (s) | CPU (s) | peak memory | own memory | result |\n"
            << "|---|---:|---:|---:|---:|---|\n";
  for(const auto& entry : all) {
    const std::vector<Measure>& r = runs.at(entry.first);
    std::vector<Measure> own = r;
    for(Measure& m : own) m.start_mib = m.peak_mib - m.start_mib;
    const std::string result = r.back().failure.empty() ? r.back().info.substr(0, r.back().info.size() - 1)
                                                        : "FAILED: " + r.back().failure;
    std::cout << "| " << entry.first << " | " << cell(r, &Measure::wall, 2) << " | " << cell(r, &Measure::cpu, 2)
              << " | " << cell(r, &Measure::peak_mib, 0) << " | " << cell(own, &Measure::start_mib, 0) << " | "
              << result << " |\n";
  }
  const std::string k = std::to_string(o.proxies);
  const auto ratio = [&](const std::string& a, const std::string& b) {
    return median_wall(runs.at(a)) / median_wall(runs.at(b));
  };
  std::cout << std::fixed << std::setprecision(2) << "\nwall-time ratios: remeshing / vsa (defaults) "
            << ratio("remeshing", "vsa") << ", remeshing / vsa (" << k << " proxies) "
            << ratio("remeshing-" + k, "vsa-" + k) << " (goal <= 1.5); segmentation / sdf "
            << ratio("segmentation", "sdf") << " (goal <= 1)\n";
}

} // namespace

int main(int argc, char** argv)
try {
  const Options o = options_of(argc, argv);
  const Mesh mesh = subdivided_mesh(o);
  if(!o.only.empty()) return run_only(o, mesh);
  const auto all = algorithms(o);
  std::map<std::string, std::vector<Measure>> runs;
  std::vector<double> abcd;
  for(std::size_t r = 0; r < o.repeats; ++r)
    for(const auto& [name, algorithm] : all) {
      const Measure m = measured_in_child(algorithm, mesh, planes_of(abcd, o.planes), o.timeout);
      if(name == "detection" && r == 0) abcd = m.planes;
      std::cerr << name << ": " << (m.failure.empty() ? std::to_string(m.wall) + " s, " + m.info : m.failure)
                << (m.failure.empty() ? "" : "\n");
      runs[name].push_back(m);
    }
  print_table(o, mesh, all, runs);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
