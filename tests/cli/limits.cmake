# The same size limits in every command (src/settings/limits.h), in one table: each over-limit
# value must exit 2 with the bound written out on stderr. Model and scene files over their byte
# limits are sparse files (nothing is read: they are refused by size before being read whole).
# Nothing reaches a GPU.
#   -DPROXYGI=<binary> -DWORK=<scratch folder>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(image "not in range 16 to 8192")
set(spp "not in range 1 to 1048576")
set(frames "not in range 1 to 1000000")
set(model_bytes "more than the limit of 1073741824 bytes \\(1 GiB\\)")
set(scene_bytes "more than the limit of 16777216 bytes \\(16 MiB\\)")
set(scene_width "output.width: must be in 16..8192 \\(got 8193\\)")
set(scene_frames "output.frames.count: must be in 1..1000000 \\(got 1000001\\)")

execute_process(COMMAND truncate -s 1073741825 ${WORK}/huge.glb RESULT_VARIABLE code)
execute_process(COMMAND truncate -s 16777217 ${WORK}/huge.json)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cannot make a sparse file with truncate")
endif()
file(WRITE ${WORK}/wide.json "{\"schema_version\": 1, \"output\": {\"width\": 8193}}")
file(WRITE ${WORK}/long.json "{\"schema_version\": 1, \"output\": {\"frames\": {\"count\": 1000001}}}")
file(WRITE ${WORK}/wide_scenario.json "{\"scenario_version\": 1, \"scene\": {\"schema_version\": 1, \"output\": {\"width\": 8193}}, \"checkpoints\": [0], \"checks\": [{\"name\": \"repeat\", \"type\": \"differential\", \"kind\": \"repeat\", \"frames\": [0]}]}")
# A Radiance HDR header claiming 8193 x 8193 pixels (the image reader checks the header first).
file(WRITE ${WORK}/huge.hdr "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8193 +X 8193\n")
set(ref --frame 0 --spp 1 -o ${WORK}/ref.exr)

# label | stderr must match | arguments (separated by ~)
set(cases
  "record --width|${image}|record~-o~${WORK}/r~--width~8193"
  "record --height|${image}|record~-o~${WORK}/r~--height~8193"
  "reference --width|${image}|reference~--frame~0~--spp~1~-o~${WORK}/ref.exr~--width~8193"
  "reference --height|${image}|reference~--frame~0~--spp~1~-o~${WORK}/ref.exr~--height~8193"
  "bench frame --size|${image}|bench~frame~--size~8193"
  "bench record --size|${image}|bench~record~--size~8193"
  "bench chart --size|${image}|bench~chart~--size~8193"
  "bench sampler --size|${image}|bench~sampler~--size~8193"
  "record scene width|${scene_width}|record~${WORK}/wide.json~-o~${WORK}/r"
  "reference scene width|${scene_width}|reference~${WORK}/wide.json~--frame~0~--spp~1~-o~${WORK}/ref.exr"
  "regress scene width|${scene_width}|regress~${WORK}/wide_scenario.json"
  "record -f|${frames}|record~mannequin~-f~1000001~-o~${WORK}/r"
  "record scene frames|${scene_frames}|record~${WORK}/long.json~-o~${WORK}/r"
  "reference scene frames|${scene_frames}|reference~${WORK}/long.json~--frame~0~--spp~1~-o~${WORK}/ref.exr"
  "reference --spp|${spp}|reference~--frame~0~--spp~1048577~-o~${WORK}/ref.exr"
  "bench chart --reference-spp|${spp}|bench~chart~--reference-spp~1048577"
  "bench sampler --spp|${spp}|bench~sampler~--spp~1048577"
  "info model bytes|${model_bytes}|info~${WORK}/huge.glb"
  "info --validate model bytes|${model_bytes}|info~${WORK}/huge.glb~--validate"
  "pose model bytes|${model_bytes}|pose~${WORK}/huge.glb"
  "fit model bytes|${model_bytes}|fit~${WORK}/huge.glb~-o~${WORK}/fit.proxies.json"
  "record model bytes|${model_bytes}|record~${WORK}/huge.glb~-o~${WORK}/r"
  "reference model bytes|${model_bytes}|reference~${WORK}/huge.glb~--frame~0~--spp~1~-o~${WORK}/ref.exr"
  "record scene bytes|${scene_bytes}|record~${WORK}/huge.json~-o~${WORK}/r"
  "reference scene bytes|${scene_bytes}|reference~${WORK}/huge.json~--frame~0~--spp~1~-o~${WORK}/ref.exr"
  "regress scenario bytes|${scene_bytes}|regress~${WORK}/huge.json"
  "compare image pixels|more than the limit of 67108864 pixels \\(8192 x 8192\\)|compare~${WORK}/huge.hdr~${WORK}/huge.hdr")

include(${CMAKE_CURRENT_LIST_DIR}/case_table.cmake)
set(failures "")
foreach(entry ${cases})
  proxygi_split_case(entry label expected args)
  execute_process(COMMAND ${PROXYGI} ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 2 OR NOT err MATCHES "${expected}")
    set(failures "${failures}\n  ${label}: exit ${code} (expected 2), stderr '${err}' (expected '${expected}')")
  endif()
endforeach()
file(REMOVE ${WORK}/huge.glb ${WORK}/huge.json)
if(failures)
  message(FATAL_ERROR "size limits:${failures}")
endif()
