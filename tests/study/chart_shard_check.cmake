# `bench chart --shard 0/2` and `1/2` merged with `bench chart --merge` give the chart of one
# unsharded run: bench-chart-scores.json (errors, no times) byte-identical as measured, and with
# the single run's times fed to the merge (--timings-from) every file, the PNGs and the bounce
# chart included (shard 0 holds the proxy and vsgl bounce rows, shard 1 the none setting).
# -DPROXYGI=... -DWORK=... [-DEXTRA=--regions]
file(REMOVE_RECURSE ${WORK})
set(quick --quick --size 48 --frames 1 --reference-spp 8 --scenes default ${EXTRA})
function(chart)
  execute_process(COMMAND ${PROXYGI} bench chart ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "bench chart ${ARGN}: exit ${code}\n${out}\n${err}")
  endif()
endfunction()
function(same a b)
  file(SHA256 ${a} ha)
  file(SHA256 ${b} hb)
  if(NOT ha STREQUAL hb)
    message(FATAL_ERROR "${b} differs from ${a}")
  endif()
endfunction()
chart(${quick} --out ${WORK}/single --cache ${WORK}/cache_single)
# The shards share one cache: shard 1 reads the reference shard 0 traced.
chart(${quick} --shard 0/2 --out ${WORK}/shard0 --cache ${WORK}/cache_shards)
chart(${quick} --shard 1/2 --out ${WORK}/shard1 --cache ${WORK}/cache_shards)
chart(--merge ${WORK}/shard0 ${WORK}/shard1 --out ${WORK}/merged)
same(${WORK}/single/bench-chart-scores.json ${WORK}/merged/bench-chart-scores.json)
chart(--merge ${WORK}/shard1 ${WORK}/shard0 --out ${WORK}/replayed --timings-from ${WORK}/single/bench-chart-timings.json)
foreach(file bench-chart-scores.json bench-chart-timings.json bench-chart.csv bench-chart.md bench-chart.png bench-chart-quality.json bench-chart-quality.png
             bench-chart-bounce.csv bench-chart-bounce.md bench-chart-bounce.png)
  same(${WORK}/single/${file} ${WORK}/replayed/${file})
endforeach()
# A shard missing is bad input, named.
execute_process(COMMAND ${PROXYGI} bench chart --merge ${WORK}/shard0 --out ${WORK}/partial RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "shard 1/2 is missing")
  message(FATAL_ERROR "merging one of two shards: exit ${code}, ${err}")
endif()
if(EXTRA STREQUAL "--regions")
  file(READ ${WORK}/merged/bench-chart-scores.json scores)
  if(NOT scores MATCHES "\"regions\": {" OR NOT scores MATCHES "\"character\": {")
    message(FATAL_ERROR "merged --regions scores carry no regions")
  endif()
endif()
message(STATUS "bench chart ${EXTRA}: 2 shards merged == single run (scores; every file with the single run's times)")
