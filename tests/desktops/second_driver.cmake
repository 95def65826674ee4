# Every chapter's golden images on a second driver: Mesa 25's lavapipe from Debian's
# bookworm-backports (Vulkan 1.4), beside the machine's own Mesa 22.3 that every other test uses.
# `scripts/setup.sh test` fetches it into <build>/mesa-backports (scripts/mesa_backports.sh: unpacked,
# never installed) before configuring. Where it is not there (a build of your own), each test is
# skipped and says how to fetch it. Each run is the chapter's
# view test as on 22.3 -- same options, validation on -- with VK_DRIVER_FILES naming the newer
# driver (its report must say so), and its image against the same golden image, within the golden
# images' bounds (5/255 on 99.9% of the pixels): the two drivers draw today's chapters alike.
set(SECOND_DRIVER ${CMAKE_BINARY_DIR}/mesa-backports)
set(SECOND_DRIVER_VERSION none)
if(EXISTS ${SECOND_DRIVER}/lvp_icd.json)
    file(READ ${SECOND_DRIVER}/version SECOND_DRIVER_VERSION)
endif()
string(STRIP "${SECOND_DRIVER_VERSION}" SECOND_DRIVER_VERSION)
string(REPLACE "+" "\\+" SECOND_DRIVER_PATTERN "${SECOND_DRIVER_VERSION}")
# A pipeline cache of their own: a cache written by the other driver is refused with a warning.
set(SECOND_DRIVER_ENV "VK_DRIVER_FILES=${SECOND_DRIVER}/lvp_icd.json"
    "LD_LIBRARY_PATH=${SECOND_DRIVER}/root/usr/lib/x86_64-linux-gnu"
    "XDG_CACHE_HOME=${CMAKE_CURRENT_BINARY_DIR}/cache-driver2")
set(SIZE640 --width 640 --height 360)
# chapter;view-or-empty;golden;size;extra options
foreach(spec "06;;chapter-06;1280 720;"
             "10;final;chapter-10-final;640 360;" "10;albedo;chapter-10-albedo;640 360;"
             "10;depth;chapter-10-depth;640 360;"
             "14;final;chapter-14-final;640 360;" "14;albedo;chapter-14-albedo;640 360;"
             "14;depth;chapter-14-depth;640 360;"
             "15;final;chapter-15-final;640 360;" "15;position;chapter-15-position;640 360;"
             "15;albedo;chapter-15-albedo;640 360;" "15;normal;chapter-15-normal;640 360;"
             "15;pbr;chapter-15-pbr;640 360;" "15;depth;chapter-15-depth;640 360;"
             "16;final;chapter-16-final;640 360;" "16;cascades;chapter-16-cascades;640 360;"
             "16;shadow-map;chapter-16-shadow-map;640 360;"
             "17;final;chapter-17-final;640 360;--animation-time 0.4"
             "17;normal;chapter-17-normal;640 360;--animation-time 0.4"
             "17;visibility;chapter-17-visibility;640 360;--animation-time 0.4"
             "18;final;chapter-17-final;640 360;--animation-time 0.4"
             "19;final;chapter-17-final;640 360;--animation-time 0.4")
    list(GET spec 0 number)
    list(GET spec 1 view)
    list(GET spec 2 golden)
    list(GET spec 3 size)
    list(GET spec 4 extra)
    separate_arguments(size)
    separate_arguments(extra)
    set(view_args)
    set(name driver2.chapter-${number})
    if(view)
        set(view_args --view ${view})
        set(name ${name}-${view})
    endif()
    list(GET size 0 width)
    list(GET size 1 height)
    if(SECOND_DRIVER_VERSION STREQUAL "none")
        foreach(test ${name} ${name}-image)
            add_test(NAME ${test} COMMAND sh -c "echo 'no second driver: scripts/mesa_backports.sh $0, then configure again'; exit 77" ${SECOND_DRIVER})
            set_tests_properties(${test} PROPERTIES SKIP_RETURN_CODE 77 LABELS driver2)
        endforeach()
        continue()
    endif()
    chapter_test(${name} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless --width ${width}
                --height ${height} ${view_args} ${extra} --benchmark --warmup 0 --frames 1
                --screenshot ${TEST_OUT}/${name}.png
        EXPECT_STDOUT "driver +llvmpipe, Mesa ${SECOND_DRIVER_PATTERN}" QUIET_STDERR)
    set_property(TEST ${name} APPEND PROPERTY ENVIRONMENT ${SECOND_DRIVER_ENV})
    set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name} LABELS driver2)
    add_test(NAME ${name}-image COMMAND image_compare ${TEST_OUT}/${name}.png --size ${width} ${height}
        --golden ${GOLDEN}/${golden}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(${name}-image PROPERTIES FIXTURES_REQUIRED ${name} LABELS driver2)
endforeach()
