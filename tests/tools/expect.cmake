# Test driver: runs COMMAND and checks how it ended.
#   cmake -DCOMMAND="prog;arg;..." [-DEXPECT_EXIT=0] [-DEXPECT_STDERR=regex] [-DEXPECT_STDOUT=regex]
#         [-DONE_LINE_STDERR=ON] [-DQUIET_STDERR=ON] [-DWORKDIR=dir] [-DUNSET_DISPLAY=ON] -P tools/expect.cmake
# ONE_LINE_STDERR: stderr must be exactly one line (the promise for bad input).
# QUIET_STDERR: stderr must be empty (no validation message, no warning).
cmake_minimum_required(VERSION 3.21)
if(NOT DEFINED EXPECT_EXIT)
    set(EXPECT_EXIT 0)
endif()
if(NOT DEFINED WORKDIR)
    set(WORKDIR ${CMAKE_CURRENT_BINARY_DIR})
endif()
if(UNSET_DISPLAY)
    unset(ENV{DISPLAY})
    unset(ENV{WAYLAND_DISPLAY})
endif()
# Sanitizer build: a run expected to fail (bad input, an injected fault, the validation
# selftest) leaves the chapter by an exception, which does not destroy the Vulkan objects made so
# far -- the process is ending and the system reclaims them. What the loader, the layers and the
# driver allocated for those objects is then suppressed (reliability/sanitizer/lsan-error-exit.supp); our own
# allocations are still checked, as are AddressSanitizer's and UBSan's findings.
if(NOT EXPECT_EXIT EQUAL 0 AND DEFINED ENV{LSAN_OPTIONS})
    string(REPLACE "lsan.supp" "lsan-error-exit.supp" options "$ENV{LSAN_OPTIONS}")
    set(ENV{LSAN_OPTIONS} "${options}")
endif()
# A backstop only, under CTest's default limit of 1500 s: a test's own limit is its TIMEOUT
# property (CTest ends the whole test there). A fixed 300 s here once cut short a test whose
# property gave it 900 s on a loaded machine.
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 1400)
message("command: ${COMMAND}\nexit: ${rc}\n--- stdout ---\n${out}--- stderr ---\n${err}--------------")
set(problems "")
if(NOT "${rc}" STREQUAL "${EXPECT_EXIT}")
    string(APPEND problems "exit code ${rc}, expected ${EXPECT_EXIT}; ")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
    string(APPEND problems "stderr does not match '${EXPECT_STDERR}'; ")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
    string(APPEND problems "stdout does not match '${EXPECT_STDOUT}'; ")
endif()
if(ONE_LINE_STDERR)
    string(REGEX MATCHALL "\n" newlines "${err}")
    list(LENGTH newlines lines)
    if(NOT lines EQUAL 1)
        string(APPEND problems "stderr has ${lines} lines, expected exactly one; ")
    endif()
endif()
if(QUIET_STDERR AND NOT err STREQUAL "")
    string(APPEND problems "stderr is not empty; ")
endif()
if(problems)
    message(FATAL_ERROR "${problems}")
endif()
