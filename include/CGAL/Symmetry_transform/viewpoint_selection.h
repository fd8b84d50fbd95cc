// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H
#define CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformRef
A viewing direction and its viewpoint score \f$ S(v) \f$ (see `viewpoint_score()`).
\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Viewpoint
{
  /// The direction \f$ v \f$ the camera looks along (or from: \f$ v \f$ and \f$ -v \f$ are the same
  /// view), a unit vector, chosen with \f$ z > 0 \f$ (with \f$ z = 0 \f$: \f$ y > 0 \f$; with
  /// \f$ y = z = 0 \f$: \f$ x > 0 \f$).
  typename GeomTraits::Vector_3 direction;
  /// \f$ S(v) \f$.
  double score;
};

namespace internal {

template <typename Symmetry>
struct Kernel_of_symmetry;

template <typename GT>
struct Kernel_of_symmetry<Principal_symmetry<GT>>
{
  typedef GT type;
};

template <typename SymmetryRange>
struct Kernel_of_symmetry_range
{
  typedef typename Kernel_of_symmetry<typename std::iterator_traits<
    decltype(std::begin(std::declval<const SymmetryRange&>()))>::value_type>::type type;
};

typedef Eigen::Vector3d Vec3;

// v / |v|, or throws on a zero or non-finite vector.
inline Vec3 unit(const Vec3& v, const char* what)
{
  const double l = v.norm();
  if(!(l > 0.) || !std::isfinite(l)) throw std::invalid_argument(std::string("Symmetry_transform: ") + what);
  return v / l;
}

// The principal planes as unit normals and weights M(u) > 0 (planes of zero measure add nothing).
struct Weighted_normals
{
  std::vector<Vec3> normals;
  std::vector<double> weights;

  template <typename SymmetryRange>
  explicit Weighted_normals(const SymmetryRange& symmetries)
  {
    for(const auto& s : symmetries) {
      const auto n = s.plane.orthogonal_vector();
      const Vec3 u = unit({double(n.x()), double(n.y()), double(n.z())},
                          "viewpoint selection: a principal plane has no normal");
      if(!(s.symmetry >= 0.) || !std::isfinite(s.symmetry))
        throw std::invalid_argument(
          "Symmetry_transform: viewpoint selection: a symmetry measure is negative or not finite");
      if(s.symmetry == 0.) continue;
      normals.push_back(u);
      weights.push_back(s.symmetry);
    }
  }

  double score(const Vec3& v) const // v a unit vector
  {
    double s = 0.;
    for(std::size_t k = 0; k < normals.size(); ++k) s += std::abs(v.dot(normals[k])) * weights[k];
    return s;
  }

  // w(v) = sum sign(v.u) M(u) u: S(x) >= w(v).x for every x, with equality at x = v.
  Vec3 linearisation(const Vec3& v) const
  {
    Vec3 w = {0., 0., 0.};
    for(std::size_t k = 0; k < normals.size(); ++k) {
      const double d = v.dot(normals[k]);
      const double s = d > 0. ? weights[k] : (d < 0. ? -weights[k] : 0.);
      for(int i = 0; i < 3; ++i) w[i] += s * normals[k][i];
    }
    return w;
  }

  // Local maximum reached from v by v <- w(v)/|w(v)|: each step maximises the minorant w(v).x of
  // S on the sphere, so S never decreases; S being linear on each cell of the arrangement of the
  // planes' great circles, the iteration stops on the exact maximum after a few steps.
  Vec3 ascend(Vec3 v) const
  {
    double s = score(v);
    for(int i = 0; i < 100; ++i) {
      const Vec3 w = linearisation(v);
      const double l = w.norm();
      if(!(l > 0.)) break;
      const Vec3 next = w / l;
      const double t = score(next);
      if(t < s) break; // rounding: keep the better one
      const bool moved = next.dot(v) < 1. - 1e-15;
      v = next;
      s = t;
      if(!moved) break;
    }
    return v;
  }
};

// The representative of {v, -v} with z > 0 (then y > 0, then x > 0; |c| <= 1e-12 counts as 0).
inline Vec3 canonical_view(Vec3 v)
{
  for(int i = 2; i >= 0; --i) {
    if(v[i] > 1e-12) return v;
    if(v[i] < -1e-12) return -v;
  }
  return v;
}

// The Fibonacci sphere: n directions, z decreasing from 1 - 1/n to -1 + 1/n.
inline std::vector<Vec3> fibonacci_sphere(std::size_t n)
{
  std::vector<Vec3> points(n);
  const double golden_angle = CGAL_PI * (3. - std::sqrt(5.));
  for(std::size_t i = 0; i < n; ++i) {
    const double z = 1. - (2. * double(i) + 1.) / double(n), r = std::sqrt((std::max)(0., 1. - z * z));
    const double phi = golden_angle * double(i);
    points[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return points;
}

template <typename GT>
Viewpoint<GT> make_viewpoint(const Vec3& v, double score)
{
  const Vec3 c = canonical_view(v);
  return Viewpoint<GT>{typename GT::Vector_3(c[0], c[1], c[2]), score};
}

} // namespace internal

/*!
\ingroup PkgSymmetryTransformRef
The viewpoint score of a view direction (thesis, Section 4.3.2):
\f[ S(v) = \sum_{u \in W} |v \cdot u| \, M(u) \f]
over the principal planes \f$ u \in W \f$ (unit normals) of symmetry measure \f$ M(u) \f$.

Each plane of symmetry prefers the views along its normal: seen from there, the two mirror halves
lie one behind the other and the image shows no redundancy, whereas a view within the plane shows
a mirror-symmetric image, half of which repeats the other. \f$ S(v) \f$ is the symmetry that the view
\f$ v \f$ does not waste, so good views have a high \f$ S \f$ (see `best_viewpoints()`) and the worst
view has the lowest (see `worst_viewpoint()`). \f$ S(v) = S(-v) \f$ and \f$ 0 \le S(v) \le \sum_u M(u) \f$.

\tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
\tparam Vector_3 `GT::Vector_3`
\param symmetries the principal symmetries
\param v the view direction, of any nonzero length (normalised here)
\returns \f$ S(v) \f$
\pre No plane has a zero normal, and every symmetry measure is nonnegative and finite.
\throws std::invalid_argument if `v` is zero or not finite, or if the precondition fails.
*/
template <typename SymmetryRange, typename Vector_3>
double viewpoint_score(const SymmetryRange& symmetries, const Vector_3& v)
{
  const internal::Weighted_normals planes(symmetries);
  return planes.score(internal::unit({double(v.x()), double(v.y()), double(v.z())},
                                     "viewpoint_score: the view direction is zero or not finite"));
}

/*!
\ingroup PkgSymmetryTransformRef
Writes the best views of a shape of principal symmetries `symmetries`, best first: the local maxima
of the viewpoint score \f$ S \f$ of `viewpoint_score()`.

\f$ S \f$ is evaluated on a deterministic Fibonacci sphere of `number_of_samples` directions; a
sample is a local maximum if it scores at least as much as every sample within 1.6 sample
spacings \f$ \sqrt{4\pi/n} \f$ (5 degrees by default; ties broken by index): maxima closer than
that may be missed. Each is then refined by the ascent
\f$ v \leftarrow w(v)/\|w(v)\| \f$, \f$ w(v) = \sum_u \mathrm{sign}(v \cdot u) M(u) u \f$: \f$ S \f$
is linear on each cell of the arrangement of the planes' great circles, \f$ w(v) \cdot x \le S(x) \f$
with equality at \f$ x = v \f$, so \f$ S \f$ never decreases and the ascent stops on the exact local
maximum. Maxima closer than 0.5 degree (as views: \f$ v \f$ and \f$ -v \f$ are one view) are merged.

The thesis states the goal as minimising the symmetry seen; \f$ S \f$ grows toward the planes'
normals, where a view shows the least mirror redundancy, so that goal is reached by maximising
\f$ S \f$. Minimising \f$ S \f$ would choose a view along a plane's normal (for three orthogonal
planes, the weakest one's: see `worst_viewpoint()`), against the off-axis views that the thesis
reports and that viewers prefer.

For three orthogonal planes of measures \f$ M_1, M_2, M_3 \f$ (a box), the best view is
\f$ (M_1, M_2, M_3)/\|(M_1,M_2,M_3)\| \f$ in the frame of their normals, off every normal, on a
diagonal \f$ (\pm 1, \pm 1, \pm 1)/\sqrt{3} \f$ when the measures are equal: the thesis reports
best views 20 to 35 degrees off the main planes (Section 4.3.3).

With no plane of positive measure, every view scores 0 and none is better than another: nothing is
written.

\tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
\tparam OutputIterator an output iterator accepting `Viewpoint<GT>`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param symmetries the principal symmetries
\param out where the views go, best (highest \f$ S \f$) first; the caller keeps as many as it wants
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_samples}
    \cgalParamDescription{the number of directions of the Fibonacci sphere searched (on the whole
      sphere, so about half as many distinct views)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{4000}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `out` past the views written
\throws std::invalid_argument if a plane has a zero normal, a symmetry measure is negative or not
finite, or `number_of_samples` is below 12.
*/
template <typename SymmetryRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator best_viewpoints(const SymmetryRange& symmetries, OutputIterator out,
                               const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Kernel_of_symmetry_range<SymmetryRange>::type GT;
  using internal::Vec3;
  const std::size_t n =
    std::size_t(parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_samples), internal::defaults::viewpoint_directions));
  if(n < 12)
    throw std::invalid_argument("Symmetry_transform: best_viewpoints: number_of_samples must be at least 12");
  const internal::Weighted_normals planes(symmetries);
  if(planes.normals.empty()) return out;

  const std::vector<Vec3> samples = internal::fibonacci_sphere(n);
  std::vector<double> scores(n);
  for(std::size_t i = 0; i < n; ++i) scores[i] = planes.score(samples[i]);

  // Neighbours within the angle r; |z_i - z_j| <= r for them, and z is monotone in the index.
  const double r = 1.6 * std::sqrt(4. * CGAL_PI / double(n)), cos_r = std::cos(r);
  const std::size_t window = std::size_t(std::ceil(r * double(n) / 2.)) + 1;
  std::vector<std::pair<double, Vec3>> maxima; // refined score, direction
  for(std::size_t i = 0; i < n; ++i) {
    bool is_max = true;
    for(std::size_t j = (i > window ? i - window : 0); is_max && j < (std::min)(n, i + window + 1); ++j) {
      if(j == i || samples[i].dot(samples[j]) < cos_r) continue;
      if(scores[j] > scores[i] || (scores[j] == scores[i] && j < i)) is_max = false;
    }
    if(!is_max) continue;
    const Vec3 v = internal::canonical_view(planes.ascend(samples[i]));
    maxima.emplace_back(planes.score(v), v);
  }
  std::stable_sort(maxima.begin(), maxima.end(),
                   [](const std::pair<double, Vec3>& a, const std::pair<double, Vec3>& b) { return a.first > b.first; });

  const double merge = std::cos(0.5 * CGAL_PI / 180.);
  std::vector<Vec3> kept;
  for(const auto& m : maxima) {
    bool duplicate = false;
    for(const Vec3& k : kept) duplicate = duplicate || std::abs(k.dot(m.second)) > merge;
    if(duplicate) continue;
    kept.push_back(m.second);
    *out++ = internal::make_viewpoint<GT>(m.second, m.first);
  }
  return out;
}

/*!
\ingroup PkgSymmetryTransformRef
The worst view of a shape of principal symmetries `symmetries`: the global minimum of the viewpoint
score \f$ S \f$ of `viewpoint_score()`, where the image is the most redundant.

\f$ S \f$ is linear on each cell of the arrangement of the great circles \f$ v \cdot u = 0 \f$ and
concave along every arc where it is positive, so its minimum lies on a vertex of the arrangement:
the minimum is taken, exactly, over the directions \f$ u_i \times u_j \f$ of every pair of planes,
and over one direction in each plane (for planes all parallel).
For three orthogonal planes, it is the normal of the weakest plane (a view within the two strongest
planes).

With no plane of positive measure, every view scores 0 and the direction \f$ (0,0,1) \f$ is returned.

\tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
\param symmetries the principal symmetries
\returns a `Viewpoint<GT>`
\throws std::invalid_argument if a plane has a zero normal or a symmetry measure is negative or not finite.
*/
template <typename SymmetryRange>
Viewpoint<typename internal::Kernel_of_symmetry_range<SymmetryRange>::type>
worst_viewpoint(const SymmetryRange& symmetries)
{
  typedef typename internal::Kernel_of_symmetry_range<SymmetryRange>::type GT;
  using internal::Vec3;
  const internal::Weighted_normals planes(symmetries);
  Vec3 best = {0., 0., 1.};
  double best_score = planes.score(best);
  auto consider = [&](const Vec3& c) {
    const double l = c.norm();
    if(!(l > 1e-9)) return;
    const Vec3 v = c / l;
    const double s = planes.score(v);
    if(s < best_score) { best = v; best_score = s; }
  };
  const std::size_t m = planes.normals.size();
  for(std::size_t i = 0; i < m; ++i) {
    const Vec3& u = planes.normals[i];
    // a direction in plane i: u crossed with the axis it is least aligned with
    Eigen::Index least;
    u.cwiseAbs().minCoeff(&least);
    consider(u.cross(Vec3::Unit(least)));
    for(std::size_t j = i + 1; j < m; ++j) consider(u.cross(planes.normals[j]));
  }
  return internal::make_viewpoint<GT>(best, best_score);
}

/*!
\ingroup PkgSymmetryTransformRef
The viewpoint score as a spherical function, ready to be exported (e.g. as a PLY file with
colours, see the example `best_viewpoint.cpp`): a unit icosphere (an icosahedron Loop-subdivided
`subdivisions` times, its vertices projected onto the sphere: \f$ 10 \cdot 4^s + 2 \f$ vertices)
whose vertex property map named `"v:score"` holds \f$ S \f$ of the vertex's direction, in
\f$ [0, \sum_u M(u)] \f$.

\tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
\param symmetries the principal symmetries
\param subdivisions the number of subdivisions \f$ s \f$ of the icosahedron
\returns a `Surface_mesh<GT::Point_3>` with a vertex property map `"v:score"` of type `double`
\throws std::invalid_argument if `subdivisions` exceeds 8, a plane has a zero normal, or a symmetry
measure is negative or not finite.
*/
template <typename SymmetryRange>
Surface_mesh<typename internal::Kernel_of_symmetry_range<SymmetryRange>::type::Point_3>
viewpoint_score_sphere(const SymmetryRange& symmetries, unsigned int subdivisions = 4)
{
  typedef typename internal::Kernel_of_symmetry_range<SymmetryRange>::type GT;
  typedef typename GT::Point_3 Point_3;
  if(subdivisions > 8)
    throw std::invalid_argument("Symmetry_transform: viewpoint_score_sphere: at most 8 subdivisions");
  const internal::Weighted_normals planes(symmetries);
  Surface_mesh<Point_3> sphere;
  make_icosahedron(sphere, Point_3(0, 0, 0), 1.);
  if(subdivisions > 0)
    Subdivision_method_3::Loop_subdivision(sphere, parameters::number_of_iterations(int(subdivisions)));
  typedef typename Surface_mesh<Point_3>::Vertex_index Vertex_index;
  auto score = sphere.template add_property_map<Vertex_index, double>("v:score", 0.).first;
  for(auto v : vertices(sphere)) {
    const Point_3& p = sphere.point(v);
    const internal::Vec3 u = internal::unit({double(p.x()), double(p.y()), double(p.z())}, "viewpoint_score_sphere");
    sphere.point(v) = Point_3(u[0], u[1], u[2]);
    score[v] = planes.score(u);
  }
  return sphere;
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H
