// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// CGAL's `callback` named parameter on the long functions: the progress rises from 0 to 1, a
// callback that always returns true changes no result, and a callback that returns false stops
// detection, remeshing and segmentation within 0.2 s with their documented results (the one
// wall-clock assertion of the suites, a bound users rely on; the latencies measured are milliseconds).

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <set>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Principal_symmetry<K> Symmetry;
typedef std::chrono::steady_clock Clock;

const auto grid_32 = CGAL::parameters::grid_resolution(32).random_seed(1);
// The one timing bound of the suites: a cancel takes effect within 0.2 s.
constexpr double max_cancel_latency_seconds = 0.2;

// Records the values passed to the callback; returns false from the first value at or above
// `cancel_at` (never if it is above 1), and counts the calls made after that.
struct Recorder
{
  double cancel_at = 2.;
  std::vector<double> values;
  std::vector<Clock::time_point> times;
  bool cancelled = false;
  std::size_t calls_after_cancel = 0;
  Clock::time_point cancel_time;

  std::function<bool(double)> callback()
  {
    return [this](double progress) {
      if(cancelled) {
        ++calls_after_cancel;
        return false;
      }
      values.push_back(progress);
      times.push_back(Clock::now());
      if(progress >= cancel_at && progress < 1.) {
        cancelled = true;
        cancel_time = Clock::now();
        return false;
      }
      return true;
    };
  }
  double seconds_since_cancel() const { return std::chrono::duration<double>(Clock::now() - cancel_time).count(); }
};

// The properties of the progress of a run that was not cancelled: from 0 to 1, never down. A run
// shorter than the 20 ms between calls reports 0 and 1 only.
void expect_complete_progress(const Recorder& r)
{
  ASSERT_GE(r.values.size(), 2u);
  EXPECT_EQ(r.values.front(), 0.);
  EXPECT_EQ(r.values.back(), 1.);
  for(std::size_t i = 1; i < r.values.size(); ++i) {
    EXPECT_GE(r.values[i], r.values[i - 1]) << "call " << i;
    EXPECT_LE(r.values[i], 1.);
  }
}

void expect_same_symmetries(const std::vector<Symmetry>& a, const std::vector<Symmetry>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].plane, b[i].plane);
    EXPECT_EQ(a[i].symmetry, b[i].symmetry);
    EXPECT_EQ(a[i].support, b[i].support);
  }
}

// An ellipsoid with a bump at one end: symmetric about y = 0 and z = 0 only, and partly about
// x = 0, so that the segmentation splits it. 20 4^subdivisions faces.
Surface_mesh bumped_ellipsoid(int subdivisions)
{
  Surface_mesh mesh = ellipsoid<Surface_mesh>(1., 0.6, 0.35, subdivisions).mesh;
  for(auto v : vertices(mesh)) {
    const Point_3 p = mesh.point(v);
    if(p.x() > 0.5) mesh.point(v) = Point_3(p.x() + 0.8 * (p.x() - 0.5), 1.3 * p.y(), 1.3 * p.z());
  }
  return mesh;
}

// The meshes of the cancellations: large enough that a run takes well over a second.
const Surface_mesh& large_mesh()
{
  static const Surface_mesh mesh = bumped_ellipsoid(7); // 327,680 faces
  return mesh;
}
const Surface_mesh& medium_mesh()
{
  static const Surface_mesh mesh = bumped_ellipsoid(6); // 81,920 faces
  return mesh;
}
// The segmentation's graph cut of a segment cannot be interrupted (CGAL::alpha_expansion_graphcut,
// some microseconds per face): on 20,480 faces a cut takes tens of milliseconds; the detections of
// the three levels of splits on a 96^3 grid take seconds.
const Surface_mesh& segmentation_mesh()
{
  static const Surface_mesh mesh = bumped_ellipsoid(5);
  return mesh;
}

// ---- Progress of complete runs, and results unchanged by a callback -------------------------

template <typename Mesh>
void check_detection_progress(const Mesh& mesh)
{
  Recorder r;
  const std::vector<Symmetry> with = ST::detect_principal_symmetries(mesh, grid_32.callback(r.callback()));
  expect_complete_progress(r);
  expect_same_symmetries(with, ST::detect_principal_symmetries(mesh, grid_32));
}

Polyhedron as_polyhedron(const Surface_mesh& mesh)
{
  Polyhedron poly;
  CGAL::copy_face_graph(mesh, poly);
  return poly;
}

TEST(ProgressCallback, DetectionProgressRisesToOneAndLeavesTheResultOnSurfaceMeshAndPolyhedron)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  check_detection_progress(mesh);
  check_detection_progress(as_polyhedron(mesh));
}

// The refinements report their progress too: a value given between two calls of the callback is
// kept for the next call. (It was lost to the polls of ISP's loops, which come more often than
// once every 20 ms, and the bar stood still through the refinements, the last 45 % of this run.)
TEST(ProgressCallback, DetectionProgressRisesThroughTheRefinements)
{
  Recorder r;
  ST::detect_principal_symmetries(medium_mesh(), CGAL::parameters::number_of_threads(1).random_seed(1).callback(r.callback()));
  ASSERT_GE(r.values.size(), 3u);
  const double seconds = std::chrono::duration<double>(r.times.back() - r.times.front()).count();
  std::set<double> last_quarter; // the values below 1 reported in the last quarter of the run
  for(std::size_t i = 0; i < r.values.size(); ++i)
    if(std::chrono::duration<double>(r.times[i] - r.times.front()).count() >= 0.75 * seconds && r.values[i] < 1.)
      last_quarter.insert(r.values[i]);
  EXPECT_GE(last_quarter.size(), 2u) << "the progress stood still through the last quarter of the run";
}

TEST(ProgressCallback, DetectionOfPointsAndSoupsReportProgress)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, points, triangles);
  Recorder on_points, on_soup;
  expect_same_symmetries(ST::detect_principal_symmetries_of_points(points, grid_32.callback(on_points.callback())),
                         ST::detect_principal_symmetries_of_points(points, grid_32));
  expect_complete_progress(on_points);
  expect_same_symmetries(
    ST::detect_principal_symmetries_of_triangle_soup(points, triangles, grid_32.callback(on_soup.callback())),
    ST::detect_principal_symmetries_of_triangle_soup(points, triangles, grid_32));
  expect_complete_progress(on_soup);
}

TEST(ProgressCallback, TransformsReportProgressAndKeepTheirValues)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  Recorder gedt, prst, pst;
  EXPECT_EQ(ST::gaussian_distance_transform(mesh, grid_32.callback(gedt.callback())).values(),
            ST::gaussian_distance_transform(mesh, grid_32).values());
  EXPECT_EQ(ST::reflective_symmetry_transform(mesh, grid_32.callback(prst.callback())).values(),
            ST::reflective_symmetry_transform(mesh, grid_32).values());
  EXPECT_EQ(ST::point_symmetry_transform(mesh, grid_32.callback(pst.callback())).grid().values(),
            ST::point_symmetry_transform(mesh, grid_32).grid().values());
  for(const Recorder* r : {&gedt, &prst, &pst}) expect_complete_progress(*r);
}

TEST(ProgressCallback, FrameAndRotationsReportProgressAndKeepTheirResults)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  Recorder frame, rotations;
  const ST::Symmetry_frame<K> a = ST::symmetry_frame(mesh, grid_32.callback(frame.callback())),
                              b = ST::symmetry_frame(mesh, grid_32);
  EXPECT_EQ(a.center, b.center);
  for(int i = 0; i < 3; ++i) EXPECT_EQ(a.axes[i], b.axes[i]);
  expect_complete_progress(frame);
  const auto with = ST::detect_rotational_symmetries(mesh, grid_32.callback(rotations.callback()));
  const auto without = ST::detect_rotational_symmetries(mesh, grid_32);
  ASSERT_EQ(with.size(), without.size());
  for(std::size_t i = 0; i < with.size(); ++i) EXPECT_EQ(with[i].axis, without[i].axis);
  expect_complete_progress(rotations);
}

struct Remeshing_result
{
  std::map<Surface_mesh::Face_index, std::size_t> proxy_of_face;
  std::vector<Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  bool manifold = false;
};

template <typename NamedParameters>
Remeshing_result remesh(const Surface_mesh& mesh, const NamedParameters& np)
{
  Remeshing_result r;
  r.manifold = ST::symmetric_approximate_triangle_mesh(
    mesh, coordinate_planes(),
    np.face_proxy_map(boost::make_assoc_property_map(r.proxy_of_face))
      .anchors(std::back_inserter(r.anchors))
      .triangles(std::back_inserter(r.triangles)));
  return r;
}

TEST(ProgressCallback, RemeshingProgressRisesToOneAndLeavesTheResult)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  Recorder r;
  const auto np = CGAL::parameters::max_number_of_proxies(60).random_seed(1);
  const Remeshing_result with = remesh(mesh, np.callback(r.callback())), without = remesh(mesh, np);
  expect_complete_progress(r);
  EXPECT_EQ(with.proxy_of_face, without.proxy_of_face);
  EXPECT_EQ(with.anchors, without.anchors);
  EXPECT_EQ(with.triangles, without.triangles);
  EXPECT_EQ(with.manifold, without.manifold);
}

template <typename Mesh>
void check_segmentation_progress(const Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor Face;
  std::map<Face, std::size_t> with, without;
  Recorder r;
  const std::size_t a = ST::segment_by_symmetry(mesh, boost::make_assoc_property_map(with), grid_32.callback(r.callback()));
  const std::size_t b = ST::segment_by_symmetry(mesh, boost::make_assoc_property_map(without), grid_32);
  expect_complete_progress(r);
  EXPECT_EQ(a, b);
  EXPECT_EQ(with, without);
}

TEST(ProgressCallback, SegmentationProgressRisesToOneAndLeavesTheResultOnSurfaceMeshAndPolyhedron)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  check_segmentation_progress(mesh);
  check_segmentation_progress(as_polyhedron(mesh));
}

// ---- Cancellation ---------------------------------------------------------------------------

// A cancel point is a value that a complete run reported at least this long before its end: a
// run that repeats the work then calls back at least once at or past it before 1, whatever the
// timing of its calls (at most one every 20 ms). A value reported just before the end (the last
// candidate refined before the tenth plane) may be skipped by a run whose calls fall otherwise.
constexpr double min_work_after_cancel_point = 0.1;

// The progress values at which the cancellations are tried: the first call, then the values that
// a complete run reported 30 % and 70 % of its time in (whatever the shares of the stages), or
// earlier ones if those were too close to the end.
std::vector<double> cancel_points(const Recorder& complete)
{
  std::vector<double> points{0.};
  auto seconds_between = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const double seconds = seconds_between(complete.times.front(), complete.times.back());
  for(double fraction : {0.3, 0.7}) {
    std::size_t i = 0;
    while(i + 2 < complete.values.size() &&
          seconds_between(complete.times.front(), complete.times[i]) < fraction * seconds)
      ++i;
    while(i > 0 && seconds_between(complete.times[i], complete.times.back()) < min_work_after_cancel_point) --i;
    points.push_back(complete.values[i]); // never the last value, 1
  }
  return points;
}

void expect_prompt_cancel(const Recorder& r, double latency, const char* what)
{
  ASSERT_TRUE(r.cancelled) << what << ": the progress never reached " << r.cancel_at;
  EXPECT_LT(latency, max_cancel_latency_seconds) << what << " cancelled at " << r.values.back();
  EXPECT_EQ(r.calls_after_cancel, 0u) << what;
  std::cout << what << ": cancelled at " << r.values.back() << ", returned " << 1000. * latency << " ms later\n";
}

TEST(ProgressCallback, CancelledDetectionStopsPromptlyWithThePlanesAcceptedSoFar)
{
  const Surface_mesh& mesh = large_mesh();
  const auto np = CGAL::parameters::number_of_threads(2).random_seed(1);
  const auto start = Clock::now();
  Recorder complete;
  const std::vector<Symmetry> all = ST::detect_principal_symmetries(mesh, np.callback(complete.callback()));
  std::cout << "detection on " << num_faces(mesh) << " faces: "
            << std::chrono::duration<double>(Clock::now() - start).count() << " s\n";
  for(double at : cancel_points(complete)) {
    Recorder r;
    r.cancel_at = at;
    const std::vector<Symmetry> some = ST::detect_principal_symmetries(mesh, np.callback(r.callback()));
    expect_prompt_cancel(r, r.seconds_since_cancel(), "detection");
    EXPECT_LT(some.size(), all.size());
    for(const Symmetry& s : some) // each plane kept is one of the complete run
      EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](const Symmetry& t) { return t.plane == s.plane; }));
  }
}

TEST(ProgressCallback, CancelledDetectionOnOneThreadStopsPromptly)
{
  const auto np = CGAL::parameters::number_of_threads(1).random_seed(1);
  Recorder complete;
  ST::detect_principal_symmetries(medium_mesh(), np.callback(complete.callback()));
  for(double at : cancel_points(complete)) {
    Recorder r;
    r.cancel_at = at;
    ST::detect_principal_symmetries(medium_mesh(), np.callback(r.callback()));
    expect_prompt_cancel(r, r.seconds_since_cancel(), "detection, one thread");
  }
}

TEST(ProgressCallback, CancelledRemeshingStopsPromptlyAndWritesNothing)
{
  const Surface_mesh& mesh = medium_mesh();
  const auto np = CGAL::parameters::number_of_threads(2).random_seed(1);
  Recorder complete;
  const auto start = Clock::now();
  remesh(mesh, np.callback(complete.callback()));
  std::cout << "remeshing of " << num_faces(mesh) << " faces: "
            << std::chrono::duration<double>(Clock::now() - start).count() << " s\n";
  for(double at : cancel_points(complete)) {
    Recorder r;
    r.cancel_at = at;
    const Remeshing_result result = remesh(mesh, np.callback(r.callback()));
    expect_prompt_cancel(r, r.seconds_since_cancel(), "remeshing");
    EXPECT_FALSE(result.manifold);
    EXPECT_TRUE(result.proxy_of_face.empty());
    EXPECT_TRUE(result.anchors.empty());
    EXPECT_TRUE(result.triangles.empty());
  }
}

TEST(ProgressCallback, CancelledSegmentationStopsPromptlyAndWritesNothing)
{
  const Surface_mesh& mesh = segmentation_mesh();
  const auto np = CGAL::parameters::number_of_threads(2).random_seed(1).grid_resolution(96);
  std::map<Surface_mesh::Face_index, std::size_t> complete_ids;
  Recorder complete;
  const auto start = Clock::now();
  ST::segment_by_symmetry(mesh, boost::make_assoc_property_map(complete_ids), np.callback(complete.callback()));
  std::cout << "segmentation of " << num_faces(mesh) << " faces: "
            << std::chrono::duration<double>(Clock::now() - start).count() << " s\n";
  for(double at : cancel_points(complete)) {
    Recorder r;
    r.cancel_at = at;
    std::map<Surface_mesh::Face_index, std::size_t> ids;
    ST::Segmentation_tree<K> tree;
    const std::size_t count = ST::segment_by_symmetry(
      mesh, boost::make_assoc_property_map(ids), np.callback(r.callback()).segmentation_tree(std::ref(tree)));
    expect_prompt_cancel(r, r.seconds_since_cancel(), "segmentation");
    EXPECT_EQ(count, 0u);
    EXPECT_TRUE(ids.empty());
    EXPECT_TRUE(tree.segments.empty());
  }
}

TEST(ProgressCallback, CancelledTransformsAreZeroAndCancelledFrameIsThePcaFrame)
{
  const Surface_mesh mesh = bumped_ellipsoid(4);
  Recorder gedt, prst, frame; // cancelled at the first call: these runs may take less than 20 ms
  gedt.cancel_at = prst.cancel_at = frame.cancel_at = 0.;
  const auto zero = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.; });
  };
  EXPECT_TRUE(zero(ST::gaussian_distance_transform(mesh, grid_32.callback(gedt.callback())).values()));
  EXPECT_TRUE(zero(ST::reflective_symmetry_transform(mesh, grid_32.callback(prst.callback())).values()));
  const ST::Symmetry_frame<K> cancelled = ST::symmetry_frame(mesh, grid_32.callback(frame.callback())),
                              pca = ST::pca_frame(mesh);
  EXPECT_EQ(cancelled.center, pca.center);
  for(int i = 0; i < 3; ++i) EXPECT_EQ(cancelled.axes[i], pca.axes[i]);
  for(const Recorder* r : {&gedt, &prst, &frame}) EXPECT_TRUE(r->cancelled);
}

TEST(ProgressCallback, AnExceptionOfTheCallbackStopsTheWorkAndReachesTheCaller)
{
  int calls = 0;
  auto throwing = [&calls](double progress) -> bool {
    ++calls;
    if(progress >= 0.3) throw std::runtime_error("stop here");
    return true;
  };
  EXPECT_THROW(ST::detect_principal_symmetries(bumped_ellipsoid(4), grid_32.number_of_threads(2).callback(throwing)),
               std::runtime_error);
  EXPECT_GE(calls, 2);
}

} // namespace
