# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The test of the batch command (cmake -DBATCH=<program> -DDATA=<data dir> -DWORK=<folder> -P <this>):
# a list of three files, a mesh, a point set with normals and a file that is no mesh, run with
# two jobs and SHREC output: three records, two with planes and one error with its reason, and a
# SHREC file per input; run again: nothing to do, the output unchanged.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/not_a_mesh.off "this is not an OFF file\n")
file(WRITE ${WORK}/list.txt "# a mesh, a point set, a bad file\n${DATA}/meshes/bull.off\n${DATA}/points_3/oni.pwn\n${WORK}/not_a_mesh.off\n")
set(run ${BATCH} --list ${WORK}/list.txt --output ${WORK}/records.jsonl --jobs 2 --resolution 32 --samples 100000
        --shrec ${WORK}/shrec)

execute_process(COMMAND ${run} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the first run failed")
endif()
file(STRINGS ${WORK}/records.jsonl records)
list(LENGTH records count)
string(REGEX MATCHALL "\"status\":\"ok\"" ok "${records}")
string(REGEX MATCHALL "\"status\":\"error\",\"reason\":\"[^\"]+\"" errors "${records}")
list(LENGTH ok ok_count)
list(LENGTH errors error_count)
if(NOT count EQUAL 3 OR NOT ok_count EQUAL 2 OR NOT error_count EQUAL 1)
  message(FATAL_ERROR "expected 3 records, 2 ok and 1 error with a reason, got:\n${records}")
endif()
foreach(stem bull oni not_a_mesh)
  if(NOT EXISTS ${WORK}/shrec/${stem}-res.txt)
    message(FATAL_ERROR "no SHREC file ${WORK}/shrec/${stem}-res.txt")
  endif()
endforeach()

file(READ ${WORK}/records.jsonl before)
execute_process(COMMAND ${run} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
file(READ ${WORK}/records.jsonl after)
if(NOT status EQUAL 0 OR NOT out MATCHES "3 files, 3 already in .*, 0 to do" OR NOT before STREQUAL after)
  message(FATAL_ERROR "the second run did something")
endif()
