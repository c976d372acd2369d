# --quiet on every command: a successful run prints nothing on stdout or stderr (no progress, no
# summary, no info lines) but warnings ("warning: ..." lines: fitting the mannequin warns that its
# surface is open). Renders tiny frames on the Vulkan device (label gpu).
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/scenario.json "{\"scenario_version\": 1, \"scene\": \"builtin:default\", \"overrides\": {\"output.width\": 16, \"output.height\": 16}, \"checkpoints\": [0], \"checks\": [{\"name\": \"repeat\", \"type\": \"differential\", \"kind\": \"repeat\", \"frames\": [0]}]}")
set(commands
  "info~mannequin"
  "info~mannequin~--validate"
  "pose~mannequin~--clip~walk~--time~0.3~-o~${WORK}/pose.obj"
  "fit~mannequin~-o~${WORK}/fit.proxies.json"
  "mannequin~-o~${WORK}/mannequin.glb"
  "reference~default~--frame~0~--spp~2~--width~16~--height~16~-o~${WORK}/ref.exr"
  "compare~${WORK}/ref.exr~${WORK}/ref.exr"
  "record~default~--frames~0:1~--width~16~--height~16~--no-mp4~-o~${WORK}/record"
  "record~mannequin~-f~1~--width~16~--height~16~-o~${WORK}/own~--write-scene~${WORK}/own.json"
  "regress~${WORK}/scenario.json~--report~${WORK}/report"
  "bench~sh~--receivers~20~--orders~3~--min-time~0.001"
  "bench~micro~--filter~^sh/~--min-time~0.001"
  "devices"
  "view~default~--offscreen~--max-frames~2~--width~16~--height~16")
set(failures "")
foreach(entry ${commands})
  string(REPLACE "~" ";" args "${entry}")
  execute_process(COMMAND ${PROXYGI} ${args} --quiet RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX REPLACE "(^|\n)warning: [^\n]*" "" rest "${err}")
  string(STRIP "${rest}" rest)
  if(NOT code EQUAL 0 OR NOT out STREQUAL "" OR NOT rest STREQUAL "")
    set(failures "${failures}\n  proxygi ${args} --quiet: exit ${code}, stdout '${out}', stderr '${err}'")
  endif()
endforeach()
if(NOT EXISTS ${WORK}/record/frame_00001.png OR NOT EXISTS ${WORK}/ref.exr OR NOT EXISTS ${WORK}/own.json)
  set(failures "${failures}\n  quiet runs did not write their files")
endif()
if(failures)
  message(FATAL_ERROR "--quiet:${failures}")
endif()
