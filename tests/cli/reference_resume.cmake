# `reference` interrupted (SIGINT, raised by the hidden --stop-after-samples hook through the
# same handler Ctrl-C reaches) keeps its whole samples, exits 1, and `--accumulate` finishes the
# run: the images are bit for bit those of an uninterrupted run with the same seed. Progress into
# a pipe is plain lines, never a carriage return. CPU only (Embree).
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(args default --frame 7 --spp 5 --width 24 --height 16 --seed 3 --threads 2)

function(run expected_code expected_stderr)
  execute_process(COMMAND ${PROXYGI} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL ${expected_code} OR NOT err MATCHES "${expected_stderr}")
    message(FATAL_ERROR "proxygi ${ARGN}: exit ${code} (expected ${expected_code})\nstderr: ${err}\n(expected '${expected_stderr}')")
  endif()
  if(err MATCHES "\r")
    message(FATAL_ERROR "proxygi ${ARGN}: a carriage return in progress written to a pipe:\n${err}")
  endif()
endfunction()

run(0 "100.0%" reference ${args} -o ${WORK}/whole.exr)
run(1 "interrupted: kept 2 of 5 samples in .*part.exr; run the same command with --accumulate" reference ${args} -o ${WORK}/part.exr
    --stop-after-samples 2)
file(READ ${WORK}/part.json record)
if(NOT record MATCHES "\"samples\": 2" OR NOT record MATCHES "\"target_samples\": 5" OR NOT EXISTS ${WORK}/part.partial)
  message(FATAL_ERROR "the interrupted run's record or partial sums are missing:\n${record}")
endif()
run(0 "resuming an interrupted run: 2 of 5 samples done, tracing the 3 missing" reference ${args} -o ${WORK}/part.exr --accumulate)
if(EXISTS ${WORK}/part.partial)
  message(FATAL_ERROR "part.partial left after the run completed")
endif()
foreach(suffix .exr .indirect.exr .variance.exr)
  file(SHA256 ${WORK}/whole${suffix} whole)
  file(SHA256 ${WORK}/part${suffix} part)
  if(NOT whole STREQUAL part)
    message(FATAL_ERROR "interrupted + resumed ${suffix} differs from the uninterrupted run")
  endif()
endforeach()
file(READ ${WORK}/part.json record)
if(NOT record MATCHES "\"samples\": 5")
  message(FATAL_ERROR "the resumed record does not count 5 samples:\n${record}")
endif()
