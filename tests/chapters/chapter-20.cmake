# chapter-20 tests: chapter-19's frame on two threads. The views against chapter-17's golden images
# (chapter-19's picture: within 1/255 on 99.9% of the pixels), headless and in a window, with
# validation (synchronization validation on); the frames that move -- the figures playing, the
# camera walking, the light walking, one and three frames in flight, a resize -- against
# chapter-19's images of the same frames, to the bit: a render thread that drew another frame's
# slot, or read the camera as the update moves it, would draw another picture. Then the
# ThreadSanitizer build (tsan.chapter-20.*): the same runs, 0 reports, and a planted race reported.
# Live reload: tests/chapters/live_reload.cmake; the fault layer: tests/reliability/fault.cmake.
set(CH20 $<TARGET_FILE:chapter-20>)
set(CH20_RUN ${CH20} --device llvmpipe --validation)

foreach(view final visibility)
    chapter_test(chapter-20.view-${view} WORKDIR /
        COMMAND ${CH20_RUN} --headless --width 640 --height 360 --view ${view} --animation-time 0.4
                --screenshot ${TEST_OUT}/chapter-20-${view}.png
        EXPECT_STDOUT "2 models, 2 meshes, 1241 vertices, 11 joints; dispatched in 1 frames" QUIET_STDERR)
    set_tests_properties(chapter-20.view-${view} PROPERTIES FIXTURES_SETUP ch20-${view})
    add_test(NAME chapter-20.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-20-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-${view}.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-20.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch20-${view})
endforeach()

if(XVFB_RUN)
    chapter_test(chapter-20.window-final
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH20_RUN} --width 640 --height 360 --frames 3
                --animation-time 0.4 --screenshot ${TEST_OUT}/chapter-20-window-final.png QUIET_STDERR)
    set_tests_properties(chapter-20.window-final PROPERTIES FIXTURES_SETUP ch20-window)
    add_test(NAME chapter-20.window-final-image COMMAND image_compare ${TEST_OUT}/chapter-20-window-final.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-final.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-20.window-final-image PROPERTIES FIXTURES_REQUIRED ch20-window)
endif()

# Frames that change, each run by chapter-19 and chapter-20 and compared to the bit: the figures
# playing (12 frames, the skinned vertices checked); the camera and the point light walking (its
# marker a moving caster: the moving casters' map made under the render thread's feet); one frame
# in flight (the update waits for the frame being recorded) and three; a resize halfway, and one
# on the last frame (the frame written for the old size is written again for the new one).
set(CH20_MOVES
    "play|--frames 12 --check-skinning"
    "walk|--frames 16 --camera-motion walk --light-motion walk"
    "one-in-flight|--frames 8 --frames-in-flight 1 --camera-motion turn"
    "three-in-flight|--frames 10 --frames-in-flight 3 --camera-motion walk"
    "resize|--frames 10 --resize 200x120 --camera-motion walk"
    "resize-last|--frames 3 --resize 640x200 --camera-motion walk")
foreach(spec ${CH20_MOVES})
    string(REPLACE "|" ";" spec "${spec}")
    list(GET spec 0 case)
    list(GET spec 1 args)
    separate_arguments(args)
    foreach(number 19 20)
        chapter_test(chapter-20.${case}-${number} WORKDIR /
            COMMAND $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless --width 320
                    --height 180 ${args} --screenshot ${TEST_OUT}/chapter-20-${case}-${number}.png QUIET_STDERR)
        set_tests_properties(chapter-20.${case}-${number} PROPERTIES FIXTURES_SETUP ch20-${case}-${number})
    endforeach()
    add_test(NAME chapter-20.${case}-image COMMAND image_compare ${TEST_OUT}/chapter-20-${case}-20.png
        --golden ${TEST_OUT}/chapter-20-${case}-19.png --max-diff 0 --max-fraction 0)
    set_tests_properties(chapter-20.${case}-image PROPERTIES FIXTURES_REQUIRED "ch20-${case}-19;ch20-${case}-20")
endforeach()

# The book's scene with Bob's format.
chapter_test(chapter-20.book-scene WORKDIR /
    COMMAND ${CH20_RUN} --headless --width 320 --height 180 --frames 5 --check-skinning
            --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book
    EXPECT_STDOUT "chapter-20: 8 draws.*skinning: 1 models, 3 meshes, 466 vertices, 2 joints.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-20.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases)

# A failure on the main thread (the update: a pose no float holds) and on the render thread (a
# shadow batch the update did not write cannot happen; the fault layer's failures on the render
# thread are in tests/reliability/fault.cmake): one line, the render thread joined.
chapter_test(hostile.chapter-20-gltf-index-past COMMAND ${CH20} --device llvmpipe --headless
        --model ${CMAKE_CURRENT_BINARY_DIR}/gltf/hostile/index_past_vertices.gltf
    EXPECT_EXIT 2 EXPECT_STDERR "^chapter-20: error: .*index_past_vertices.gltf: meshes\\[0\\].primitives\\[0\\] indices \\(accessor 2\\) refers to vertex 7 of 3"
    ONE_LINE_STDERR)
set_tests_properties(hostile.chapter-20-gltf-index-past PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")

standalone_build_test(20 --width 320 --height 180 --frames 3 --check-skinning)

# --- ThreadSanitizer ---------------------------------------------------------------------------
# chapter-20 configured alone with -DVKBOOK_TSAN=ON (cmake/VulkanBook.cmake) into tsan/, as a
# reader's standalone build, then its runs: every report fails the run (ThreadSanitizer's exit code
# 66, and stderr not empty). tests/reliability/tsan/tsan.supp sets aside only reports inside
# lavapipe and the validation layer, which are not built with ThreadSanitizer.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(TSAN_DIR ${CMAKE_CURRENT_BINARY_DIR}/tsan)
    set(TSAN_CH20 ${TSAN_DIR}/bin/chapter-20)
    set(tsan_launcher "")
    set(tsan_env ${TEST_ENV} "TSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/reliability/tsan/tsan.supp:second_deadlock_stack=1")
    if(CCACHE)
        set(tsan_launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
        list(APPEND tsan_env CCACHE_DIR=${CMAKE_CURRENT_BINARY_DIR}/tsan-ccache CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}
             CCACHE_NOHASHDIR=1 CCACHE_TEMPDIR=${CMAKE_CURRENT_BINARY_DIR}/tsan-ccache/tmp)
    endif()
    add_test(NAME tsan.chapter-20.build
        COMMAND sh -c "${CMAKE_COMMAND} -S \"$2\" -B \"$1\" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVKBOOK_TSAN=ON -DCMAKE_UNITY_BUILD=ON ${tsan_launcher} >/dev/null && ${CMAKE_COMMAND} --build \"$1\" -j2 >/dev/null"
        _ ${TSAN_DIR} ${PROJECT_SOURCE_DIR}/chapter-20)
    set_tests_properties(tsan.chapter-20.build PROPERTIES FIXTURES_SETUP tsan-chapter-20 ENVIRONMENT "${tsan_env}"
                         LABELS slow COST 40)
    # tsan_test(NAME ARGS...): a run of the ThreadSanitizer build, 0 reports.
    function(tsan_test name)
        chapter_test(${name} ${ARGN})
        set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED "tsan-chapter-20;gltf-cases" ENVIRONMENT "${tsan_env}")
    endfunction()
    # Headless: the figures playing, the camera and the light walking, with validation.
    tsan_test(tsan.chapter-20.headless WORKDIR /
        COMMAND ${TSAN_CH20} --device llvmpipe --validation --headless --width 320 --height 180 --frames 16
                --camera-motion walk --light-motion walk --check-skinning
        EXPECT_STDOUT "guards intact" QUIET_STDERR)
    # One frame in flight and three, the overlay, a resize.
    tsan_test(tsan.chapter-20.in-flight WORKDIR /
        COMMAND ${TSAN_CH20} --device llvmpipe --headless --width 320 --height 180 --frames 8
                --frames-in-flight 1 --gui --camera-motion turn QUIET_STDERR)
    tsan_test(tsan.chapter-20.resize WORKDIR /
        COMMAND ${TSAN_CH20} --device llvmpipe --headless --width 320 --height 180 --frames 10
                --frames-in-flight 3 --gui --resize 200x120 QUIET_STDERR)
    # The book's scene (Bob in its format).
    tsan_test(tsan.chapter-20.book-scene WORKDIR /
        COMMAND ${TSAN_CH20} --device llvmpipe --headless --width 320 --height 180 --frames 5
                --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book QUIET_STDERR)
    if(XVFB_RUN)
        # In a window: the overlay, the window resized through the window system.
        tsan_test(tsan.chapter-20.window
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${TSAN_CH20} --device llvmpipe --validation
                    --width 320 --height 180 --frames 10 --gui --resize 200x150 --camera-motion walk QUIET_STDERR)
    endif()
    # Ctrl+C in the middle of a long frame (tests/reliability/stop_run.sh): one line, exit 130, no
    # report -- the main thread stops while the render thread is drawing.
    add_test(NAME tsan.chapter-20.stop-mid-frame
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/reliability/stop_run.sh ${TSAN_CH20} frame --device llvmpipe --headless
                --width 320 --height 180 --model ${CMAKE_CURRENT_BINARY_DIR}/gltf/extremes/stacked_450.gltf
                --shadow-redraw always --frames 1000)
    set_tests_properties(tsan.chapter-20.stop-mid-frame PROPERTIES FIXTURES_REQUIRED "tsan-chapter-20;gltf-cases"
                         ENVIRONMENT "${tsan_env}" TIMEOUT 120 RUN_SERIAL TRUE)
    # The planted race: VKBOOK_TEST_RACE=camera makes the render thread read the live camera, as the
    # book's render task does, while the update walks it. ThreadSanitizer must say so, naming both.
    tsan_test(tsan.chapter-20.planted-race WORKDIR /
        COMMAND ${TSAN_CH20} --device llvmpipe --headless --width 320 --height 180 --frames 8 --camera-motion walk
        EXPECT_EXIT 66
        EXPECT_STDERR "WARNING: ThreadSanitizer: data race.*chapter-20/main.cpp.*common::moveForTesting")
    set_property(TEST tsan.chapter-20.planted-race APPEND PROPERTY ENVIRONMENT VKBOOK_TEST_RACE=camera)
endif()
