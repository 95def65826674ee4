# chapter-18 tests: chapter-17's picture drawn through buffer device addresses -- the views against
# chapter-17's golden images (within 1/255 on 99.9% of the pixels), headless and in a window, with
# validation (synchronization validation on); the skinned vertices read back through the pointers'
# dispatches (a mesh in three chunks on a device of 64 groups a dispatch: each chunk's addresses offset right); the book's
# format and scene; what a pointer has no net for -- an index or a joint id past its buffer, in glTF
# and in the book's format -- refused at load in one line; a skinning shader without its bounds check
# caught; the standalone build. Devices without the features: tests/desktops/desktops.cmake.
set(CH18 $<TARGET_FILE:chapter-18>)
set(CH18_RUN ${CH18} --device llvmpipe --validation)

foreach(view final normal visibility)
    chapter_test(chapter-18.view-${view} WORKDIR /
        COMMAND ${CH18_RUN} --headless --width 640 --height 360 --view ${view} --animation-time 0.4
                --screenshot ${TEST_OUT}/chapter-18-${view}.png
        EXPECT_STDOUT "2 models, 2 meshes, 1241 vertices, 11 joints; dispatched in 1 frames" QUIET_STDERR)
    set_tests_properties(chapter-18.view-${view} PROPERTIES FIXTURES_SETUP ch18-${view})
    add_test(NAME chapter-18.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-18-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-${view}.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-18.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch18-${view})
endforeach()

if(XVFB_RUN)
    chapter_test(chapter-18.window-final
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH18_RUN} --width 640 --height 360 --frames 3
                --animation-time 0.4 --screenshot ${TEST_OUT}/chapter-18-window-final.png QUIET_STDERR)
    set_tests_properties(chapter-18.window-final PROPERTIES FIXTURES_SETUP ch18-window)
    add_test(NAME chapter-18.window-final-image COMMAND image_compare ${TEST_OUT}/chapter-18-window-final.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-final.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-18.window-final-image PROPERTIES FIXTURES_REQUIRED ch18-window)
endif()

# Playing 12 frames (two frames in flight: every skinned buffer rewritten while the frame before may
# still read it, ordered by the barrier before the dispatch): the GPU's vertices equal to the
# reference, and the image chapter-17's at the same frame.
chapter_test(chapter-18.play WORKDIR /
    COMMAND ${CH18_RUN} --headless --width 320 --height 180 --frames 12 --check-skinning
            --screenshot ${TEST_OUT}/chapter-18-play.png
    EXPECT_STDOUT "dispatched in 12 frames.*skinning check: 1241 vertices in 2 meshes.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-18.play PROPERTIES FIXTURES_SETUP ch18-play)
add_test(NAME chapter-18.play-image COMMAND image_compare ${TEST_OUT}/chapter-18-play.png --size 320 180
    --golden ${TEST_OUT}/chapter-17-play-scrolled.png --max-diff 1 --max-fraction 0.001)
set_tests_properties(chapter-18.play-image PROPERTIES FIXTURES_REQUIRED "ch18-play;ch17-play-scrolled")

# The hard cases of chapter-17's figures through pointers: 33 vertices (a group and one), 256 joints;
# and a mesh in chunks, each dispatch's addresses offset to its first vertex: a device that allows
# 64 groups a dispatch (the fault layer's VKBOOK_MAX_COMPUTE_GROUPS) takes a strip of 4,097
# vertices in three (2,048, 2,048 and 1), every vertex checked against the reference.
foreach(case strip33:33:1:0 chain256:6669:1:0 strip4097:4097:3:64)
    string(REPLACE ":" ";" parts ${case})
    list(GET parts 0 figure)
    list(GET parts 1 vertices)
    list(GET parts 2 dispatches)
    list(GET parts 3 groups)
    chapter_test(chapter-18.skin-${figure} WORKDIR /
        COMMAND ${CH18_RUN} --headless --width 320 --height 180 --frames 2 --check-skinning
                --model ${FIGURES}/${figure}.gltf
        EXPECT_STDOUT "${vertices} vertices, [0-9]+ joints. dispatched in 2 frames \\(${dispatches} dispatches each\\).*skinning check: ${vertices} vertices in 1 meshes.*guards intact"
        QUIET_STDERR)
    set_tests_properties(chapter-18.skin-${figure} PROPERTIES FIXTURES_REQUIRED ch17-figures)
    if(NOT groups EQUAL 0)
        set_property(TEST chapter-18.skin-${figure} APPEND PROPERTY ENVIRONMENT
                     XDG_DATA_HOME=${CMAKE_CURRENT_BINARY_DIR}/fault_layer VKBOOK_FAULT_LAYER=1
                     VKBOOK_MAX_COMPUTE_GROUPS=${groups})
    endif()
endforeach()

# The check can fail here too: chapter-18's skinning shader without its bounds check writes past a
# mesh of 31 vertices into the guard.
add_test(NAME chapter-18.check-finds-missing-bounds-check COMMAND sh -c
    "rm -rf $2 && cp -r $1 $2 && sed -i '/if (index >= dispatch.count) return;/d' $2/chapter-18/skin.comp && ! grep -q 'dispatch.count) return' $2/chapter-18/skin.comp && $0 --device llvmpipe --headless --frames 1 --check-skinning --shader-dir $2 --model $3 2>&1 | grep -q 'the skinning pass wrote past model 0.s mesh of 31 vertices'"
    ${CH18} ${PROJECT_SOURCE_DIR}/shaders ${CMAKE_CURRENT_BINARY_DIR}/shaders-no-bounds-check-18 ${FIGURES}/strip31.gltf)
set_tests_properties(chapter-18.check-finds-missing-bounds-check PROPERTIES FIXTURES_REQUIRED ch17-figures)

# The book's format and scene (tools/gltf_cases.cpp, writeBookFigure), played and read back.
chapter_test(chapter-18.book-scene WORKDIR /
    COMMAND ${CH18_RUN} --headless --width 320 --height 180 --frames 5 --check-skinning
            --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book
    EXPECT_STDOUT "chapter-18: 8 draws.*skinning: 1 models, 3 meshes, 466 vertices, 2 joints.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-18.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases)

# What a pointer reads without a net, refused when the model is loaded (one line, exit 2): an index
# past its mesh's vertices and a joint id past the skin's joints, in glTF and in the book's format.
set(SKINS ${CMAKE_CURRENT_BINARY_DIR}/gltf/skins)
set(GH ${CMAKE_CURRENT_BINARY_DIR}/gltf/hostile)
function(pointer_hostile name expected file)
    chapter_test(hostile.chapter-18-${name} COMMAND ${CH18} --device llvmpipe --headless --model ${file}
        EXPECT_EXIT 2 EXPECT_STDERR "^chapter-18: error: ${file}: ${expected}" ONE_LINE_STDERR)
    set_tests_properties(hostile.chapter-18-${name} PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
endfunction()
pointer_hostile(gltf-index-past "meshes\\[0\\].primitives\\[0\\] indices \\(accessor 2\\) refers to vertex 7 of 3"
    ${GH}/index_past_vertices.gltf)
pointer_hostile(gltf-joint-past "meshes\\[0\\].primitives\\[0\\] vertex 7 names joint 5. its skin has 2"
    ${SKINS}/joint_past_skin.gltf)
pointer_hostile(book-index-past "mesh 0's index 6 is 4, past its 4 vertices"
    ${CMAKE_CURRENT_BINARY_DIR}/gltf/book-hostile/index_past_vertices/tree.json)
pointer_hostile(book-joint-past "anim_meshes 0's vertex 7 names bone 7. the animations have 2 joints"
    ${SKINS}/book_bone_past.json)

standalone_build_test(18 --width 320 --height 180 --frames 3 --check-skinning)
