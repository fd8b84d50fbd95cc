# The target CGAL::Symmetry_transform_precompiled: CGAL::Symmetry_transform with the package's code
# that depends on no user type compiled once per build tree, in a static library built in the
# user's project, instead of in every translation unit: the detection's heavy templates for
# CGAL's Epick kernel and the package's double kernel (internal/detection/precompiled_core.h),
# and the double-only functions and member functions, which its users see declared only
# (internal/common/core_definitions.h). All the files of one program must link the same target.
# It gets the flags of its own directory and of CGAL::Symmetry_transform only: a program built
# with definitions that change CGAL's or Eigen's code (CGAL_LINKED_WITH_TBB, -ffast-math, another
# -std, ...) must use the header-only target. Used by the package's build and its package config.
function(cgal_symmetry_transform_add_precompiled_core source)
  if(TARGET CGAL_Symmetry_transform_precompiled)
    return()
  endif()
  add_library(CGAL_Symmetry_transform_precompiled STATIC EXCLUDE_FROM_ALL "${source}")
  target_link_libraries(CGAL_Symmetry_transform_precompiled PUBLIC CGAL::Symmetry_transform)
  target_compile_definitions(CGAL_Symmetry_transform_precompiled PUBLIC CGAL_SYMMETRY_TRANSFORM_PRECOMPILED_CORE)
  # So that a shared library or a Python module can link it too.
  set_target_properties(CGAL_Symmetry_transform_precompiled PROPERTIES POSITION_INDEPENDENT_CODE ON)
  add_library(CGAL::Symmetry_transform_precompiled ALIAS CGAL_Symmetry_transform_precompiled)
endfunction()
