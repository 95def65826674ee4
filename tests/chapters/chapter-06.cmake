# chapter-06 tests: the triangle headless and windowed, the golden image, the command line.
set(CH06 $<TARGET_FILE:chapter-06>)
set(CH06_RUN ${CH06} --device llvmpipe --validation)

# Headless, run from / to show the executable finds its shaders wherever it is started.
chapter_test(chapter-06.headless WORKDIR /
    COMMAND ${CH06_RUN} --headless --screenshot ${TEST_OUT}/chapter-06.png QUIET_STDERR)
set_tests_properties(chapter-06.headless PROPERTIES FIXTURES_SETUP ch06-image)
# The image: its size, red at the centre, the clear colour (0.5, 0.7, 0.9) in the corners --
# both stored sRGB-encoded -- and the golden image within Filament's tolerance.
add_test(NAME chapter-06.image COMMAND image_compare ${TEST_OUT}/chapter-06.png --size 1280 720
    --pixel-linear 640 360 1 0 0
    --pixel-linear 0 0 0.5 0.7 0.9 --pixel-linear 1279 0 0.5 0.7 0.9
    --pixel-linear 0 719 0.5 0.7 0.9 --pixel-linear 1279 719 0.5 0.7 0.9
    --golden ${GOLDEN}/chapter-06.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-06.image PROPERTIES FIXTURES_REQUIRED ch06-image)

# Several frames in flight with a resize half-way: the last frame has the new size.
chapter_test(chapter-06.headless-resize
    COMMAND ${CH06_RUN} --headless --frames 8 --resize 640x480 --screenshot ${TEST_OUT}/chapter-06-resized.png
    QUIET_STDERR)
set_tests_properties(chapter-06.headless-resize PROPERTIES FIXTURES_SETUP ch06-resized)
add_test(NAME chapter-06.headless-resize-image COMMAND image_compare ${TEST_OUT}/chapter-06-resized.png
    --size 640 480 --pixel-linear 320 240 1 0 0 --pixel-linear 0 0 0.5 0.7 0.9)
set_tests_properties(chapter-06.headless-resize-image PROPERTIES FIXTURES_REQUIRED ch06-resized)

# A window under Xvfb, resized through the window system half-way through 60 frames.
if(XVFB_RUN)
    chapter_test(chapter-06.window
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH06_RUN} --frames 60 --resize 800x600
                --screenshot ${TEST_OUT}/chapter-06-window.png QUIET_STDERR)
    set_tests_properties(chapter-06.window PROPERTIES FIXTURES_SETUP ch06-window)
    add_test(NAME chapter-06.window-image COMMAND image_compare ${TEST_OUT}/chapter-06-window.png
        --size 800 600 --pixel-linear 400 300 1 0 0 --pixel-linear 0 0 0.5 0.7 0.9)
    set_tests_properties(chapter-06.window-image PROPERTIES FIXTURES_REQUIRED ch06-window)
else()
    message(WARNING "Xvfb not found: the windowed tests are not registered (apt-get install xvfb)")
endif()

# Without --headless and without a display: a clear error, exit 1.
chapter_test(chapter-06.no-display UNSET_DISPLAY COMMAND ${CH06}
    EXPECT_EXIT 1 EXPECT_STDERR "cannot open a window.*--headless" ONE_LINE_STDERR)

chapter_test(chapter-06.help COMMAND ${CH06} --help EXPECT_STDOUT "usage: chapter-06.*--screenshot" QUIET_STDERR)

# Bad command lines: exit 2 and one line naming the problem.
function(ch06_bad name expected)
    chapter_test(chapter-06.bad-${name} COMMAND ${CH06} --headless ${ARGN}
                 EXPECT_EXIT 2 EXPECT_STDERR "${expected}" ONE_LINE_STDERR)
endfunction()
ch06_bad(unknown-flag "unknown option '--frobnicate'" --frobnicate)
ch06_bad(width-zero "--width must be between 1 and 16384, got 0" --width 0)
ch06_bad(width-huge "--width must be between 1 and 16384, got 99999" --width 99999)
ch06_bad(height-not-a-number "--height expects a whole number, got '12x'" --height 12x)
ch06_bad(frames-zero "--frames must be between 1 and" --frames 0)
ch06_bad(missing-value "--width needs a value" --width)
ch06_bad(stray-argument "unexpected argument 'triangle'" triangle)
ch06_bad(screenshot-no-directory "cannot write screenshot '/nonexistent-dir/out.png': directory '/nonexistent-dir' does not exist"
         --screenshot /nonexistent-dir/out.png)
ch06_bad(screenshot-is-directory "must end in .png" --screenshot ${TEST_OUT})
ch06_bad(screenshot-directory-named-png "cannot write screenshot '.*dir.png': it is a directory"
         --screenshot ${TEST_OUT}/dir.png)
ch06_bad(no-such-device "no Vulkan device matches --device 'no-such-gpu' \\(devices: '" --device no-such-gpu)
ch06_bad(resize-without-frames "--resize needs --frames 2 or more" --resize 64x64)
file(MAKE_DIRECTORY ${TEST_OUT}/dir.png)

# A damaged or foreign pipeline cache is ignored with a warning and then replaced.
add_test(NAME chapter-06.pipeline-cache COMMAND ${CMAKE_COMMAND} -DCHAPTER=${CH06}
         -DCACHE_HOME=${CMAKE_CURRENT_BINARY_DIR}/cache-test-06 -P ${CMAKE_CURRENT_SOURCE_DIR}/chapters/pipeline_cache.cmake)
# A run killed between writing its new cache and the rename that replaces the old one: the old
# cache whole, the next run quiet (gdb stops it at rename(), tests/reliability/cache_crash.sh). And runs at
# once, several rounds, sharing one cache: every run quiet.
find_program(GDB gdb)
if(GDB AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
    chapter_test(chapter-06.pipeline-cache-killed-at-rename
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/reliability/cache_crash.sh $<TARGET_FILE:chapter-06> --headless --device llvmpipe
                --frames 1
        EXPECT_STDOUT "killed at rename.*the old cache is whole.*the next run loads the old cache")
endif()
chapter_test(chapter-15.pipeline-cache-concurrent-runs
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/reliability/concurrent_runs.sh 4 3 -- $<TARGET_FILE:chapter-15> --headless
            --device llvmpipe --validation --width 320 --height 180 --frames 2)
set_property(TEST chapter-15.pipeline-cache-concurrent-runs APPEND PROPERTY
    ENVIRONMENT XDG_CACHE_HOME=${CMAKE_CURRENT_BINARY_DIR}/cache-concurrent)

standalone_build_test(06 BUILD_TYPE Debug)  # shaders with debug information
