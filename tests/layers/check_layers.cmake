# cmake -DBUILD_DIR=... -DUPWARD="probe=header;..." -DDOWNWARD=probe -P check_layers.cmake
# Builds each probe of tests/layers/CMakeLists.txt: an upward one must fail because its
# header is not found (not for another reason); the downward one must compile.
foreach(entry ${UPWARD})
  string(REPLACE "=" ";" parts "${entry}")
  list(GET parts 0 probe)
  list(GET parts 1 header)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${probe}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${probe}: an include of ${header} compiled; the layer below sees it")
  endif()
  # GCC: "<header>: No such file or directory"; clang: "'<header>' file not found".
  string(FIND "${out}${err}" "${header}: No such file" gcc_found)
  string(FIND "${out}${err}" "'${header}' file not found" clang_found)
  if(gcc_found EQUAL -1 AND clang_found EQUAL -1)
    message(FATAL_ERROR "${probe} failed, but not on the missing ${header}:\n${out}${err}")
  endif()
  message(STATUS "${probe}: ${header} not found, as it must be")
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${DOWNWARD}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${DOWNWARD}: the top layer cannot include the layers below it:\n${out}${err}")
endif()
message(STATUS "${DOWNWARD}: compiles")
