# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The test of an example's command line (cmake -DPROGRAM=<program> -DWORK=<folder> [-DBATCH=ON]
# -P <this>), with no detection run: --help and -h print the usage on stdout and exit with 0; an
# unknown option, or a known one without its value, is an error that names it, on stderr; a
# missing file's error names the file, and only with no file given (the default of CGAL's sample
# data missing) does it speak of CGAL_DATA_DIR. The batch command creates no output on an
# unknown option and takes -h for help, a file named -h only after --.
get_filename_component(name ${PROGRAM} NAME_WE)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/empty)

# run(<arguments>...): runs the program in WORK; sets status, out and err.
macro(run)
  execute_process(COMMAND ${PROGRAM} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

# expect_error(<regex> <arguments>...): the run fails with an error matching <regex> on stderr,
# and creates no file in WORK.
function(expect_error regex)
  run(${ARGN})
  file(GLOB created LIST_DIRECTORIES false ${WORK}/*)
  if(status EQUAL 0 OR NOT err MATCHES "${regex}" OR NOT out STREQUAL "" OR created)
    string(REPLACE ";" " " arguments "${ARGN}")
    message(FATAL_ERROR "${name} ${arguments}: expected an error matching '${regex}' and no output, got status ${status}, "
                        "stdout '${out}', stderr '${err}', files '${created}'")
  endif()
endfunction()

foreach(help --help -h)
  run(${help} --resolution 8)
  if(NOT status EQUAL 0 OR NOT out MATCHES "^usage: ${name} " OR NOT out MATCHES "--resolution N" OR NOT err STREQUAL "")
    message(FATAL_ERROR "${name} ${help}: expected the usage on stdout and status 0, got status ${status}, "
                        "stdout '${out}', stderr '${err}'")
  endif()
endforeach()
expect_error("unknown option '--no-such-option' \\(see ${name} --help\\)" --no-such-option ${WORK}/no_such_mesh.off)
expect_error("unknown option '-x'" -x)
expect_error("--resolution expects a value" ${WORK}/no_such_mesh.off --resolution)
expect_error("--resolution expects an integer >= [0-9]+, not 'abc'" --resolution abc)

if(NOT BATCH)
  expect_error("no such file: '${WORK}/no_such_mesh.off'" ${WORK}/no_such_mesh.off)
  if(err MATCHES "CGAL_DATA_DIR")
    message(FATAL_ERROR "${name}: the error of a missing file given speaks of CGAL_DATA_DIR: '${err}'")
  endif()
  expect_error("no such file: '--help'" -- --help)
  set(ENV{CGAL_DATA_DIR} ${WORK}/empty)
  expect_error("no file given, .*CGAL_DATA_DIR is '${WORK}/empty'")
else()
  # A file named -h after --: a record of it (an error: there is no such file), nothing else.
  run(--output ${WORK}/records.jsonl -- -h)
  file(READ ${WORK}/records.jsonl records)
  if(NOT status EQUAL 0 OR NOT records MATCHES "^{\"file\":\"-h\",\"status\":\"error\",\"reason\":\"no such file\"")
    message(FATAL_ERROR "${name} -- -h: expected a record of the file -h, got status ${status}, records '${records}', "
                        "stderr '${err}'")
  endif()
endif()
