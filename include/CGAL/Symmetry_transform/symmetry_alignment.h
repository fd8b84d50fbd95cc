// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H

#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformRef

A canonical coordinate frame of a shape: an origin and three unit, pairwise orthogonal axes
forming a right-handed basis (`axes[2]` \f$ = \f$ `axes[0]` \f$ \times \f$ `axes[1]`).

Built by `symmetry_frame()` (centre of symmetry and principal symmetry axes, thesis section 4.1)
or by `pca_frame()` (centre of mass and principal axes of inertia, the classical baseline);
`to_canonical()` gives the rigid motion that takes the frame to the origin and the coordinate axes.

\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Symmetry_frame
{
  /// The origin of the frame: the centre of symmetry, or the centre of mass.
  typename GeomTraits::Point_3 center;
  /// The three axes, unit and right-handed, most significant first.
  std::array<typename GeomTraits::Vector_3, 3> axes;
};

namespace internal {

// The mass of a shape: its surface (area measure) for a mesh, its points (counting measure) for
// a point set. Its moments are computed exactly on the triangles: the integral of a polynomial
// of degree k of a linear function s over a triangle T of area A is
// 2A k!/(k+2)! h_k(s_0, s_1, s_2), h_k the complete homogeneous symmetric polynomial of the
// values at the corners. Plain doubles and Eigen (the numerical layer).
class Mass_distribution
{
public:
  explicit Mass_distribution(std::vector<Dtriangle> triangles)
    : triangles_(std::move(triangles))
  {
    const Shape_frame frame = frame_of_triangles(triangles_);
    center_ = Eigen::Vector3d(frame.center.x(), frame.center.y(), frame.center.z());
    radius_ = frame.radius;
    for(const Dtriangle& t : triangles_) mass_ += std::sqrt(t.squared_area());
  }

  explicit Mass_distribution(std::vector<Dpoint> points)
    : points_(std::move(points))
  {
    const Shape_frame frame = frame_of_points(points_);
    center_ = Eigen::Vector3d(frame.center.x(), frame.center.y(), frame.center.z());
    radius_ = frame.radius;
    mass_ = double(points_.size());
  }

  const Eigen::Vector3d& center() const { return center_; }
  double radius() const { return radius_; }

  // The covariance about the centre of mass, per unit mass: for a triangle with corners v_i
  // relative to the centre, A/12 (sum_i v_i v_i^T + (sum_i v_i)(sum_i v_i)^T).
  Eigen::Matrix3d covariance() const
  {
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    for(const Dtriangle& t : triangles_) {
      const Eigen::Vector3d v[3] = {corner(t, 0) - center_, corner(t, 1) - center_, corner(t, 2) - center_};
      const Eigen::Vector3d sum = v[0] + v[1] + v[2];
      c += std::sqrt(t.squared_area()) / 12. *
           (v[0] * v[0].transpose() + v[1] * v[1].transpose() + v[2] * v[2].transpose() + sum * sum.transpose());
    }
    for(const Dpoint& p : points_) {
      const Eigen::Vector3d v = to_eigen(p) - center_;
      c += v * v.transpose();
    }
    return c / mass_;
  }

  // The mean of s |s|, s = (x - origin) . axis the signed distance to the plane through `origin`
  // normal to `axis`, per unit mass, over R^2: positive when the mass on the positive side,
  // weighted by its squared distance to the plane, exceeds that on the negative side. Exact on a
  // triangle: where s keeps its sign, +-A/6 h_2(s_0, s_1, s_2); otherwise the triangle is split
  // where s = 0 into the corner alone on its side, a triangle of area A t_j t_k
  // (t = s_i / (s_i - s_j)) on which the integral of s^2 is A t_j t_k s_i^2 / 6, and the rest.
  double signed_square_moment(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) const
  {
    double m = 0.;
    for(const Dtriangle& t : triangles_) {
      const double s[3] = {(corner(t, 0) - origin).dot(axis), (corner(t, 1) - origin).dot(axis),
                           (corner(t, 2) - origin).dot(axis)};
      const double area = std::sqrt(t.squared_area());
      const double all = area / 6. * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[0] * s[1] + s[1] * s[2] + s[2] * s[0]);
      const int positive = int(s[0] > 0.) + int(s[1] > 0.) + int(s[2] > 0.),
                negative = int(s[0] < 0.) + int(s[1] < 0.) + int(s[2] < 0.);
      if(negative == 0) { m += all; continue; }
      if(positive == 0) { m -= all; continue; }
      // The corner alone on its side (strictly), the other two on the other side or on the plane.
      int i = 0;
      if(positive == 1) while(!(s[i] > 0.)) ++i;
      else while(!(s[i] < 0.)) ++i;
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const double alone = area * (s[i] / (s[i] - s[j])) * (s[i] / (s[i] - s[k])) * s[i] * s[i] / 6.;
      m += (s[i] > 0. ? 1. : -1.) * (alone - (all - alone));
    }
    for(const Dpoint& p : points_) {
      const double s = (to_eigen(p) - origin).dot(axis);
      m += s * std::abs(s);
    }
    return m / mass_ / (radius_ * radius_);
  }

private:
  static Eigen::Vector3d corner(const Dtriangle& t, int i) { return to_eigen(t[i]); }

  std::vector<Dtriangle> triangles_;
  std::vector<Dpoint> points_;
  Eigen::Vector3d center_;
  double radius_ = 0.;
  double mass_ = 0.;
};

// Below this normalised moment (|mean of s |s|| / R^2), the mass is taken as balanced along an axis.
constexpr double balanced_moment = 1e-3;
// The second plane: its normal within this angle of perpendicular to the first axis.
constexpr double second_plane_tolerance_degrees = 10.;
// The plane of the centre: its normal within this angle of the third axis; otherwise it is
// searched in the transform, with the third axis as normal (the thesis's rule).
constexpr double center_plane_tolerance_degrees = 10.;

// The eigenvectors of a symmetric matrix, largest eigenvalue first.
inline std::array<Eigen::Vector3d, 3> principal_axes(const Eigen::Matrix3d& covariance)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Matrix3d& v = solver.eigenvectors(); // eigenvalues in increasing order
  return {Eigen::Vector3d(v.col(2)), Eigen::Vector3d(v.col(1)), Eigen::Vector3d(v.col(0))};
}

// Orients the axes (unit, orthogonal) towards more mass about `origin` and makes them
// right-handed: each axis a gets the sign that makes the mean of s |s|, s = (x - origin) . a,
// positive; an axis along which the mass is balanced (|mean| <= balanced_moment R^2) gets the
// sign that makes its largest coordinate (in absolute value, the first of equals) positive. If
// the result is left-handed, the axis with the smallest |mean| (the last of equals) is turned
// round: the axes along which the mass is the most lopsided keep their orientation.
inline std::array<Eigen::Vector3d, 3> oriented_axes(std::array<Eigen::Vector3d, 3> axes, const Eigen::Vector3d& origin,
                                                    const Mass_distribution& mass)
{
  double strength[3];
  for(int i = 0; i < 3; ++i) {
    const double m = mass.signed_square_moment(origin, axes[i]);
    strength[i] = std::abs(m);
    bool flip = m < 0.;
    if(strength[i] <= balanced_moment) {
      Eigen::Index largest = 0;
      axes[i].cwiseAbs().maxCoeff(&largest);
      flip = axes[i][largest] < 0.;
      strength[i] = 0.;
    }
    if(flip) axes[i] = -axes[i];
  }
  if(axes[0].cross(axes[1]).dot(axes[2]) < 0.) {
    int weakest = 2;
    for(int i = 1; i >= 0; --i)
      if(strength[i] < strength[weakest]) weakest = i;
    axes[weakest] = -axes[weakest];
  }
  return axes;
}

struct Eigen_frame
{
  Eigen::Vector3d center;
  std::array<Eigen::Vector3d, 3> axes;
};

inline Eigen_frame pca_frame(const Mass_distribution& mass)
{
  return {mass.center(), oriented_axes(principal_axes(mass.covariance()), mass.center(), mass)};
}

struct Unit_plane
{
  Eigen::Vector3d normal; // unit
  double d;               // normal . x + d = 0
};

// The strongest plane of the transform with unit normal n (the thesis's search for the plane
// that fixes the centre of symmetry): offsets every quarter bin, within 98 % of the radius;
// returns the plane and its value.
template <typename GT>
std::pair<Unit_plane, double> strongest_plane_of_normal(const Reflective_symmetry_transform<GT>& prst,
                                                        const Eigen::Vector3d& n)
{
  const Plane_bins& bins = prst.bins();
  const double n_dot_center = n.dot(Eigen::Vector3d(bins.center[0], bins.center[1], bins.center[2]));
  const std::size_t steps = 4 * bins.n;
  std::pair<Unit_plane, double> best{{n, 0.}, -std::numeric_limits<double>::infinity()};
  for(std::size_t i = 0; i < steps; ++i) {
    const double r = 0.98 * bins.radius * (2. * (double(i) + 0.5) / double(steps) - 1.);
    const double value = prst.value(typename GT::Plane_3(n.x(), n.y(), n.z(), -(n_dot_center + r)));
    if(value > best.second) best = {{n, -(n_dot_center + r)}, value};
  }
  return best;
}

// The strongest plane of the transform among those perpendicular to the unit vector `axis`
// (the thesis's search for the second axis): normals every half degree.
template <typename GT>
Unit_plane strongest_plane_perpendicular_to(const Reflective_symmetry_transform<GT>& prst, const Eigen::Vector3d& axis)
{
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  std::pair<Unit_plane, double> best{{e1, 0.}, -std::numeric_limits<double>::infinity()};
  for(int step = 0; step < 360; ++step) {
    const double t = step * CGAL_PI / 360.;
    const std::pair<Unit_plane, double> candidate = strongest_plane_of_normal(prst, std::cos(t) * e1 + std::sin(t) * e2);
    if(candidate.second > best.second) best = candidate;
  }
  return best.first;
}

// The frame of the principal symmetries (strongest first), by the rules of symmetry_frame(): a
// second or third plane missing among them is searched in the transform, as the thesis does.
template <typename GT>
Eigen_frame symmetry_frame(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                           const Reflective_symmetry_transform<GT>& prst)
{
  typedef Unit_plane Plane;
  std::vector<Plane> planes;
  for(const Principal_symmetry<GT>& s : symmetries) {
    const Eigen::Vector3d n(CGAL::to_double(s.plane.a()), CGAL::to_double(s.plane.b()), CGAL::to_double(s.plane.c()));
    const double l = n.norm();
    if(!(l > 0.) || !std::isfinite(l)) continue;
    planes.push_back({n / l, CGAL::to_double(s.plane.d()) / l});
  }
  if(planes.empty()) return pca_frame(mass);

  const double second_tolerance = std::sin(second_plane_tolerance_degrees * CGAL_PI / 180.),
               center_tolerance = std::cos(center_plane_tolerance_degrees * CGAL_PI / 180.);
  const Plane& first = planes.front();
  std::array<Eigen::Vector3d, 3> axes;
  axes[0] = first.normal;
  const auto second = std::find_if(planes.begin() + 1, planes.end(), [&](const Plane& p) {
    return std::abs(p.normal.dot(axes[0])) <= second_tolerance;
  });
  const Plane* found_second = second != planes.end() ? &*second : nullptr;
  const Plane second_plane = found_second ? *found_second : strongest_plane_perpendicular_to(prst, axes[0]);
  axes[1] = (second_plane.normal - second_plane.normal.dot(axes[0]) * axes[0]).normalized();
  axes[2] = axes[0].cross(axes[1]);
  const auto third = std::find_if(planes.begin() + 1, planes.end(), [&](const Plane& p) {
    return &p != found_second && std::abs(p.normal.dot(axes[2])) >= center_tolerance;
  });
  const Plane third_plane = third != planes.end() ? *third : strongest_plane_of_normal(prst, axes[2]).first;
  // The centre: the intersection of the three planes.
  Eigen::Matrix3d n;
  n << first.normal.transpose(), second_plane.normal.transpose(), third_plane.normal.transpose();
  const Eigen::Vector3d center = n.partialPivLu().solve(Eigen::Vector3d(-first.d, -second_plane.d, -third_plane.d));
  return {center, oriented_axes(axes, center, mass)};
}

template <typename GT>
Symmetry_frame<GT> to_symmetry_frame(const Eigen_frame& f)
{
  Symmetry_frame<GT> result;
  result.center = to_point<GT>(f.center);
  for(std::size_t i = 0; i < 3; ++i) result.axes[i] = to_vector<GT>(f.axes[i]);
  return result;
}

template <typename TriangleMesh, typename NamedParameters>
Mass_distribution mass_of_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  return Mass_distribution(triangles_of_mesh(tm, np));
}

template <typename PointRange, typename NamedParameters>
Mass_distribution mass_of_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  return Mass_distribution(points_of_range(points, NP_helper::get_const_point_map(points, np)));
}

} // namespace internal

/*!
\ingroup PkgSymmetryTransformRef

Computes the symmetry frame of a triangle mesh (thesis, section 4.1): its principal symmetry
axes and centre of symmetry, from the principal symmetries given by
`detect_principal_symmetries(tm, np)`, strongest first.

- First axis: the normal of the strongest plane.
- Second axis: the normal of the strongest plane within 10 degrees of perpendicular to the
  first axis, made exactly perpendicular to it (Gram-Schmidt).
- Third axis: the cross product of the first two.
- Centre of symmetry: the intersection of those two planes with the strongest remaining plane
  whose normal is within 10 degrees of the third axis.

When no principal plane qualifies, the planes are searched in the reflective symmetry transform
itself, as the thesis does: with no plane within 10 degrees of perpendicular to the first axis,
the second plane is the strongest plane of the transform whose normal is perpendicular to the
first axis (normals every half degree, offsets every quarter bin); with no plane within 10
degrees of the third axis, the centre lies on the strongest plane of the transform whose normal
is the third axis. With no principal plane at all, the frame is `pca_frame(tm, np)`.

Orientation: each axis \f$ a \f$ is turned towards more mass about the centre \f$ c \f$: so
that the area-weighted mean of the signed squared distance \f$ s\,|s| \f$,
\f$ s = (x - c) \cdot a \f$, over the surface is positive (computed exactly on the triangles,
each split along the plane \f$ s = 0 \f$). Where that mean is at most \f$ 10^{-3} R^2 \f$, the
mass is balanced along the axis (across a plane of symmetry through \f$ c \f$, say) and the
sign of the axis is arbitrary: it is the one that makes its largest coordinate positive. If the
three axes so oriented form a left-handed basis, the one with the smallest mean (the least
lopsided) is turned round.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the mesh
\param np named parameters: all those of `detect_principal_symmetries()`, to which they are
          passed on (`grid_resolution`, `number_of_samples`, `random_seed`, `max_number_of_planes`, ...), and

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the symmetry frame: unit, right-handed axes and the centre of symmetry.
\throws std::invalid_argument on the bad inputs of `detect_principal_symmetries()` (empty mesh,
        non-triangle face, all faces degenerate, NaN or infinite coordinate, ...).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>
symmetry_frame(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const internal::Mass_distribution mass = internal::mass_of_mesh(tm, np);
  const internal::Detection<GT> detection = internal::detection_of_mesh(tm, np);
  return internal::to_symmetry_frame<GT>(internal::symmetry_frame(mass, detection.symmetries, detection.prst));
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the symmetry frame of a point set, as `symmetry_frame()` does for a mesh, from the
principal symmetries given by `detect_principal_symmetries_of_points(points, np)`; the mass is
that of the points, each of weight 1 (centre of mass: their mean; the means that orient the axes:
means over the points).

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param points the points
\param np named parameters: all those of `detect_principal_symmetries_of_points()`, to which
          they are passed on, and

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of the point range}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is `%Point_3`}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the symmetry frame: unit, right-handed axes and the centre of symmetry.
\throws std::invalid_argument on the bad inputs of `detect_principal_symmetries_of_points()`
        (empty range, a single point, NaN or infinite coordinate, ...).
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
symmetry_frame_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  const internal::Mass_distribution mass = internal::mass_of_points(points, np);
  const internal::Detection<GT> detection = internal::detection_of_points(points, np);
  return internal::to_symmetry_frame<GT>(internal::symmetry_frame(mass, detection.symmetries, detection.prst));
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the classical canonical frame of a triangle mesh, the baseline of `symmetry_frame()`:
the area-weighted centre of mass of its surface and the principal axes of the surface, the
eigenvectors of its covariance matrix \f$ \int (x - c)(x - c)^T \, dA \f$ (computed exactly on
the triangles), largest variance first. The axes are oriented as in `symmetry_frame()`, about
the centre of mass: towards a positive mean of \f$ s\,|s| \f$, the sign of a balanced axis set
by its largest coordinate, then right-handed by turning round the least lopsided axis. Where two
variances are equal (a shape of revolution, a cube) the corresponding axes are arbitrary.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the mesh
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the frame of the centre of mass and the principal axes.
\throws std::invalid_argument on an empty mesh, a non-triangle face, a mesh whose faces are all
        degenerate, or a NaN or infinite coordinate.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>
pca_frame(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  return internal::to_symmetry_frame<GT>(internal::pca_frame(internal::mass_of_mesh(tm, np)));
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the classical canonical frame of a point set, as `pca_frame()` does for a mesh: the
mean of the points and the eigenvectors of their covariance matrix, largest variance first,
oriented as in `pca_frame()` (with means over the points) and right-handed.

\tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param points the points
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of the point range}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is `%Point_3`}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the frame of the centre of mass and the principal axes.
\throws std::invalid_argument on an empty range, a single point (repeated or not), or a NaN or
        infinite coordinate.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
pca_frame_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  return internal::to_symmetry_frame<GT>(internal::pca_frame(internal::mass_of_points(points, np)));
}

/*!
\ingroup PkgSymmetryTransformRef

The rigid motion that takes a frame to the canonical one: its centre to the origin and its
axes to the coordinate axes, \f$ x \mapsto (a_0 \cdot (x - c),\ a_1 \cdot (x - c),\ a_2 \cdot (x - c)) \f$.
Apply it to a mesh with `CGAL::Polygon_mesh_processing::transform()`.

\tparam GeomTraits a model of `Kernel`
\param frame a frame, from `symmetry_frame()` or `pca_frame()` (unit, orthogonal, right-handed axes)
\returns the transformation, a rotation (determinant 1) followed by a translation.
*/
template <typename GeomTraits>
typename GeomTraits::Aff_transformation_3 to_canonical(const Symmetry_frame<GeomTraits>& frame)
{
  typedef typename GeomTraits::FT FT;
  const auto& a = frame.axes;
  const typename GeomTraits::Vector_3 c = frame.center - CGAL::ORIGIN;
  return typename GeomTraits::Aff_transformation_3(a[0].x(), a[0].y(), a[0].z(), FT(-(a[0] * c)),
                                                   a[1].x(), a[1].y(), a[1].z(), FT(-(a[1] * c)),
                                                   a[2].x(), a[2].y(), a[2].z(), FT(-(a[2] * c)));
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H
