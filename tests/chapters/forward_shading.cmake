# chapter-15-lab: --shading forward, the renderer deferred shading is measured
# against. Its image must be the deferred one's: with the reference G-buffer (32-bit floats
# throughout, standard depth, as forward's), the light output equals the loop's up to fp32
# rounding of the sum (pfm_compare's bound), on the default scene and on many lights with ranges,
# under validation (synchronization validation on), across a resize; and its picture is the book's
# golden image. Plus what it refuses.

# forward_case(NAME LIGHTS ARGS...): forward and deferred (reference G-buffer) light outputs compared.
function(forward_case name lights)
    cmake_parse_arguments(F "" "" "ARGS" ${ARGN})
    foreach(shading forward deferred)
        set(extra "")
        if(shading STREQUAL deferred)
            set(extra --gbuffer reference)
        endif()
        chapter_test(chapter-15-lab.forward-${name}-${shading}
            COMMAND ${LAB_RUN} --headless ${F_ARGS} --shading ${shading} ${extra} --check-output
                    --dump ${TEST_OUT}/forward-${name}-${shading}
            EXPECT_STDOUT "0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
        set_tests_properties(chapter-15-lab.forward-${name}-${shading} PROPERTIES
            FIXTURES_SETUP forward-${name}-${shading})
    endforeach()
    add_test(NAME chapter-15-lab.forward-${name}-equals-deferred
        COMMAND pfm_compare ${TEST_OUT}/forward-${name}-forward/light.pfm
                ${TEST_OUT}/forward-${name}-deferred/light.pfm --lights ${lights} --min-lit 0.2)
    set_tests_properties(chapter-15-lab.forward-${name}-equals-deferred PROPERTIES
        FIXTURES_REQUIRED "forward-${name}-forward;forward-${name}-deferred")
endfunction()

forward_case(default 2 ARGS ${CULL_SIZE} --frames 3)
forward_case(lights-256 256 ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-256/scene.json)
# A resize while frames are in flight: the output and depth follow the window.
forward_case(resize 2 ARGS ${CULL_SIZE} --frames 4 --resize 333x197 --frames-in-flight 3)

# As a picture: forward shading of the default scene against the book's deferred golden image (the
# two differ by the book G-buffer's half floats: 2/255 at most when this was written).
chapter_test(chapter-15-lab.forward-final WORKDIR /
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --shading forward --screenshot ${TEST_OUT}/chapter-15-forward.png
    EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
set_tests_properties(chapter-15-lab.forward-final PROPERTIES FIXTURES_SETUP ch15-forward)
add_test(NAME chapter-15-lab.forward-final-image COMMAND image_compare ${TEST_OUT}/chapter-15-forward.png
    --size 640 360 --golden ${GOLDEN}/chapter-15-final.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-15-lab.forward-final-image PROPERTIES FIXTURES_REQUIRED ch15-forward)

# Forward shading allocates depth alone, no G-buffer attachment, and says so: 4 bytes a pixel
# against the deferred layouts' 36 (book), 68 (reference) and 16 (compact).
chapter_test(chapter-15-lab.forward-allocates-depth-only
    COMMAND ${LAB_RUN} --headless ${CULL_SIZE} --shading forward --benchmark --warmup 0 --frames 1
    EXPECT_STDOUT "gbuffer_bytes_per_pixel +4\n" QUIET_STDERR)

# The overlay with forward shading: no G-buffer or light-pass choice, no G-buffer view.
chapter_test(chapter-15-lab.forward-gui
    COMMAND ${LAB_RUN} --headless --width 640 --height 360 --shading forward --gui --frames 3 QUIET_STDERR)

# What needs a G-buffer is refused, each with one line.
foreach(case "light-pass compute|--light-pass compute shades the G-buffer: --shading forward has none"
             "light-culling tiled|--light-culling tiled bounds its tiles with the G-buffer's depth"
             "gbuffer compact|--shading forward has no G-buffer to lay out \\(--gbuffer\\)"
             "view normal|--view shows the G-buffer's attachments: --shading forward has only the final image")
    string(REPLACE "|" ";" case "${case}")
    list(GET case 0 option)
    list(GET case 1 message)
    string(REPLACE " " ";" option_args "${option}")
    string(REPLACE " " "-" option_name "${option}")
    chapter_test(chapter-15-lab.forward-refuses-${option_name}
        COMMAND ${LAB} --headless --shading forward --${option_args}
        EXPECT_EXIT 2 EXPECT_STDERR "${message}" ONE_LINE_STDERR)
endforeach()
chapter_test(chapter-15-lab.bad-shading COMMAND ${LAB} --headless --shading forward+
    EXPECT_EXIT 2 EXPECT_STDERR "--shading must be one of deferred\\|forward" ONE_LINE_STDERR)
