cmake_minimum_required(VERSION 3.25)
# A lab in quick mode, then its chart drawn from what it wrote: proves both
# still work. Timings are printed, never judged.
# -DLAB= -DOUT= -DPYTHON= -DPLOT= -DCSV= -DNAME= -DARGS=a|b|c
# Without -DLAB, the chart is drawn from the CSV another test's run of the
# same lab wrote into OUT (rasterlab_chart's REUSE).
string(REPLACE "|" ";" args "${ARGS}")
if(DEFINED LAB)
  execute_process(COMMAND "${LAB}" --quick --out "${OUT}" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${LAB} --quick failed (${result})")
  endif()
elseif(NOT EXISTS "${OUT}/${CSV}")
  message(FATAL_ERROR "${OUT}/${CSV} is missing: its lab's quick run did not write it")
endif()
execute_process(COMMAND "${PYTHON}" "${PLOT}" "${OUT}/${CSV}" ${args} --svg "${OUT}/${NAME}.svg"
                        --table "${OUT}/${NAME}.md"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "plotting ${OUT}/${CSV} failed (${result})")
endif()
