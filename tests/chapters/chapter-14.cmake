# chapter-14 tests: every view against its golden image, the same images as chapter-10 (the two
# chapters compute the same thing), 1, 2 and 3 frames in flight, FXAA, a window resized under Xvfb.
set(CH14 $<TARGET_FILE:chapter-14>)
set(CH14_RUN ${CH14} --device llvmpipe --validation)
set(CH14_SIZE --width 640 --height 360)

foreach(view final albedo depth)
    chapter_test(chapter-14.view-${view} WORKDIR /
        COMMAND ${CH14_RUN} --headless ${CH14_SIZE} --view ${view} --screenshot ${TEST_OUT}/chapter-14-${view}.png
        EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    set_tests_properties(chapter-14.view-${view} PROPERTIES FIXTURES_SETUP ch14-${view})
    add_test(NAME chapter-14.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-14-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-14-${view}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-14.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch14-${view})
    # Render-pass deferred shading (chapter-10) and dynamic rendering (chapter-14) agree, on
    # images both rendered in this run.
    add_test(NAME chapter-14.same-as-chapter-10-${view} COMMAND image_compare ${TEST_OUT}/chapter-14-${view}.png
        --golden ${TEST_OUT}/chapter-10-${view}.png --max-diff 1 --max-fraction 0)
    set_tests_properties(chapter-14.same-as-chapter-10-${view} PROPERTIES FIXTURES_REQUIRED "ch14-${view};ch10-${view}")
endforeach()

# 1, 2 and 3 frames in flight, more frames than that: no message, the same image.
foreach(inflight 1 2 3)
    chapter_test(chapter-14.frames-in-flight-${inflight}
        COMMAND ${CH14_RUN} --headless ${CH14_SIZE} --frames 7 --frames-in-flight ${inflight}
                --screenshot ${TEST_OUT}/chapter-14-inflight-${inflight}.png QUIET_STDERR)
    set_tests_properties(chapter-14.frames-in-flight-${inflight} PROPERTIES FIXTURES_SETUP ch14-inflight-${inflight})
    add_test(NAME chapter-14.frames-in-flight-${inflight}-image
        COMMAND image_compare ${TEST_OUT}/chapter-14-inflight-${inflight}.png --size 640 360
                --golden ${GOLDEN}/chapter-14-final.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-14.frames-in-flight-${inflight}-image PROPERTIES
        FIXTURES_REQUIRED ch14-inflight-${inflight})
endforeach()

# FXAA (a specialization constant of the post pass).
chapter_test(chapter-14.fxaa COMMAND ${CH14_RUN} --headless ${CH14_SIZE} --fxaa
    --screenshot ${TEST_OUT}/chapter-14-fxaa.png QUIET_STDERR)
set_tests_properties(chapter-14.fxaa PROPERTIES FIXTURES_SETUP ch14-fxaa)
add_test(NAME chapter-14.fxaa-image COMMAND image_compare ${TEST_OUT}/chapter-14-fxaa.png --size 640 360
    --golden ${GOLDEN}/chapter-14-fxaa.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-14.fxaa-image PROPERTIES FIXTURES_REQUIRED ch14-fxaa)

if(XVFB_RUN)
    chapter_test(chapter-14.window
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH14_RUN} ${CH14_SIZE} --frames 30 --resize 800x450
                --screenshot ${TEST_OUT}/chapter-14-window.png QUIET_STDERR)
    set_tests_properties(chapter-14.window PROPERTIES FIXTURES_SETUP ch14-window)
    add_test(NAME chapter-14.window-image COMMAND image_compare ${TEST_OUT}/chapter-14-window.png --size 800 450)
    set_tests_properties(chapter-14.window-image PROPERTIES FIXTURES_REQUIRED ch14-window)
endif()

chapter_test(chapter-14.model COMMAND ${CH14_RUN} --headless ${CH14_SIZE}
    --model $<TARGET_FILE_DIR:chapter-14>/scenes/default/courtyard.obj --screenshot ${TEST_OUT}/chapter-14-model.png
    QUIET_STDERR)
set_tests_properties(chapter-14.model PROPERTIES FIXTURES_SETUP ch14-model)
add_test(NAME chapter-14.model-image COMMAND image_compare ${TEST_OUT}/chapter-14-model.png
    --golden ${GOLDEN}/chapter-10-model.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-14.model-image PROPERTIES FIXTURES_REQUIRED ch14-model)

chapter_test(chapter-14.bad-scene COMMAND ${CH14_RUN} --headless --scene ${DATA}/wrong_type.json
    EXPECT_EXIT 2 EXPECT_STDERR "^chapter-14: error: .*wrong_type.json: models\\[0\\].scale" ONE_LINE_STDERR)
chapter_test(chapter-14.bad-frames-in-flight COMMAND ${CH14} --headless --frames-in-flight 4
    EXPECT_EXIT 2 EXPECT_STDERR "--frames-in-flight must be between 1 and 3, got 4" ONE_LINE_STDERR)

standalone_build_test(14 --width 320 --height 180)
