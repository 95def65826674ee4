# Pipelines made for the scene (--pipelines specialised, the default) against generic ones
# (--pipelines generic): the pipelines each scene makes, counted -- one per material class its
# materials have and none for a class no material has, the light pass specialised to its lights
# of each kind -- and the images the same to the bit, under validation.
set(FEATURES_SCENE ${CMAKE_CURRENT_BINARY_DIR}/gltf/features/features.json)  # tools/gltf_cases.cpp
set(BOOK_STANDIN ${CMAKE_CURRENT_BINARY_DIR}/gltf/book)

# pipelines_count(NAME CHAPTER EXPECT_STDOUT ARGS...): a one-frame benchmark whose report must match.
function(pipelines_count name chapter expect)
    chapter_test(pipelines.count-${name}
        COMMAND $<TARGET_FILE:${chapter}> --device llvmpipe --validation --headless --width 320 --height 180
                --benchmark --warmup 0 --frames 1 ${ARGN}
        EXPECT_STDOUT "${expect}" QUIET_STDERR)
    set_tests_properties(pipelines.count-${name} PROPERTIES FIXTURES_REQUIRED gltf-cases)
endfunction()

# The default scene: its OBJ materials are opaque or cut-out, with a texture or without (chapters
# 10 and 14: 3 classes); chapter-15 also tells apart the normal and metal-rough maps (4 classes).
pipelines_count(chapter-10-default chapter-10 "pipelines +specialised.*scene_pipelines +3\n")
pipelines_count(chapter-14-default chapter-14 "pipelines +specialised.*scene_pipelines +3\n")
pipelines_count(chapter-15-default chapter-15
    "pipelines +specialised.*scene_pipelines +4\n.*light_pipeline +1 directional, 1 point\n")
pipelines_count(chapter-10-generic chapter-10 "scene_pipelines +1\n" --pipelines generic)
pipelines_count(chapter-14-generic chapter-14 "scene_pipelines +1\n" --pipelines generic)
# Generic chapter-15: one per alpha test and sidedness the scene has (the default scene: 2).
pipelines_count(chapter-15-generic chapter-15 "scene_pipelines +2\n.*light_pipeline +generic\n"
    --pipelines generic)
# Every feature alone and all at once, 11 draws of 10 classes (and the default material and one
# no primitive uses: 13 materials); its lights listed point, directional, point.
pipelines_count(chapter-15-features chapter-15
    "chapter-15: 11 draws.*13 materials, 3 lights.*scene_pipelines +10\n.*light_pipeline +1 directional, 2 point\n"
    --scene ${FEATURES_SCENE})
# Generic: each pairing of the alpha test with the culling.
pipelines_count(chapter-15-features-generic chapter-15 "scene_pipelines +4\n.*light_pipeline +generic\n"
    --scene ${FEATURES_SCENE} --pipelines generic)
# Chapters 10 and 14 tell apart only the alpha test and the texture: 3 classes.
pipelines_count(chapter-10-features chapter-10 "scene_pipelines +3\n" --scene ${FEATURES_SCENE})
pipelines_count(chapter-14-features chapter-14 "scene_pipelines +3\n" --scene ${FEATURES_SCENE})
# No lights (ambient light only): both loops vanish; a sun alone: the point lights' loop does.
pipelines_count(chapter-15-no-lights chapter-15 "light_pipeline +0 directional, 0 point\n"
    --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/cases/ambient.json)
pipelines_count(chapter-15-sun-only chapter-15 "light_pipeline +1 directional, 0 point\n"
    --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/cases/sun.json)
# The lab: tiled culling keeps its own loop over the tile lists (not specialised); the forward
# renderer makes the scene's pipelines from its own shader (and no light pass).
pipelines_count(lab-features-compute chapter-15-lab "scene_pipelines +10\n.*light_pipeline +1 directional, 2 point\n"
    --scene ${FEATURES_SCENE} --light-pass compute --gbuffer compact)
pipelines_count(lab-features-tiled chapter-15-lab "scene_pipelines +10\n.*light_pipeline +generic\n"
    --scene ${FEATURES_SCENE} --light-culling tiled)
pipelines_count(lab-features-forward chapter-15-lab "scene_pipelines +10\n.*light_pipeline +none" --scene ${FEATURES_SCENE}
    --shading forward)

# pipelines_identical(NAME CHAPTER ARGS...): a screenshot with each form; the two PNGs must be equal
# to the bit.
function(pipelines_identical name chapter)
    foreach(form specialised generic)
        chapter_test(pipelines.identical-${name}-${form}
            COMMAND $<TARGET_FILE:${chapter}> --device llvmpipe --validation --headless --width 320 --height 180
                    --pipelines ${form} --screenshot ${TEST_OUT}/pipelines-${name}-${form}.png ${ARGN}
            QUIET_STDERR)
        set_tests_properties(pipelines.identical-${name}-${form} PROPERTIES
            FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP pipelines-${name}-${form})
    endforeach()
    add_test(NAME pipelines.identical-${name}
        COMMAND image_compare ${TEST_OUT}/pipelines-${name}-specialised.png
                --golden ${TEST_OUT}/pipelines-${name}-generic.png --max-diff 0 --max-fraction 0)
    set_tests_properties(pipelines.identical-${name} PROPERTIES
        FIXTURES_REQUIRED "pipelines-${name}-specialised;pipelines-${name}-generic")
endfunction()

pipelines_identical(chapter-10 chapter-10)
pipelines_identical(chapter-14 chapter-14)
pipelines_identical(chapter-15 chapter-15)
pipelines_identical(chapter-10-features chapter-10 --scene ${FEATURES_SCENE})
pipelines_identical(chapter-14-features chapter-14 --scene ${FEATURES_SCENE})
pipelines_identical(chapter-15-features chapter-15 --scene ${FEATURES_SCENE})
# Both forms read the same material flags, so their agreement does not prove the flags right: the
# specialised image against a golden one, as every other scene's (each feature visible: the
# golden's quads, left to right and down, are the features in the order gltf_cases writes them).
add_test(NAME pipelines.chapter-15-features-image
    COMMAND image_compare ${TEST_OUT}/pipelines-chapter-15-features-specialised.png --size 320 180
            --golden ${GOLDEN}/gltf-features.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(pipelines.chapter-15-features-image PROPERTIES
    FIXTURES_REQUIRED pipelines-chapter-15-features-specialised)
pipelines_identical(chapter-15-book-scene chapter-15 --book-scene ${BOOK_STANDIN})
pipelines_identical(chapter-15-no-lights chapter-15 --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/cases/ambient.json)

# The float images themselves: the lab's --dump (light output and G-buffer as PFM) of both forms,
# byte for byte, with each G-buffer layout and light-pass form, on the default scene, every feature
# and 1,024 point lights.
function(pipelines_dumps name)
    foreach(form specialised generic)
        chapter_test(pipelines.dump-${name}-${form}
            COMMAND ${LAB_RUN} --headless --width 320 --height 180 --pipelines ${form} --check-output
                    --dump ${TEST_OUT}/pipelines-dump-${name}-${form} ${ARGN}
            EXPECT_STDOUT "0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
        set_tests_properties(pipelines.dump-${name}-${form} PROPERTIES
            FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP pipelines-dump-${name}-${form})
    endforeach()
    add_test(NAME pipelines.dump-${name}-identical
        COMMAND diff -r ${TEST_OUT}/pipelines-dump-${name}-specialised ${TEST_OUT}/pipelines-dump-${name}-generic)
    set_tests_properties(pipelines.dump-${name}-identical PROPERTIES
        FIXTURES_REQUIRED "pipelines-dump-${name}-specialised;pipelines-dump-${name}-generic")
endfunction()

pipelines_dumps(default-book)
pipelines_dumps(default-compact-compute --gbuffer compact --light-pass compute)
pipelines_dumps(features-book --scene ${FEATURES_SCENE})
pipelines_dumps(features-reference-compute --scene ${FEATURES_SCENE} --gbuffer reference --light-pass compute)
pipelines_dumps(lights-1024 --scene ${CMAKE_BINARY_DIR}/bin/scenes/lights-1024/scene.json)
pipelines_dumps(features-forward --scene ${FEATURES_SCENE} --shading forward)
pipelines_dumps(features-tiled --scene ${FEATURES_SCENE} --light-culling tiled)
