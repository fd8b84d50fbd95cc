# cmake -DDOXYGEN=<exe> -DDOXYFILE=<file> -DWARNINGS=<log> -DHTML_DIR=<html> -P check_doxygen_warnings.cmake
# Runs doxygen and fails if it wrote anything to its WARN_LOGFILE or to stderr; then shortens the
# navigation entries of the HTML it wrote, as the target doc_Symmetry_transform does.
file(REMOVE ${WARNINGS})
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} RESULT_VARIABLE rc ERROR_VARIABLE err)
set(log "")
if(EXISTS ${WARNINGS})
  file(READ ${WARNINGS} log)
endif()
string(STRIP "${log}${err}" problems)
if(NOT rc EQUAL 0 OR NOT problems STREQUAL "")
  string(REGEX MATCHALL "warning:" found "${problems}")
  list(LENGTH found count)
  message("${problems}\n")  # as doxygen wrote it (FATAL_ERROR would re-wrap the lines)
  message(FATAL_ERROR "doxygen: exit code ${rc}, ${count} warning(s) (log: ${WARNINGS})")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/shorten_navigation_entries.cmake)
message(STATUS "doxygen: no warnings")
