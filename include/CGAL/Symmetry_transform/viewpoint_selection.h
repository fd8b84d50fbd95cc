// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H
#define CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H

#include <CGAL/Symmetry_transform/Viewpoint.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/viewpoint/score_sphere.h>
#include <CGAL/Symmetry_transform/internal/viewpoint/view_search.h>
#include <CGAL/Symmetry_transform/internal/viewpoint/weighted_normals.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h> // the ranges it takes: detect_principal_symmetries()

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <stdexcept>

namespace CGAL::Symmetry_transform {

/// \ingroup PkgSymmetryTransformViewpointRef
/// The geometric traits class `GT` of a range of `Principal_symmetry<GT>`, such as the result of
/// `detect_principal_symmetries()`: the viewpoints of those symmetries are given in it.
template <typename SymmetryRange>
#ifdef DOXYGEN_RUNNING
using Geom_traits_of_symmetries = unspecified_type;
#else
using Geom_traits_of_symmetries = typename internal::Kernel_of_symmetry_range<SymmetryRange>::type;
#endif

/*!
 * \ingroup PkgSymmetryTransformViewpointRef
 * The viewpoint score of a view direction (thesis, section 4.3.2):
 * \f[ S(v) = \sum_{u \in W} |v \cdot u| \, M(u) \f]
 * over the principal planes \f$ u \in W \f$ (unit normals) of symmetry measure \f$ M(u) \f$: the
 * symmetry that the view \f$ v \f$ does not waste on mirror halves seen side by side. Good views
 * have a high \f$ S \f$; \f$ S(v) = S(-v) \f$ and \f$ 0 \le S(v) \le \sum_u M(u) \f$ (see
 * \ref SymmetryTransformViewpoints).
 *
 * \tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
 * \tparam Vector_3 `GT::Vector_3`
 * \param symmetries the principal symmetries
 * \param v the view direction, of any nonzero length (normalised here)
 * \returns \f$ S(v) \f$
 * \throws std::invalid_argument if `v` is zero or not finite, a plane has a zero normal, or a
 *         symmetry measure is negative or not finite.
*/
template <typename SymmetryRange, typename Vector_3>
double viewpoint_score(const SymmetryRange& symmetries, const Vector_3& v)
{
  const internal::Weighted_normals planes(symmetries);
  return planes.score(internal::unit(internal::to_vec3(v), "viewpoint_score: the view direction is zero or not finite"));
}

/*!
 * \ingroup PkgSymmetryTransformViewpointRef
 * Writes the best views of a shape of principal symmetries `symmetries`, best first: the local
 * maxima of the viewpoint score \f$ S \f$ of `viewpoint_score()` over a Fibonacci sphere of
 * `number_of_directions` directions, each refined to the exact maximum, those closer than 0.5 degree
 * merged (\ref SymmetryTransformViewpoints). For three orthogonal planes of measures
 * \f$ M_1, M_2, M_3 \f$ the best view is \f$ (M_1, M_2, M_3) \f$ in the frame of their normals.
 * With no plane of positive measure, nothing is written.
 *
 * \tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
 * \tparam OutputIterator an output iterator accepting `Viewpoint<GT>`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 * \param symmetries the principal symmetries
 * \param out where the views go, best (highest \f$ S \f$) first; the caller keeps as many as it wants
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_directions}
 *     \cgalParamDescription{the number of directions of the Fibonacci sphere searched (on the whole
 *       sphere, so about half as many distinct views); from 12 to \f$ 10^7 \f$}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{4000}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns `out` past the views written
 * \throws std::invalid_argument if a plane has a zero normal, a symmetry measure is negative or not
 * finite, or `number_of_directions` lies out of [12, 10^7].
*/
template <typename SymmetryRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator best_viewpoints(const SymmetryRange& symmetries, OutputIterator out,
                               const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_symmetries<SymmetryRange> GT;
  internal::check_named_parameters(np);
  const std::size_t directions = internal::read_count(np, internal_np::st_number_of_directions,
                                                      internal::defaults::viewpoint_directions,
                                                      internal::parameter_ranges::number_of_directions);
  const internal::Weighted_normals planes(symmetries);
  if(planes.normals.empty()) return out;
  for(const internal::Scored_view& view : internal::distinct_views(internal::local_maxima(planes, directions)))
    *out++ = internal::make_viewpoint<GT>(view.second, view.first);
  return out;
}

/*!
 * \ingroup PkgSymmetryTransformViewpointRef
 * The worst view of a shape of principal symmetries `symmetries`: the global minimum of the viewpoint
 * score \f$ S \f$ of `viewpoint_score()`, where the image is the most redundant, found exactly among
 * the vertices of the arrangement of the planes' great circles (\ref SymmetryTransformViewpoints).
 * For three orthogonal planes, it is the normal of the weakest plane. With no plane of positive
 * measure, every view scores 0 and the direction \f$ (0,0,1) \f$ is returned.
 *
 * \tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
 * \param symmetries the principal symmetries
 * \returns a `Viewpoint<GT>`
 * \throws std::invalid_argument if a plane has a zero normal or a symmetry measure is negative or not finite.
*/
template <typename SymmetryRange>
Viewpoint<Geom_traits_of_symmetries<SymmetryRange>>
worst_viewpoint(const SymmetryRange& symmetries)
{
  typedef Geom_traits_of_symmetries<SymmetryRange> GT;
  const internal::Scored_view worst = internal::worst_view(internal::Weighted_normals(symmetries));
  return internal::make_viewpoint<GT>(worst.second, worst.first);
}

/*!
 * \ingroup PkgSymmetryTransformViewpointRef
 * The viewpoint score as a spherical function, ready to be exported (e.g. as a PLY file with
 * colours, see the example `best_viewpoint.cpp`): a unit icosphere (an icosahedron Loop-subdivided
 * `subdivisions` times, its vertices projected onto the sphere: \f$ 10 \cdot 4^s + 2 \f$ vertices)
 * whose vertex property map named `"v:score"` holds \f$ S \f$ of the vertex's direction, in
 * \f$ [0, \sum_u M(u)] \f$.
 *
 * \tparam SymmetryRange a range of `Principal_symmetry<GT>`, e.g. the result of `detect_principal_symmetries()`
 * \param symmetries the principal symmetries
 * \param subdivisions the number of subdivisions \f$ s \f$ of the icosahedron, at most 8
 * \returns a `Surface_mesh<GT::Point_3>` with a vertex property map `"v:score"` of type `double`
 * \throws std::invalid_argument if `subdivisions` exceeds 8, a plane has a zero normal, or a symmetry
 * measure is negative or not finite.
*/
template <typename SymmetryRange>
Surface_mesh<typename Geom_traits_of_symmetries<SymmetryRange>::Point_3>
viewpoint_score_sphere(const SymmetryRange& symmetries, unsigned int subdivisions = 4)
{
  typedef Geom_traits_of_symmetries<SymmetryRange> GT;
  return internal::score_sphere<GT>(internal::Weighted_normals(symmetries), subdivisions);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_SELECTION_H
