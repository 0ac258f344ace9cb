cmake_minimum_required(VERSION 3.25)
# Decodes one file several times, each with malloc filling new memory with
# another byte (glibc's MALLOC_PERTURB_), and fails unless every run gave the
# same answer: the same picture, or the same refusal. A decoder that reads
# memory it never wrote gives different pictures.
# -DPROGRAM=<imgconv> -DINPUT=<file> -DOUT=<folder>
file(MAKE_DIRECTORY "${OUT}")
get_filename_component(stem "${INPUT}" NAME_WE)
set(first "")
foreach(perturb 0 1 42 85 170 255)
  set(out "${OUT}/${stem}_${perturb}.tga")
  file(REMOVE "${out}")
  if(perturb EQUAL 0)
    set(env_args --unset=MALLOC_PERTURB_)
  else()
    set(env_args MALLOC_PERTURB_=${perturb})
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env_args} "${PROGRAM}" "${INPUT}" "${out}"
                  RESULT_VARIABLE result ERROR_VARIABLE stderr OUTPUT_QUIET)
  if(result EQUAL 0)
    file(SHA256 "${out}" answer)
    set(answer "picture ${answer}")
  else()
    string(REPLACE "${out}" "" stderr "${stderr}")
    set(answer "refusal (${result}): ${stderr}")
  endif()
  message(STATUS "MALLOC_PERTURB_=${perturb}: ${answer}")
  if(first STREQUAL "")
    set(first "${answer}")
  elseif(NOT answer STREQUAL first)
    message(FATAL_ERROR "${INPUT} decoded differently from one run to the next")
  endif()
endforeach()
