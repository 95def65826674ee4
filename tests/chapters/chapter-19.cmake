# chapter-19 tests: chapter-18's picture drawn from buffers of draw commands -- the views against
# chapter-17's golden images (within 1/255 on 99.9% of the pixels), headless and in a window, with
# validation (synchronization validation on); playing, with the skinned figures' own commands; the
# instanced path (1,000 draws of one mesh and material: one command, one indirect draw) against
# chapter-18's image of the same scene; buffers grown by capacity (a walk whose shadow draws change
# every frame makes each slot's three buffers once); a mesh without a material; the book's scene;
# the standalone build. Devices without the features: tests/desktops/desktops.cmake; the host-side
# commands and groups: tests/unit/global_buffers_test.cpp.
set(CH19 $<TARGET_FILE:chapter-19>)
set(CH19_RUN ${CH19} --device llvmpipe --validation)

foreach(view final normal visibility)
    chapter_test(chapter-19.view-${view} WORKDIR /
        COMMAND ${CH19_RUN} --headless --width 640 --height 360 --view ${view} --animation-time 0.4
                --screenshot ${TEST_OUT}/chapter-19-${view}.png
        EXPECT_STDOUT "2 models, 2 meshes, 1241 vertices, 11 joints; dispatched in 1 frames" QUIET_STDERR)
    set_tests_properties(chapter-19.view-${view} PROPERTIES FIXTURES_SETUP ch19-${view})
    add_test(NAME chapter-19.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-19-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-${view}.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-19.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch19-${view})
endforeach()

if(XVFB_RUN)
    chapter_test(chapter-19.window-final
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH19_RUN} --width 640 --height 360 --frames 3
                --animation-time 0.4 --screenshot ${TEST_OUT}/chapter-19-window-final.png QUIET_STDERR)
    set_tests_properties(chapter-19.window-final PROPERTIES FIXTURES_SETUP ch19-window)
    add_test(NAME chapter-19.window-final-image COMMAND image_compare ${TEST_OUT}/chapter-19-window-final.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-final.png --max-diff 1 --max-fraction 0.001)
    set_tests_properties(chapter-19.window-final-image PROPERTIES FIXTURES_REQUIRED ch19-window)
endif()

# Playing 12 frames: each figure's posed mesh a command of its own; the skinned vertices against the
# reference, the image chapter-17's at the same frame.
chapter_test(chapter-19.play WORKDIR /
    COMMAND ${CH19_RUN} --headless --width 320 --height 180 --frames 12 --check-skinning
            --screenshot ${TEST_OUT}/chapter-19-play.png
    EXPECT_STDOUT "indirect: scene 21 commands for 21 instances in 21 indirect draws.*skinning check: 1241 vertices in 2 meshes.*guards intact"
    QUIET_STDERR)
set_tests_properties(chapter-19.play PROPERTIES FIXTURES_SETUP ch19-play)
add_test(NAME chapter-19.play-image COMMAND image_compare ${TEST_OUT}/chapter-19-play.png --size 320 180
    --golden ${TEST_OUT}/chapter-17-play-scrolled.png --max-diff 1 --max-fraction 0.001)
set_tests_properties(chapter-19.play-image PROPERTIES FIXTURES_REQUIRED "ch19-play;ch17-play-scrolled")

# The instanced path, which the book's scene never takes: 1,000 placements of one cube
# (bench/instance_scene.py), one command of 1,000 instances in one indirect draw per pass; the image
# chapter-18's, which draws them one by one.
set(INSTANCES ${CMAKE_CURRENT_BINARY_DIR}/instances-1000.json)
add_test(NAME chapter-19.instance-scene COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/bench/instance_scene.py
    1000 ${INSTANCES} $<TARGET_FILE_DIR:chapter-19>/scenes/default)
set_tests_properties(chapter-19.instance-scene PROPERTIES FIXTURES_SETUP ch19-instance-scene)
foreach(number 18 19)
    set(expect "chapter-18: 1000 draws")
    if(number STREQUAL "19")
        set(expect "indirect: scene 1 commands for 1000 instances in 1 indirect draws. shadow 1 commands for 1000 instances in 1 indirect draws")
    endif()
    chapter_test(chapter-19.instanced-${number} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless --width 320 --height 180
                --scene ${INSTANCES} --screenshot ${TEST_OUT}/chapter-19-instanced-${number}.png
        EXPECT_STDOUT "${expect}" QUIET_STDERR)
    set_tests_properties(chapter-19.instanced-${number} PROPERTIES FIXTURES_REQUIRED ch19-instance-scene
                         FIXTURES_SETUP ch19-instanced-${number})
endforeach()
add_test(NAME chapter-19.instanced-image COMMAND image_compare ${TEST_OUT}/chapter-19-instanced-19.png --size 320 180
    --golden ${TEST_OUT}/chapter-19-instanced-18.png --max-diff 1 --max-fraction 0.001)
set_tests_properties(chapter-19.instanced-image PROPERTIES FIXTURES_REQUIRED "ch19-instanced-18;ch19-instanced-19")

# Buffers grow by their capacity, not by last frame's count: a figure walking out of a cascade
# changes the shadow pass's draws every frame, and each frame slot still makes its matrices,
# instances and commands once (two slots: six buffers in 30 frames).
chapter_test(chapter-19.buffers-grow-once WORKDIR /
    COMMAND ${CH19_RUN} --headless --width 320 --height 180 --frames 30
            --scene $<TARGET_FILE_DIR:chapter-19>/scenes/default/walk-away.json
    EXPECT_STDOUT "indirect: scene [0-9]+ commands .* 6 buffers made" QUIET_STDERR)

# A mesh of the book's format without a material id: drawn with the default material (the book's
# sample writes index -1), as chapter-18 draws it.
foreach(number 18 19)
    chapter_test(chapter-19.no-material-${number} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless --width 320 --height 180
                --model ${CMAKE_CURRENT_BINARY_DIR}/gltf/book-hostile/windows_paths/tree.json
                --screenshot ${TEST_OUT}/chapter-19-no-material-${number}.png
        EXPECT_STDOUT "2 draws" QUIET_STDERR)
    set_tests_properties(chapter-19.no-material-${number} PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases"
                         FIXTURES_SETUP ch19-no-material-${number})
endforeach()
add_test(NAME chapter-19.no-material-image COMMAND image_compare ${TEST_OUT}/chapter-19-no-material-19.png
    --size 320 180 --golden ${TEST_OUT}/chapter-19-no-material-18.png --max-diff 1 --max-fraction 0.001)
set_tests_properties(chapter-19.no-material-image PROPERTIES FIXTURES_REQUIRED "ch19-no-material-18;ch19-no-material-19")

# The book's scene with Bob's format.
chapter_test(chapter-19.book-scene WORKDIR /
    COMMAND ${CH19_RUN} --headless --width 320 --height 180 --frames 5 --check-skinning
            --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book
    EXPECT_STDOUT "chapter-19: 8 draws.*skinning: 1 models, 3 meshes, 466 vertices, 2 joints.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-19.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases)

# An index past its mesh: refused at load, as in chapter-18 (the instances' pointers have no net).
chapter_test(hostile.chapter-19-gltf-index-past COMMAND ${CH19} --device llvmpipe --headless
        --model ${CMAKE_CURRENT_BINARY_DIR}/gltf/hostile/index_past_vertices.gltf
    EXPECT_EXIT 2 EXPECT_STDERR "^chapter-19: error: .*index_past_vertices.gltf: meshes\\[0\\].primitives\\[0\\] indices \\(accessor 2\\) refers to vertex 7 of 3"
    ONE_LINE_STDERR)
set_tests_properties(hostile.chapter-19-gltf-index-past PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")

standalone_build_test(19 --width 320 --height 180 --frames 3 --check-skinning)
