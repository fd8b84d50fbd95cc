// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The alignment experiment of the thesis (section 4.1.3): how far the frame of a partial scan is
// from the frame of the whole shape, for the symmetry frame (centre of symmetry, principal
// symmetry axes) and for the PCA frame (centre of mass, principal axes). Two sets: CGAL's sample
// meshes (--set demo) and man-made objects built in code with perfect symmetries, like the
// thesis's models (--set man-made, test/Symmetry_transform/include/Symmetry_transform_man_made_shapes.h).
//
// Per shape, 8 virtual range scans: a scanner at each corner of a cube around the shape, at twice
// the diagonal of the bounding box from its centre, looking at the centre, with a field of view
// of 0.4 radian sampled by a square grid of rays (--rays per side); each ray that hits the mesh
// (first intersection in a CGAL::AABB_tree) gives a point. Errors of a scan's frame against the
// whole shape's: translational, |c_scan - c_whole| / R (R the radius of the shape); rotational,
// the largest angle between corresponding axes, each axis taken as a line (no sign), in the
// order of the frames and, as equally strong planes may come in either order, for the best
// pairing of the axes (the smallest largest angle over the 6 permutations).
//
// The symmetry frame is computed by the rule of symmetry_frame() (greedy), by that of its
// partial_data(true) (joint_var_prior_inertia) and, for comparison, by the other rules of
// internal/alignment/joint_frame.h (--rules), and by the rules `full*` of this program (the three
// orthogonal planes searched in the whole transform; RESULTS.md, "Alignment"), all from one detection of the
// principal symmetries per scan and per whole shape (cached in --cache DIR if given, so that
// rules are compared without detecting again). Prints, per rule, a row per shape, the
// histograms of both errors, the fraction of scans whose centre of symmetry is closer to its
// whole-shape value than the centre of mass is to its own (the thesis: 90 %, and 1.5 times closer
// on average) and the median rotational errors; with --diagnostics, per scan, why its frame
// departs from the whole's (the planes chosen, their sources, the whole's planes in the scan's
// transform); with --errors FILE, every scan's errors (for plot_alignment_histograms.py).
//
// usage: alignment_experiment [--set demo|man-made] [--meshes a.off,b.off,...] [--resolution N]
//        [--rays N] [--samples N] [--seed N] [--cache DIR] [--rules greedy,joint,...] [--diagnostics 1]
//        [--errors FILE]
// --samples: Monte Carlo pairs of each detection's PRST (default: the detection's own, 5e5);
// --seed: their seed (default 1). A cache holds the detections of one choice of both.
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/internal/alignment/joint_frame.h>

#include <Symmetry_transform_man_made_shapes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "benchmark_utilities.h"
#include "detection_cache.h"

namespace {

using benchmark_utilities::median;
using benchmark_utilities::mesh_path;
using benchmark_utilities::split;
using detection_cache::cached;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::Symmetry_transform::internal::AABB_traits_3<K, Primitive>> Tree;
namespace ST = CGAL::Symmetry_transform;
namespace STI = CGAL::Symmetry_transform::internal;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef STI::Eigen_frame Frame;
typedef STI::Detection<K> Detection;

const char* default_meshes = "bull.off,cow.off,camel.off,dino.off,elephant.off,triceratops.off,homer.off,"
                             "lion.off,bear.off,armadillo.off,man.off,mannequin-devil.off,diplodocus.off,"
                             "couplingdown.off,fandisk.off,rotor_small.off";

int positive(const std::string& option, const std::string& text)
{
  if(text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos || std::stoi(text) < 1)
    throw std::invalid_argument(option + " expects a positive integer, not '" + text + "'");
  return std::stoi(text);
}

// ---------------------------------------------------------------------------------------------
// Scans
// ---------------------------------------------------------------------------------------------

// The point of a ray's first intersection with the mesh, if it is a point: a boost::variant
// before CGAL 6.0, a std::variant since.
template <typename Intersection>
const K::Point_3* point_of(const Intersection& intersection)
{
#if CGAL_VERSION_NR >= 1060000000
  return std::get_if<K::Point_3>(&intersection);
#else
  return boost::get<K::Point_3>(&intersection);
#endif
}

// The points of a range scan from `eye` looking at `target`: a rays x rays grid over a square
// field of view of 0.4 radian.
std::vector<K::Point_3> range_scan(const Tree& tree, const K::Point_3& eye, const K::Point_3& target, int rays)
{
  const K::Vector_3 forward = (target - eye) / std::sqrt((target - eye).squared_length());
  K::Vector_3 right = CGAL::cross_product(forward, std::abs(forward.z()) < 0.9 ? K::Vector_3(0, 0, 1) : K::Vector_3(1, 0, 0));
  right = right / std::sqrt(right.squared_length());
  const K::Vector_3 up = CGAL::cross_product(right, forward);
  const double half_width = std::tan(0.2);
  std::vector<K::Point_3> points;
  for(int i = 0; i < rays; ++i)
    for(int j = 0; j < rays; ++j) {
      const double u = half_width * (2. * (i + 0.5) / rays - 1.), v = half_width * (2. * (j + 0.5) / rays - 1.);
      const auto hit = tree.first_intersection(K::Ray_3(eye, forward + u * right + v * up));
      if(hit)
        if(const K::Point_3* p = point_of(hit->first)) points.push_back(*p);
    }
  return points;
}

// The 8 scans of a mesh, from the corners of a cube around its bounding box (fewer than 100
// points: left out, as empty).
std::vector<std::vector<K::Point_3>> corner_scans(const Mesh& mesh, int rays)
{
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const K::Point_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  std::vector<std::vector<K::Point_3>> scans;
  for(int corner = 0; corner < 8; ++corner) {
    const K::Vector_3 direction((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
    const K::Point_3 eye = center + (2. * diagonal / std::sqrt(3.)) * direction;
    scans.push_back(range_scan(tree, eye, center, rays));
    if(scans.back().size() < 100) scans.back().clear();
  }
  return scans;
}

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------

// The largest angle, in degrees, between the axes of a and the axes of b in the order `order`,
// taken as lines.
double axes_angle(const Frame& a, const Frame& b, const std::array<int, 3>& order = {0, 1, 2})
{
  double worst = 0.;
  for(int k = 0; k < 3; ++k) {
    const double c = std::abs(a.axes[std::size_t(k)].dot(b.axes[std::size_t(order[std::size_t(k)])]));
    worst = std::max(worst, std::acos(std::min(1., c)) * 180. / CGAL_PI);
  }
  return worst;
}

// The same for the best pairing of the axes.
double unordered_axes_angle(const Frame& a, const Frame& b)
{
  std::array<int, 3> order = {0, 1, 2};
  double best = 180.;
  do best = std::min(best, axes_angle(a, b, order));
  while(std::next_permutation(order.begin(), order.end()));
  return best;
}

struct Histogram
{
  std::vector<double> edges; // bins [edges[i], edges[i+1]), the last one open
  std::vector<int> counts;
  explicit Histogram(std::vector<double> e) : edges(std::move(e)), counts(edges.size(), 0) {}
  void add(double x)
  {
    std::size_t i = edges.size() - 1;
    while(i > 0 && x < edges[i]) --i;
    ++counts[i];
  }
};

void print_histograms(const std::string& what, const Histogram& symmetry, const Histogram& pca, const std::string& unit)
{
  std::cout << "\n| " << what << " | symmetry frame | PCA frame |\n|---|---:|---:|\n";
  for(std::size_t i = 0; i < symmetry.edges.size(); ++i) {
    std::ostringstream bin;
    if(i + 1 < symmetry.edges.size())
      bin << "[" << symmetry.edges[i] << ", " << symmetry.edges[i + 1] << ") " << unit;
    else
      bin << ">= " << symmetry.edges[i] << " " << unit;
    std::cout << "| " << bin.str() << " | " << symmetry.counts[i] << " | " << pca.counts[i] << " |\n";
  }
}

// The errors of one scan's frame: translational (% R), rotational in order and paired (degrees).
struct Errors
{
  double translation, rotation, paired;
};

Errors errors(const Frame& scan, const Frame& whole, double radius)
{
  return {100. * (scan.center - whole.center).norm() / radius, axes_angle(scan, whole), unordered_axes_angle(scan, whole)};
}

// ---------------------------------------------------------------------------------------------
// Rules and their tallies
// ---------------------------------------------------------------------------------------------

typedef std::function<STI::Frame_choice(const STI::Mass_distribution&, const Detection&)> Rule;

STI::Frame_choice greedy_rule(const STI::Mass_distribution& mass, const Detection& d)
{
  const std::vector<STI::Dplane> planes = STI::planes_of(d.symmetries);
  if(planes.empty()) return {{}, STI::pca_frame(mass)};
  return STI::greedy_frame_choice(mass, planes, d.prst);
}

Rule rule_of(const STI::Frame_rule& rule)
{
  return [rule](const STI::Mass_distribution& mass, const Detection& d) {
    if(d.symmetries.empty()) return STI::Frame_choice{{}, STI::pca_frame(mass)};
    return STI::frame_choice(mass, d.symmetries, d.prst, rule);
  };
}

Rule rule_of(bool joint, bool support_weighted, bool least_squares_center, bool accumulate = false,
             bool order_by_accumulated = false, int variance_order = 0, double mass_prior = 0., double pca_below = 0.,
             bool blend_only_when_weak = false)
{
  return rule_of(STI::Frame_rule{joint, support_weighted, least_squares_center, accumulate, order_by_accumulated,
                                 variance_order, mass_prior, pca_below, blend_only_when_weak});
}

// `rule` (one whose centre does not switch on blend_only_when_weak) with every plane searched in
// the transform, which no principal symmetry holds, moved through the centre of mass: along its
// normal the centre is then the centre of mass's (RESULTS.md, "Alignment").
Rule with_searched_through_mass(const STI::Frame_rule& rule)
{
  return [rule](const STI::Mass_distribution& mass, const Detection& d) {
    if(d.symmetries.empty()) return STI::Frame_choice{{}, STI::pca_frame(mass)};
    STI::Frame_choice choice = STI::frame_choice(mass, d.symmetries, d.prst, rule);
    for(STI::Frame_plane& f : choice.planes)
      if(f.principal == STI::searched_plane) f.plane.offset = f.plane.normal.dot(mass.center());
    const Eigen::Vector3d center =
      rule.least_squares_center ? STI::least_squares_center(choice.planes, STI::weighted_planes(d.symmetries, rule), d.prst,
                                                            mass.center(), rule.mass_prior)
                                : STI::intersection(choice.planes);
    choice.frame = {center, STI::oriented_axes(choice.frame.axes, center, mass)};
    return choice;
  };
}

// The thesis's suggested search (section 4.1.4): the three mutually orthogonal planes of the
// whole transform that hold the most symmetry together (internal/alignment/orthogonal_planes.h).

// How a full-search frame is finished (RESULTS.md, "Alignment").
struct Full_search
{
  bool variance_order = true;  // axes by the variance of the mass, not by the planes' values
  double mass_prior = 0.;      // > 0: the least-squares centre of the planes and the centre of mass
  double weak_fraction = 0.;   // a plane below this fraction of the strongest goes through the centre of mass
  bool refine = false;         // the normals turned to the largest summed interpolated value
  enum Snap { NONE, PLANE, NORMAL, PRINCIPAL } snap = NONE;  // take the nearest principal plane, or only its
                                                            // normal, or the plane weighing its value
  bool excess_weight = false;  // a plane weighs 2 v - 1 in the centre (v: its value; 1/2 is the value of no symmetry)
};

// The point c minimising sum_p (2 v_p - 1)^+ (n_p . c - d_p)^2 + prior (n_p . (c - m))^2 over the
// three planes p (v_p their values, m the centre of mass).
Eigen::Vector3d excess_weighted_center(const std::array<STI::Frame_plane, 3>& planes, const std::array<double, 3>& value,
                                       const Eigen::Vector3d& mass_center, double prior)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for(std::size_t k = 0; k < 3; ++k) {
    const Eigen::Vector3d& n = planes[k].plane.normal;
    const double w = std::max(0., 2. * value[k] - 1.);
    a += (w + prior) * n * n.transpose();
    b += (w * planes[k].plane.offset + prior * n.dot(mass_center)) * n;
  }
  return a.ldlt().solve(b);
}

// The three orthonormal normals turned, by ever smaller rotations about each of them, to the
// largest summed value of their strongest planes in the transform (offsets searched each time).
std::array<Eigen::Vector3d, 3> refined_normals(std::array<Eigen::Vector3d, 3> normals, const Detection& d)
{
  const auto score = [&](const std::array<Eigen::Vector3d, 3>& m) {
    double sum = 0.;
    for(const Eigen::Vector3d& v : m) sum += STI::strongest_plane_of_normal(d.prst, v).second;
    return sum;
  };
  double current = score(normals);
  for(double step = 2.; step > 0.02; step /= 2.)
    for(bool improved = true; improved;) {
      improved = false;
      for(int axis = 0; axis < 3; ++axis)
        for(const double sign : {-1., 1.}) {
          const Eigen::Matrix3d r = Eigen::AngleAxisd(sign * step * CGAL_PI / 180., normals[std::size_t(axis)]).toRotationMatrix();
          const std::array<Eigen::Vector3d, 3> turned = {r * normals[0], r * normals[1], r * normals[2]};
          const double s = score(turned);
          if(s > current) { current = s; normals = turned; improved = true; }
        }
    }
  return normals;
}

// The strongest plane of each normal (or, by `options.snap`, of the nearest principal plane's
// normal, or that plane itself), its value, and the weak ones through the centre of mass.
std::pair<std::array<STI::Frame_plane, 3>, std::array<double, 3>>
full_search_planes(const std::array<Eigen::Vector3d, 3>& normals, const std::vector<STI::Weighted_plane>& principal,
                   const STI::Mass_distribution& mass, const Detection& d, const Full_search& options)
{
  std::array<STI::Frame_plane, 3> planes;
  std::array<double, 3> value;
  for(std::size_t k = 0; k < 3; ++k) {
    const int nearest = options.snap == Full_search::NONE ? -1 : STI::strongest_principal(principal, normals[k], true, {-1, -1});
    const Eigen::Vector3d& normal = nearest >= 0 ? principal[std::size_t(nearest)].plane.normal : normals[k];
    const std::pair<STI::Dplane, double> p = STI::strongest_plane_of_normal(d.prst, normal);
    planes[k] = {p.first, STI::searched_plane};
    value[k] = p.second;
    if(nearest >= 0 && options.snap == Full_search::PRINCIPAL) planes[k].plane = principal[std::size_t(nearest)].plane;
    if(nearest >= 0 && options.snap == Full_search::PLANE) {
      const std::pair<STI::Dplane, double> searched = STI::strongest_plane_of_normal(d.prst, normals[k]);
      planes[k] = {principal[std::size_t(nearest)].plane, nearest};
      value[k] = searched.second;
    }
  }
  const double strongest = std::max({value[0], value[1], value[2]});
  for(std::size_t k = 0; k < 3; ++k)
    if(value[k] < options.weak_fraction * strongest) planes[k].plane.offset = planes[k].plane.normal.dot(mass.center());
  return {planes, value};
}

Rule full_search(const Full_search& options)
{
  return [=](const STI::Mass_distribution& mass, const Detection& d) {
    std::array<Eigen::Vector3d, 3> normals = STI::most_symmetric_orthogonal_normals(d.prst);
    if(options.refine) normals = refined_normals(normals, d);
    const std::vector<STI::Weighted_plane> principal = STI::weighted_planes(d.symmetries, STI::Frame_rule{});
    const auto [planes, value] = full_search_planes(normals, principal, mass, d, options);
    std::array<std::size_t, 3> order = {0, 1, 2};
    const Eigen::Matrix3d covariance = mass.covariance();
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const Eigen::Vector3d &na = planes[a].plane.normal, &nb = planes[b].plane.normal;
      return options.variance_order ? na.dot(covariance * na) > nb.dot(covariance * nb) : value[a] > value[b];
    });
    STI::Frame_choice choice;
    choice.planes = {planes[order[0]], planes[order[1]], planes[order[2]]};
    std::array<Eigen::Vector3d, 3> axes;
    axes[0] = choice.planes[0].plane.normal;
    const Eigen::Vector3d& m = choice.planes[1].plane.normal;
    axes[1] = (m - m.dot(axes[0]) * axes[0]).normalized();
    axes[2] = axes[0].cross(axes[1]);
    const std::vector<STI::Weighted_plane> parallel = options.snap == Full_search::PLANE ? principal : std::vector<STI::Weighted_plane>{};
    const std::array<double, 3> ordered_value = {value[order[0]], value[order[1]], value[order[2]]};
    const Eigen::Vector3d center = options.excess_weight ? excess_weighted_center(choice.planes, ordered_value, mass.center(), options.mass_prior)
                                   : options.mass_prior > 0.
                                     ? STI::least_squares_center(choice.planes, parallel, d.prst, mass.center(), options.mass_prior)
                                     : STI::intersection(choice.planes);
    choice.frame = {center, STI::oriented_axes(axes, center, mass)};
    return choice;
  };
}

// A full-search rule: axes by `variance_order`, centre with `mass_prior`, and the rest of `options`.
Rule full_search(bool variance_order, double mass_prior, Full_search options = {})
{
  options.variance_order = variance_order;
  options.mass_prior = mass_prior;
  return full_search(options);
}

// A rule for partial data compared with the library's (the axes of the joint variance with the
// prior of inertia, and this centre).
const STI::Frame_rule joint_var_prior_inertia{true, false, true, false, false, 1, 0.2, 1., false};

// symmetry_frame(..., partial_data(true)): the axes of the joint rule, the centre of the
// orthogonal planes (the planes listed are those of its axes).
const Rule partial_data_rule = [](const STI::Mass_distribution& mass, const Detection& d) {
  STI::Frame_choice choice = STI::frame_choice(mass, d.symmetries, d.prst, STI::partial_data_rule);
  choice.frame = STI::partial_data_frame(mass, d.symmetries, d.prst);
  return choice;
};

// The axes of `axes_rule` (oriented again about the new centre) with the centre of `center_rule`.
Rule axes_and_center(const Rule& axes_rule, const Rule& center_rule)
{
  return [=](const STI::Mass_distribution& mass, const Detection& d) {
    STI::Frame_choice choice = axes_rule(mass, d);
    const Eigen::Vector3d center = center_rule(mass, d).frame.center;
    choice.frame = {center, STI::oriented_axes(choice.frame.axes, center, mass)};
    return choice;
  };
}

std::map<std::string, Rule> rules()
{
  return {{"greedy", greedy_rule},
          {"greedy_ls", rule_of(false, false, true)},
          {"joint", rule_of(true, false, false)},
          {"joint_support", rule_of(true, true, false)},
          {"joint_ls", rule_of(true, false, true)},
          {"joint_support_ls", rule_of(true, true, true)},
          {"cluster", rule_of(true, false, false, true)},
          {"cluster_ls", rule_of(true, false, true, true)},
          {"cluster_support_ls", rule_of(true, true, true, true)},
          {"cluster_ordered_ls", rule_of(true, false, true, true, true)},
          {"cluster_support_ordered_ls", rule_of(true, true, true, true, true)},
          {"joint_support_ls_var", rule_of(true, true, true, false, false, 1)},
          {"joint_support_ls_tol", rule_of(true, true, true, false, false, 2)},
          {"cluster_support_ls_var", rule_of(true, true, true, true, false, 1)},
          {"cluster_support_ls_tol", rule_of(true, true, true, true, false, 2)},
          {"greedy_var", rule_of(false, false, false, false, false, 1)},
          {"greedy_tol", rule_of(false, false, false, false, false, 2)},
          {"joint_support_ls_var_prior", rule_of(true, true, true, false, false, 1, 0.2)},
          {"cluster_support_ls_var_prior", rule_of(true, true, true, true, false, 1, 0.2)},
          {"cluster_support_ls_var_prior5", rule_of(true, true, true, true, false, 1, 0.5)},
          {"cluster_support_ls_var_prior_inertia", rule_of(true, true, true, true, false, 1, 0.2, 1.)},
          {"cluster_support_ls_var_prior_inertia9", rule_of(true, true, true, true, false, 1, 0.2, 0.9)},
          {"cluster_support_ls_var_prior_inertia8", rule_of(true, true, true, true, false, 1, 0.2, 0.8)},
          {"cluster_support_ls_prior_inertia", rule_of(true, true, true, true, false, 0, 0.2, 1.)},
          {"joint_var", rule_of(true, false, false, false, false, 1)},
          {"joint_var_inertia", rule_of(true, false, false, false, false, 1, 0., 1.)},
          {"joint_var_inertia8", rule_of(true, false, false, false, false, 1, 0., 0.8)},
          {"joint_var_prior_inertia", rule_of(joint_var_prior_inertia)},
          {"partial_data", partial_data_rule}, // symmetry_frame(..., partial_data(true))
          {"joint_var_weak_prior_inertia", rule_of(true, false, true, false, false, 1, 0.2, 1., true)},
          {"joint_var_weak_prior_inertia95", rule_of(true, false, true, false, false, 1, 0.2, 0.95, true)},
          {"joint_var_weak_prior_inertia9", rule_of(true, false, true, false, false, 1, 0.2, 0.9, true)},
          {"joint_var_weak_prior_inertia8", rule_of(true, false, true, false, false, 1, 0.2, 0.8, true)},
          {"joint_var_weak_prior5_inertia9", rule_of(true, false, true, false, false, 1, 0.5, 0.9, true)},
          {"greedy_var_inertia", rule_of(false, false, false, false, false, 1, 0., 1.)},
          {"greedy_mass", with_searched_through_mass({false, false, false, false, false, 0, 0., 0., false})},
          {"joint_mass", with_searched_through_mass({true, false, false, false, false, 0, 0., 0., false})},
          {"joint_var_mass", with_searched_through_mass({true, false, false, false, false, 1, 0., 0., false})},
          {"joint_var_inertia_mass", with_searched_through_mass({true, false, false, false, false, 1, 0., 1., false})},
          {"joint_var_prior_inertia_mass", with_searched_through_mass(joint_var_prior_inertia)},
          {"greedy_ls_var_prior_inertia", rule_of(false, false, true, false, false, 1, 0.2, 1.)},
          {"full", full_search(false, 0.)},
          {"full_var", full_search(true, 0.)},
          {"full_var_prior", full_search(true, 0.2)},
          {"full_prior", full_search(false, 0.2)},
          {"full_var_refined", full_search(true, 0., {true, 0., 0., true, Full_search::NONE})},
          {"full_var_prior_refined", full_search(true, 0.2, {true, 0., 0., true, Full_search::NONE})},
          {"full_var_snap", full_search(true, 0., {true, 0., 0., false, Full_search::PLANE})},
          {"full_var_prior_snap", full_search(true, 0.2, {true, 0., 0., false, Full_search::PLANE})},
          {"full_var_refined_snap", full_search(true, 0., {true, 0., 0., true, Full_search::PLANE})},
          {"full_var_prior_refined_snap", full_search(true, 0.2, {true, 0., 0., true, Full_search::PLANE})},
          {"full_var_nsnap", full_search(true, 0., {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior_nsnap", full_search(true, 0.2, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_refined_nsnap", full_search(true, 0., {true, 0., 0., true, Full_search::NORMAL})},
          {"full_var_prior_refined_nsnap", full_search(true, 0.2, {true, 0., 0., true, Full_search::NORMAL})},
          {"full_var_prior1_nsnap", full_search(true, 0.1, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior3_nsnap", full_search(true, 0.3, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior10_nsnap", full_search(true, 1.0, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior35_nsnap", full_search(true, 0.35, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior4_nsnap", full_search(true, 0.4, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior5_nsnap", full_search(true, 0.5, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_prior45_nsnap", full_search(true, 0.45, {true, 0., 0., false, Full_search::NORMAL})},
          {"full_var_weak6", full_search(true, 0., {true, 0., 0.6, false, Full_search::NONE})},
          {"full_var_weak7", full_search(true, 0., {true, 0., 0.7, false, Full_search::NONE})},
          {"full_var_weak8", full_search(true, 0., {true, 0., 0.8, false, Full_search::NONE})},
          {"full_var_weak9", full_search(true, 0., {true, 0., 0.9, false, Full_search::NONE})},
          {"full_var_prior4_psnap", full_search(true, 0.4, {true, 0., 0., false, Full_search::PRINCIPAL})},
          {"full_var_prior3_psnap", full_search(true, 0.3, {true, 0., 0., false, Full_search::PRINCIPAL})},
          {"full_var_excess1_nsnap", full_search(true, 0.1, {true, 0., 0., false, Full_search::NORMAL, true})},
          {"full_var_excess2_nsnap", full_search(true, 0.2, {true, 0., 0., false, Full_search::NORMAL, true})},
          {"full_var_excess05_nsnap", full_search(true, 0.05, {true, 0., 0., false, Full_search::NORMAL, true})},
          {"joint_axes_full_center3", axes_and_center(rule_of(joint_var_prior_inertia), full_search(true, 0.3, {true, 0., 0., false, Full_search::NORMAL}))},
          {"joint_axes_full_center4", axes_and_center(rule_of(joint_var_prior_inertia), full_search(true, 0.4, {true, 0., 0., false, Full_search::NORMAL}))},
          {"joint_axes_full_center5", axes_and_center(rule_of(joint_var_prior_inertia), full_search(true, 0.5, {true, 0., 0., false, Full_search::NORMAL}))}};
}

// What a rule (or PCA) gave over all scans of a set.
struct Tally
{
  std::vector<Errors> scans;
  std::vector<std::string> rows;
  Histogram translation{{0, 1, 2, 5, 10, 20}}, rotation{{0, 1, 5, 15, 45}};
  void add(const Errors& e)
  {
    scans.push_back(e);
    translation.add(e.translation);
    rotation.add(e.rotation);
  }
  template <typename F>
  std::vector<double> list(F f) const
  {
    std::vector<double> v;
    for(const Errors& e : scans) v.push_back(f(e));
    return v;
  }
};

// A shape of a set: its name, its mesh, and the planes it has by construction (man-made set).
struct Shape
{
  std::string name;
  Mesh mesh;
  std::vector<K::Plane_3> planes;
};

std::vector<Shape> shapes_of_set(const std::string& set, const std::string& meshes)
{
  std::vector<Shape> shapes;
  if(set == "man-made") {
    for(const auto& make : st_man_made::man_made_shapes()) {
      st_man_made::Man_made_shape s = make();
      shapes.push_back({s.name, std::move(s.mesh), s.planes});
    }
    return shapes;
  }
  if(set != "demo") throw std::invalid_argument("--set expects demo or man-made, not '" + set + "'");
  for(const std::string& name : split(meshes)) {
    Mesh mesh;
    const std::string path = mesh_path(name);
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) {
      std::cerr << "skipped " << path << ": cannot read it\n";
      continue;
    }
    if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
    shapes.push_back({name, std::move(mesh), {}});
  }
  return shapes;
}

// ---------------------------------------------------------------------------------------------
// Diagnostics
// ---------------------------------------------------------------------------------------------

std::string source_of(const STI::Frame_plane& p)
{
  return p.principal == STI::searched_plane ? "searched" : "P" + std::to_string(p.principal + 1);
}

// The label of a plane of a scan: the whole's frame plane (W1, W2, W3) it matches within 10
// degrees and 5 % R, or "-".
std::string match(const STI::Dplane& p, const STI::Frame_choice& whole, double radius)
{
  for(int i = 0; i < 3; ++i) {
    const STI::Dplane& w = whole.planes[std::size_t(i)].plane;
    const double c = p.normal.dot(w.normal), s = c < 0. ? -1. : 1.;
    if(std::abs(c) >= std::cos(10. * CGAL_PI / 180.) &&
       std::abs(p.offset - s * w.offset - (p.normal - s * w.normal).dot(whole.frame.center)) < 0.05 * radius)
      return "W" + std::to_string(i + 1);
  }
  return "-";
}

void print_diagnostics(int corner, std::size_t points, const Detection& scan, const STI::Frame_choice& choice,
                       const Detection& whole, const STI::Frame_choice& whole_choice, const Errors& e,
                       const Errors& pca, double radius)
{
  std::cout << "  scan " << corner << " (" << points << " points): translation " << e.translation << " % R (PCA "
            << pca.translation << "), rotation " << e.rotation << " deg (PCA " << pca.rotation << "), paired " << e.paired
            << "\n    principal planes of the scan (M, support, match):";
  for(std::size_t i = 0; i < scan.symmetries.size(); ++i)
    std::cout << " P" << i + 1 << " " << scan.symmetries[i].symmetry << "/" << scan.symmetries[i].support << "/"
              << match(STI::to_dplane(scan.symmetries[i].plane), whole_choice, radius);
  std::cout << "\n    frame planes of the scan:";
  for(const STI::Frame_plane& p : choice.planes)
    std::cout << " " << source_of(p) << " (" << match(p.plane, whole_choice, radius) << ", PRST "
              << scan.prst.value(STI::to_plane<K>(p.plane)) << ")";
  std::cout << "\n    the whole's frame planes, in the scan's transform (whole's transform):";
  for(const STI::Frame_plane& p : whole_choice.planes) {
    const K::Plane_3 plane = STI::to_plane<K>(p.plane);
    std::cout << " " << source_of(p) << " " << scan.prst.value(plane) << " (" << whole.prst.value(plane) << ")";
  }
  std::cout << "; strongest bin of the scan " << scan.prst.value(scan.prst.maximum()) << "\n";
}

// ---------------------------------------------------------------------------------------------
// The experiment
// ---------------------------------------------------------------------------------------------

struct Options
{
  std::string set = "demo", meshes = default_meshes, cache, errors_file;
  std::vector<std::string> rules = {"greedy"};
  int resolution = 64, rays = 120, seed = 1;
  long samples = long(STI::defaults::detection_monte_carlo_pairs); // of each detection's PRST
  bool diagnostics = false;
};

Options parse(int argc, char** argv)
{
  Options o;
  for(const auto& [arg, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(arg == "--set") o.set = value;
    else if(arg == "--meshes") o.meshes = value;
    else if(arg == "--resolution") o.resolution = positive(arg, value);
    else if(arg == "--rays") o.rays = positive(arg, value);
    else if(arg == "--samples") o.samples = positive(arg, value);
    else if(arg == "--seed") o.seed = positive(arg, value);
    else if(arg == "--cache") o.cache = value;
    else if(arg == "--rules") o.rules = split(value);
    else if(arg == "--diagnostics") o.diagnostics = value != "0";
    else if(arg == "--errors") o.errors_file = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  const std::map<std::string, Rule> known = rules();
  for(const std::string& r : o.rules)
    if(!known.count(r)) throw std::invalid_argument("unknown rule: " + r);
  return o;
}

double radius_of(const Mesh& mesh, const Eigen::Vector3d& center)
{
  double radius = 0.;
  for(const auto v : vertices(mesh)) radius = std::max(radius, (STI::to_eigen(STI::to_dpoint(mesh.point(v))) - center).norm());
  return radius;
}

std::string fixed(double x)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << x;
  return out.str();
}

// A row of the per-shape table of a rule: scans, closer, mean errors of symmetry / PCA.
std::string row(const Shape& shape, std::size_t points, const std::vector<Errors>& sym, const std::vector<Errors>& pca,
                double whole_vs_truth)
{
  const std::size_t n = sym.size();
  int closer = 0;
  double t[2] = {0, 0}, r[2] = {0, 0}, p[2] = {0, 0};
  for(std::size_t i = 0; i < n; ++i) {
    closer += sym[i].translation < pca[i].translation;
    t[0] += sym[i].translation, t[1] += pca[i].translation;
    r[0] += sym[i].rotation, r[1] += pca[i].rotation;
    p[0] += sym[i].paired, p[1] += pca[i].paired;
  }
  std::ostringstream out;
  out << "| " << shape.name << " | " << num_faces(shape.mesh) << " | " << n << " | " << points / std::max<std::size_t>(n, 1)
      << " | " << closer << " / " << n << " | " << fixed(t[0] / n) << " / " << fixed(t[1] / n) << " | " << fixed(r[0] / n)
      << " / " << fixed(r[1] / n) << " | " << fixed(p[0] / n) << " / " << fixed(p[1] / n) << " |";
  if(whole_vs_truth >= 0.) out << " " << fixed(whole_vs_truth) << " |";
  return out.str();
}

// The largest angle between a true axis (the normals of the planes by construction, x y z) and
// the nearest axis of the whole's frame; -1 with no plane by construction.
double whole_versus_truth(const Shape& shape, const Frame& whole)
{
  if(shape.planes.empty()) return -1.;
  Frame truth{whole.center, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}};
  return unordered_axes_angle(whole, truth);
}

void print_summary(const std::string& rule, const Tally& sym, const Tally& pca, bool truth_column)
{
  std::cout << "\n### Rule `" << rule << "`\n\n| shape | faces | scans | points per scan | centre of symmetry closer | "
            << "mean translational error, symmetry / PCA (% R) | mean rotational error, symmetry / PCA (deg) | the same, "
            << "axes paired at best (deg) |" << (truth_column ? " whole's symmetry frame vs true axes, paired (deg) |" : "")
            << "\n|---|---:|---:|---:|---:|---:|---:|---:|" << (truth_column ? "---:|" : "") << "\n";
  for(const std::string& r : sym.rows) std::cout << r << "\n";
  print_histograms("translational error", sym.translation, pca.translation, "% R");
  print_histograms("rotational error", sym.rotation, pca.rotation, "deg");
  std::size_t closer = 0;
  double sum[2] = {0, 0};
  for(std::size_t i = 0; i < sym.scans.size(); ++i) {
    closer += sym.scans[i].translation < pca.scans[i].translation;
    sum[0] += sym.scans[i].translation, sum[1] += pca.scans[i].translation;
  }
  const std::size_t n = sym.scans.size();
  const auto rotation = [](const Errors& e) { return e.rotation; };
  const auto paired = [](const Errors& e) { return e.paired; };
  const auto translation = [](const Errors& e) { return e.translation; };
  std::cout << "\nRule `" << rule << "`: centre of symmetry closer than the centre of mass in " << closer << " of " << n
            << " scans (" << fixed(100. * closer / n) << " %); mean translational error " << fixed(sum[0] / n)
            << " % R (symmetry) vs " << fixed(sum[1] / n) << " % R (PCA): " << fixed(sum[1] / sum[0])
            << " times closer on average; median translational error " << fixed(median(sym.list(translation))) << " vs "
            << fixed(median(pca.list(translation))) << " % R; median rotational error " << fixed(median(sym.list(rotation)))
            << " deg vs " << fixed(median(pca.list(rotation))) << " (PCA), paired at best "
            << fixed(median(sym.list(paired))) << " vs " << fixed(median(pca.list(paired))) << ".\n";
}

} // namespace

int main(int argc, char** argv)
try {
  const Options o = parse(argc, argv);
  std::cout << "Command: `alignment_experiment --set " << o.set << (o.set == "demo" ? " --meshes " + o.meshes : "")
            << " --resolution " << o.resolution << " --rays " << o.rays << " --samples " << o.samples
            << " --seed " << o.seed << "`\n" << std::fixed << std::setprecision(3);
  const auto np =
    CGAL::parameters::grid_resolution(o.resolution).random_seed(unsigned(o.seed)).number_of_samples(std::size_t(o.samples));
  const std::map<std::string, Rule> known = rules();
  std::map<std::string, Tally> tallies;
  Tally pca;
  std::ofstream errors_out;
  if(!o.errors_file.empty()) errors_out.open(o.errors_file);
  for(const Shape& shape : shapes_of_set(o.set, o.meshes)) {
    const std::string key = o.set + "_" + shape.name + "_" + std::to_string(o.resolution);
    const STI::Mass_distribution whole_mass = STI::mass_of_mesh(shape.mesh, np);
    const Detection whole = cached(o.cache, key + "_whole", [&] { return STI::detection_of_mesh(shape.mesh, np); });
    const Frame whole_pca = STI::pca_frame(whole_mass);
    const double radius = radius_of(shape.mesh, whole_pca.center);
    const std::vector<std::vector<K::Point_3>> scans = corner_scans(shape.mesh, o.rays);
    std::map<std::string, STI::Frame_choice> whole_choice;
    for(const std::string& r : o.rules) whole_choice[r] = known.at(r)(whole_mass, whole);
    if(o.diagnostics) std::cout << "\n" << shape.name << "\n";
    std::map<std::string, std::vector<Errors>> shape_errors;
    std::vector<Errors> pca_errors;
    std::size_t points = 0;
    for(int corner = 0; corner < 8; ++corner) {
      const std::vector<K::Point_3>& scan = scans[std::size_t(corner)];
      if(scan.empty()) continue;
      points += scan.size();
      const STI::Mass_distribution mass = STI::mass_of_points(scan, np);
      const Detection d = cached(o.cache, key + "_scan" + std::to_string(corner), [&] { return STI::detection_of_points(scan, np); });
      const Errors p = errors(STI::pca_frame(mass), whole_pca, radius);
      pca_errors.push_back(p);
      pca.add(p);
      for(const std::string& r : o.rules) {
        const STI::Frame_choice choice = known.at(r)(mass, d);
        const Errors e = errors(choice.frame, whole_choice[r].frame, radius);
        shape_errors[r].push_back(e);
        tallies[r].add(e);
        if(o.diagnostics && r == o.rules.front())
          print_diagnostics(corner, scan.size(), d, choice, whole, whole_choice[r], e, p, radius);
        if(errors_out.is_open())
          errors_out << o.set << " " << r << " " << shape.name << " " << corner << " " << e.translation << " " << e.rotation
                     << " " << e.paired << " " << p.translation << " " << p.rotation << " " << p.paired << "\n";
      }
    }
    if(pca_errors.empty()) continue;
    for(const std::string& r : o.rules)
      tallies[r].rows.push_back(row(shape, points, shape_errors[r], pca_errors,
                                    whole_versus_truth(shape, whole_choice[r].frame)));
    std::cerr << shape.name << " done\n";
  }
  if(pca.scans.empty()) throw std::runtime_error("no scan (are the meshes in " SYMMETRY_TRANSFORM_DATA_DIR "/meshes?)");
  for(const std::string& r : o.rules) print_summary(r, tallies[r], pca, o.set == "man-made");
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
