# Runs COMMAND with ARGS (a ;-list) and checks its exit code (EXPECT_CODE), and when given: that
# stdout matches EXPECT_STDOUT, stderr matches EXPECT_STDERR, and the file EXPECT_FILE is written
# (removed first, so a stale one cannot pass).
if(DEFINED EXPECT_FILE)
  file(REMOVE ${EXPECT_FILE})
endif()
execute_process(COMMAND ${COMMAND} ${ARGS} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL ${EXPECT_CODE})
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout lacks '${EXPECT_STDOUT}'\nstdout: ${out}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr lacks '${EXPECT_STDERR}'\nstderr: ${err}")
endif()
if(DEFINED EXPECT_FILE AND NOT EXISTS ${EXPECT_FILE})
  message(FATAL_ERROR "${EXPECT_FILE} was not written")
endif()
