# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the target TARGET of the build tree BUILD_DIR (configuration CONFIG), prints what the build
# printed, and then "build succeeded" or "build failed": the tests does_not_compile_* (CMakeLists.txt
# beside this file) judge that text by regular expressions, which ignore the exit status.
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target "${TARGET}" --config "${CONFIG}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(status EQUAL 0)
  message("build succeeded")
else()
  message("build failed")
endif()
