# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs one test (tests/CMakeLists.txt): viscoslide on NAME.prm, unless the
# test is RUNS_ITSELF (its check makes every run), then CHECK.check (CHECK
# defaults to NAME) with the arguments WORK_DIR VISCOSLIDE MPIEXEC
# SOURCE_DIR, then numdiff of the check's summary against the stored
# NAME.output.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

if(NOT RUNS_ITSELF)
  if(NOT EXISTS ${SOURCE_DIR}/${NAME}.prm)
    message(FATAL_ERROR "${NAME}: no ${NAME}.prm to run (a test whose check "
      "makes every run is declared RUNS_ITSELF)")
  endif()
  if(NPROC GREATER 1)
    set(_cmd ${MPIEXEC} -np ${NPROC} ${VISCOSLIDE})
  else()
    set(_cmd ${VISCOSLIDE})
  endif()
  execute_process(COMMAND ${_cmd} ${SOURCE_DIR}/${NAME}.prm
    WORKING_DIRECTORY ${WORK_DIR}
    OUTPUT_FILE ${WORK_DIR}/stdout ERROR_FILE ${WORK_DIR}/stderr
    RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    file(READ ${WORK_DIR}/stderr _err)
    message(FATAL_ERROR "${NAME}: viscoslide failed (${_rc}):\n${_err}")
  endif()
endif()

execute_process(COMMAND ${PYTHON} ${SOURCE_DIR}/${CHECK}.check
    ${WORK_DIR} ${VISCOSLIDE} ${MPIEXEC} ${SOURCE_DIR}
  WORKING_DIRECTORY ${WORK_DIR}
  OUTPUT_FILE ${WORK_DIR}/summary
  ERROR_VARIABLE _err
  RESULT_VARIABLE _rc)
file(READ ${WORK_DIR}/summary _summary)
message("${_summary}${_err}")
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: physical check failed:\n${_err}")
endif()

separate_arguments(_tol UNIX_COMMAND "${NUMDIFF_TOLERANCE}")
execute_process(COMMAND ${NUMDIFF} -q ${_tol} -s " \t\n=,:;<>[](){}^"
    ${SOURCE_DIR}/${NAME}.output ${WORK_DIR}/summary
  OUTPUT_VARIABLE _diff RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  execute_process(COMMAND ${NUMDIFF} ${_tol} -s " \t\n=,:;<>[](){}^"
      ${SOURCE_DIR}/${NAME}.output ${WORK_DIR}/summary
    OUTPUT_VARIABLE _diff)
  message(FATAL_ERROR "${NAME}: summary differs from the stored "
    "${NAME}.output:\n${_diff}")
endif()
