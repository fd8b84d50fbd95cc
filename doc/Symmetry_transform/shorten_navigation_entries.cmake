# cmake -DHTML_DIR=<doxygen html folder> -P shorten_navigation_entries.cmake
# Doxygen 1.9 names the functions of a group in the navigation tree by their qualified name, which
# the narrow tree cuts to "CGAL::Symmetry_transform..." for every one of them. The scope is dropped,
# as HIDE_SCOPE_NAMES already does for the classes.
file(GLOB trees ${HTML_DIR}/group__*.js)
foreach(tree IN LISTS trees)
  file(READ ${tree} entries)
  string(REPLACE "[ \"CGAL::Symmetry_transform::" "[ \"" shortened "${entries}")
  if(NOT shortened STREQUAL entries)
    file(WRITE ${tree} "${shortened}")
  endif()
endforeach()
