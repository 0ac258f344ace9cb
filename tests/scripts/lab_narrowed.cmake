cmake_minimum_required(VERSION 3.25)
# A lab run narrowed by --benchmark_filter to one section writes that
# section's table and no other; a filter that leaves no section whole is
# refused; the tables it leaves out, left by an earlier run, are removed so
# that they cannot pass for this run's. -DLAB= -DOUT= -DFILTER= -DWRITES= -DSKIPS=a|b
file(REMOVE_RECURSE "${OUT}")
string(REPLACE "|" ";" skips "${SKIPS}")
foreach(table IN LISTS skips)
  file(WRITE "${OUT}/${table}" "an earlier run's table\n")
endforeach()
execute_process(COMMAND "${LAB}" --quick --out "${OUT}" "--benchmark_filter=${FILTER}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${LAB} --benchmark_filter=${FILTER} failed (${result})")
endif()
if(NOT EXISTS "${OUT}/${WRITES}")
  message(FATAL_ERROR "the narrowed run did not write ${WRITES}")
endif()
foreach(table IN LISTS skips)
  if(EXISTS "${OUT}/${table}")
    message(FATAL_ERROR "the narrowed run wrote ${table}, whose cells it did not all run (or left an earlier run's)")
  endif()
endforeach()
execute_process(COMMAND "${LAB}" --quick --out "${OUT}/none" "--benchmark_filter=^no such cell$"
                RESULT_VARIABLE result ERROR_VARIABLE error)
if(result EQUAL 0 OR NOT error MATCHES "left no section of the lab whole")
  message(FATAL_ERROR "a filter matching no cell was not refused (${result}): ${error}")
endif()
