// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_GEOM_TRAITS_H
#define CGAL_SYMMETRY_TRANSFORM_GEOM_TRAITS_H

#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>

namespace CGAL::Symmetry_transform {

/// \ingroup PkgSymmetryTransformRef
/// The geometric traits class of a triangle mesh called with named parameters: the type of the
/// named parameter `geom_traits` if given, otherwise the kernel of the point type of the mesh's
/// vertex point map. The functions that take a mesh return their results in it. Not defined for
/// a `Voxel_grid`, so that the overloads on meshes and on grids do not compete.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
using Geom_traits_of_mesh = unspecified_type;
#else
using Geom_traits_of_mesh = typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type;
#endif

/// \ingroup PkgSymmetryTransformRef
/// The geometric traits class of a range of points called with named parameters: the type of the
/// named parameter `geom_traits` if given, otherwise the kernel of the value type of the point
/// map. The functions that take points return their results in it.
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
using Geom_traits_of_points = unspecified_type;
#else
using Geom_traits_of_points = typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits;
#endif

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_GEOM_TRAITS_H
