cmake_minimum_required(VERSION 3.25)
# Golden-image test: run a lesson with fixed arguments, then compare its image
# with the reference through imgdiff. On a mismatch imgdiff prints the figures
# and writes <output>.diff.png beside the output.
#
# -DPROGRAM= -DARGS=a|b|c -DOUTPUT= -DREFERENCE= -DIMGDIFF= -DTOLERANCE=x|y
# -DUPDATE=1 copies the output over the reference instead (commit it with the
# reason the picture changed).
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" tolerance "${TOLERANCE}")
get_filename_component(output_dir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${output_dir}")
file(REMOVE "${OUTPUT}")

execute_process(COMMAND "${PROGRAM}" -o "${OUTPUT}" ${args} RESULT_VARIABLE program_result)
if(NOT program_result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${program_result})")
endif()

if(UPDATE)
  file(COPY_FILE "${OUTPUT}" "${REFERENCE}")
  message(STATUS "updated ${REFERENCE}")
  return()
endif()

if(NOT EXISTS "${REFERENCE}")
  message(FATAL_ERROR "no reference image ${REFERENCE}")
endif()
execute_process(COMMAND "${IMGDIFF}" "${REFERENCE}" "${OUTPUT}" ${tolerance} --diff "${OUTPUT}.diff.png"
                RESULT_VARIABLE diff_result)
if(NOT diff_result EQUAL 0)
  message(FATAL_ERROR "${OUTPUT} differs from ${REFERENCE} beyond the tolerance")
endif()
