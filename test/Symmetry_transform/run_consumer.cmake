# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The package as a user gets it (cmake -DBUILD=<build folder> -DWORK=<folder>
# -DCGAL_CONFIG=<CGAL_DIR> -DSOURCE=<consumer/> -P <this>): installed into WORK/prefix, then
# consumer/ configured, built and run with CGAL found outside /usr/include, where CMake puts its
# folder on the command line: a copy of Debian's CGAL (headers and CMake files) when CGAL is
# installed in /usr, the CGAL given otherwise.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# step(<what> <command>...): runs the command, fails the test with its output if it fails.
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

step("install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)

get_filename_component(cgal_config ${CGAL_CONFIG} ABSOLUTE)
if(cgal_config MATCHES "^/usr/")
  # Debian's config finds the headers in the nearest parent folder that holds include/CGAL/config.h.
  file(COPY /usr/include/CGAL DESTINATION ${WORK}/cgal/include)
  file(COPY ${cgal_config}/ DESTINATION ${WORK}/cgal/lib/cmake/CGAL)
  set(cgal_config ${WORK}/cgal/lib/cmake/CGAL)
endif()

step("configure" ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/build -DCMAKE_BUILD_TYPE=Release
     -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCGAL_DIR=${cgal_config})
# With Makefiles, the compiler's flags show where the copy of CGAL stands on the command line.
set(flags_file ${WORK}/build/CMakeFiles/consumer.dir/flags.make)
if(cgal_config MATCHES "^${WORK}" AND EXISTS ${flags_file})
  file(READ ${flags_file} flags)
  string(FIND "${flags}" "${WORK}/cgal/include" outside)
  if(outside EQUAL -1)
    message(FATAL_ERROR "the copy of CGAL is not on the command line:\n${flags}")
  endif()
endif()
step("build" ${CMAKE_COMMAND} --build ${WORK}/build)
step("run" ${WORK}/build/consumer)
step("run with the precompiled core" ${WORK}/build/consumer_precompiled)
