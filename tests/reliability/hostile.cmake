# Hostile inputs (docs/reliability.md): empty, binary, huge and lying files, values at and
# beyond their limits. Each ends in exit 2 with one line naming the file (and line or key), or in
# a documented fallback with one warning line; never a crash, hang or validation message.
# The inputs are written at test time by tools/hostile_inputs.cpp (tests/data/README.md lists them).
add_executable(hostile_inputs tools/hostile_inputs.cpp)
target_link_libraries(hostile_inputs PRIVATE vkbook::stb)
vkbook_warnings(hostile_inputs)
set_target_properties(hostile_inputs PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/bin)

set(HOSTILE ${CMAKE_CURRENT_BINARY_DIR}/hostile)
add_test(NAME hostile.generate-inputs COMMAND hostile_inputs ${HOSTILE})
set_tests_properties(hostile.generate-inputs PROPERTIES FIXTURES_SETUP hostile-inputs)

# Loader-level checks (triangle counts and areas of concave polygons, byte order marks, limits).
target_sources(unit_tests PRIVATE unit/hostile_loader_test.cpp)

set(HOSTILE_RUN --device llvmpipe --validation --headless --width 64 --height 36)

# hostile_test(NAME CHAPTER EXIT EXPECTED args...): EXIT 2: one line, "chapter-NN: error: " then
# EXPECTED; EXIT 0: EXPECTED matches stdout, stderr empty; EXIT warn: exit 0 and EXPECTED is the
# whole of stderr (one warning line).
function(hostile_test name chapter exit expected)
    set(command $<TARGET_FILE:chapter-${chapter}> ${HOSTILE_RUN} ${ARGN})
    if(exit STREQUAL "2")
        chapter_test(hostile.${name} COMMAND ${command}
                     EXPECT_EXIT 2 EXPECT_STDERR "^chapter-${chapter}: error: ${expected}" ONE_LINE_STDERR)
    elseif(exit STREQUAL "warn")
        chapter_test(hostile.${name} COMMAND ${command} EXPECT_STDERR "^warning: ${expected}\n$")
    else()
        chapter_test(hostile.${name} COMMAND ${command} EXPECT_STDOUT "${expected}" QUIET_STDERR)
    endif()
    set_tests_properties(hostile.${name} PROPERTIES FIXTURES_REQUIRED hostile-inputs)
endfunction()

# --- OBJ and MTL -------------------------------------------------------------------------------
set(H ${HOSTILE})
hostile_test(obj-empty 15 2 "${DATA}/empty.obj: the model has no triangles" --model ${DATA}/empty.obj)
# Not a file, or too large a one: refused before reading a byte (reading /dev/zero or a pipe
# would never end; a 3 GiB file would be held in memory whole).
hostile_test(obj-dev-zero 15 2 "/dev/zero: not a regular file" --model /dev/zero)
hostile_test(obj-fifo 15 2 "${H}/fifo.obj: not a regular file" --model ${H}/fifo.obj)
hostile_test(obj-directory 15 2 "${H}/directory.obj: is a directory, not a file" --model ${H}/directory.obj)
hostile_test(obj-3gib 15 2 "${H}/sparse_3gib.obj: 3072 MiB, more than the 2048 MiB an input file may have"
             --model ${H}/sparse_3gib.obj)
hostile_test(scene-dev-zero 10 2 "/dev/zero: not a regular file" --scene /dev/zero)
hostile_test(scene-fifo 14 2 "${H}/fifo.obj: not a regular file" --scene ${H}/fifo.obj)
hostile_test(obj-garbage 15 2 "${H}/garbage.obj:[0-9]+: not a text file \\(a NUL byte\\)" --model ${H}/garbage.obj)
hostile_test(mtl-garbage 15 2 "${H}/garbage.mtl:[0-9]+: not a text file \\(a NUL byte\\)" --model ${H}/garbage_mtl.obj)
hostile_test(mtl-empty 15 warn
    "${H}/empty_mtl.obj:2: material 'm' is in none of its MTL files. using the default material"
    --model ${H}/empty_mtl.obj)
hostile_test(obj-utf16 15 2 "${H}/utf16.obj: UTF-16 text. save it as UTF-8 or ASCII" --model ${H}/utf16.obj)
hostile_test(obj-utf16-no-bom 15 2 "${H}/utf16_nobom.obj:1: not a text file" --model ${H}/utf16_nobom.obj)
hostile_test(obj-utf8-bom 15 0 " 1 triangles" --model ${H}/utf8_bom.obj)
hostile_test(obj-usemtl-only 15 2 "${H}/usemtl_only.obj: the model has no triangles" --model ${H}/usemtl_only.obj)
hostile_test(obj-points-lines 15 2 "${H}/points_lines.obj: the model has no triangles" --model ${H}/points_lines.obj)
hostile_test(obj-huge-comment 15 0 " 1 triangles" --model ${H}/huge_comment.obj)
string(REPEAT 0 31 ZEROS31)  # the message quotes the first 32 characters of the number
hostile_test(obj-huge-number 15 2 "${H}/huge_number.obj:1: 'v' has '1${ZEROS31}[.][.][.]', not a finite number\n$"
    --model ${H}/huge_number.obj)
hostile_test(obj-huge-v-line 15 2 "${H}/huge_v_line.obj:1: 'v' has more than 7 numbers" --model ${H}/huge_v_line.obj)
hostile_test(obj-zero-index 15 2 "${H}/zero_index.obj: Failed parse `f' line\\(e.g. zero value for face index. line 4.\\)"
    --model ${H}/zero_index.obj)
hostile_test(obj-index-overflow 15 2 "${H}/int_overflow_index.obj:4: 'f' has '99999999999999999999', not a vertex index"
    --model ${H}/int_overflow_index.obj)
hostile_test(obj-quad-bad-index 15 2 "${H}/quad_bad_index.obj: a face refers to a vertex"
    --model ${H}/quad_bad_index.obj)
hostile_test(obj-concave 15 0 " 4 triangles" --model ${H}/concave.obj)
hostile_test(obj-255-corners 15 0 " 253 triangles" --model ${H}/polygon255.obj)
hostile_test(obj-300-corners 15 2 "${H}/polygon300.obj:301: a face of 300 corners \\(at most 255\\)"
    --model ${H}/polygon300.obj)
hostile_test(obj-negative-index-10 10 2 ".*negative_index.obj: a face refers to a vertex" --model ${DATA}/negative_index.obj)
hostile_test(obj-garbage-14 14 2 "${H}/garbage.obj:[0-9]+: not a text file" --model ${H}/garbage.obj)
hostile_test(obj-concave-14 14 0 " 4 triangles" --model ${H}/concave.obj)

# --- Textures (each on a quad, tex_NAME.obj) ----------------------------------------------------
hostile_test(png-1x1 15 0 " 2 triangles, 3 textures" --model ${H}/tex_1x1.obj)
hostile_test(png-16384x1 15 0 " 2 triangles, 3 textures" --model ${H}/tex_16384x1.obj)
hostile_test(png-16385x1 15 2 "${H}/16385x1.png: image size 16385x1 exceeds the device limit of 16384"
    --model ${H}/tex_16385x1.obj)
hostile_test(png-grey 15 0 " 2 triangles, 3 textures" --model ${H}/tex_grey.obj)
hostile_test(png-grey-alpha 15 0 " 2 triangles, 3 textures" --model ${H}/tex_grey_alpha.obj)
hostile_test(png-16-bit 15 0 " 2 triangles, 3 textures" --model ${H}/tex_rgb16.obj)
hostile_test(png-header-lies 15 2 "${H}/header_lies.png: corrupt image \\(not enough pixels\\)"
    --model ${H}/tex_header_lies.obj)
hostile_test(png-header-lies-at-limit 15 2 "${H}/header_at_limit.png: corrupt image \\(not enough pixels\\)"
    --model ${H}/tex_header_at_limit.obj)
hostile_test(png-header-huge 15 2 "${H}/header_huge.png: image size 100000x100000 exceeds the device limit"
    --model ${H}/tex_header_huge.obj)
hostile_test(png-truncated 15 2 "${H}/truncated.png: corrupt image" --model ${H}/tex_truncated.obj)
hostile_test(png-empty 15 2 "${H}/empty.png: not a readable image \\(unknown image type\\)" --model ${H}/tex_empty.obj)
hostile_test(png-garbage 15 2 "${H}/garbage.png: not a readable image" --model ${H}/tex_garbage.obj)
hostile_test(png-hdr-loop 15 2 "${H}/loop.png: a Radiance HDR image. textures are read from PNG, JPEG, BMP or TGA images"
    --model ${H}/tex_hdr.obj)
hostile_test(bmp-header-only 15 2 "${H}/header_only.bmp: corrupt image \\(its pixels end at byte 118 of 1073741878\\)"
    --model ${H}/tex_bmp.obj)
hostile_test(jpeg-scans 15 2 "${H}/scans.jpg: a JPEG of more than 100 scans \\(each one decodes the whole image again\\)"
    --model ${H}/tex_scans.obj)
hostile_test(obj-tags 15 2 "${H}/tags.obj:4: 't' \\(tags\\) is not supported" --model ${H}/tags.obj)
hostile_test(obj-hex-number 15 2 "${H}/hex.obj:2: 'v' has '0x1p3', not a finite number" --model ${H}/hex.obj)
hostile_test(obj-mtllib-repeated 15 0 " 1 triangles" --model ${H}/mtllib_repeated.obj)
set_tests_properties(hostile.obj-mtllib-repeated PROPERTIES TIMEOUT 60)
hostile_test(png-16385x1-10 10 2 "${H}/16385x1.png: image size 16385x1 exceeds" --model ${H}/tex_16385x1.obj)
hostile_test(png-header-lies-14 14 2 "${H}/header_lies.png: corrupt image" --model ${H}/tex_header_lies.obj)

# --- Scene files ---------------------------------------------------------------------------------
hostile_test(json-empty 15 2 "${H}/scene_empty.json: invalid JSON: parse error at line 1, column 1"
    --scene ${H}/scene_empty.json)
hostile_test(json-garbage 15 2 "${H}/scene_garbage.json: invalid JSON: parse error at line 1, column 1"
    --scene ${H}/scene_garbage.json)
hostile_test(json-utf16 15 2 "${H}/scene_utf16.json: UTF-16 text. save it as UTF-8" --scene ${H}/scene_utf16.json)
hostile_test(json-root-array 15 2 "${H}/scene_root_array.json: scene: expected an object" --scene ${H}/scene_root_array.json)
hostile_test(json-models-object 15 2 "${H}/scene_models_object.json: models: expected a non-empty array"
    --scene ${H}/scene_models_object.json)
hostile_test(json-file-number 15 2 "${H}/scene_file_number.json: models\\[0\\].file: expected a non-empty string"
    --scene ${H}/scene_file_number.json)
hostile_test(json-fov-string 15 2 "${H}/scene_fov_string.json: camera.fov: expected a number" --scene ${H}/scene_fov_string.json)
hostile_test(json-lights-object 15 2 "${H}/scene_lights_object.json: lights: expected an array"
    --scene ${H}/scene_lights_object.json)
hostile_test(json-color-string 15 2 "${H}/scene_color_string.json: lights\\[0\\].color\\[1\\]: expected a number"
    --scene ${H}/scene_color_string.json)
hostile_test(json-intensity-bool 15 2 "${H}/scene_intensity_bool.json: ambient.intensity: expected a number"
    --scene ${H}/scene_intensity_bool.json)
hostile_test(json-position-short 15 2 "${H}/scene_position_short.json: camera.position: expected an array of 3 numbers"
    --scene ${H}/scene_position_short.json)
hostile_test(json-marker-fraction 15 2 "${H}/scene_marker_fraction.json: lights\\[0\\].marker: must be between 0 and 0, got 0.5"
    --scene ${H}/scene_marker_fraction.json)
hostile_test(json-nan-literal 15 2 "${H}/scene_nan.json: invalid JSON: parse error at line 1, column 60: syntax error"
    --scene ${H}/scene_nan.json)
hostile_test(json-minus-infinity 15 2 "${H}/scene_minus_inf.json: invalid JSON: number overflow parsing '-1e999'"
    --scene ${H}/scene_minus_inf.json)
hostile_test(json-underflow-scale 15 2 "${H}/scene_underflow_scale.json: models\\[0\\].scale: must not be zero"
    --scene ${H}/scene_underflow_scale.json)
hostile_test(json-negative-ambient 15 2 "${H}/scene_negative_ambient.json: ambient.intensity: must be between 0 and 1e\\+30, got -0.5"
    --scene ${H}/scene_negative_ambient.json)
hostile_test(json-negative-color 15 2 "${H}/scene_negative_color.json: lights\\[0\\].color\\[0\\]: must be between 0"
    --scene ${H}/scene_negative_color.json)
# Colour and intensity each in range, their product not: refused before it renders infinite pixels.
hostile_test(json-radiance-overflow 15 2 "${H}/scene_radiance_overflow.json: lights\\[0\\]: color x intensity is 1e\\+40, more than 1e20: the shading would overflow 32-bit floats"
    --scene ${H}/scene_radiance_overflow.json)
hostile_test(json-ambient-overflow 15 2 "${H}/scene_ambient_overflow.json: ambient: color x intensity is 1e\\+50, more than 1e20"
    --scene ${H}/scene_ambient_overflow.json)
hostile_test(json-no-lights 15 0 " 0 lights" --scene ${H}/scene_no_lights.json)
hostile_test(json-no-models 15 2 ".*no_models.json: models: expected a non-empty array" --scene ${DATA}/no_models.json)
hostile_test(json-deep-nesting 15 2 "${H}/scene_deep.json: models\\[0\\]: expected an object" --scene ${H}/scene_deep.json)
hostile_test(json-100000-lights 15 0 " 100000 lights" --scene ${H}/scene_lights_100000.json)
hostile_test(json-100001-lights 15 2 "${H}/scene_lights_100001.json: lights: 100001 lights, at most 100000"
    --scene ${H}/scene_lights_100001.json)
hostile_test(json-100000-models 15 0 "100000 draws" --scene ${H}/scene_models_100000.json)
hostile_test(json-100001-models 15 2 "${H}/scene_models_100001.json: models: 100001 models, at most 100000"
    --scene ${H}/scene_models_100001.json)
hostile_test(json-draws-over 15 2 "${H}/eleven.obj: the scene places it as model 90910, past 1000000 draws"
    --scene ${H}/scene_draws_over.json)
hostile_test(json-garbage-10 10 2 "${H}/scene_garbage.json: invalid JSON" --scene ${H}/scene_garbage.json)
hostile_test(json-wrong-type-14 14 2 "${H}/scene_color_string.json: lights\\[0\\].color\\[1\\]: expected a number"
    --scene ${H}/scene_color_string.json)

# --- The command line ----------------------------------------------------------------------------
# Values at their limits are accepted (with --help, which parses everything and renders nothing,
# where rendering them would take long); beyond them, one line naming the option.
set(CH15 $<TARGET_FILE:chapter-15>)
function(cli_bad name expected)
    chapter_test(hostile.cli-${name} COMMAND ${CH15} --headless ${ARGN}
                 EXPECT_EXIT 2 EXPECT_STDERR "^chapter-15: error: ${expected}\n$" ONE_LINE_STDERR)
endfunction()
function(cli_good name)
    chapter_test(hostile.cli-${name} COMMAND ${CH15} --headless ${ARGN} --help EXPECT_STDOUT "usage: chapter-15" QUIET_STDERR)
endfunction()
cli_bad(width-0 "--width must be between 1 and 16384, got 0" --width 0)
cli_bad(width-16385 "--width must be between 1 and 16384, got 16385" --width 16385)
cli_bad(height-huge "--height must be between 1 and 16384, got 99999999999999999999" --height 99999999999999999999)
cli_bad(width-negative "--width expects a whole number, got '-64'" --width -64)
cli_bad(width-not-a-number "--width expects a whole number, got '64px'" --width 64px)
cli_bad(frames-0 "--frames must be between 1 and 10000000, got 0" --frames 0)
cli_bad(frames-huge "--frames must be between 1 and 10000000, got 10000001" --frames 10000001)
cli_good(frames-max --frames 10000000)
cli_bad(frames-in-flight-0 "--frames-in-flight must be between 1 and 3, got 0" --frames-in-flight 0)
cli_bad(frames-in-flight-4 "--frames-in-flight must be between 1 and 3, got 4" --frames-in-flight 4)
cli_bad(resize-0x0 "--resize must be between 1 and 16384, got 0" --frames 2 --resize 0x0)
cli_bad(resize-no-x "--resize expects WIDTHxHEIGHT, got '64'" --frames 2 --resize 64)
cli_bad(resize-no-height "--resize expects a whole number, got ''" --frames 2 --resize 64x)
cli_bad(resize-three "--resize expects a whole number, got '36x2'" --frames 2 --resize 64x36x2)
cli_bad(resize-one-frame "--resize needs --frames 2 or more \\(it happens after half of them\\)" --resize 64x36)
cli_bad(warmup-over "--warmup must be between 0 and 100000, got 100001" --benchmark --warmup 100001)
cli_bad(warmup-alone "--warmup goes with --benchmark" --warmup 5)
cli_good(warmup-max --benchmark --warmup 100000)
cli_bad(missing-value "--width needs a value" --width)
cli_bad(option-as-value "--frames expects a whole number, got '--validation'" --frames --validation)
# An empty argument does not survive a CMake list: sh passes it.
foreach(spec "width:--width expects a whole number, got ''" "scene:--scene needs a file name"
             "model:--model needs a file name")
    string(REGEX MATCH "^[a-z]+" option "${spec}")
    string(REGEX REPLACE "^[a-z]+:" "" expected "${spec}")
    chapter_test(hostile.cli-empty-${option} COMMAND sh -c "\"$0\" --headless --${option} ''" ${CH15}
                 EXPECT_EXIT 2 EXPECT_STDERR "^chapter-15: error: ${expected}\n$" ONE_LINE_STDERR)
endforeach()
cli_bad(unknown-option "unknown option '--widht' \\(see --help\\)" --widht 64)
cli_bad(stray-argument "unexpected argument 'scene.json' \\(see --help\\)" scene.json)
# Rendered at the limits: 16384 wide, and 1 high; one and three frames in flight; a resize.
hostile_test(cli-width-16384 15 0 "chapter-15:" --width 16384 --height 1)
hostile_test(cli-frames-in-flight-1 15 0 "chapter-15:" --frames-in-flight 1 --frames 3)
hostile_test(cli-frames-in-flight-3 15 0 "chapter-15:" --frames-in-flight 3 --frames 4)
hostile_test(cli-resize-1x1 15 0 "chapter-15:" --frames 2 --resize 1x1)
hostile_test(cli-warmup-0 15 0 "GPU frame" --benchmark --warmup 0 --frames 1)
hostile_test(cli-equals-form 15 0 "chapter-15: 19 draws" --width=32 --height=18 --view=albedo)
# Repeated options: the last one wins (bench/run.sh relies on it); the image is 32x18.
chapter_test(hostile.cli-repeated COMMAND ${CH15} ${HOSTILE_RUN} --width 9999 --width 32 --height 18
             --screenshot ${TEST_OUT}/hostile-repeated.png QUIET_STDERR)
set_tests_properties(hostile.cli-repeated PROPERTIES FIXTURES_SETUP hostile-repeated)
add_test(NAME hostile.cli-repeated-image COMMAND image_compare ${TEST_OUT}/hostile-repeated.png --size 32 18)
set_tests_properties(hostile.cli-repeated-image PROPERTIES FIXTURES_REQUIRED hostile-repeated)
hostile_test(cli-width-0-10 10 2 "--width must be between 1 and 16384, got 0" --width 0)
hostile_test(cli-frames-in-flight-4-14 14 2 "--frames-in-flight must be between 1 and 3, got 4" --frames-in-flight 4)
# Output paths are checked before any work, as --screenshot's are (tests/chapters/chapter-06.cmake).
hostile_test(cli-json-no-directory 06 2 "cannot write benchmark report '/no/such/dir/report.json': directory '/no/such/dir' does not exist"
             --benchmark --frames 2 --json /no/such/dir/report.json)
hostile_test(cli-json-is-directory 06 2 "cannot write benchmark report '/tmp': it is a directory"
             --benchmark --frames 2 --json /tmp)
