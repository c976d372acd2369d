# `proxygi record MODEL.glb` with models built by the glTF writer (write_test_models):
#  1. unnamed.glb and duplicate.glb render twice (the rig fitted, then read from the cache file)
#     to the same frames, and to the frames of named.glb (same figure): the shadow follows the
#     feet whatever the bones are called; the warning about the names is printed;
#  2. a rig the user fitted with --tolerance 0.02 and named in a scene survives record unchanged;
#  3. a model in a read-only folder renders; its rig goes to $XDG_CACHE_HOME/proxygi, and fit says
#     so; fit -o into that folder is a runtime failure (exit 1). As root this runs as nobody.
#   -DPROXYGI=<binary> -DWRITE_MODELS=<write_test_models> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${WRITE_MODELS} ${WORK}/models RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "write_test_models failed (${code})")
endif()

function(run expected_code)
  cmake_parse_arguments(ARG "" "STDERR;NOT_STDERR;STDOUT" "" ${ARGN})
  execute_process(COMMAND ${ARG_UNPARSED_ARGUMENTS} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL ${expected_code})
    message(FATAL_ERROR "${ARG_UNPARSED_ARGUMENTS}: exit ${code}, expected ${expected_code}\n${out}\n${err}")
  endif()
  if(ARG_STDERR AND NOT err MATCHES "${ARG_STDERR}")
    message(FATAL_ERROR "${ARG_UNPARSED_ARGUMENTS}: stderr lacks '${ARG_STDERR}'\n${err}")
  endif()
  if(ARG_NOT_STDERR AND err MATCHES "${ARG_NOT_STDERR}")
    message(FATAL_ERROR "${ARG_UNPARSED_ARGUMENTS}: stderr has '${ARG_NOT_STDERR}'\n${err}")
  endif()
  if(ARG_STDOUT AND NOT out MATCHES "${ARG_STDOUT}")
    message(FATAL_ERROR "${ARG_UNPARSED_ARGUMENTS}: stdout lacks '${ARG_STDOUT}'\n${out}")
  endif()
endfunction()

# RMSE of two frames (proxygi compare) below `limit`.
function(expect_close a b limit)
  execute_process(COMMAND ${PROXYGI} compare ${a} ${b} --json RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "compare ${a} ${b}: exit ${code}\n${err}")
  endif()
  string(JSON rmse GET "${out}" rmse)
  if(rmse GREATER ${limit})
    message(FATAL_ERROR "${a} vs ${b}: rmse ${rmse} > ${limit}")
  endif()
endfunction()

set(record_args -f 3 --width 96 --height 64)
run(0 ${PROXYGI} record ${WORK}/models/named.glb ${record_args} -o ${WORK}/named STDERR "fitted")
foreach(model unnamed duplicate)
  run(0 ${PROXYGI} record ${WORK}/models/${model}.glb ${record_args} -o ${WORK}/${model}_fitted
      STDERR "proxy spheres are bound by node index.*fitted")
  if(NOT EXISTS ${WORK}/models/${model}.proxies.json)
    message(FATAL_ERROR "no rig cached for ${model}.glb")
  endif()
  run(0 ${PROXYGI} record ${WORK}/models/${model}.glb ${record_args} -o ${WORK}/${model}_cached NOT_STDERR "fitted")
  foreach(frame 00000 00001 00002)
    expect_close(${WORK}/${model}_fitted/frame_${frame}.png ${WORK}/${model}_cached/frame_${frame}.png 0.002)
    expect_close(${WORK}/${model}_fitted/frame_${frame}.png ${WORK}/named/frame_${frame}.png 0.004)
  endforeach()
endforeach()

# A user's rig, fitted at a non-default tolerance and named in a scene, is used as it is.
run(0 ${PROXYGI} fit ${WORK}/models/named.glb --tolerance 0.02 -o ${WORK}/models/my.proxies.json)
file(SHA256 ${WORK}/models/my.proxies.json before)
file(WRITE ${WORK}/models/scene.json "{\"schema_version\": 1, \"characters\": [{\"model\": \"named.glb\", \"clip\": 0, \"proxies\": \"my.proxies.json\"}], \"output\": {\"width\": 32, \"height\": 32, \"frames\": {\"count\": 2}}}")
run(0 ${PROXYGI} record ${WORK}/models/scene.json -o ${WORK}/user_rig NOT_STDERR "fitted")
file(SHA256 ${WORK}/models/my.proxies.json after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "record rewrote the user's rig my.proxies.json")
endif()

# A read-only model folder.
file(MAKE_DIRECTORY ${WORK}/readonly ${WORK}/cache ${WORK}/readonly_out)
file(COPY ${WORK}/models/named.glb DESTINATION ${WORK}/readonly)
include(${CMAKE_CURRENT_LIST_DIR}/as_nobody.cmake)
proxygi_as_nobody("read-only folder check" ${WORK}/cache ${WORK}/readonly_out)
file(CHMOD ${WORK}/readonly DIRECTORY_PERMISSIONS OWNER_READ OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(env ${CMAKE_COMMAND} -E env XDG_CACHE_HOME=${WORK}/cache)
run(0 ${env} ${as_user} ${PROXYGI} fit ${WORK}/readonly/named.glb STDERR "cached the rig in ${WORK}/cache/proxygi"
    STDOUT "wrote ${WORK}/cache/proxygi/")
run(0 ${env} ${as_user} ${PROXYGI} fit ${WORK}/readonly/named.glb STDOUT "reused ${WORK}/cache/proxygi/")
run(0 ${env} ${as_user} ${PROXYGI} record ${WORK}/readonly/named.glb -f 1 --width 32 --height 32 -o ${WORK}/readonly_out
    NOT_STDERR "fitted")
run(1 ${env} ${as_user} ${PROXYGI} fit ${WORK}/readonly/named.glb -o ${WORK}/readonly/mine.proxies.json STDERR "readonly/mine.proxies.json")
file(CHMOD ${WORK}/readonly DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
