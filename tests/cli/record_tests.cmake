# proxygi record: planner unit tests, argument errors (exit 2), and GPU runs checking
# determinism, resume and shard merging (record_gpu_check.cmake).
proxygi_test(record_plan_tests
  SOURCES ${PROJECT_SOURCE_DIR}/tests/record/record_plan_test.cpp ${PROJECT_SOURCE_DIR}/tests/record/task_queue_test.cpp
  DEPS proxygi::base proxygi::scene proxygi::run
  LABELS unit)

set(_record_expect ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
set(_record_out ${CMAKE_CURRENT_BINARY_DIR}/record_args)
# name | arguments (;-list) | stderr must contain
foreach(_case
    "bad_frames|record;-o;${_record_out};--frames;5|--frames '5'"
    "reversed_frames|record;-o;${_record_out};--frames;9:3|first frame is after"
    "frames_outside_scene|record;-o;${_record_out};--frames;0:9999|outside the scene's frames 0:95"
    "bad_shard|record;-o;${_record_out};--shard;2/2|below N"
    "bad_shard_text|record;-o;${_record_out};--shard;x|--shard 'x'"
    "unknown_scene_file|record;${_record_out}/no-such-scene.json;-o;${_record_out}|no-such-scene.json"
    "width_too_small|record;-o;${_record_out};--width;8|width"
    "mp4_and_no_mp4|record;-o;${_record_out};--mp4;--no-mp4|excludes"
    "missing_output|record|output")
  string(REPLACE "|" ";" _fields "${_case}")
  list(GET _fields 0 _name)
  list(GET _fields -1 _stderr)
  list(SUBLIST _fields 1 -1 _args)
  list(REMOVE_AT _args -1)
  add_test(NAME cli.record.${_name} COMMAND ${CMAKE_COMMAND} -DCOMMAND=$<TARGET_FILE:proxygi>
           "-DARGS=${_args}" -DEXPECT_CODE=2 "-DEXPECT_STDERR=${_stderr}" -P ${_record_expect})
  set_tests_properties(cli.record.${_name} PROPERTIES LABELS unit)
endforeach()

add_test(NAME cli.record.deterministic_resumable_sharded
         COMMAND ${CMAKE_COMMAND} -DPROXYGI=$<TARGET_FILE:proxygi> -DSOURCE_ASSETS=${PROJECT_SOURCE_DIR}/assets
                 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/record_gpu -P ${CMAKE_CURRENT_SOURCE_DIR}/record_gpu_check.cmake)
set_tests_properties(cli.record.deterministic_resumable_sharded PROPERTIES LABELS gpu TIMEOUT 900)
