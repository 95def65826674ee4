# The tests of a Windows build (label "windows"). The cross build on Linux (the windows-cross
# preset, scripts/windows-cross.sh) runs every .exe under Wine, all on one Xvfb display that a
# fixture starts first and ends last (Wine's Vulkan needs an X display even to render headless);
# a native Windows build runs them directly. Every chapter renders its default scene and every
# --view, and chapters 10, 14 and 15 its glTF form, compared with the same golden images as the
# Linux build within the same tolerance; bad command lines exit 2 with one
# line; the data is found next to the .exe from any working directory, also from a directory
# whose name has spaces and non-ASCII characters; chapter-15 runs in a window with a resize, and
# with tiled light culling on a many-light scene.
#
# Validation: Debian has no Windows build of the validation layer. Under Wine the Linux layer is
# loaded by the Linux loader below winevulkan (VK_LOADER_LAYERS_ENABLE), with synchronization
# validation (VK_LAYER_ENABLES), and its messages reach the program's messenger: --validation
# counts them as on Linux, and windows.validation-selftest proves it.
set(WIN_FIXTURES "")
if(CMAKE_CROSSCOMPILING)
    if(NOT XVFB)
        message(FATAL_ERROR "the Windows tests under Wine need Xvfb (apt-get install xvfb)")
    endif()
    set(WIN_RUN ${CMAKE_CROSSCOMPILING_EMULATOR})
    add_test(NAME windows.display-start COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/desktops/wine_display.sh start ${CMAKE_BINARY_DIR})
    add_test(NAME windows.display-stop COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/desktops/wine_display.sh stop ${CMAKE_BINARY_DIR})
    set_tests_properties(windows.display-start PROPERTIES LABELS windows FIXTURES_SETUP win-display)
    set_tests_properties(windows.display-stop PROPERTIES LABELS windows FIXTURES_CLEANUP win-display)
    set(WIN_FIXTURES win-display)
    set(WIN_ENV ${TEST_ENV} "VK_LOADER_LAYERS_ENABLE=*validation"
                "VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT")
else()
    set(WIN_RUN "")
    set(WIN_ENV ${TEST_ENV})
endif()
set(WIN_OUT ${TEST_OUT}/windows)
file(MAKE_DIRECTORY ${WIN_OUT})

# windows_test(NAME ...chapter_test arguments): a chapter_test with the label and environment.
function(windows_test name)
    chapter_test(${name} ${ARGN})
    set_tests_properties(${name} PROPERTIES LABELS windows ENVIRONMENT "${WIN_ENV}" TIMEOUT 180
                                            FIXTURES_REQUIRED "${WIN_FIXTURES}")
endfunction()
# windows_image(NAME IMAGE image_compare-arguments...): compares IMAGE once test NAME has made it.
function(windows_image name image)
    add_test(NAME ${name}-image COMMAND ${WIN_RUN} $<TARGET_FILE:image_compare> ${image} ${ARGN})
    set_tests_properties(${name} PROPERTIES FIXTURES_SETUP win-${name})
    set_tests_properties(${name}-image PROPERTIES LABELS windows FIXTURES_REQUIRED "win-${name};${WIN_FIXTURES}"
                                                  TIMEOUT 120)
endfunction()

set(GOLDEN_MATCH --max-diff 5 --max-fraction 0.001)  # the Linux tests' tolerance
set(SIZE --width 640 --height 360)

# Every chapter and every view, headless, started from / (not the .exe's directory).
windows_test(windows.chapter-06 WORKDIR /
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-06> --device llvmpipe --validation --headless
            --screenshot ${WIN_OUT}/chapter-06.png QUIET_STDERR)
windows_image(windows.chapter-06 ${WIN_OUT}/chapter-06.png --size 1280 720
    --golden ${GOLDEN}/chapter-06.png ${GOLDEN_MATCH})
foreach(spec "10;final;albedo;depth" "14;final;albedo;depth" "15;final;position;albedo;normal;pbr;depth"
             "16;final;cascades;shadow-map")
    list(POP_FRONT spec number)
    foreach(view IN LISTS spec)
        set(name windows.chapter-${number}-${view})
        windows_test(${name} WORKDIR /
            COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless ${SIZE}
                    --view ${view} --screenshot ${WIN_OUT}/chapter-${number}-${view}.png
            EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
        windows_image(${name} ${WIN_OUT}/chapter-${number}-${view}.png --size 640 360
            --golden ${GOLDEN}/chapter-${number}-${view}.png ${GOLDEN_MATCH})
    endforeach()
endforeach()
# chapter-17: the figures at a fixed time (the compute pass, the glTF skins), its golden images.
foreach(view final normal visibility)
    windows_test(windows.chapter-17-${view} WORKDIR /
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-17> --device llvmpipe --validation --headless ${SIZE}
                --view ${view} --animation-time 0.4 --check-skinning --screenshot ${WIN_OUT}/chapter-17-${view}.png
        EXPECT_STDOUT "skinning check: 1241 vertices in 2 meshes.*guards intact" QUIET_STDERR)
    windows_image(windows.chapter-17-${view} ${WIN_OUT}/chapter-17-${view}.png --size 640 360
        --golden ${GOLDEN}/chapter-17-${view}.png ${GOLDEN_MATCH})
endforeach()
# chapter-18: the same figures through buffer device addresses (winevulkan forwards them to lavapipe):
# chapter-17's golden image.
windows_test(windows.chapter-18-final WORKDIR /
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-18> --device llvmpipe --validation --headless ${SIZE}
            --animation-time 0.4 --check-skinning --screenshot ${WIN_OUT}/chapter-18-final.png
    EXPECT_STDOUT "skinning check: 1241 vertices in 2 meshes.*guards intact" QUIET_STDERR)
windows_image(windows.chapter-18-final ${WIN_OUT}/chapter-18-final.png --size 640 360
    --golden ${GOLDEN}/chapter-17-final.png ${GOLDEN_MATCH})
# chapter-19: the same figures drawn indirectly.
windows_test(windows.chapter-19-final WORKDIR /
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-19> --device llvmpipe --validation --headless ${SIZE}
            --animation-time 0.4 --check-skinning --screenshot ${WIN_OUT}/chapter-19-final.png
    EXPECT_STDOUT "skinning check: 1241 vertices in 2 meshes.*guards intact" QUIET_STDERR)
windows_image(windows.chapter-19-final ${WIN_OUT}/chapter-19-final.png --size 640 360
    --golden ${GOLDEN}/chapter-17-final.png ${GOLDEN_MATCH})
# chapter-20: the same frame on two threads (std::thread on MinGW-w64's POSIX threads), walking.
windows_test(windows.chapter-20-final WORKDIR /
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-20> --device llvmpipe --validation --headless ${SIZE}
            --animation-time 0.4 --check-skinning --screenshot ${WIN_OUT}/chapter-20-final.png
    EXPECT_STDOUT "skinning check: 1241 vertices in 2 meshes.*guards intact" QUIET_STDERR)
windows_image(windows.chapter-20-final ${WIN_OUT}/chapter-20-final.png --size 640 360
    --golden ${GOLDEN}/chapter-17-final.png ${GOLDEN_MATCH})
# The default courtyard as glTF (tinygltf, fetched for this build): the OBJ form's golden images.
foreach(number 10 14 15)
    windows_test(windows.chapter-${number}-gltf WORKDIR /
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless ${SIZE}
                --scene $<TARGET_FILE_DIR:chapter-${number}>/scenes/default/scene-gltf.json
                --screenshot ${WIN_OUT}/chapter-${number}-gltf.png EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    windows_image(windows.chapter-${number}-gltf ${WIN_OUT}/chapter-${number}-gltf.png --size 640 360
        --golden ${GOLDEN}/chapter-${number}-final.png ${GOLDEN_MATCH})
endforeach()
windows_test(windows.chapter-14-fxaa WORKDIR /
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-14> --device llvmpipe --validation --headless ${SIZE} --fxaa
            --screenshot ${WIN_OUT}/chapter-14-fxaa.png QUIET_STDERR)
windows_image(windows.chapter-14-fxaa ${WIN_OUT}/chapter-14-fxaa.png --size 640 360
    --golden ${GOLDEN}/chapter-14-fxaa.png ${GOLDEN_MATCH})

# The executables with their data copied into a directory whose name has spaces and non-ASCII
# characters, started from another directory: the data is found next to the .exe
# (GetModuleFileNameW), and the screenshot goes to a path of the same kind.
set(ODD_DIR "${WIN_OUT}/dir with spaces ü é ñ")
add_test(NAME windows.copy-to-odd-directory
    COMMAND ${CMAKE_COMMAND} -E copy_directory $<TARGET_FILE_DIR:chapter-15> "${ODD_DIR}/bin")
set_tests_properties(windows.copy-to-odd-directory PROPERTIES LABELS windows FIXTURES_SETUP win-odd-dir)
windows_test(windows.chapter-15-odd-directory WORKDIR ${WIN_OUT}
    COMMAND ${WIN_RUN} "${ODD_DIR}/bin/$<TARGET_FILE_NAME:chapter-15>" --device llvmpipe --validation --headless
            ${SIZE} --screenshot "${ODD_DIR}/chapter-15 ü.png" EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
set_tests_properties(windows.chapter-15-odd-directory PROPERTIES FIXTURES_REQUIRED "win-odd-dir;${WIN_FIXTURES}")
# image_compare takes the path through a char* argv (the Windows code page): it reads a copy.
windows_image(windows.chapter-15-odd-directory ${WIN_OUT}/chapter-15-odd-directory.png --size 640 360
    --golden ${GOLDEN}/chapter-15-final.png ${GOLDEN_MATCH})
add_test(NAME windows.chapter-15-odd-directory-copy
    COMMAND ${CMAKE_COMMAND} -E copy "${ODD_DIR}/chapter-15 ü.png" ${WIN_OUT}/chapter-15-odd-directory.png)
set_tests_properties(windows.chapter-15-odd-directory-copy PROPERTIES LABELS windows
    FIXTURES_REQUIRED win-windows.chapter-15-odd-directory FIXTURES_SETUP win-odd-copy)
set_tests_properties(windows.chapter-15-odd-directory-image PROPERTIES FIXTURES_REQUIRED "win-odd-copy;${WIN_FIXTURES}")

# Runs of the same chapter at once share its pipeline cache: each reads it at start and replaces
# it at exit, which Windows refuses while the other side has the file open. Four at once, three
# rounds: every run exits 0 with nothing on stderr.
add_test(NAME windows.chapter-15-concurrent-runs
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/reliability/concurrent_runs.sh 4 3 --
            ${WIN_RUN} $<TARGET_FILE:chapter-15> --device llvmpipe --headless --width 64 --height 36)
set_tests_properties(windows.chapter-15-concurrent-runs PROPERTIES LABELS windows ENVIRONMENT "${WIN_ENV}"
                     TIMEOUT 180 FIXTURES_REQUIRED "${WIN_FIXTURES}")

# Bad command lines: exit 2 and one line naming the problem, as on Linux.
foreach(number 06 10 14 15 16 17 18 19)
    windows_test(windows.chapter-${number}-bad-option
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-${number}> --headless --frames-in-flight 4
        EXPECT_EXIT 2 EXPECT_STDERR "--frames-in-flight" ONE_LINE_STDERR)
endforeach()
# The lab (chapter-15-lab): tiled light culling (compute passes, an indirect dispatch) on the many-light
# scene, against the Linux build's golden image.
windows_test(windows.chapter-15-lab-lights-1024-tiled
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15-lab> --device llvmpipe --validation --headless ${SIZE}
            --scene $<TARGET_FILE_DIR:chapter-15-lab>/scenes/lights-1024/scene.json --light-culling tiled
            --screenshot ${WIN_OUT}/chapter-15-lights-1024.png EXPECT_STDOUT "1024 lights.*light culling" QUIET_STDERR)
windows_image(windows.chapter-15-lab-lights-1024-tiled ${WIN_OUT}/chapter-15-lights-1024.png --size 640 360
    --golden ${GOLDEN}/chapter-15-lights-1024.png ${GOLDEN_MATCH})

# The lab: forward shading (--shading forward), against the book's deferred golden image.
windows_test(windows.chapter-15-lab-forward
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15-lab> --device llvmpipe --validation --headless ${SIZE} --shading forward
            --screenshot ${WIN_OUT}/chapter-15-forward.png EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
windows_image(windows.chapter-15-lab-forward ${WIN_OUT}/chapter-15-forward.png --size 640 360
    --golden ${GOLDEN}/chapter-15-final.png ${GOLDEN_MATCH})

# The --gui overlay: Dear ImGui built from source (the portable dependency path), the GUI pass
# against the Linux build's golden image.
windows_test(windows.chapter-15-gui
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless ${SIZE} --gui
            --screenshot ${WIN_OUT}/chapter-15-gui.png EXPECT_STDOUT "GUI buffers grew" QUIET_STDERR)
windows_image(windows.chapter-15-gui ${WIN_OUT}/chapter-15-gui.png --size 640 360
    --golden ${GOLDEN}/chapter-15-gui.png ${GOLDEN_MATCH})

windows_test(windows.chapter-15-missing-scene
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --headless --device llvmpipe --scene ${WIN_OUT}/no-such-scene.json
    EXPECT_EXIT 2 EXPECT_STDERR "no-such-scene.json: no such file" ONE_LINE_STDERR)

# In a window (Wine's X11 driver on the test's Xvfb display): a few frames, resized half-way
# through the window system; the last frame has the new size.
if(CMAKE_CROSSCOMPILING)
    windows_test(windows.chapter-15-window
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --device llvmpipe --validation ${SIZE} --frames 12
                --resize 400x240 --screenshot ${WIN_OUT}/chapter-15-window.png QUIET_STDERR)
    windows_image(windows.chapter-15-window ${WIN_OUT}/chapter-15-window.png --size 400 240)
endif()

# --validation can fail on Windows too: the self-test's deliberate mistakes are reported. Under
# Wine, one is not: a sampler left alive at vkDestroyDevice (winevulkan destroys the device's
# objects itself before passing vkDestroyDevice on, so the layer never sees the leak); the
# self-test then ends with exit code 1, naming it. Core and synchronization validation work.
if(CMAKE_CROSSCOMPILING)
    windows_test(windows.validation-selftest
        COMMAND ${WIN_RUN} $<TARGET_FILE:validation_selftest> --validation --device llvmpipe
        EXPECT_EXIT 1 EXPECT_STDOUT "core validation reported the misuse: yes\nsynchronization validation reported the hazard: yes\nobject tracking reported the leaked sampler: NO")
else()
    windows_test(windows.validation-selftest
        COMMAND $<TARGET_FILE:validation_selftest> --validation --device llvmpipe
        EXPECT_EXIT 3 EXPECT_STDOUT "core validation reported the misuse: yes.*synchronization validation reported the hazard: yes.*object tracking reported the leaked sampler: yes")
endif()

# Readers' desktops (tests/desktops/desktops.cmake has the Linux set): a 10-bit and an 8-bit UNORM present
# format headless, encoded by our passes, against the sRGB golden images; the overlay in 10 bits;
# the overlay at HiDPI scale 2 drawn through the same pass.
foreach(spec "06;A2R10G10B10_UNORM_PACK32;chapter-06" "15;A2B10G10R10_UNORM_PACK32;chapter-15-final"
             "14;B8G8R8A8_UNORM;chapter-14-final")
    list(POP_FRONT spec number format golden)
    set(size ${SIZE})
    if(number STREQUAL "06")
        set(size)
    endif()
    windows_test(windows.format-${format}.chapter-${number}
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless ${size}
                --target-format ${format} --screenshot ${WIN_OUT}/format-${format}.chapter-${number}.png QUIET_STDERR)
    windows_image(windows.format-${format}.chapter-${number} ${WIN_OUT}/format-${format}.chapter-${number}.png
        --golden ${GOLDEN}/${golden}.png ${GOLDEN_MATCH})
endforeach()
windows_test(windows.format-A2R10G10B10_UNORM_PACK32.chapter-15-gui
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless ${SIZE} --gui
            --target-format A2R10G10B10_UNORM_PACK32 --screenshot ${WIN_OUT}/format-10bit-gui.png QUIET_STDERR)
windows_image(windows.format-A2R10G10B10_UNORM_PACK32.chapter-15-gui ${WIN_OUT}/format-10bit-gui.png
    --golden ${GOLDEN}/chapter-15-gui.png ${GOLDEN_MATCH})
windows_test(windows.gui-scale-2
    COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 1280
            --height 720 --gui --gui-scale 2 QUIET_STDERR)

# Runtime shader compilation needs shaderc (and glslang, SPIRV-Tools, SPIRV-Cross) built for
# Windows, which this cross build does not do (docs/live-shaders.md says why); the Visual Studio
# build takes them from the Vulkan SDK. Each program must say which applies, and refuse
# --shader-dir with one line.
if(VKBOOK_HAVE_RUNTIME_SHADERS)
    set(WIN_SHADERS "shaders: compiled at run time from .* when newer than the build's SPIR-V")
else()
    set(WIN_SHADERS "shaders: the build's SPIR-V \\(this build has no runtime compilation \\(built without shaderc\\)\\)")
    windows_test(windows.shader-dir-refused
        COMMAND ${WIN_RUN} $<TARGET_FILE:chapter-15> --headless --shader-dir .
        EXPECT_EXIT 2 ONE_LINE_STDERR
        EXPECT_STDERR "--shader-dir: this build has no runtime shader compilation \\(built without shaderc\\)")
endif()
foreach(program chapter-06 chapter-10 chapter-14 chapter-15 chapter-15-lab)
    windows_test(windows.${program}-help-shaders COMMAND ${WIN_RUN} $<TARGET_FILE:${program}> --help
        EXPECT_STDOUT "${WIN_SHADERS}")
endforeach()
