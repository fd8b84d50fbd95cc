// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Time, memory and accuracy of detect_principal_symmetries() next to the classical peer program
// ShapeSymmetry of Michael Kazhdan's ShapeSPH (the reflective symmetry descriptor of Kazhdan et
// al., SGP 2004), on the same triangle meshes. The peer is not part of the project: build it
// yourself from its public repository and give the path of its ShapeSymmetry binary with --peer.
//
// For each shape, the triangulated mesh is written once as an ASCII PLY file (float coordinates,
// triangles) in the work folder, since the peer reads PLY only. Then, --repeats times, alternately:
//   - the peer, as a child process (its output to /dev/null) with --in FILE.ply --out WORK/NAME
//     and its defaults (a 64^3 grid, one thread per processor): the wall time from its start to
//     its exit, the reading of the PLY file included, and its peak memory, ru_maxrss of wait4(),
//     both measured by a fresh copy of this program that starts it (run_peer());
//   - ours: detect_principal_symmetries(mesh) with the default parameters (threads: all cores) on
//     the mesh already loaded: the wall time, and the peak memory, VmHWM of /proc/self/status
//     after the call, the peak having been reset to the current resident size before it (by
//     writing 5 to /proc/self/clear_refs). That peak includes the mesh and the program: the
//     resident size before the call (after malloc_trim) is printed too.
// Times are medians over the repeats, memory figures maxima.
//
// With --sde 1, the symmetry distance error (symmetry_distance_error() with its defaults) of the
// strongest plane of each, and the angle between their normals: ours is the first plane
// returned; the peer's is the plane through the area-weighted centroid of the triangles (the
// peer translates the mesh there and scales it uniformly, without rotating it) whose normal is
// the direction of the best value of WORK/NAME.ref.sgrid, its lowest: without --gedt the peer's
// descriptor is a sum of squared distances between the shape and its reflection, 0 for a perfect
// symmetry. A .sgrid file is an int32 resolution r and r * r float32 values; the value at
// values[j * r + i] belongs to the direction theta = 2 pi i / r, phi = pi (2 j + 1) / (2 r),
// (sin phi cos theta, cos phi, sin phi sin theta) in the mesh's own x, y, z: the peer
// rasterizes the point (x, y, z) into its voxel (x, y, z) and samples that grid along these
// directions (SphericalGrid.inl, CubeGrid::SphereSample, Rasterizer.h of its source).
//
// usage: peer_comparison --peer PATH/ShapeSymmetry [--set demo|psb] [--data PSB_DIR]
//          [--meshes a.off,b.off|all] [--loop L] [--work DIR] [--sde 0|1] [--repeats N]
//          [--output FILE.tsv]
// --set demo (the default) compares the meshes of --meshes (default bull.off,refined_elephant.off),
// read and triangulated as principal_symmetries_timing reads them: a bare name is one of CGAL's
// sample meshes in SYMMETRY_TRANSFORM_DATA_DIR/meshes/, a name with a '/' a path, `all` every .off
// file there. --set psb --data DIR compares the first model of every class of the Princeton Shape
// Benchmark's test set (psb_models.h; research use only, never committed). --loop L
// Loop-subdivides each mesh L times first (bunny00.off with --loop 2: 1.2M faces). --work DIR
// keeps the PLY files and the peer's output there (default: a temporary folder under /tmp, removed
// at the end). --output FILE.tsv writes the rows as tab-separated values too.
// Prints Markdown on std::cout (the command, hardware_concurrency, the date, a row per shape, a
// summary, the shapes skipped), progress on std::cerr.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <fcntl.h>
#include <malloc.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "benchmark_utilities.h"
#include "psb_models.h"

extern char** environ;

namespace {

using benchmark_utilities::median;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Principal_symmetry<K> Symmetry;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

const char* const default_meshes = "bull.off,refined_elephant.off";
// ru_maxrss and the sizes of /proc/self/status are in KiB; the tables give MiB.
const double kib_per_mib = 1024.;
// The digits that give a float back exactly from its decimal text (the peer reads floats).
const int float_digits = 9;
// The largest resolution accepted in a .sgrid file (the peer's default is 64).
const std::int32_t largest_sgrid_resolution = 4096;
const double high_percentile = 0.95;
const std::size_t slowest_count = 10;

const char* const usage_options = " --peer PATH/ShapeSymmetry [--set demo|psb] [--data PSB_DIR]"
                                  " [--meshes a.off,b.off|all] [--loop L] [--work DIR] [--sde 0|1]"
                                  " [--repeats N] [--output FILE.tsv]\n";

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
  std::string peer, set = "demo", data, meshes, work, output;
  unsigned loop = 0, repeats = 1;
  bool sde = true;
};

void check(const char* program, const Options& o)
{
  if(o.peer.empty()) fail(program, "--peer PATH/ShapeSymmetry is required");
  if(access(o.peer.c_str(), X_OK) != 0) fail(program, "--peer: " + o.peer + " is not an executable file");
  if(o.set != "demo" && o.set != "psb") fail(program, "--set expects demo or psb, not '" + o.set + "'");
  if(o.set == "psb" && o.data.empty()) fail(program, "--set psb needs --data DIR (the benchmark's folder)");
  if(o.set != "psb" && !o.data.empty()) fail(program, "--data is for --set psb");
  if(o.set != "demo" && !o.meshes.empty()) fail(program, "--meshes is for --set demo");
}

Options parse(int argc, char** argv)
{
  std::vector<std::pair<std::string, std::string>> pairs;
  try { pairs = benchmark_utilities::option_pairs(argc, argv); } catch(const std::invalid_argument& e) { fail(argv[0], e.what()); }
  Options o;
  for(const auto& [option, value] : pairs) {
    if(option == "--peer") o.peer = value;
    else if(option == "--set") o.set = value;
    else if(option == "--data") o.data = value;
    else if(option == "--meshes") o.meshes = value;
    else if(option == "--work") o.work = value;
    else if(option == "--output") o.output = value;
    else if(option == "--loop") o.loop = natural(argv[0], option, value, true);
    else if(option == "--repeats") o.repeats = natural(argv[0], option, value, false);
    else if(option == "--sde" && (value == "0" || value == "1")) o.sde = value == "1";
    else if(option == "--sde") fail(argv[0], "--sde expects 0 or 1, not '" + value + "'");
    else fail(argv[0], "unknown option '" + option + "'");
  }
  check(argv[0], o);
  return o;
}

// A shape to compare: its name and its file.
struct Source
{
  std::string name, path;
  bool psb = false;
};

std::vector<Source> sources(const Options& o)
{
  std::vector<Source> s;
  if(o.set == "psb") {
    for(const psb_models::Model& m : psb_models::first_test_models(o.data)) s.push_back({m.name, m.path.string(), true});
    return s;
  }
  const std::string list = o.meshes.empty() ? default_meshes : o.meshes;
  const std::vector<std::string> names =
    list == "all" ? benchmark_utilities::all_sample_meshes() : benchmark_utilities::split(list);
  for(const std::string& name : names) s.push_back({name, benchmark_utilities::mesh_path(name)});
  return s;
}

// The triangle mesh of a shape, Loop-subdivided `loop` times; throws if it cannot be read.
Mesh read_shape(const Source& s, unsigned loop)
{
  Mesh mesh;
  if(s.psb) {
    psb_models::read_triangle_mesh(s.path, mesh);
  } else {
    if(!CGAL::IO::read_polygon_mesh(s.path, mesh) || faces(mesh).empty())
      throw std::runtime_error("cannot read " + s.path);
    if(!CGAL::is_triangle_mesh(mesh) && !PMP::triangulate_faces(mesh))
      throw std::runtime_error("cannot triangulate " + s.path);
  }
  if(loop > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(loop));
  return mesh;
}

// The mesh as an ASCII PLY file of float coordinates and triangles, as the peer reads it.
void write_ply(const Mesh& mesh, const std::string& file)
{
  std::ofstream out(file);
  out << "ply\nformat ascii 1.0\nelement vertex " << num_vertices(mesh)
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << num_faces(mesh)
      << "\nproperty list uchar int vertex_indices\nend_header\n"
      << std::setprecision(float_digits);
  std::vector<std::size_t> index(mesh.num_vertices()); // consecutive indices, should the mesh have removed vertices
  std::size_t next = 0;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    index[std::size_t(v)] = next++;
    const K::Point_3& p = mesh.point(v);
    out << float(p.x()) << ' ' << float(p.y()) << ' ' << float(p.z()) << '\n';
  }
  for(Mesh::Face_index f : faces(mesh)) {
    out << '3';
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh)) out << ' ' << index[std::size_t(v)];
    out << '\n';
  }
  if(!out) throw std::runtime_error("cannot write " + file);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Peer_run
{
  double seconds = 0., peak_mib = 0.;
};

// The peer is run by a copy of this program started with this flag, which runs the peer, waits
// for it and prints its wall time and peak memory. ru_maxrss keeps a process's peak across exec:
// a peer started by this process would report at least this one's peak (the loaded meshes), one
// started by a fresh copy only that copy's few MiB.
const char* const measure_peer_flag = "--measure-peer";

// The fresh copy: runs `command` (a null-terminated argument list) with its output to /dev/null,
// prints "seconds peak_kib" of it; returns 0 if it ran and exited with 0.
int measure_peer(char** command)
{
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid < 0) return EXIT_FAILURE;
  if(pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    if(null < 0 || dup2(null, STDOUT_FILENO) < 0 || dup2(null, STDERR_FILENO) < 0) _exit(EXIT_FAILURE);
    execv(command[0], command);
    _exit(EXIT_FAILURE);
  }
  int status = 0;
  rusage usage{};
  while(wait4(pid, &status, 0, &usage) < 0)
    if(errno != EINTR) return EXIT_FAILURE;
  std::printf("%.9f %ld\n", seconds_since(start), usage.ru_maxrss);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Runs the peer on `ply` (its descriptors to `header`.*.sgrid) through a fresh copy of this
// program (measure_peer()), and reads what it measured.
Peer_run run_peer(const std::string& peer, const std::string& ply, const std::string& header)
{
  std::vector<std::string> words = {"/proc/self/exe", measure_peer_flag, peer, "--in", ply, "--out", header};
  std::vector<char*> arguments;
  for(std::string& w : words) arguments.push_back(w.data());
  arguments.push_back(nullptr);
  int out[2];
  if(pipe(out) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  posix_spawn_file_actions_addclose(&actions, out[1]);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, words[0].c_str(), &actions, nullptr, arguments.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string measured;
  char buffer[256];
  for(ssize_t n; error == 0 && (n = read(out[0], buffer, sizeof buffer)) != 0;)
    if(n > 0) measured.append(buffer, std::size_t(n));
    else if(errno != EINTR) break;
  close(out[0]);
  if(error != 0) throw std::runtime_error("cannot start " + peer + ": " + std::strerror(error));
  int status = 0;
  while(waitpid(pid, &status, 0) < 0)
    if(errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  Peer_run run;
  double peak_kib = 0.;
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !(std::istringstream(measured) >> run.seconds >> peak_kib))
    throw std::runtime_error("the peer failed (wait status " + std::to_string(status) + ")");
  run.peak_mib = peak_kib / kib_per_mib;
  return run;
}

// A size of /proc/self/status ("VmRSS", "VmHWM"; given in kB) in MiB.
double status_mib(const std::string& field)
{
  std::ifstream in("/proc/self/status");
  for(std::string line; std::getline(in, line);)
    if(line.compare(0, field.size() + 1, field + ":") == 0) return std::atof(line.c_str() + field.size() + 1) / kib_per_mib;
  throw std::runtime_error("no " + field + " in /proc/self/status");
}

// Resets the peak resident size (VmHWM) to the current resident size.
void reset_peak_memory()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  if(!out) throw std::runtime_error("cannot write /proc/self/clear_refs");
}

struct Our_run
{
  double seconds = 0., rss_before_mib = 0., peak_mib = 0.;
  std::vector<Symmetry> planes;
};

Our_run run_ours(const Mesh& mesh)
{
  Our_run r;
  malloc_trim(0); // the memory freed since, by the previous shapes, back to the system
  reset_peak_memory();
  r.rss_before_mib = status_mib("VmRSS");
  const auto start = std::chrono::steady_clock::now();
  r.planes = ST::detect_principal_symmetries(mesh);
  r.seconds = seconds_since(start);
  r.peak_mib = status_mib("VmHWM");
  return r;
}

// The direction of the lowest value of the peer's reflective descriptor (see the head of this file).
K::Vector_3 peer_best_normal(const std::string& sgrid)
{
  std::ifstream in(sgrid, std::ios::binary);
  std::int32_t r = 0;
  in.read(reinterpret_cast<char*>(&r), sizeof r);
  if(!in || r <= 0 || r > largest_sgrid_resolution) throw std::runtime_error("cannot read " + sgrid);
  std::vector<float> values(std::size_t(r) * std::size_t(r));
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  if(!in) throw std::runtime_error(sgrid + " is truncated");
  const std::size_t best = std::size_t(std::min_element(values.begin(), values.end()) - values.begin());
  const double i = double(best % std::size_t(r)), j = double(best / std::size_t(r));
  const double theta = 2. * CGAL_PI * i / r, phi = CGAL_PI * (2. * j + 1.) / (2. * r);
  return K::Vector_3(std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta));
}

// The centroid of the triangles' centroids weighted by their areas: the peer's centre.
K::Point_3 area_weighted_centroid(const Mesh& mesh)
{
  K::Vector_3 sum = CGAL::NULL_VECTOR;
  double area = 0.;
  for(Mesh::Face_index f : faces(mesh)) {
    const Mesh::Halfedge_index h = halfedge(f, mesh);
    const K::Point_3 &p = mesh.point(source(h, mesh)), &q = mesh.point(target(h, mesh)),
                     &s = mesh.point(target(next(h, mesh), mesh));
    const double a = std::sqrt(K::Triangle_3(p, q, s).squared_area());
    sum = sum + a * (CGAL::centroid(p, q, s) - CGAL::ORIGIN);
    area += a;
  }
  if(!(area > 0.)) throw std::runtime_error("the mesh has no area");
  return CGAL::ORIGIN + sum / area;
}

double angle_degrees(const K::Vector_3& a, const K::Vector_3& b)
{
  const double c = std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos((std::min)(1., c)) * 180. / CGAL_PI;
}

// One shape's figures: times in seconds, memory in MiB; the accuracy is left out with --sde 0,
// and ours and the angle when we find no plane.
struct Row
{
  std::string name;
  std::size_t faces = 0;
  double peer_seconds = 0., our_seconds = 0., peer_mib = 0., our_mib = 0., rss_before_mib = 0.;
  std::optional<double> our_sde, peer_sde, angle;
  double ratio() const { return our_seconds / peer_seconds; }
  bool ours_better() const { return our_sde && peer_sde && *our_sde < *peer_sde; }
};

void measure_accuracy(const Mesh& mesh, const std::vector<Symmetry>& planes, const std::string& sgrid, Row& r)
{
  const K::Vector_3 peer_normal = peer_best_normal(sgrid);
  r.peer_sde = ST::symmetry_distance_error(mesh, K::Plane_3(area_weighted_centroid(mesh), peer_normal));
  if(planes.empty()) return;
  const K::Plane_3& ours = planes.front().plane;
  r.our_sde = ST::symmetry_distance_error(mesh, ours);
  r.angle = angle_degrees(ours.orthogonal_vector(), peer_normal);
}

// The name with the characters other than letters, digits, '.', '-' and '_' made '_'.
std::string file_stem(std::string name)
{
  for(char& c : name)
    if(!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return name;
}

Row compare(const std::string& name, const Mesh& mesh, const Options& o, const std::filesystem::path& work)
{
  const std::string ply = (work / (file_stem(name) + ".ply")).string(), header = (work / file_stem(name)).string();
  const std::string sgrid = header + ".ref.sgrid";
  write_ply(mesh, ply);
  Row r;
  r.name = name;
  r.faces = num_faces(mesh);
  std::vector<double> peer_times, our_times;
  std::vector<Symmetry> planes;
  for(unsigned k = 0; k < o.repeats; ++k) {
    std::filesystem::remove(sgrid); // no descriptor of an earlier run is read
    std::cerr << name << " (" << r.faces << " faces): peer..." << std::flush;
    const Peer_run p = run_peer(o.peer, ply, header);
    std::cerr << " " << p.seconds << " s; ours..." << std::flush;
    Our_run u = run_ours(mesh);
    std::cerr << " " << u.seconds << " s" << std::endl;
    peer_times.push_back(p.seconds);
    our_times.push_back(u.seconds);
    r.peer_mib = (std::max)(r.peer_mib, p.peak_mib);
    r.our_mib = (std::max)(r.our_mib, u.peak_mib);
    r.rss_before_mib = (std::max)(r.rss_before_mib, u.rss_before_mib);
    planes = std::move(u.planes);
  }
  r.peer_seconds = median(peer_times);
  r.our_seconds = median(our_times);
  if(o.sde) measure_accuracy(mesh, planes, sgrid, r);
  return r;
}

// The folder of the PLY files and of the peer's output: --work DIR, kept, or a temporary folder
// under /tmp, removed at the end.
class Work_folder
{
public:
  explicit Work_folder(const std::string& given)
  {
    if(!given.empty()) {
      path_ = given;
      std::filesystem::create_directories(path_);
      return;
    }
    std::string pattern = (std::filesystem::temp_directory_path() / "peer_comparison.XXXXXX").string();
    if(mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder");
    path_ = pattern;
    temporary_ = true;
  }
  ~Work_folder()
  {
    std::error_code ignored;
    if(temporary_) std::filesystem::remove_all(path_, ignored);
  }
  Work_folder(const Work_folder&) = delete;
  Work_folder& operator=(const Work_folder&) = delete;
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
  bool temporary_ = false;
};

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

// The cells of a row, in the order of the tables' columns; "-" for what --sde 0 leaves out,
// "none" for our SDE when we find no plane. The SDEs get all their digits in the TSV file.
std::vector<std::string> cells(const Row& r, bool sde, bool tsv)
{
  const std::string absent = sde ? "none" : "-";
  const char* const sde_format = tsv ? "%.9g" : "%.3g";
  return {r.name,
          std::to_string(r.faces),
          format("%.3f", r.peer_seconds),
          format("%.3f", r.our_seconds),
          format("%.2f", r.ratio()),
          format("%.1f", r.peer_mib),
          format("%.1f", r.our_mib),
          format("%.1f", r.rss_before_mib),
          r.our_sde ? format(sde_format, *r.our_sde) : absent,
          r.peer_sde ? format(sde_format, *r.peer_sde) : "-",
          sde ? (r.ours_better() ? "yes" : "no") : "-",
          r.angle ? format("%.1f", *r.angle) : "-"};
}

const std::vector<std::string> column_titles = {
  "shape", "faces", "peer (s)", "ours (s)", "ours / peer", "peer peak (MiB)", "ours peak (MiB)",
  "ours RSS before (MiB)", "SDE ours", "SDE peer", "ours better", "angle (deg)"};

std::string joined(const std::vector<std::string>& items, const std::string& before, const std::string& between,
                   const std::string& after)
{
  std::string line = before;
  for(std::size_t i = 0; i < items.size(); ++i) line += (i > 0 ? between : "") + items[i];
  return line + after;
}

std::string today()
{
  const std::time_t now = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M %Z", std::localtime(&now));
  return buffer;
}

void print_header(int argc, char** argv, const Options& o)
{
  std::string command = argv[0];
  for(int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];
  std::cout << "Command: `" << command << "`; hardware_concurrency " << std::thread::hardware_concurrency()
            << "; date " << today() << ".\nPeer: ShapeSymmetry with its defaults, PLY reading included; ours: "
            << "detect_principal_symmetries() with its defaults on the loaded mesh; times: median of " << o.repeats
            << " run(s), alternately the peer then ours; peaks: maxima.\n\n"
            << joined(column_titles, "| ", " | ", " |\n") << "|---|";
  for(std::size_t c = 1; c < column_titles.size(); ++c) std::cout << "---:|";
  std::cout << "\n";
}

double percentile(std::vector<double> v, double p)
{
  std::sort(v.begin(), v.end());
  return v[std::size_t(std::lround(p * double(v.size() - 1)))];
}

// A line of the summary: the median and high percentile of the figure over the rows that have it.
void print_distribution(const std::string& label, const std::vector<Row>& rows,
                        const std::function<std::optional<double>(const Row&)>& figure, const char* fmt)
{
  std::vector<double> v;
  for(const Row& r : rows)
    if(const std::optional<double> x = figure(r)) v.push_back(*x);
  if(v.empty()) return;
  std::cout << "| " << label << " | " << v.size() << " | " << format(fmt, median(v)) << " | "
            << format(fmt, percentile(v, high_percentile)) << " |\n";
}

void print_summary(std::vector<Row> rows, const std::vector<std::string>& skipped, bool sde)
{
  std::cout << "\n| over the shapes | shapes | median | " << format("%.0f", 100. * high_percentile)
            << "th percentile |\n|---|---:|---:|---:|\n";
  print_distribution("ours / peer (time)", rows, [](const Row& r) { return r.ratio(); }, "%.2f");
  print_distribution("peer (s)", rows, [](const Row& r) { return r.peer_seconds; }, "%.3f");
  print_distribution("ours (s)", rows, [](const Row& r) { return r.our_seconds; }, "%.3f");
  print_distribution("SDE ours", rows, [](const Row& r) { return r.our_sde; }, "%.3g");
  print_distribution("SDE peer", rows, [](const Row& r) { return r.peer_sde; }, "%.3g");
  if(sde) {
    const auto better = std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.ours_better(); });
    std::cout << "\nOurs better (SDE ours < SDE peer) on " << better << " of " << rows.size() << " shapes.\n";
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.ratio() > b.ratio(); });
  std::cout << "\nSlowest ratios ours / peer:";
  for(std::size_t i = 0; i < (std::min)(slowest_count, rows.size()); ++i)
    std::cout << (i > 0 ? ", " : " ") << rows[i].name << " " << format("%.2f", rows[i].ratio());
  std::cout << "\n\nSkipped: " << (skipped.empty() ? "none" : joined(skipped, "", "; ", "")) << ".\n";
}

} // namespace

int main(int argc, char** argv)
try {
  if(argc > 2 && std::string(argv[1]) == measure_peer_flag) return measure_peer(argv + 2);
  const Options o = parse(argc, argv);
  std::ofstream tsv;
  if(!o.output.empty()) {
    tsv.open(o.output);
    if(!(tsv << joined(column_titles, "", "\t", "\n"))) throw std::runtime_error("cannot write " + o.output);
  }
  const Work_folder work(o.work);
  print_header(argc, argv, o);
  std::vector<Row> rows;
  std::vector<std::string> skipped;
  for(const Source& s : sources(o)) {
    try {
      rows.push_back(compare(s.name, read_shape(s, o.loop), o, work.path()));
    } catch(const std::exception& e) {
      std::cerr << "skipped " << s.name << ": " << e.what() << std::endl;
      skipped.push_back(s.name + " (" + e.what() + ")");
      continue;
    }
    std::cout << joined(cells(rows.back(), o.sde, false), "| ", " | ", " |\n") << std::flush;
    if(tsv.is_open()) tsv << joined(cells(rows.back(), o.sde, true), "", "\t", "\n") << std::flush;
  }
  print_summary(rows, skipped, o.sde);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
