# chapter-15-lab's skinning study (chapter-15-lab/skinning_study.cpp, docs/chapter-15-lab.md): every
# form run with validation (synchronization validation on), its table checked against what the page
# says of it (tests/chapters/skinning_study_check.py): chapter-17's form and the vertex shader's
# within chapter-17's bound of the double-precision reference, 16-bit joints and four of eight
# influences measurably worse, the candy wrapper collapsed by linear blending and not by dual
# quaternions; what the study cannot be combined with, refused.
set(SKINNING_CSV ${TEST_OUT}/lab-skinning-study.csv)
chapter_test(lab.skinning-study
    COMMAND $<TARGET_FILE:chapter-15-lab> --device llvmpipe --validation --skinning-study ${SKINNING_CSV}
            --skinning-study-size small
    EXPECT_STDOUT "skinning study on llvmpipe.*wrote " QUIET_STDERR)
set_tests_properties(lab.skinning-study PROPERTIES FIXTURES_SETUP lab-skinning)
add_test(NAME lab.skinning-study-table
    COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/chapters/skinning_study_check.py ${SKINNING_CSV})
set_tests_properties(lab.skinning-study-table PROPERTIES FIXTURES_REQUIRED lab-skinning)
# The check can fail: a table whose dual quaternions collapse the wrapper as linear blending does,
# one whose vertex shader drew nothing in its timed passes (it read the compute pass's buffer
# instead of skinning), one whose vertex shader skinned differently.
foreach(broken "dqs-collapses:s/^\\(candy wrapper,.*,compute,dual quaternion,.*\\),[0-9.]*,\\([0-9]*\\),\\(.llvmpipe\\)/\\1,0.0100,\\2,\\3/"
               "vertex-shader-drew-nothing:s/^\\(tentacle,.*,vertex shader,.*\\),[0-9]*,\\(.llvmpipe\\)/\\1,0,\\2/"
               "vertex-shader-differs:s/^\\(tentacle,[0-9]*,vertex shader,\\([^,]*,\\)\\{8\\}\\)[^,]*/\\11.000e-06/")
    string(FIND "${broken}" ":" colon)
    string(SUBSTRING "${broken}" 0 ${colon} case)
    math(EXPR colon "${colon} + 1")
    string(SUBSTRING "${broken}" ${colon} -1 edit)
    add_test(NAME lab.skinning-study-table-finds-${case} COMMAND sh -c
        "sed '${edit}' $1 > $2 && ! cmp -s $1 $2 && ! python3 $0 $2 > /dev/null"
        ${CMAKE_CURRENT_SOURCE_DIR}/chapters/skinning_study_check.py ${SKINNING_CSV}
        ${TEST_OUT}/lab-skinning-study-${case}.csv)
    set_tests_properties(lab.skinning-study-table-finds-${case} PROPERTIES FIXTURES_REQUIRED lab-skinning)
endforeach()

chapter_test(lab.skinning-study-with-scene
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --scene nowhere.json
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --scene")
chapter_test(lab.skinning-study-with-shadows
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --shadows vsm
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --shadows")
chapter_test(lab.skinning-study-size-alone
    COMMAND $<TARGET_FILE:chapter-15-lab> --headless --skinning-study-size small
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study-size needs --skinning-study")
chapter_test(lab.skinning-study-unwritable
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study /nonexistent-dir/table.csv
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "cannot write '/nonexistent-dir/table.csv'")
chapter_test(lab.skinning-study-with-screenshot
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --screenshot ${TEST_OUT}/x.png
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --screenshot")
chapter_test(lab.skinning-study-with-benchmark
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --benchmark
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --benchmark")
chapter_test(lab.skinning-study-with-cascades
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --cascades 2
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --cascades")
chapter_test(lab.skinning-study-into-a-directory
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "not a regular file")
chapter_test(lab.skinning-study-with-width
    COMMAND $<TARGET_FILE:chapter-15-lab> --skinning-study ${TEST_OUT}/x.csv --width 640
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--skinning-study draws its own figures and no frames: no --width or --height")
