# `regress --calibrate 2` only proposes; `--calibrate 2 --write` writes the proposals into a copy
# of crossfade.json (its layout kept: only tolerance values change or are appended), prints the
# diff, and a second --write finds nothing to change.
# -DPROXYGI=... -DSUITE=... -DWORK=...
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
configure_file(${SUITE}/crossfade.json ${WORK}/crossfade.json COPYONLY)
function(calibrate)
  execute_process(COMMAND ${PROXYGI} regress ${WORK}/crossfade.json --calibrate 2 ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "regress --calibrate 2 ${ARGN}: exit ${code}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
file(READ ${SUITE}/crossfade.json original)

calibrate()
file(READ ${WORK}/crossfade.json text)
if(NOT text STREQUAL original)
  message(FATAL_ERROR "--calibrate without --write changed the scenario")
endif()

calibrate(--write)
file(READ ${WORK}/crossfade.json text)
# On lavapipe the runs are bit-identical: the proposals are the floors.
foreach(expected
    [[{"name": "frame", "type": "image", "pixel_threshold": 1, "max_failing_fraction": 0.0005}]]
    [[{"name": "fade_tracks", "type": "tracks", "frames": [22, 24, 26, 28, 30, 32, 34, 36, 38, 72, 90, 96, 110], "vertices": 16, "joint_mm": 0.01, "vertex_mm": 0.01, "proxy_mm": 0.01}]])
  string(FIND "${text}" "${expected}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the calibrated file lacks ${expected}:\n${text}")
  endif()
endforeach()
foreach(expected [[-    {"name": "frame", "type": "image", "pixel_threshold": 3, "max_failing_fraction": 0.001},]]
                 [[+    {"name": "frame", "type": "image", "pixel_threshold": 1, "max_failing_fraction": 0.0005},]])
  string(FIND "${out}" "${expected}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the printed diff lacks ${expected}:\n${out}")
  endif()
endforeach()
# Only the two check lines changed.
string(REGEX MATCHALL "\n@@ line" hunks "\n${out}")
list(LENGTH hunks count)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "expected 2 changed lines, got ${count}:\n${out}")
endif()

calibrate(--write)
if(NOT out MATCHES "already holds the proposed tolerances")
  message(FATAL_ERROR "a second --write should change nothing:\n${out}")
endif()
message(STATUS "calibrate --write: proposals written into a copy, diff printed, idempotent")
