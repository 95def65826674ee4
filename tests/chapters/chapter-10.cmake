# chapter-10 tests: the default scene headless (every --view against its golden image), a window
# resized under Xvfb, --model with a reader's OBJ, and each kind of bad input.
set(CH10 $<TARGET_FILE:chapter-10>)
set(CH10_RUN ${CH10} --device llvmpipe --validation)
set(DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
# Goldens are 640x360: big enough to see every object, small enough to keep in the repository.
set(CH10_SIZE --width 640 --height 360)

# Every view of the default scene, from / (the scene is found next to the executable).
foreach(view final albedo depth)
    chapter_test(chapter-10.view-${view} WORKDIR /
        COMMAND ${CH10_RUN} --headless ${CH10_SIZE} --view ${view} --screenshot ${TEST_OUT}/chapter-10-${view}.png
        EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    set_tests_properties(chapter-10.view-${view} PROPERTIES FIXTURES_SETUP ch10-${view})
    add_test(NAME chapter-10.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-10-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-10-${view}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-10.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch10-${view})
endforeach()

# More frames than frames in flight, camera unchanged: the same image as one frame.
chapter_test(chapter-10.frames COMMAND ${CH10_RUN} --headless ${CH10_SIZE} --frames 5
    --screenshot ${TEST_OUT}/chapter-10-frames.png QUIET_STDERR)
set_tests_properties(chapter-10.frames PROPERTIES FIXTURES_SETUP ch10-frames)
add_test(NAME chapter-10.frames-image COMMAND image_compare ${TEST_OUT}/chapter-10-frames.png
    --size 640 360 --golden ${GOLDEN}/chapter-10-final.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-10.frames-image PROPERTIES FIXTURES_REQUIRED ch10-frames)

if(XVFB_RUN)
    chapter_test(chapter-10.window
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CH10_RUN} ${CH10_SIZE} --frames 30 --resize 800x450
                --screenshot ${TEST_OUT}/chapter-10-window.png QUIET_STDERR)
    set_tests_properties(chapter-10.window PROPERTIES FIXTURES_SETUP ch10-window)
    add_test(NAME chapter-10.window-image COMMAND image_compare ${TEST_OUT}/chapter-10-window.png --size 800 450)
    set_tests_properties(chapter-10.window-image PROPERTIES FIXTURES_REQUIRED ch10-window)
endif()

# A reader's OBJ with its MTL and textures, framed by the default camera.
chapter_test(chapter-10.model
    COMMAND ${CH10_RUN} --headless ${CH10_SIZE} --model $<TARGET_FILE_DIR:chapter-10>/scenes/default/courtyard.obj
            --screenshot ${TEST_OUT}/chapter-10-model.png
    EXPECT_STDOUT "15088 triangles, 5 textures" QUIET_STDERR)
set_tests_properties(chapter-10.model PROPERTIES FIXTURES_SETUP ch10-model)
add_test(NAME chapter-10.model-image COMMAND image_compare ${TEST_OUT}/chapter-10-model.png
    --size 640 360 --golden ${GOLDEN}/chapter-10-model.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-10.model-image PROPERTIES FIXTURES_REQUIRED ch10-model)

# A missing texture falls back to the default texture with a warning and still renders.
chapter_test(chapter-10.missing-texture COMMAND ${CH10_RUN} --headless --model ${DATA}/missing_texture.obj
    EXPECT_STDERR "^warning: texture '.*no_such_texture.png' not found. using the default texture\n$")

# Bad input: exit 2 and one line naming the file (and the key or line where there is one).
function(ch10_bad name expected)
    chapter_test(chapter-10.bad-${name} COMMAND ${CH10_RUN} --headless ${ARGN}
                 EXPECT_EXIT 2 EXPECT_STDERR "^chapter-10: error: ${expected}" ONE_LINE_STDERR)
endfunction()
ch10_bad(missing-model "/no/such/model.obj: no such file" --model /no/such/model.obj)
# The camera's pitch: +-89 degrees accepted, a hair beyond refused (lookAt needs the view off vertical).
foreach(pitch 90 -89.01 89)
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/scenes/pitch${pitch}.json
         "{\"models\": [{\"file\": \"${CMAKE_BINARY_DIR}/bin/scenes/default/courtyard.obj\"}], \"camera\": {\"position\": [0, 3, 12], \"pitch\": ${pitch}}}\n")
endforeach()
ch10_bad(pitch-beyond-89 ".*pitch90.json: camera.pitch: must be between -89 and 89, got 90"
         --scene ${CMAKE_CURRENT_BINARY_DIR}/scenes/pitch90.json)
ch10_bad(pitch-below-89 ".*pitch-89.01.json: camera.pitch: must be between -89 and 89, got -89.01"
         --scene ${CMAKE_CURRENT_BINARY_DIR}/scenes/pitch-89.01.json)
chapter_test(chapter-10.pitch-89 COMMAND ${CH10_RUN} --headless --frames 1
             --scene ${CMAKE_CURRENT_BINARY_DIR}/scenes/pitch89.json QUIET_STDERR)
ch10_bad(missing-scene "/no/such/scene.json: no such file" --scene /no/such/scene.json)
ch10_bad(empty-obj ".*empty.obj: the model has no triangles" --model ${DATA}/empty.obj)
ch10_bad(obj-index-range ".*bad_index.obj: a face refers to a vertex" --model ${DATA}/bad_index.obj)
ch10_bad(obj-negative-index ".*negative_index.obj: a face refers to a vertex" --model ${DATA}/negative_index.obj)
ch10_bad(obj-bad-number ".*bad_number.obj:2: 'v' has 'zero', not a finite number" --model ${DATA}/bad_number.obj)
ch10_bad(mtl-bad-number ".*bad_number.mtl:2: 'Kd' has 'abc', not a finite number" --model ${DATA}/bad_mtl.obj)
ch10_bad(mtl-missing ".*missing_mtl.obj: a material library it names cannot be read" --model ${DATA}/missing_mtl.obj)
ch10_bad(corrupt-png ".*corrupt.png: not a readable image" --model ${DATA}/corrupt_texture.obj)
ch10_bad(json-syntax ".*syntax_error.json: invalid JSON: parse error at line 1" --scene ${DATA}/syntax_error.json)
ch10_bad(json-wrong-type ".*wrong_type.json: models\\[0\\].scale: expected an array of 3 numbers" --scene ${DATA}/wrong_type.json)
ch10_bad(json-negative-intensity ".*negative_intensity.json: lights\\[0\\].intensity: must be between 0"
         --scene ${DATA}/negative_intensity.json)
ch10_bad(json-unknown-key ".*unknown_key.json: scene: unknown key 'colour'" --scene ${DATA}/unknown_key.json)
ch10_bad(json-missing-model ".*no_such_model.obj: no such file" --scene ${DATA}/missing_model.json)
ch10_bad(json-no-models ".*no_models.json: models: expected a non-empty array" --scene ${DATA}/no_models.json)
ch10_bad(json-infinite-number ".*huge_number.json: invalid JSON: number overflow" --scene ${DATA}/huge_number.json)
ch10_bad(unknown-view "--view must be one of final\\|albedo\\|depth, got 'normal'" --view normal)
ch10_bad(scene-and-model "--scene, --model and --book-scene exclude each other" --scene a.json --model b.obj)

# chapter-06 draws no scene: the scene options are refused there.
chapter_test(chapter-06.bad-scene-option COMMAND ${CH06} --headless --scene x.json
    EXPECT_EXIT 2 EXPECT_STDERR "chapter-06 draws no scene and takes no --scene" ONE_LINE_STDERR)

standalone_build_test(10 --width 320 --height 180)
