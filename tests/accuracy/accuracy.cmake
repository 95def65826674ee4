# Accuracy tests of chapter-15-lab (chapter-15's passes) on the hard scenes (tests/data/scenes/): every G-buffer layout renders
# with a finite, non-negative light output; on the same fp32 G-buffer the GPU's shading matches the
# CPU's fp64 shading (tests/accuracy/reference_render.cpp); and the compact layout comes closer
# than the book's to the reference (all-fp32 G-buffer, shaded in fp64).
set(ACCURACY_OUT ${TEST_OUT}/accuracy)
set(ACCURACY_SIZE --width 480 --height 270)
set(SCENE_DIR ${CMAKE_BINARY_DIR}/bin/scenes/default)
set(HARD_SCENES far-from-origin grazing-light light-touching-surface mirror-sphere intense-light)
set(REFERENCE_RENDER $<TARGET_FILE:reference_render>)

foreach(scene IN LISTS HARD_SCENES)
    configure_file(data/scenes/${scene}.json.in ${CMAKE_CURRENT_BINARY_DIR}/scenes/${scene}.json @ONLY)
    set(scene_file ${CMAKE_CURRENT_BINARY_DIR}/scenes/${scene}.json)
    foreach(layout reference book compact)
        chapter_test(accuracy.${scene}.render-${layout}
            COMMAND ${LAB} --device llvmpipe --validation --headless ${ACCURACY_SIZE} --scene ${scene_file}
                    --gbuffer ${layout} --check-output --dump ${ACCURACY_OUT}/${scene}-${layout}
            EXPECT_STDOUT "0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
        set_tests_properties(accuracy.${scene}.render-${layout} PROPERTIES FIXTURES_SETUP acc-${scene}-${layout})
    endforeach()
    # The shading itself: GPU against fp64 on the very same G-buffer (fp32, and the book's fp16).
    foreach(layout reference book)
        add_test(NAME accuracy.${scene}.shading-${layout}
            COMMAND ${REFERENCE_RENDER} ${scene_file} ${ACCURACY_OUT}/${scene}-${layout}
                    --compare ${layout}=${ACCURACY_OUT}/${scene}-${layout}/light.pfm --max-abs 0.05 --min-psnr 100)
        set_tests_properties(accuracy.${scene}.shading-${layout} PROPERTIES FIXTURES_REQUIRED acc-${scene}-${layout})
    endforeach()
    # The storage: each layout's image against the reference; compact must be the closer one.
    add_test(NAME accuracy.${scene}.compact-beats-book
        COMMAND ${REFERENCE_RENDER} ${scene_file} ${ACCURACY_OUT}/${scene}-reference
                --compare book=${ACCURACY_OUT}/${scene}-book/light.pfm
                --compare compact=${ACCURACY_OUT}/${scene}-compact/light.pfm --better compact book)
    set_tests_properties(accuracy.${scene}.compact-beats-book PROPERTIES
        FIXTURES_REQUIRED "acc-${scene}-reference;acc-${scene}-book;acc-${scene}-compact")
endforeach()
