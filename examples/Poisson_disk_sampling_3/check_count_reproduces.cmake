# SPDX-License-Identifier: GPL-3.0-or-later
# Runs PROGRAM with the arguments ARGS (separated by '|', "--count N" among them) writing OUT_A, reads
# the minimum_distance and random_seed it reports, runs it again with the same arguments but
# "--minimum-distance" and "--seed" set to these in place of "--count N" and any "--seed", writing
# OUT_B, and prints "the same samples" where the two files are equal: the reproducibility the reports
# promise (a --count search found a distance, and the seed of the run it kept).
string(REPLACE "|" ";" arguments "${ARGS}")
file(REMOVE "${OUT_A}" "${OUT_B}")
execute_process(COMMAND "${PROGRAM}" ${arguments} -o "${OUT_A}" RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the --count run failed (exit status ${status})")
endif()
string(REGEX MATCH "minimum_distance: ([^\n]+)" _ "${out}")
set(distance "${CMAKE_MATCH_1}")
string(REGEX MATCH "random_seed: ([0-9]+)" _ "${out}")
set(seed "${CMAKE_MATCH_1}")
if(distance STREQUAL "" OR seed STREQUAL "")
  message(FATAL_ERROR "the report gives no minimum_distance or random_seed")
endif()
# the arguments without "--count N" and "--seed S"
set(again "")
set(skip FALSE)
foreach(a IN LISTS arguments)
  if(skip)
    set(skip FALSE)
  elseif(a STREQUAL "--count" OR a STREQUAL "--seed")
    set(skip TRUE)
  else()
    list(APPEND again "${a}")
  endif()
endforeach()
execute_process(COMMAND "${PROGRAM}" ${again} --minimum-distance "${distance}" --seed "${seed}" -o "${OUT_B}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the --minimum-distance run failed (exit status ${status})")
endif()
file(SHA256 "${OUT_A}" a)
file(SHA256 "${OUT_B}" b)
if(a STREQUAL b)
  message("the same samples")
else()
  message("different samples")
endif()
