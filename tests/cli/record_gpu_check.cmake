# GPU check of `proxygi record` (3 frames of the default scene at 64x64):
#  1. two runs into two folders write byte-identical PNGs (determinism);
#  2. a second run into the same folder renders nothing and skips all 3 frames (resume);
#  3. --shard 0/2 and --shard 1/2 into one folder write the same files as a single run;
#  4. the folder's manifest (record.json): another size or scene is refused (exit 2) unless
#     --overwrite, a folder of frames without a manifest is refused, --verify renders a truncated
#     frame again, --aov resume needs every AOV file, a dead process's temporary is removed.
# Uses a scratch assets folder (the mannequin copied from the source tree or generated) so the
# proxy rig cache is written under the build tree, never into the sources.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/assets)
if(EXISTS ${SOURCE_ASSETS}/mannequin.glb)
  file(COPY ${SOURCE_ASSETS}/mannequin.glb DESTINATION ${WORK}/assets)
else()
  execute_process(COMMAND ${PROXYGI} mannequin -o ${WORK}/assets/mannequin.glb RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "proxygi mannequin failed (${code})")
  endif()
endif()
set(ENV{PROXYGI_ASSETS} ${WORK}/assets)
set(frames 00000 00001 00002)

function(record out_dir expected_stderr)
  execute_process(COMMAND ${PROXYGI} record default -o ${out_dir} --frames 0:2 --width 64 --height 64 ${ARGN}
                  RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "record ${ARGN} into ${out_dir}: exit ${code}\n${err}")
  endif()
  if(NOT err MATCHES "${expected_stderr}")
    message(FATAL_ERROR "record ${ARGN} into ${out_dir}: stderr lacks '${expected_stderr}'\n${err}")
  endif()
endfunction()

function(expect_same_frames a b)
  foreach(f ${frames})
    if(NOT EXISTS ${a}/frame_${f}.png OR NOT EXISTS ${b}/frame_${f}.png)
      message(FATAL_ERROR "frame_${f}.png missing in ${a} or ${b}")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a}/frame_${f}.png ${b}/frame_${f}.png RESULT_VARIABLE differ)
    if(NOT differ EQUAL 0)
      message(FATAL_ERROR "frame_${f}.png differs between ${a} and ${b}")
    endif()
  endforeach()
endfunction()

record(${WORK}/a "3 frames rendered, 0 skipped")
record(${WORK}/b "3 frames rendered, 0 skipped")
expect_same_frames(${WORK}/a ${WORK}/b)

# Resume: a finished folder renders nothing (a sentinel in place of a frame stays untouched);
# a deleted frame is rendered again, alone, to the same bytes.
file(WRITE ${WORK}/a/frame_00001.png "sentinel")
record(${WORK}/a "0 frames rendered, 3 skipped")
file(READ ${WORK}/a/frame_00001.png kept)
if(NOT kept STREQUAL "sentinel")
  message(FATAL_ERROR "resume rewrote frame_00001.png")
endif()
file(REMOVE ${WORK}/a/frame_00001.png)
record(${WORK}/a "1 frames rendered, 2 skipped")
# --verify: a frame that does not decode (here: truncated) is rendered again.
file(WRITE ${WORK}/a/frame_00002.png "PNG, cut short")
record(${WORK}/a "1 frames rendered, 2 skipped" --verify)
expect_same_frames(${WORK}/a ${WORK}/b)

record(${WORK}/sharded "2 frames rendered, 0 skipped" --shard 0/2)
record(${WORK}/sharded "1 frames rendered, 0 skipped" --shard 1/2)
expect_same_frames(${WORK}/a ${WORK}/sharded)
file(GLOB leftovers ${WORK}/a/*.tmp* ${WORK}/sharded/*.tmp*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()

# The manifest: a folder made by another size or scene is refused, not silently "skipped".
function(record_refused out_dir expected_stderr)
  execute_process(COMMAND ${PROXYGI} record ${ARGN} -o ${out_dir} --frames 0:2
                  RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 2 OR NOT err MATCHES "${expected_stderr}")
    message(FATAL_ERROR "record ${ARGN} into ${out_dir}: exit ${code} (expected 2), stderr lacks '${expected_stderr}'?\n${err}")
  endif()
endfunction()
if(NOT EXISTS ${WORK}/a/record.json)
  message(FATAL_ERROR "record wrote no manifest")
endif()
record_refused(${WORK}/a "recorded at 64x64, not 80x64" default --width 80 --height 64)
record_refused(${WORK}/a "different scene" crowd --width 64 --height 64)
file(MAKE_DIRECTORY ${WORK}/foreign)
file(WRITE ${WORK}/foreign/frame_00000.png "someone else's")
record_refused(${WORK}/foreign "no record.json" default --width 64 --height 64)
record(${WORK}/foreign "3 frames rendered, 0 skipped" --overwrite)
expect_same_frames(${WORK}/foreign ${WORK}/b)
# A temporary of a process that no longer runs is removed; a frame whose AOVs are incomplete is
# rendered again.
file(WRITE ${WORK}/a/frame_00000.png.tmp-999999999 "stale")
record(${WORK}/a "removed 1 temporary file")
record(${WORK}/a "3 frames rendered, 0 skipped" --aov)
file(REMOVE ${WORK}/a/aov/frame_00001_indirect.exr)
record(${WORK}/a "1 frames rendered, 2 skipped" --aov)
