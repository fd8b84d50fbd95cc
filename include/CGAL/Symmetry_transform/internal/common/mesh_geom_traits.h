// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_MESH_GEOM_TRAITS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_MESH_GEOM_TRAITS_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>

namespace CGAL::Symmetry_transform::internal {

// The traits of a mesh, as GetGeomTraits, but with no `type` for a Voxel_grid: the transforms
// are overloaded on meshes and grids, and this keeps the mesh overloads out of the way of
// grids (SFINAE) instead of failing deep inside GetGeomTraits.
template <typename TriangleMesh, typename NamedParameters>
struct Mesh_geom_traits
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type type;
};

template <typename GT, typename NamedParameters>
struct Mesh_geom_traits<Voxel_grid<GT>, NamedParameters>
{};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_MESH_GEOM_TRAITS_H
