# Runs a case's scene generator into WORK_DIR and fails unless every file in FILES is identical
# to the committed one in CASE_DIR (the committed scenes are exactly what the script writes).
# usage: cmake -DPYTHON=... -DSCRIPT=... [-DSCRIPT_ARGS=...] -DCASE_DIR=... -DWORK_DIR=... -DFILES="a;b" -P compare_generated.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${SCRIPT_ARGS} ${WORK_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} failed (${rc}): ${err}")
endif()
foreach(f ${FILES})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/${f} ${CASE_DIR}/${f} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${CASE_DIR}/${f} differs from what ${SCRIPT} writes: regenerate it")
  endif()
  message(STATUS "${f}: identical to the generator's output")
endforeach()
