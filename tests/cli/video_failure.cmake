# An ffmpeg that fails names its output, the temporary "video.mp4.tmp-PID" the encode writes to:
# record must report the failure (exit 1) naming DIR/video.mp4, never the temporary, and leave no
# temporary behind. A fake ffmpeg on PATH prints what a real one prints for an unwritable output.
# Renders two tiny frames on the Vulkan device first (label gpu).
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)
file(WRITE ${WORK}/bin/ffmpeg "#!/bin/sh\nfor a; do last=$a; done\necho \"$last: Permission denied\" >&2\nexit 1\n")
file(CHMOD ${WORK}/bin/ffmpeg PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(record record default --frames 0:1 --width 16 --height 16 -o ${WORK}/out)
execute_process(COMMAND ${PROXYGI} ${record} --no-mp4 RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "record failed (${code}): ${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env PATH=${WORK}/bin:$ENV{PATH} ${PROXYGI} ${record} --mp4
                RESULT_VARIABLE code ERROR_VARIABLE err)
string(FIND "${err}" "${WORK}/out/video.mp4: Permission denied" named)
file(GLOB left ${WORK}/out/*.tmp-*)
if(NOT code EQUAL 1 OR named EQUAL -1 OR err MATCHES "\\.tmp-" OR left)
  message(FATAL_ERROR "ffmpeg failure: exit ${code} (expected 1), stderr '${err}' (must name ${WORK}/out/video.mp4, "
                      "no .tmp- file), left: ${left}")
endif()
