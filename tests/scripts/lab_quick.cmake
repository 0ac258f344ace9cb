cmake_minimum_required(VERSION 3.25)
# A lab in quick mode, then its chart drawn from what it wrote: proves both
# still work. Timings are printed, never judged.
# -DLAB= -DOUT= -DPYTHON= -DPLOT= -DCSV= -DNAME= -DARGS=a|b|c
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${LAB}" --quick --out "${OUT}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${LAB} --quick failed (${result})")
endif()
execute_process(COMMAND "${PYTHON}" "${PLOT}" "${OUT}/${CSV}" ${args} --svg "${OUT}/${NAME}.svg"
                        --table "${OUT}/${NAME}.md"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "plotting ${OUT}/${CSV} failed (${result})")
endif()
