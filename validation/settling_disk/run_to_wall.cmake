# Runs `ibms run SCENE --set ... -o OUTPUT --quiet` for a settling case. Without a contact model
# (the settling scenes set none: contact.stiffness = 0) the disk keeps sinking until its rim reaches the bottom wall;
# the run then stops with exit code 3 and "left the box", after writing everything up to that
# point. That end is accepted here (the check verifies touchdown was reached); any other failure
# fails the test.  usage: cmake -DIBMS=... -DSCENE=... -DOUTPUT=... -DSETS="k=v;k=v" -P run_to_wall.cmake
set(args run ${SCENE} -o ${OUTPUT} --quiet)
foreach(s ${SETS})
  list(APPEND args --set ${s})
endforeach()
execute_process(COMMAND ${IBMS} ${args} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(STATUS "run finished at end_time")
elseif(rc EQUAL 3 AND err MATCHES "left the box")
  message(STATUS "run stopped at the wall (no contact model): ${err}")
else()
  message(FATAL_ERROR "ibms run failed (exit ${rc}): ${err}")
endif()
