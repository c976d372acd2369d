# One table of bad inputs run through every command that reads a model or a scene: each must
# exit 2 (bad input) and say what was wrong on stderr; nothing reaches a GPU (the inputs are
# refused first). Failures are collected and reported together.
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/garbage.glb "this is not a glTF file")
file(WRITE ${WORK}/broken.json "{\"schema_version\": 1, \"characters\": [")
file(WRITE ${WORK}/typeless_camera.json "{\"schema_version\": 1, \"camera\": {\"position\": [0, 1, 4], \"target\": [0, 1, 0]}, \"characters\": [{\"model\": \"builtin:mannequin\"}], \"output\": {\"width\": 16, \"height\": 16, \"frames\": {\"count\": 1}}}")
file(WRITE ${WORK}/missing_model.json "{\"schema_version\": 1, \"characters\": [{\"model\": \"gone.glb\"}]}")
set(missing ${WORK}/no-such-model.glb)

# command | arguments (separated by ~; INPUT is replaced)
set(commands
  "info|INPUT"
  "pose|INPUT"
  "fit|INPUT~-o~${WORK}/fit.proxies.json"
  "record|INPUT~-o~${WORK}/record"
  "reference|INPUT~--frame~0~--spp~1~-o~${WORK}/reference.exr")
# input | stderr must match
set(inputs
  "${missing}|no-such-model.glb"
  "${WORK}/garbage.glb|garbage.glb"
  "--no-such-flag|unknown option '--no-such-flag'")

set(failures "")
function(check label expected_code expected_stderr)
  execute_process(COMMAND ${PROXYGI} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL ${expected_code} OR NOT err MATCHES "${expected_stderr}")
    set(failures "${failures}\n  ${label}: exit ${code} (expected ${expected_code}), stderr '${err}' (expected '${expected_stderr}')" PARENT_SCOPE)
  endif()
endfunction()

foreach(command_entry ${commands})
  string(REPLACE "|" ";" fields "${command_entry}")
  list(GET fields 0 command)
  list(GET fields 1 template)
  string(REPLACE "~" ";" template "${template}")
  foreach(input_entry ${inputs})
    string(REPLACE "|" ";" input_fields "${input_entry}")
    list(GET input_fields 0 input)
    list(GET input_fields 1 expected)
    set(args ${template})
    list(TRANSFORM args REPLACE "^INPUT$" "${input}")
    if(input MATCHES "^--")  # the flag instead of the input, with a valid model
      list(TRANSFORM args REPLACE "^${input}$" "mannequin")
      list(APPEND args ${input})
    endif()
    check("${command} ${input}" 2 "${expected}" ${command} ${args})
  endforeach()
endforeach()

# Scene inputs of the commands that take a scene.
foreach(command record reference)
  set(rest -o ${WORK}/${command}_out)
  if(command STREQUAL "reference")
    set(rest --frame 0 --spp 1 -o ${WORK}/reference.exr)
  endif()
  check("${command} broken scene" 2 "broken.json" ${command} ${WORK}/broken.json ${rest})
  check("${command} scene naming a missing model" 2 "missing_model.json: characters.0.: .*gone.glb" ${command} ${WORK}/missing_model.json ${rest})
  check("${command} --clip with a scene" 2 "--clip is for a model" ${command} default --clip walk ${rest})
  check("${command} unknown clip" 2 "no clip 'moonwalk'" ${command} mannequin --clip moonwalk ${rest})
endforeach()

# Usage and range errors, readable.
check("no command" 2 "Usage")
check("unknown command" 2 "unknown command 'no-such-command'" no-such-command)
check("fit tolerance range" 2 "not in range 0.0001" fit mannequin --tolerance 1e400 -o ${WORK}/fit.proxies.json)
check("reference frame range" 2 "outside the scene's frames 0:95" reference --frame 99999 --spp 1 -o ${WORK}/reference.exr)
check("fit -o extension" 2 "written as JSON" fit mannequin -o ${WORK}/rig.txt)
check("pose -o extension" 2 "must end in .obj or .ply" pose mannequin -o ${WORK}/mesh.stl)
check("reference -o extension" 2 "written as .exr" reference --frame 0 --spp 1 -o ${WORK}/reference.png)
check("record frames range" 2 "outside the scene's frames" record -o ${WORK}/record --frames 0:9999)
check("info validate" 0 "^$" info mannequin --validate --quiet)
check("camera without type is fixed" 0 "reference" reference ${WORK}/typeless_camera.json --frame 0 --spp 1 -o ${WORK}/typeless.exr)

if(failures)
  message(FATAL_ERROR "exit codes:${failures}")
endif()
