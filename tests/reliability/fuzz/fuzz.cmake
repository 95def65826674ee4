# Fuzzing (docs/reliability.md): tests/reliability/fuzz/run.sh builds the libFuzzer targets of
# tests/reliability/fuzz/ (the OBJ/MTL loader with tangents, the glTF loader, the scene JSON reader) with clang, in a build tree
# of their own, and runs each for 20 s over a copy of its committed corpus, which holds the
# regression inputs. A crash, hang, leak, sanitizer report or any exception but InputError fails.
# Needs clang++-14 and its libFuzzer runtime (Debian: clang-14, libclang-rt-14-dev); without them
# the test is left out with a warning. Longer runs: tests/reliability/fuzz/run.sh 600 (seconds per target).
find_program(VKBOOK_FUZZ_CXX NAMES clang++-14 clang++)

set(fuzz_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
if(VKBOOK_FUZZ_CXX AND NOT VKBOOK_FUZZ_LINKS STREQUAL VKBOOK_FUZZ_CXX)
    # Does this clang link a fuzz target with the sanitizers? (libFuzzer ships apart from clang.)
    file(WRITE ${fuzz_dir}/probe.cpp
         "#include <cstddef>\n#include <cstdint>\n"
         "extern \"C\" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n")
    execute_process(COMMAND ${VKBOOK_FUZZ_CXX} -fsanitize=fuzzer,address,undefined ${fuzz_dir}/probe.cpp
                            -o ${fuzz_dir}/probe
                    RESULT_VARIABLE probe_result OUTPUT_QUIET ERROR_QUIET)
    if(probe_result EQUAL 0)  # remembered for this compiler only
        set(VKBOOK_FUZZ_LINKS ${VKBOOK_FUZZ_CXX} CACHE INTERNAL "the clang that links libFuzzer targets")
    else()
        unset(VKBOOK_FUZZ_LINKS CACHE)
    endif()
endif()

if(NOT VKBOOK_FUZZ_CXX)
    message(WARNING "clang++-14 not found: the fuzz test is left out (Debian: apt install clang-14 libclang-rt-14-dev)")
elseif(NOT VKBOOK_FUZZ_LINKS STREQUAL VKBOOK_FUZZ_CXX)
    message(WARNING "${VKBOOK_FUZZ_CXX} cannot link a libFuzzer target with ASan and UBSan: the fuzz test is "
                    "left out (Debian: apt install libclang-rt-14-dev)")
else()
    add_test(NAME fuzz.loaders COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/reliability/fuzz/run.sh 20)
    # Its own clang build tree inside this one; the first run builds it (about a minute) unless the
    # fuzz-targets target has (scripts/setup.sh test builds it with the rest, before the tests).
    set_tests_properties(fuzz.loaders PROPERTIES
        LABELS fuzz
        TIMEOUT 600
        ENVIRONMENT "FUZZ_CXX=${VKBOOK_FUZZ_CXX};FUZZ_BUILD_DIR=${fuzz_dir}/build")
    add_custom_target(fuzz-targets
        COMMAND ${CMAKE_COMMAND} -E env FUZZ_CXX=${VKBOOK_FUZZ_CXX} FUZZ_BUILD_DIR=${fuzz_dir}/build
                ${CMAKE_CURRENT_SOURCE_DIR}/reliability/fuzz/run.sh --build-only
        COMMENT "Building the libFuzzer targets with ${VKBOOK_FUZZ_CXX} (tests/reliability/fuzz/run.sh --build-only)"
        VERBATIM)
endif()
