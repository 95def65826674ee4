# chapter-15-lab: what goes beyond the book, on chapter-15's passes. Its tests here: the compute
# light pass against the fragment one, and the overlay's live switch; chapters/light_culling.cmake,
# chapters/forward_shading.cmake and accuracy/accuracy.cmake hold the rest. Without options the lab renders what
# chapter-15 renders: its final image against chapter-15's golden image.
set(LAB $<TARGET_FILE:chapter-15-lab>)
set(LAB_RUN ${LAB} --device llvmpipe --validation)
set(LAB_SIZE --width 640 --height 360)

chapter_test(chapter-15-lab.book-final WORKDIR /
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --screenshot ${TEST_OUT}/chapter-15-lab-book-final.png --check-output
    EXPECT_STDOUT "chapter-15-lab: 19 draws, 70656 triangles.*0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
set_tests_properties(chapter-15-lab.book-final PROPERTIES FIXTURES_SETUP lab-book-final)
add_test(NAME chapter-15-lab.book-final-image COMMAND image_compare ${TEST_OUT}/chapter-15-lab-book-final.png
    --size 640 360 --golden ${GOLDEN}/chapter-15-final.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-15-lab.book-final-image PROPERTIES FIXTURES_REQUIRED lab-book-final)

standalone_build_test(15-lab --width 320 --height 180)

# --light-pass compute: the same shading in a compute dispatch. Its image must match the fragment
# form's rendered in this test run (views final and normal, both layouts), within one 8-bit step;
# the final image also against the golden image; resizing rewrites its storage-image descriptor.
foreach(layout book compact)
    foreach(view final normal)
        foreach(kind fragment compute)
            set(name chapter-15-lab.light-${kind}-${layout}-${view})
            chapter_test(${name}
                COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --gbuffer ${layout} --light-pass ${kind} --view ${view}
                        --screenshot ${TEST_OUT}/${name}.png QUIET_STDERR)
            set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name})
        endforeach()
        add_test(NAME chapter-15-lab.light-compute-${layout}-${view}-matches-fragment
            COMMAND image_compare ${TEST_OUT}/chapter-15-lab.light-compute-${layout}-${view}.png --size 640 360
                    --golden ${TEST_OUT}/chapter-15-lab.light-fragment-${layout}-${view}.png --max-diff 1 --max-fraction 0)
        set_tests_properties(chapter-15-lab.light-compute-${layout}-${view}-matches-fragment PROPERTIES
            FIXTURES_REQUIRED "chapter-15-lab.light-compute-${layout}-${view};chapter-15-lab.light-fragment-${layout}-${view}")
    endforeach()
endforeach()
add_test(NAME chapter-15-lab.light-compute-book-final-image
    COMMAND image_compare ${TEST_OUT}/chapter-15-lab.light-compute-book-final.png --size 640 360
            --golden ${GOLDEN}/chapter-15-final.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-15-lab.light-compute-book-final-image PROPERTIES
    FIXTURES_REQUIRED chapter-15-lab.light-compute-book-final)
chapter_test(chapter-15-lab.light-compute-resize
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --light-pass compute --frames 4 --resize 333x197 --check-output
    EXPECT_STDOUT "light output 333x197: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
chapter_test(chapter-15-lab.bad-light-pass COMMAND ${LAB_RUN} --headless --light-pass tiles
    EXPECT_EXIT 2 EXPECT_STDERR "--light-pass must be one of fragment\\|compute" ONE_LINE_STDERR)

# The overlay's G-buffer combo (80,264), then "compact" in its list (45,322); then a resize
# (at frame 7 of 14): the G-buffer and every pass made again, validation-clean.
chapter_test(chapter-15-lab.gui-switch-gbuffer
    COMMAND ${LAB} --device llvmpipe --validation --headless --width 640 --height 360 --gui
            --frames 14 --resize 500x300 --gui-click 80,264@2+45,322@5 --check-output
    EXPECT_STDOUT "switched to the compact G-buffer, fragment light pass.*0 NaN, 0 infinite, 0 negative"
    QUIET_STDERR)
# ... and the light-pass combo (80,287), "compute" (45,328), with three frames in flight.
chapter_test(chapter-15-lab.gui-switch-light-pass
    COMMAND ${LAB} --device llvmpipe --validation --headless --width 640 --height 360 --gui
            --frames 10 --frames-in-flight 3 --gui-click 80,287@2+45,328@5 --check-output
    EXPECT_STDOUT "switched to the book G-buffer, compute light pass.*0 NaN, 0 infinite, 0 negative" QUIET_STDERR)

# --acquire late: the off-screen passes submitted before the image is acquired; the same image as
# the book's order, over frames and a resize, with synchronization validation quiet.
chapter_test(chapter-15-lab.acquire-late
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --acquire late --frames 6 --resize 500x300 --gui
    QUIET_STDERR)
chapter_test(chapter-15-lab.acquire-late-final
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --acquire late --frames 3
            --screenshot ${TEST_OUT}/chapter-15-lab-acquire-late.png QUIET_STDERR)
set_tests_properties(chapter-15-lab.acquire-late-final PROPERTIES FIXTURES_SETUP lab-acquire-late)
add_test(NAME chapter-15-lab.acquire-late-image COMMAND image_compare ${TEST_OUT}/chapter-15-lab-acquire-late.png
    --size 640 360 --golden ${GOLDEN}/chapter-15-final.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-15-lab.acquire-late-image PROPERTIES FIXTURES_REQUIRED lab-acquire-late)
if(XVFB_RUN)
    chapter_test(chapter-15-lab.acquire-late-window
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${LAB_RUN} ${LAB_SIZE} --acquire late --frames 30
                --resize 500x300 --gui QUIET_STDERR)
endif()
