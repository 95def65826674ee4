# A damaged pipeline cache file is ignored with a warning, and the next run replaces it.
#   cmake -DCHAPTER=path/to/chapter-NN -DCACHE_HOME=dir -P chapters/pipeline_cache.cmake
cmake_minimum_required(VERSION 3.21)
file(REMOVE_RECURSE ${CACHE_HOME})
set(ENV{XDG_CACHE_HOME} ${CACHE_HOME})
set(run ${CHAPTER} --headless --device llvmpipe)

execute_process(COMMAND ${run} RESULT_VARIABLE rc ERROR_VARIABLE err)
file(GLOB caches ${CACHE_HOME}/vulkan-book-cpp/*.bin)
if(NOT rc EQUAL 0 OR NOT caches)
    message(FATAL_ERROR "first run: exit ${rc}, cache files '${caches}', stderr: ${err}")
endif()
message("first run wrote ${caches}")

# Each damaged file and the reason the warning must give. The last one is a well-formed
# VkPipelineCacheHeaderVersionOne (headerSize 32, version 1) from vendor 0xC0DE, device 1, with a
# zero UUID: a cache from another device, written with printf because it holds NUL bytes.
set(foreign "\\040\\0\\0\\0\\001\\0\\0\\0\\336\\300\\0\\0\\001\\0\\0\\0")
string(REPEAT "\\0" 20 zeros)
set(cases "garbage, not a pipeline cache|shorter than a cache header"
          "|shorter than a cache header"
          "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA|header size is wrong"
          "FOREIGN|written by another device or driver")
foreach(case IN LISTS cases)
    string(REPLACE "|" ";" case "${case}")
    list(GET case 0 content)
    list(GET case 1 reason)
    foreach(cache IN LISTS caches)
        if(content STREQUAL "FOREIGN")
            execute_process(COMMAND printf "${foreign}${zeros}" OUTPUT_FILE ${cache})
        else()
            file(WRITE ${cache} "${content}")
        endif()
    endforeach()
    execute_process(COMMAND ${run} RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT err MATCHES "warning: ignoring pipeline cache .*${reason}")
        message(FATAL_ERROR "damaged cache (${content}): exit ${rc}, expected 0 and a warning '${reason}'; stderr: ${err}")
    endif()
    message("damaged cache (${content}): ${err}")
endforeach()

execute_process(COMMAND ${run} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
    message(FATAL_ERROR "after the damaged run the cache should be valid again: exit ${rc}, stderr: ${err}")
endif()
file(GLOB leftovers ${CACHE_HOME}/vulkan-book-cpp/*.tmp*)
if(leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
message("the rewritten cache loads without a warning")
