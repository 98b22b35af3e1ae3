# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the program PROGRAM with the arguments ARGS (separated by '|'), prints what it wrote, and then,
# unless its exit status is STATUS, a line "exit status ..., expected ..." that fails the test: the
# command-line tests (CMakeLists.txt beside this file) judge the text by regular expressions, which
# ignore the exit status of the command itself.
string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${arguments} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status STREQUAL "${STATUS}")
  message("exit status ${status}, expected ${STATUS}")
endif()
