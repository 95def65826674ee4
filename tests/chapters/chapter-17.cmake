# chapter-17 tests: the default scene's figures at a fixed animation time against golden images (the
# final image, a G-buffer view, the sun's visibility), with validation (synchronization validation
# on); the GPU's skinned vertices read back against the double-precision reference on the hard
# cases (vertex counts around the group of 32 and past 2^20, 256 joints, the fourth weight, a
# non-uniformly scaled joint, keys on opposite hemispheres, one key frame) with the guard past each
# buffer intact; a pose that does not change costs no dispatch; hostile skins and animations
# refused in one line; the standalone build.
set(CH17 $<TARGET_FILE:chapter-17>)
set(CH17_RUN ${CH17} --device llvmpipe --validation)
set(FIGURES ${CMAKE_CURRENT_BINARY_DIR}/figures)

foreach(view final normal visibility)
    chapter_test(chapter-17.view-${view} WORKDIR /
        COMMAND ${CH17_RUN} --headless --width 640 --height 360 --view ${view} --animation-time 0.4
                --screenshot ${TEST_OUT}/chapter-17-${view}.png
        EXPECT_STDOUT "2 models, 2 meshes, 1241 vertices, 11 joints; dispatched in 1 frames" QUIET_STDERR)
    set_tests_properties(chapter-17.view-${view} PROPERTIES FIXTURES_SETUP ch17-${view})
    add_test(NAME chapter-17.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-17-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-${view}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-17.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch17-${view})
endforeach()

# In a window (Xvfb), at the same time: the headless golden images.
if(XVFB_RUN)
    chapter_test(chapter-17.window-final
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH17_RUN} --width 640 --height 360 --frames 3
                --animation-time 0.4 --screenshot ${TEST_OUT}/chapter-17-window-final.png QUIET_STDERR)
    set_tests_properties(chapter-17.window-final PROPERTIES FIXTURES_SETUP ch17-window)
    add_test(NAME chapter-17.window-final-image COMMAND image_compare ${TEST_OUT}/chapter-17-window-final.png
        --size 640 360 --golden ${GOLDEN}/chapter-17-final.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-17.window-final-image PROPERTIES FIXTURES_REQUIRED ch17-window)
endif()

# Playing: the figures posed every frame, the GPU's vertices equal to the reference; the shadow
# cache draws them as moving casters (the cascades drawn whole once, on the first frame) and the
# image is the one the book's way (every cascade redrawn every frame) gives, to the bit.
foreach(redraw scrolled always)
    set(whole "whole 1, 1, 1")  # scrolled: each cascade drawn whole once, on the first frame
    if(redraw STREQUAL "always")
        set(whole "whole 12, 12, 12")
    endif()
    chapter_test(chapter-17.play-${redraw} WORKDIR /
        COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 12 --shadow-redraw ${redraw}
                --check-skinning --screenshot ${TEST_OUT}/chapter-17-play-${redraw}.png
        EXPECT_STDOUT "${whole}.*dispatched in 12 frames.*skinning check: 1241 vertices in 2 meshes.*guards intact"
        QUIET_STDERR)
    set_tests_properties(chapter-17.play-${redraw} PROPERTIES FIXTURES_SETUP ch17-play-${redraw})
endforeach()
add_test(NAME chapter-17.play-same-image COMMAND image_compare ${TEST_OUT}/chapter-17-play-scrolled.png
    --size 320 180 --golden ${TEST_OUT}/chapter-17-play-always.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-17.play-same-image PROPERTIES FIXTURES_REQUIRED "ch17-play-scrolled;ch17-play-always")

# A figure that walks out of a cascade (the default scene's walk-away.json: 30 m away from the camera
# in a second, half a metre a frame): drawn apart as a moving caster in cascade 1 while it is in
# it, and in cascade 2 throughout, never redrawing a cascade whole; at frame 10 (in cascade 1), 18
# (just out of it) and 30, the image is the one redrawing every cascade every frame gives, to the
# bit (no shadow left behind where it was, none missing where it is).
set(WALK_AWAY $<TARGET_FILE_DIR:chapter-17>/scenes/default/walk-away.json)
foreach(frames 10 18 30)
    foreach(redraw scrolled always)
        set(expect "whole ${frames}, ${frames}, ${frames}")
        if(redraw STREQUAL "scrolled")
            # In cascade 1 from the first frame to the 17th (drawn apart after the first, which
            # draws every cascade whole), in cascade 2 throughout: 9, 17 and 17 frames of 10, 18, 30.
            math(EXPR last "${frames} - 1")
            set(inFirst ${last})
            if(frames GREATER 18)
                set(inFirst 17)
            endif()
            set(expect "whole 1, 1, 1.*moving casters drawn apart in 0, ${inFirst}, ${last} frames")
        endif()
        chapter_test(chapter-17.walk-away-${frames}-${redraw} WORKDIR /
            COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames ${frames} --shadow-redraw ${redraw}
                    --scene ${WALK_AWAY} --screenshot ${TEST_OUT}/chapter-17-walk-away-${frames}-${redraw}.png
            EXPECT_STDOUT "${expect}" QUIET_STDERR)
        set_tests_properties(chapter-17.walk-away-${frames}-${redraw} PROPERTIES
            FIXTURES_SETUP ch17-walk-away-${frames}-${redraw})
    endforeach()
    add_test(NAME chapter-17.walk-away-${frames}-same-image COMMAND image_compare
        ${TEST_OUT}/chapter-17-walk-away-${frames}-scrolled.png --size 320 180
        --golden ${TEST_OUT}/chapter-17-walk-away-${frames}-always.png --max-diff 0 --max-fraction 0)
    set_tests_properties(chapter-17.walk-away-${frames}-same-image PROPERTIES
        FIXTURES_REQUIRED "ch17-walk-away-${frames}-scrolled;ch17-walk-away-${frames}-always")
endforeach()

# What does not change costs nothing: a fixed time is skinned once, however many frames; a scene
# without animated models makes no pass at all.
chapter_test(chapter-17.fixed-time-skins-once WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 6 --animation-time 0.25
    EXPECT_STDOUT "dispatched in 1 frames" QUIET_STDERR)
chapter_test(chapter-17.nothing-animated WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 2
            --scene $<TARGET_FILE_DIR:chapter-17>/scenes/default/scene.json
    EXPECT_STDOUT "skinning: none \\(nothing in the scene is animated\\)" QUIET_STDERR)
# Looping: eleven days into the clips (10^6 s, a whole number of both clips' lengths) is their
# start, to the bit.
foreach(time 0 1000000)
    chapter_test(chapter-17.time-${time} WORKDIR /
        COMMAND ${CH17_RUN} --headless --width 320 --height 180 --animation-time ${time}
                --screenshot ${TEST_OUT}/chapter-17-time-${time}.png QUIET_STDERR)
    set_tests_properties(chapter-17.time-${time} PROPERTIES FIXTURES_SETUP ch17-time-${time})
endforeach()
add_test(NAME chapter-17.time-loops-exactly COMMAND image_compare ${TEST_OUT}/chapter-17-time-1000000.png
    --size 320 180 --golden ${TEST_OUT}/chapter-17-time-0.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-17.time-loops-exactly PROPERTIES FIXTURES_REQUIRED "ch17-time-0;ch17-time-1000000")
foreach(bad -1 nan inf 1e10 2s 0x10)
    chapter_test(chapter-17.animation-time-${bad} COMMAND ${CH17} --headless --animation-time "${bad}"
        EXPECT_EXIT 2 EXPECT_STDERR "--animation-time must be a number of seconds from 0 to 1e9, got '${bad}'"
        ONE_LINE_STDERR)
endforeach()

# The hard cases (scenes/generate_figure.cpp), each played three frames and read back.
add_test(NAME chapter-17.generate-figures COMMAND sh -c
    "mkdir -p \"$FIGURES\" && for spec in 'strip 1' 'strip 31' 'strip 33' 'strip 4097' 'strip 1048577' 'strip 3145728' 'chain 256' fourth scaled hemispheres one-key tube walker arm; do set -- $spec; \"$0\" $1 \"$FIGURES/$1$2.gltf\" $2 || exit 1; done"
    $<TARGET_FILE:generate_figure>)
set_tests_properties(chapter-17.generate-figures PROPERTIES FIXTURES_SETUP ch17-figures
    ENVIRONMENT FIGURES=${FIGURES})
foreach(case strip1:1 strip31:31 strip33:33 strip1048577:1048577 strip3145728:3145728 chain256:6669 fourth:1025 scaled:1025
             hemispheres:1025 one-key:1025 tube:2145 walker:216 arm:1025)
    string(REPLACE ":" ";" parts ${case})
    list(GET parts 0 figure)
    list(GET parts 1 vertices)
    set(dispatches 1)
    if(vertices GREATER 2097120)  # 65,535 groups of 32, lavapipe's maxComputeWorkGroupCount[0]
        set(dispatches 2)
    endif()
    chapter_test(chapter-17.skin-${figure} WORKDIR /
        COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 3 --check-skinning
                --model ${FIGURES}/${figure}.gltf
        EXPECT_STDOUT "${vertices} vertices, [0-9]+ joints. dispatched in 3 frames \\(${dispatches} dispatches each\\).*skinning check: ${vertices} vertices in 1 meshes.*guards intact"
        QUIET_STDERR)
    set_tests_properties(chapter-17.skin-${figure} PROPERTIES FIXTURES_REQUIRED ch17-figures)
endforeach()
# 3 x 2^20 vertices: more groups than lavapipe's maxComputeWorkGroupCount[0] (65,535) -- two dispatches.
set_tests_properties(chapter-17.skin-strip1048577 chapter-17.skin-strip3145728 PROPERTIES TIMEOUT 300)


# The check can fail: the skinning shader without its bounds check writes past a mesh of 31
# vertices into the guard, and the run says so.
add_test(NAME chapter-17.check-finds-missing-bounds-check COMMAND sh -c
    "rm -rf $2 && cp -r $1 $2 && sed -i '/if (index >= dispatch.count) return;/d' $2/chapter-17/skin.comp && ! grep -q 'dispatch.count) return' $2/chapter-17/skin.comp && $0 --device llvmpipe --headless --frames 1 --check-skinning --shader-dir $2 --model $3 2>&1 | grep -q 'the skinning pass wrote past model 0.s mesh of 31 vertices'"
    ${CH17} ${PROJECT_SOURCE_DIR}/shaders ${CMAKE_CURRENT_BINARY_DIR}/shaders-no-bounds-check ${FIGURES}/strip31.gltf)
set_tests_properties(chapter-17.check-finds-missing-bounds-check PROPERTIES FIXTURES_REQUIRED ch17-figures)

# Skins and animations that break the rules (tools/gltf_cases.cpp, skins/): one line each, exit 2.
set(SKINS ${CMAKE_CURRENT_BINARY_DIR}/gltf/skins)
function(skin_hostile name expected file)
    chapter_test(hostile.skin-${name} COMMAND ${CH17} --device llvmpipe --headless --model ${SKINS}/${file}
        EXPECT_EXIT 2 EXPECT_STDERR "^chapter-17: error: ${SKINS}/${file}: ${expected}" ONE_LINE_STDERR)
    set_tests_properties(hostile.skin-${name} PROPERTIES FIXTURES_REQUIRED gltf-cases)
endfunction()
skin_hostile(joint-past-skin "meshes\\[0\\].primitives\\[0\\] vertex 7 names joint 5. its skin has 2" joint_past_skin.gltf)
skin_hostile(negative-weight "meshes\\[0\\].primitives\\[0\\] vertex 7 has a negative weight" negative_weight.gltf)
skin_hostile(weights-sum-half "meshes\\[0\\].primitives\\[0\\] vertex 7's weights sum to 0.5, not 1"
    weights_sum_half.gltf)
# A legal tiny scale (1e-40 on the elbow) is drawn, its normals' matrix by the cofactors, not refused as
# not finite.
chapter_test(chapter-17.scale-tiny WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 3 --check-skinning --model ${SKINS}/scale_tiny.gltf
    EXPECT_STDOUT "skinning check: .*guards intact" QUIET_STDERR)
set_tests_properties(chapter-17.scale-tiny PROPERTIES FIXTURES_REQUIRED gltf-cases)
# A vertex whose weights are all 0 is drawn where the mesh puts it (the bind pose), not refused.
chapter_test(chapter-17.weights-zero WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 3 --check-skinning --model ${SKINS}/weights_zero.gltf
    EXPECT_STDOUT "skinning check: .*guards intact" QUIET_STDERR)
set_tests_properties(chapter-17.weights-zero PROPERTIES FIXTURES_REQUIRED gltf-cases)
skin_hostile(inverse-bind-not-affine "skins\\[0\\].inverseBindMatrices\\[1\\]'s fourth row is not 0, 0, 0, 1 \\(not an affine transform\\)"
    inverse_bind_not_affine.gltf)
skin_hostile(cubic-overshoot "the scene reaches 674[0-9.]+ on an axis; the G-buffer keeps world positions in 16-bit floats"
    cubic_overshoot.gltf)
skin_hostile(weights-nan "meshes\\[0\\].primitives\\[0\\] WEIGHTS_0 \\(accessor 4\\) holds a non-finite number"
    weights_nan.gltf)
skin_hostile(times-decreasing
    "animations\\[0\\].samplers\\[0\\].input's key frame times are not increasing from 0 or more \\(key 1\\)"
    times_decreasing.gltf)
skin_hostile(cubic-one-key "animations\\[0\\].samplers\\[0\\] is CUBICSPLINE with fewer than 2 key frames"
    cubic_one_key.gltf)
skin_hostile(interpolation-unknown
    "animations\\[0\\].samplers\\[0\\].interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE"
    interpolation_unknown.gltf)
skin_hostile(zero-quaternion
    "animations\\[0\\].samplers\\[0\\].output's rotation 1 is not a unit quaternion \\(it is zero\\)"
    zero_quaternion.gltf)
skin_hostile(animated-matrix-node
    "animations\\[0\\].channels\\[0\\] animates node 1, which has a matrix" animated_matrix_node.gltf)
skin_hostile(too-many-joints "the model has skin joints: 5000. at most 4096 are loaded" too_many_joints.gltf)
skin_hostile(too-many-clips "the model has animations: 1025. at most 1024 are loaded" too_many_clips.gltf)
skin_hostile(joint-cycle "node 0 is on a cycle of the node hierarchy" joint_cycle.gltf)
# Weights that miss 1 by 8-bit rounding are taken (made to sum to 1); the figure skins right.
chapter_test(hostile.skin-weights-rounded COMMAND ${CH17_RUN} --headless --frames 2 --check-skinning
    --model ${SKINS}/weights_rounded.gltf EXPECT_STDOUT "skinning check: 25 vertices.*guards intact" QUIET_STDERR)
set_tests_properties(hostile.skin-weights-rounded PROPERTIES FIXTURES_REQUIRED gltf-cases)

standalone_build_test(17 --width 320 --height 180 --frames 3 --check-skinning)

# The book's converted format with its animation (tools/gltf_cases.cpp, writeBookFigure): played and
# read back against the reference; --book-scene opens the book's chapter-17 scene with its Bob (a
# stand-in in the test clone); what breaks the format refused in one line.
chapter_test(chapter-17.book-format WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 5 --check-skinning --model ${SKINS}/book_arm.json
    EXPECT_STDOUT "skinning check: 466 vertices in 3 meshes.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-17.book-format PROPERTIES FIXTURES_REQUIRED gltf-cases)
# The book's format as its generator writes it (tools/gltf_cases.cpp, writeBookFigure), against a golden
# image at 0.4 s: the arm textured though its diffuse colour is (0, 0, 0, 1) (the texture replaces the
# colour, as in the book's shader), the prop no bone touches (weights 0) in its bind pose, the mesh that
# repeats the arm's vertex ranges swung whole by its own weights; the pose at 0.4 s of the clip's 1 s
# (frame_millis read as the clip's length: key frame 9.6 of 24). Then the clip loops at its length: 1.25 s
# is 0.25 s, to the bit.
foreach(time 0.4 0.25 1.25)
    chapter_test(chapter-17.book-figure-${time} WORKDIR /
        COMMAND ${CH17_RUN} --headless --width 320 --height 180 --animation-time ${time}
                --model ${SKINS}/book_arm.json --screenshot ${TEST_OUT}/chapter-17-book-figure-${time}.png
        EXPECT_STDOUT "skinning: 1 models, 3 meshes, 466 vertices" QUIET_STDERR)
    set_tests_properties(chapter-17.book-figure-${time} PROPERTIES FIXTURES_REQUIRED gltf-cases
                         FIXTURES_SETUP ch17-book-figure-${time})
endforeach()
add_test(NAME chapter-17.book-figure-image COMMAND image_compare ${TEST_OUT}/chapter-17-book-figure-0.4.png
    --size 320 180 --golden ${GOLDEN}/chapter-17-book-figure.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-17.book-figure-image PROPERTIES FIXTURES_REQUIRED ch17-book-figure-0.4)
add_test(NAME chapter-17.book-figure-loops COMMAND image_compare ${TEST_OUT}/chapter-17-book-figure-1.25.png
    --size 320 180 --golden ${TEST_OUT}/chapter-17-book-figure-0.25.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-17.book-figure-loops PROPERTIES
                     FIXTURES_REQUIRED "ch17-book-figure-0.25;ch17-book-figure-1.25")
chapter_test(chapter-17.book-scene WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --frames 5 --check-skinning
            --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book
    EXPECT_STDOUT "chapter-17: 8 draws.*skinning: 1 models, 3 meshes, 466 vertices, 2 joints.*guards intact" QUIET_STDERR)
set_tests_properties(chapter-17.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases)
chapter_test(chapter-17.book-scene-without-bob WORKDIR /
    COMMAND ${CH17_RUN} --headless --width 320 --height 180 --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book-without-tree/booksamples/chapter-15/resources/models/sponza/Sponza.gltf
    EXPECT_STDERR "^warning: the book's Bob is not at .*boblamp.json: the scene without him\n$")
set_tests_properties(chapter-17.book-scene-without-bob PROPERTIES FIXTURES_REQUIRED gltf-cases)
skin_hostile(book-bone-past "anim_meshes 0's vertex 7 names bone 7. the animations have 2 joints" book_bone_past.json)
skin_hostile(book-weights-sum "anim_meshes 0's vertex 7's weights sum to 0.25, not 1" book_weights_sum.json)
skin_hostile(book-anim-meshes-short "\"anim_meshes\" is not a list with an entry for each of its 3 meshes"
    book_anim_meshes_short.json)
skin_hostile(book-frames-differ "animation 0's frame 3 has 1 joint matrices where the first frame has 2"
    book_frames_differ.json)
skin_hostile(book-matrix-nan "animation 0's frame 2 has a matrix value that is not a finite number within 1e15"
    book_matrix_nan.json)
skin_hostile(book-matrix-m33 "animation 0's frame 2 has a joint matrix whose last row \\(m03, m13, m23, m33\\) is not 0, 0, 0, 1"
    book_matrix_m33.json)
skin_hostile(book-repeat-weights-none "anim_meshes 2 has not 4 weights and 4 bone ids for each of its 221 vertices"
    book_repeat_weights_none.json)
skin_hostile(book-bone-nested "nested deeper than 16 levels \\(the book's converted format nests 7\\)"
    book_bone_nested.json)
skin_hostile(book-many-values "more than 4194304 JSON values and keys in the model's files, more than our limits allow"
    book_many_values.json)
skin_hostile(book-json-too-large "314572800 bytes, more than the 268435456 our limits allow for the book's converted JSON"
    book_json_too_large.json)
skin_hostile(joint-past-skin-at-weight-0 "meshes\\[0\\].primitives\\[0\\] vertex 7 names joint 200. its skin has 2"
    joint_past_skin_at_weight_0.gltf)
skin_hostile(joints-normalized "meshes\\[0\\].primitives\\[0\\] JOINTS_0 is normalized \\(joint ids are whole numbers\\)"
    joints_normalized.gltf)
skin_hostile(same-target-twice
    "animations\\[0\\].channels\\[1\\] animates node 1's rotation again \\(an animation targets each property once\\)"
    same_target_twice.gltf)
skin_hostile(key-far-away "the model's animations move it beyond 1e15 from the origin" key_far_away.gltf)
