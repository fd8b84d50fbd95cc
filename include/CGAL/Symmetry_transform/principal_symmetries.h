// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/detection/candidates.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformRef
A principal symmetry of a shape: a local maximum of its reflective symmetry transform,
refined to high precision.
\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Principal_symmetry
{
  /// The plane of reflection, with a unit normal.
  typename GeomTraits::Plane_3 plane;
  /// Its symmetry measure in \f$ [0,1] \f$, evaluated on the Gaussian distance transform by `symmetry_measure()`.
  double symmetry;
  /// The fraction of the shape (of its area for a mesh, of its points for a point set) that the
  /// reflection maps onto the shape: the mean Gaussian weight \f$ \exp(-d^2/2\sigma^2) \f$ of the
  /// distance \f$ d \f$ from a reflected sample to the shape.
  double support;
};

namespace internal {

template <typename GT>
typename GT::Plane_3 to_plane(const Dplane& p)
{
  return typename GT::Plane_3(p.normal[0], p.normal[1], p.normal[2], -p.offset);
}


// ISP settings from the named parameters; the GEDT of the shape tells which points lie beyond
// its 3 sigma band.
template <typename GT, typename NamedParameters>
Isp_settings isp_settings(const NamedParameters& np, const Voxel_grid<GT>& gedt)
{
  const Grid_settings grid = grid_settings(np, gedt.radius());
  Isp_settings settings;
  settings.sigma = grid.sigma();
  settings.radius = gedt.radius();
  settings.max_iterations =
    unsigned(parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_iterations), 20));
  settings.threads = grid.threads;
  settings.beyond_band = [&gedt](const Eigen::Vector3d& p) { return gedt.trilinear_value(p.x(), p.y(), p.z()) == 0.; };
  return settings;
}

// The PRST of a detection. Its maxima need only be located to a bin or two, ISP doing the
// rest: 5e5 Monte Carlo samples suffice (a quarter of the transform's default) unless the
// user chose a number.
template <typename GT, typename NamedParameters>
Reflective_symmetry_transform<GT> detection_transform(const Voxel_grid<GT>& gedt, const NamedParameters& np)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::number_of_samples_t>::value)
    return reflective_symmetry_transform(gedt, np.number_of_samples(500000));
  else
    return reflective_symmetry_transform(gedt, np);
}

// A triangle surface ready for refinement: its GEDT, the AABB tree of its triangles, and the
// closest triangle of each voxel of the GEDT's band (recorded with the GEDT) for the walk of ISP.
// Built in place: the tree and the field refer to the triangles.
template <typename GT>
class Triangle_surface
{
  std::vector<std::int32_t> closest_triangles_; // moved into the field

public:
  const std::vector<Dtriangle> triangles;
  const Voxel_grid<GT> gedt;
  const Triangle_matcher matcher;
  const Closest_triangle_field field;

  template <typename NamedParameters>
  Triangle_surface(std::vector<Dtriangle> surface_triangles, const NamedParameters& np)
    : triangles(std::move(surface_triangles)),
      gedt(gaussian_distance_transform_of_triangles<GT>(triangles, np, &closest_triangles_)), matcher(triangles),
      field(triangles, matcher, std::move(closest_triangles_), gedt.origin(), gedt.voxel_size(), gedt.resolution())
  {}
  Triangle_surface(const Triangle_surface&) = delete;
  Triangle_surface& operator=(const Triangle_surface&) = delete;
};

// Candidates of the PRST refined by ISP (walking with `walk_matcher` if given), kept if they
// stay near their bin, measured on the GEDT, merged when equal, strongest first.
template <typename GT, typename Matcher, typename NamedParameters, typename Walk_matcher = Matcher>
std::vector<Principal_symmetry<GT>> refine_candidates(const Voxel_grid<GT>& gedt,
                                                      const Reflective_symmetry_transform<GT>& prst,
                                                      const std::vector<Eigen::Vector3d>& samples,
                                                      const Matcher& matcher, const NamedParameters& np,
                                                      const Walk_matcher* walk_matcher = nullptr)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t max_planes = std::size_t(choose_parameter(get_parameter(np, internal_np::st_max_number_of_planes), 10));
  const double t = double(choose_parameter(get_parameter(np, internal_np::st_symmetry_threshold), 0.1));
  const double l = double(choose_parameter(get_parameter(np, internal_np::st_laplacian_threshold), 0.1));
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  const Isp_settings settings = isp_settings(np, gedt);

  // Candidates on one ridge of the transform converge to the same plane: the cheap coarse phase
  // of ISP tells them apart, and only the first of each gets the fine phase.
  std::vector<Dplane> accepted; // the coarse and the refined plane of each accepted candidate
  std::vector<Principal_symmetry<GT>> result;
  const double angle = prst.bins().theta_step(), distance = prst.bins().offset_step();
  const Eigen::Vector3d center = center_of(prst.bins());
  // The thesis drops a candidate that leaves its bin: an unstable maximum. Monte Carlo noise
  // and the smoothing move maxima along flat ridges by a few bins, hence a reach of 3 bins.
  constexpr long unstable_reach = 3;
  std::vector<std::array<std::size_t, 3>> candidates = symmetry_candidates(prst, t, l);
  // Most candidates are dropped as duplicates or unstable; beyond a few per plane asked for, the
  // weaker ones would be cut off anyway.
  if(candidates.size() > 10 * max_planes) candidates.resize(10 * max_planes);
  for(const auto& bin : candidates) {
    if(result.size() == max_planes) break;
    const auto start = std::chrono::steady_clock::now();
    auto near_accepted = [&](const Dplane& plane, double factor) {
      return std::any_of(accepted.begin(), accepted.end(),
                         [&](const Dplane& p) { return same_plane(p, plane, factor * angle, factor * distance, center); });
    };
    // Stop refining as soon as the plane heads for an accepted one or out of reach of its bin.
    auto abandon = [&](const Dplane& plane) {
      return near_accepted(plane, 2.) || !stays_near_bin(prst, plane, bin, unstable_reach);
    };
    const Isp_result coarse = iterative_symmetric_points(samples, to_dplane(prst.plane(bin)), matcher, settings,
                                                         Isp_phase::COARSE, abandon, walk_matcher);
    // The coarse phase stops within about a bin of the optimum: closer than two bins to an
    // accepted plane, the fine phase would only find that plane again.
    // A start that the coarse phase cannot settle is on a slope or a ridge, not near a maximum;
    // with no normals (a point set), the point-to-point fit creeps and needs the fine phase.
    const bool seen = near_accepted(coarse.plane, 2.), settled = coarse.converged || !Matcher::has_normals;
    Isp_result refined = coarse;
    if(!seen && settled)
      refined = iterative_symmetric_points(samples, coarse.plane, matcher, settings, Isp_phase::FINE, abandon, walk_matcher);
    const char* verdict = seen || near_accepted(refined.plane, 2.)              ? "same as an accepted plane"
                          : !stays_near_bin(prst, refined.plane, bin, unstable_reach) ? "left its bin"
                          : !settled || !(refined.support > 0.)                      ? "no convergence"
                                                                                     : nullptr;
    if(verbose)
      std::cerr << "  candidate (" << bin[0] << "," << bin[1] << "," << bin[2] << ") SM " << prst.value(bin)
                << ": ISP " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                << " s (" << coarse.iterations << " + " << (seen || !settled ? 0u : refined.iterations)
                << " iterations), support " << refined.support << (verdict ? ", dropped: " : ", accepted") << (verdict ? verdict : "")
                << "\n";
    if(verdict != nullptr) continue;
    accepted.push_back(coarse.plane);
    accepted.push_back(refined.plane);
    const typename GT::Plane_3 plane = to_plane<GT>(refined.plane);
    result.push_back({plane, symmetry_measure(gedt, plane), refined.support});
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Principal_symmetry<GT>& a, const Principal_symmetry<GT>& b) { return a.symmetry > b.symmetry; });
  if(result.size() > max_planes) result.resize(max_planes);
  return result;
}

// A detection and the transform it started from (the symmetry frame searches the transform too).
template <typename GT>
struct Detection
{
  std::vector<Principal_symmetry<GT>> symmetries;
  Reflective_symmetry_transform<GT> prst;
};

template <typename GT, typename NamedParameters>
Detection<GT> detection_of_surface(const Triangle_surface<GT>& surface, const NamedParameters& np)
{
  Reflective_symmetry_transform<GT> prst = detection_transform(surface.gedt, np);
  std::vector<Principal_symmetry<GT>> symmetries = refine_candidates(
    surface.gedt, prst, surface_samples(surface.triangles, np), surface.matcher, np, &surface.field);
  return {std::move(symmetries), std::move(prst)};
}

template <typename TriangleMesh, typename NamedParameters>
Detection<typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type> detection_of_mesh(const TriangleMesh& tm,
                                                                                          const NamedParameters& np)
{
  typedef typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  const Triangle_surface<GT> surface(triangles_of_mesh(tm, vpm), np);
  return detection_of_surface(surface, np);
}

template <typename PointRange, typename NamedParameters>
Detection<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
detection_of_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;
  const std::vector<Dpoint> samples = points_of_range(points, NP_helper::get_const_point_map(points, np));
  const Voxel_grid<GT> gedt = gaussian_distance_transform_of_points(points, np);
  Reflective_symmetry_transform<GT> prst = detection_transform(gedt, np);
  const Point_matcher matcher(samples);
  std::vector<Principal_symmetry<GT>> symmetries = refine_candidates(gedt, prst, point_samples(samples, np), matcher, np);
  return {std::move(symmetries), std::move(prst)};
}

} // namespace internal

/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a triangle mesh from its reflective symmetry transform:
the local maxima of `prst` whose symmetry measure exceeds \f$ t\,(1 - |r|/R) \f$ and whose
negative discrete Laplacian exceeds \f$ l \f$, with \f$ t \f$ and \f$ l \f$ fractions of those
of the strongest maximum, each refined by Iterative Symmetric Points (ISP): surface samples
are reflected through the plane and matched to their closest points on the mesh, and the
plane re-fitted by least squares, with the Gaussian weights \f$ \exp(-d^2/2\sigma^2) \f$ of
the match distances \f$ d \f$, until the weights stop growing. The matches are first
approximate (the closest triangles of the voxels around the point, recorded with the GEDT),
then exact (`CGAL::AABB_tree`) for the last steps (\ref SymmetryTransformPrincipal).
If the matches are then much closer than \f$ \sigma \f$ (an exact symmetry), the refinement goes
on with weights of half and a quarter of that width, so that the parts of the shape the plane
does not map lose their say: the local symmetries of a part of a composite shape come out
exact. Candidates are refined in decreasing order of the transform. One that moves more than 3
bins away from its bin, or that a first refinement on an eighth of the samples cannot settle
(on a mesh), is dropped (an unstable maximum); candidates that converge to an accepted plane are merged. The
symmetry of each plane is then measured on the GEDT by `symmetry_measure()`.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the mesh
\param prst its reflective symmetry transform, from `reflective_symmetry_transform(tm, np)`
\param np named parameters: those of `gaussian_distance_transform()` (the GEDT is recomputed
with them, and its width sets the Gaussian weights of ISP), and

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_refinement_samples}
    \cgalParamDescription{the number of surface samples reflected at each ISP iteration}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10000}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of ISP iterations of each stage of a refinement; a
                           plane still moving then (on a flat ridge of an approximate symmetry)
                           is taken where it is}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_planes}
    \cgalParamDescription{the largest number of planes returned: the refinement of the
                           candidates, in decreasing order of the transform, stops when this
                           many planes have been accepted}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{symmetry_threshold}
    \cgalParamDescription{\f$ t \f$ as a fraction of the symmetry measure of the strongest maximum}
    \cgalParamType{`double`}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{laplacian_threshold}
    \cgalParamDescription{\f$ l \f$ as a fraction of the negative Laplacian of the strongest maximum}
    \cgalParamType{`double`}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the surface samples}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{whether to print each candidate and its refinement on `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the principal symmetries, strongest first.
\throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
principal_symmetries(
  const TriangleMesh& tm,
  const Reflective_symmetry_transform<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>& prst,
  const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, vpm), np);
  return internal::refine_candidates(surface.gedt, prst, internal::surface_samples(surface.triangles, np),
                                     surface.matcher, np, &surface.field);
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a triangle mesh: its reflective symmetry transform by
`reflective_symmetry_transform(tm, np)`, then `principal_symmetries(tm, prst, np)`.
The named parameters are those of both functions, except that `number_of_samples` (the Monte
Carlo samples of the transform) defaults to \f$ 5 \cdot 10^5 \f$ here: the maxima need only be
located within a bin or two, the refinement does the rest.
\param tm the mesh
\param np the named parameters
\returns the principal symmetries, strongest first.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
detect_principal_symmetries(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_mesh(tm, np).symmetries;
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a point set, as `detect_principal_symmetries()`, with
ISP matching reflected points to their nearest points (`CGAL::Kd_tree`) and fitting the plane
to the point pairs.
\param points the points
\param np the named parameters of `detect_principal_symmetries()`, and `point_map`
\returns the principal symmetries, strongest first.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>>
detect_principal_symmetries_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_points(points, np).symmetries;
}

/*!
\ingroup PkgSymmetryTransformRef

Refines a rough plane of symmetry of a triangle mesh by Iterative Symmetric Points, as in
`principal_symmetries()`, without a transform: the plane converges to the nearest local
maximum of the Gaussian-weighted support (within `number_of_iterations` steps of each stage).
A plane that is already an exact local symmetry, of a part of a composite shape for instance,
stays where it is.
\param tm the mesh
\param plane the starting plane
\param np named parameters: `number_of_refinement_samples`, `number_of_iterations`,
          `random_seed`, and those of `gaussian_distance_transform()` that set the Gaussian width
          (`grid_resolution`, `gaussian_width`, `grid_margin`) and `vertex_point_map`
\returns the refined plane, with a unit normal; `plane` itself (normalised) if no reflected
sample lies near the surface.
\throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3
refine_symmetry_plane(const TriangleMesh& tm,
                      const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, vpm), np);
  const internal::Isp_settings settings = internal::isp_settings(np, surface.gedt);
  return internal::to_plane<GT>(internal::iterative_symmetric_points(internal::surface_samples(surface.triangles, np),
                                                                     internal::to_dplane(plane), surface.matcher,
                                                                     settings, internal::Isp_phase::BOTH, {},
                                                                     &surface.field)
                                  .plane);
}

/*!
\ingroup PkgSymmetryTransformRef

Computes how much each face of a triangle mesh supports the reflection through `plane`
(thesis, Figure 3.7): the mean, over points of the face (its centroid and three interior
points), of \f$ \exp(-d^2/2\sigma^2) \f$, \f$ d \f$ the distance from the reflected point to
the mesh and \f$ \sigma \f$ the width of the Gaussian distance transform. 1 means the face
is mirrored onto the surface, 0 that its mirror image is far from it.
\tparam FaceSupportMap a model of `WritablePropertyMap` with the face descriptor as key and `double` as value
\param tm the mesh
\param plane the plane of reflection
\param face_support_map receives the support of each face, in \f$ [0,1] \f$
\param np named parameters: `grid_resolution`, `gaussian_width`, `grid_margin` (they set
          \f$ \sigma \f$ as in `gaussian_distance_transform()`), `number_of_threads`, `vertex_point_map`
\returns the supported fraction of the area: the area-weighted mean of the face supports.
\throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename FaceSupportMap,
          typename NamedParameters = parameters::Default_named_parameters>
double symmetry_support(const TriangleMesh& tm,
                        const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                        FaceSupportMap face_support_map, const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, vpm);
  const internal::Triangle_matcher matcher(triangles);
  const internal::Grid_settings grid = internal::grid_settings(np, internal::frame_of_triangles(triangles).radius);
  const internal::Dplane mirror = internal::to_dplane(plane);
  const double sigma = grid.sigma();

  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  std::vector<double> support(face_list.size()), area(face_list.size());
  internal::parallel_for(face_list.size(), grid.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f) {
      const auto h = halfedge(face_list[f], tm);
      const Eigen::Vector3d a = internal::to_eigen(internal::to_dpoint(get(vpm, source(h, tm)))),
                            b = internal::to_eigen(internal::to_dpoint(get(vpm, target(h, tm)))),
                            c = internal::to_eigen(internal::to_dpoint(get(vpm, target(next(h, tm), tm))));
      area[f] = 0.5 * (b - a).cross(c - a).norm();
      double sum = 0.;
      internal::Triangle_matcher::Hint hint;
      for(const Eigen::Vector3d& p : {Eigen::Vector3d((a + b + c) / 3.), Eigen::Vector3d((4. * a + b + c) / 6.),
                                      Eigen::Vector3d((a + 4. * b + c) / 6.), Eigen::Vector3d((a + b + 4. * c) / 6.)}) {
        const Eigen::Vector3d image = mirror.reflect(p);
        sum += std::exp(-(image - matcher.closest(image, hint, false).first).squaredNorm() / (2. * sigma * sigma));
      }
      support[f] = sum / 4.;
    }
  });
  double supported = 0., total = 0.;
  for(std::size_t f = 0; f < face_list.size(); ++f) {
    put(face_support_map, face_list[f], support[f]);
    supported += area[f] * support[f];
    total += area[f];
  }
  return supported / total;
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
