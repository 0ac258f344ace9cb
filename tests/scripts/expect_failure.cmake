cmake_minimum_required(VERSION 3.25)
# Runs a command that must fail: non-zero exit, a message matching
# EXPECT_REGEX on stderr, and (if FORBIDDEN_FILE is given) no such file after.
# -DCOMMAND=a|b|c -DEXPECT_REGEX= [-DFORBIDDEN_FILE=]
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE result ERROR_VARIABLE stderr OUTPUT_VARIABLE stdout)
message(STATUS "exit ${result}; stderr: ${stderr}")
if(result EQUAL 0)
  message(FATAL_ERROR "expected a failure, got exit code 0")
endif()
if(NOT stderr MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_REGEX}'")
endif()
if(FORBIDDEN_FILE AND EXISTS "${FORBIDDEN_FILE}")
  message(FATAL_ERROR "${FORBIDDEN_FILE} was written although the program failed")
endif()
