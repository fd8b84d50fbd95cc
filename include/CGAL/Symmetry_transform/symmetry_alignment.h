// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H

#include <CGAL/Symmetry_transform/Symmetry_frame.h>
#include <CGAL/Symmetry_transform/internal/alignment/frame_rules.h>
#include <CGAL/Symmetry_transform/internal/alignment/joint_frame.h>
#include <CGAL/Symmetry_transform/internal/alignment/mass_distribution.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>

#include <array>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the symmetry frame of a triangle mesh (thesis, section 4.1): the centre of symmetry and
 * the axes of the principal symmetries that `detect_principal_symmetries(tm, np)` finds. The first
 * axis is the normal of the strongest plane, the second that of the strongest plane nearly
 * perpendicular to it, the third their cross product, each turned towards more mass; a plane missing
 * among the principal ones is searched in the transform (see \ref SymmetryTransformAlignment).
 * With `partial_data(true)`, the rule measured best on partial range scans is used instead.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed
 *           below, and those of `detect_principal_symmetries()`, to which they are passed on
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPartialData
 *   \cgalParamGeomTraits
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamCallback{the PCA frame\, as `pca_frame()`}
 * \cgalNamedParamsEnd
 *
 * \returns the symmetry frame: unit, right-handed axes and the centre of symmetry.
 * \throws std::invalid_argument on the bad inputs of `detect_principal_symmetries()` (empty mesh,
 *         non-triangle face, all faces degenerate, NaN or infinite coordinate, ...).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
symmetry_frame(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::symmetry_frame_under_progress(
      np, [&] { return internal::detection_of_mesh(tm, np); }, [&] { return internal::mass_of_mesh(tm, np); }));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the symmetry frame of a point set, by the rules of `symmetry_frame()`, from the
 * principal symmetries that `detect_principal_symmetries_of_points(points, np)` finds. The mass is
 * that of the points, each of weight 1: the centre of mass is their mean, and the means that orient
 * the axes are means over the points.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters": those listed below,
 *           and those of `detect_principal_symmetries_of_points()`, which are passed on to it
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPartialData
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{passed on to `detect_principal_symmetries_of_points()`: with normals\, ISP fits point to plane}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the PCA frame\, as `pca_frame_of_points()`}
 * \cgalNamedParamsEnd
 *
 * \returns the symmetry frame: unit, right-handed axes and the centre of symmetry.
 * \throws std::invalid_argument on the bad inputs of `detect_principal_symmetries_of_points()`
 *         (empty range, a single point, NaN or infinite coordinate, ...).
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_points<PointRange, NamedParameters>>
symmetry_frame_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::symmetry_frame_under_progress(
      np, [&] { return internal::detection_of_points(points, np); },
      [&] { return internal::mass_of_points(points, np); }));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the classical canonical frame of a triangle mesh, the baseline of `symmetry_frame()`:
 * the area-weighted centre of mass of its surface and its principal axes of inertia, the
 * eigenvectors of the covariance \f$ \int (x - c)(x - c)^T \, dA \f$, largest variance first,
 * oriented by the rules of `symmetry_frame()` about the centre of mass. Where two variances are
 * equal (a shape of revolution, a cube), the corresponding axes are arbitrary.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the frame of the centre of mass and the principal axes.
 * \throws std::invalid_argument on an empty mesh, a non-triangle face, a mesh whose faces are all
 *         degenerate, or a NaN or infinite coordinate.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
pca_frame(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::pca_frame(internal::mass_of_mesh(tm, np)));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the classical canonical frame of a point set, as `pca_frame()` does for a mesh: the
 * mean of the points and the eigenvectors of their covariance matrix, largest variance first,
 * oriented by the rules of `symmetry_frame()` (with means over the points).
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters", those below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamGeomTraits
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{not read: the mass is that of the points}
 * \cgalNamedParamsEnd
 *
 * \returns the frame of the centre of mass and the principal axes.
 * \throws std::invalid_argument on an empty range, a single point (repeated or not), or a NaN or
 *         infinite coordinate.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_points<PointRange, NamedParameters>>
pca_frame_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::pca_frame(internal::mass_of_points(points, np)));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the symmetry frame of a triangle soup, by the rules of `symmetry_frame()`, from the
 * principal symmetries that `detect_principal_symmetries_of_triangle_soup(points, triangles, np)`
 * finds. The mass is the area of the soup's triangles, as a mesh's is the area of its faces: a
 * triangle given twice (a double-sided face) weighs twice, which can move the centre of mass but
 * not the centre of symmetry, the intersection of the planes.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters": those listed below,
 *           and those of `detect_principal_symmetries_of_triangle_soup()`, which are passed on to it
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPartialData
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the PCA frame\, as `pca_frame_of_triangle_soup()`}
 * \cgalNamedParamsEnd
 *
 * \returns the symmetry frame: unit, right-handed axes and the centre of symmetry.
 * \throws std::invalid_argument on the bad inputs of `detect_principal_symmetries_of_triangle_soup()`
 *         (no triangle, an index out of range, all triangles degenerate, NaN or infinite coordinate, ...).
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_points<PointRange, NamedParameters>>
symmetry_frame_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                                const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::symmetry_frame_under_progress(
      np, [&] { return internal::detection_of_triangle_soup(points, triangles, np); },
      [&] { return internal::Mass_distribution(internal::triangles_of_soup(points, triangles, np)); }));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * Computes the classical canonical frame of a triangle soup, as `pca_frame()` does for a mesh,
 * with the area of the soup's triangles as mass.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among those listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the frame of the centre of mass and the principal axes.
 * \throws std::invalid_argument on no triangle, an index out of range, all triangles degenerate,
 *         or a NaN or infinite coordinate.
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_frame<Geom_traits_of_points<PointRange, NamedParameters>>
pca_frame_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                           const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::to_symmetry_frame<GT>(internal::pca_frame(internal::Mass_distribution(
    internal::triangles_of_soup(points, triangles, np))));
}

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * The rigid motion that takes a frame to the canonical one: its centre to the origin and its
 * axes to the coordinate axes, \f$ x \mapsto (a_0 \cdot (x - c),\ a_1 \cdot (x - c),\ a_2 \cdot (x - c)) \f$.
 * Apply it to a mesh with `CGAL::Polygon_mesh_processing::transform()`.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \param frame a frame, from `symmetry_frame()` or `pca_frame()` (unit, orthogonal, right-handed axes)
 * \returns the transformation, a rotation (determinant 1) followed by a translation.
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

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_ALIGNMENT_H
