# The --gui overlay of chapters 14, 15, 16 and chapter-15-lab (common/app/gui.cpp, common/passes/gui_pass.cpp):
# golden images headless (the overlay is deterministic there: timings as placeholders); scripted
# clicks on the overlay (--gui-click); the buffers growing when the help window opens; a size too
# small for the overlay; the GUI pass's row in --benchmark; and in a real window under Xvfb,
# xdotool clicks, drags and F1. The lab's live switch of G-buffer layout and light pass is tested
# in chapter-15-lab.cmake.
foreach(chapter 14 15 15-lab)
    set(run $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation)
    chapter_test(chapter-${chapter}.gui
        COMMAND ${run} --headless --width 640 --height 360 --gui --screenshot ${TEST_OUT}/chapter-${chapter}-gui.png
        EXPECT_STDOUT "GUI buffers grew" QUIET_STDERR)
    set_tests_properties(chapter-${chapter}.gui PROPERTIES FIXTURES_SETUP ch${chapter}-gui)
    add_test(NAME chapter-${chapter}.gui-image COMMAND image_compare ${TEST_OUT}/chapter-${chapter}-gui.png
        --size 640 360 --golden ${GOLDEN}/chapter-${chapter}-gui.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-${chapter}.gui-image PROPERTIES FIXTURES_REQUIRED ch${chapter}-gui)
    # Too small for the overlay: it is clipped, nothing breaks.
    chapter_test(chapter-${chapter}.gui-tiny COMMAND ${run} --headless --width 64 --height 48 --gui QUIET_STDERR)
    chapter_test(chapter-${chapter}.gui-benchmark
        COMMAND ${run} --headless --width 320 --height 180 --gui --benchmark --warmup 0 --frames 3
        EXPECT_STDOUT "GPU gui +[0-9]" QUIET_STDERR)
endforeach()

# The help box (27,218) opens a window of text: the buffers grow (to more vertices than the
# overlay alone, about 1,450), without a validation message.
chapter_test(chapter-14.gui-help-grows
    COMMAND $<TARGET_FILE:chapter-14> --device llvmpipe --validation --headless --width 640 --height 360 --gui
            --frames 6 --gui-click 27,218@2
    EXPECT_STDOUT "GUI buffers grew [0-9]+ times, to [3-9][0-9][0-9][0-9] vertices" QUIET_STDERR)
# The FXAA box (27,241), clicked: the image shows it ticked (and is anti-aliased).
chapter_test(chapter-14.gui-click-fxaa
    COMMAND $<TARGET_FILE:chapter-14> --device llvmpipe --validation --headless --width 640 --height 360 --gui
            --frames 6 --gui-click 27,241@2 --screenshot ${TEST_OUT}/chapter-14-gui-fxaa.png QUIET_STDERR)
set_tests_properties(chapter-14.gui-click-fxaa PROPERTIES FIXTURES_SETUP ch14-gui-fxaa)
add_test(NAME chapter-14.gui-click-fxaa-ticked
    COMMAND image_compare ${TEST_OUT}/chapter-14-gui-fxaa.png --pixel 27 241 47 93 149 --pixel-tolerance 6)
set_tests_properties(chapter-14.gui-click-fxaa-ticked PROPERTIES FIXTURES_REQUIRED ch14-gui-fxaa)

# chapter-16: the overlay after three frames (its shadow rows: each cascade's slice, texel and
# draws); "show cascades" (253,160) clicked: the box ticked and the floor tinted by its cascade
# (green, the second; untinted it is 80,71,58).
set(run16 $<TARGET_FILE:chapter-16> --device llvmpipe --validation --headless)
chapter_test(chapter-16.gui
    COMMAND ${run16} --width 640 --height 360 --gui --frames 3 --screenshot ${TEST_OUT}/chapter-16-gui.png
    EXPECT_STDOUT "GUI buffers grew" QUIET_STDERR)
set_tests_properties(chapter-16.gui PROPERTIES FIXTURES_SETUP ch16-gui)
add_test(NAME chapter-16.gui-image COMMAND image_compare ${TEST_OUT}/chapter-16-gui.png
    --size 640 360 --golden ${GOLDEN}/chapter-16-gui.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-16.gui-image PROPERTIES FIXTURES_REQUIRED ch16-gui)
chapter_test(chapter-16.gui-tiny COMMAND ${run16} --width 64 --height 48 --gui --frames 3 QUIET_STDERR)
chapter_test(chapter-16.gui-benchmark
    COMMAND ${run16} --width 320 --height 180 --gui --benchmark --warmup 0 --frames 3
    EXPECT_STDOUT "GPU gui +[0-9]" QUIET_STDERR)
chapter_test(chapter-16.gui-click-cascades
    COMMAND ${run16} --width 640 --height 360 --gui --frames 6 --gui-click 253,160@3
            --screenshot ${TEST_OUT}/chapter-16-gui-cascades.png QUIET_STDERR)
set_tests_properties(chapter-16.gui-click-cascades PROPERTIES FIXTURES_SETUP ch16-gui-cascades)
add_test(NAME chapter-16.gui-click-cascades-shown COMMAND image_compare ${TEST_OUT}/chapter-16-gui-cascades.png
    --pixel 253 160 66 150 250 --pixel 320 340 39 71 26 --pixel-tolerance 6)
set_tests_properties(chapter-16.gui-click-cascades-shown PROPERTIES FIXTURES_REQUIRED ch16-gui-cascades)

chapter_test(chapter-15.gui-click-bad COMMAND $<TARGET_FILE:chapter-15> --headless --gui --gui-click 10,20
    EXPECT_EXIT 2 EXPECT_STDERR "--gui-click must be X,Y@FRAME" ONE_LINE_STDERR)

if(XVFB_RUN)
    find_program(XDOTOOL xdotool)
    if(XDOTOOL)
        set(window_options --device llvmpipe --validation --width 640 --height 360 --gui)
        chapter_test(chapter-14.window-gui-click
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_gui.sh click
                    $<TARGET_FILE:chapter-14> ${TEST_OUT}/chapter-14-window-gui-click.png ${window_options}
            QUIET_STDERR)
        set_tests_properties(chapter-14.window-gui-click PROPERTIES FIXTURES_SETUP ch14-window-gui-click)
        add_test(NAME chapter-14.window-gui-click-ticked
            COMMAND image_compare ${TEST_OUT}/chapter-14-window-gui-click.png --pixel 27 241 47 93 149
                    --pixel-tolerance 6)
        set_tests_properties(chapter-14.window-gui-click-ticked PROPERTIES FIXTURES_REQUIRED ch14-window-gui-click)
        chapter_test(chapter-14.window-gui-f1
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_gui.sh f1
                    $<TARGET_FILE:chapter-14> ${TEST_OUT}/chapter-14-window-gui-f1.png ${window_options}
            QUIET_STDERR)
        set_tests_properties(chapter-14.window-gui-f1 PROPERTIES FIXTURES_SETUP ch14-window-gui-f1)
        # The overlay's title bar (41,74,122) is gone: the sky behind it is black.
        add_test(NAME chapter-14.window-gui-f1-hidden
            COMMAND image_compare ${TEST_OUT}/chapter-14-window-gui-f1.png --pixel 100 18 0 0 0 --pixel-tolerance 6)
        set_tests_properties(chapter-14.window-gui-f1-hidden PROPERTIES FIXTURES_REQUIRED ch14-window-gui-f1)
        foreach(mode drag-overlay drag-scene)
            chapter_test(chapter-15.window-gui-${mode}
                COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_gui.sh ${mode}
                        $<TARGET_FILE:chapter-15> ${window_options}
                QUIET_STDERR)
        endforeach()
    else()
        message(WARNING "xdotool not found: the windowed GUI tests are not registered (apt-get install xdotool)")
    endif()
endif()
