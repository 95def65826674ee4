# Runs a chapter with the validation layer's best-practices checks on (besides core and
# synchronization validation) and fails on any message whose ID is not one of the IDs reviewed
# and deliberately accepted in docs/reliability.md. A new kind of message fails the test until it
# is fixed or reviewed.
#   cmake -DCOMMAND="chapter;args..." -DACCEPTED="ID;ID..." -P chapters/best_practices.cmake
cmake_minimum_required(VERSION 3.21)
set(ENV{VK_LAYER_ENABLES} VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT)
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
string(REGEX MATCHALL "\\[ [A-Za-z0-9_-]+ \\]" ids "${err}")
list(LENGTH ids count)
list(REMOVE_DUPLICATES ids)
set(unexpected "")
foreach(id IN LISTS ids)
    string(REGEX REPLACE "^\\[ (.*) \\]$" "\\1" id "${id}")
    if(NOT id IN_LIST ACCEPTED)
        list(APPEND unexpected ${id})
    endif()
endforeach()
message("command: ${COMMAND}\nexit: ${rc}\n${count} message(s) with the IDs: ${ids}")
# Exit 3 is --validation's "there were messages"; anything else but 0 is a failure of its own.
if(NOT rc EQUAL 0 AND NOT rc EQUAL 3)
    message(FATAL_ERROR "exit code ${rc}\n${err}")
endif()
string(REGEX MATCHALL "validation (error|warning): " lines "${err}")
list(LENGTH lines message_lines)
if(NOT message_lines EQUAL count)
    message(FATAL_ERROR "${message_lines} validation messages but ${count} message IDs: a message without an ID\n${err}")
endif()
if(unexpected)
    message(FATAL_ERROR "message IDs not reviewed in docs/reliability.md: ${unexpected}\n${err}")
endif()
