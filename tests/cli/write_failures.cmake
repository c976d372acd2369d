# Every command that writes a file, pointed at a folder it may not write to: each must fail
# with exit 1 and a message naming the user's path, never the temporary file ("NAME.tmp-PID",
# base/atomic_file.h) that the write went through. Runs as the user nobody when the tests run
# as root (root writes anywhere). Nothing reaches a GPU.
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/ro/record ${WORK}/images)
include(${CMAKE_CURRENT_LIST_DIR}/as_nobody.cmake)
proxygi_as_nobody("write failure checks" ${WORK}/images)
# An image to compare, written where the user may write.
execute_process(COMMAND ${as_user} ${PROXYGI} reference default --frame 0 --spp 1 --width 16 --height 16 -o ${WORK}/images/a.exr
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "reference into a writable folder failed (${code}): ${err}")
endif()
file(CHMOD ${WORK}/ro ${WORK}/ro/record DIRECTORY_PERMISSIONS OWNER_READ OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

# label | path the message must name | arguments (separated by ~)
set(cases
  "fit -o|${WORK}/ro/rig.proxies.json|fit~mannequin~-o~${WORK}/ro/rig.proxies.json"
  "mannequin -o|${WORK}/ro/m.glb|mannequin~-o~${WORK}/ro/m.glb"
  "pose -o|${WORK}/ro/pose.obj|pose~mannequin~-o~${WORK}/ro/pose.obj"
  "reference -o|${WORK}/ro/r.exr|reference~default~--frame~0~--spp~1~--width~16~--height~16~-o~${WORK}/ro/r.exr"
  "compare --error-image|${WORK}/ro/error.png|compare~${WORK}/images/a.exr~${WORK}/images/a.exr~--error-image~${WORK}/ro/error.png"
  "record -o|${WORK}/ro/record|record~default~--frames~0:0~--width~16~--height~16~-o~${WORK}/ro/record")
include(${CMAKE_CURRENT_LIST_DIR}/case_table.cmake)
set(failures "")
foreach(entry ${cases})
  proxygi_split_case(entry label path args)
  execute_process(COMMAND ${as_user} ${PROXYGI} ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "${path}" named)
  if(NOT code EQUAL 1 OR named EQUAL -1 OR err MATCHES "\\.tmp-" OR out MATCHES "\\.tmp-")
    set(failures "${failures}\n  ${label}: exit ${code} (expected 1), stderr '${err}' (must name ${path}, no .tmp- file)")
  endif()
endforeach()
file(GLOB left ${WORK}/ro/*.tmp-* ${WORK}/ro/record/*.tmp-*)
if(left)
  set(failures "${failures}\n  temporary files left: ${left}")
endif()
file(CHMOD ${WORK}/ro ${WORK}/ro/record DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
if(failures)
  message(FATAL_ERROR "write failures:${failures}")
endif()
