# glTF 2.0 (docs/chapter-10.md, "glTF models"): the default scene's glTF form against the OBJ
# form's golden images in chapters 10, 14 and 15; cases that show one rule of the specification
# each (against golden images); the same model as .gltf, with data: URIs and as .glb, rendering
# the same; hostile files, each refused in one line (exit 2) or taken with one warning. The files
# are written at test time by tools/gltf_cases.cpp; the loader's numbers are checked by
# unit/gltf_test.cpp.
add_executable(gltf_cases tools/gltf_cases.cpp)
target_link_libraries(gltf_cases PRIVATE vkbook::stb glm::glm nlohmann_json::nlohmann_json)
vkbook_warnings(gltf_cases)
set_target_properties(gltf_cases PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/bin)
target_sources(unit_tests PRIVATE unit/gltf_test.cpp)
target_link_libraries(unit_tests PRIVATE nlohmann_json::nlohmann_json vkbook::tinygltf)

set(GLTF ${CMAKE_CURRENT_BINARY_DIR}/gltf)
add_test(NAME gltf.generate-cases COMMAND gltf_cases ${GLTF})
set_tests_properties(gltf.generate-cases PROPERTIES FIXTURES_SETUP gltf-cases)

# The default courtyard as glTF (bin/scenes/default/scene-gltf.json) renders as the OBJ one: the
# same golden images, the same tolerance.
set(GLTF_SCENE ${CMAKE_BINARY_DIR}/bin/scenes/default/scene-gltf.json)
foreach(chapter 10 14 15)
    chapter_test(gltf.chapter-${chapter}-courtyard WORKDIR /
        COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless --width 640 --height 360
                --scene ${GLTF_SCENE} --screenshot ${TEST_OUT}/gltf-chapter-${chapter}.png
        EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    set_tests_properties(gltf.chapter-${chapter}-courtyard PROPERTIES FIXTURES_SETUP gltf-ch${chapter})
    add_test(NAME gltf.chapter-${chapter}-courtyard-image COMMAND image_compare ${TEST_OUT}/gltf-chapter-${chapter}.png
        --size 640 360 --golden ${GOLDEN}/chapter-${chapter}-final.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(gltf.chapter-${chapter}-courtyard-image PROPERTIES FIXTURES_REQUIRED gltf-ch${chapter})
endforeach()

# The cases: double- and single-sided quads seen from behind, MASK at 0.25 and 0.75, a mirrored
# node, an occlusion map; under ambient light only (the occlusion map darkens half a quad) and under
# a sun only (it darkens nothing).
foreach(light ambient sun)
    chapter_test(gltf.cases-${light} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 640 --height 160
                --scene ${GLTF}/cases/${light}.json --screenshot ${TEST_OUT}/gltf-cases-${light}.png
        EXPECT_STDOUT "chapter-15: 6 draws" QUIET_STDERR)
    set_tests_properties(gltf.cases-${light} PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP gltf-cases-${light})
    add_test(NAME gltf.cases-${light}-image COMMAND image_compare ${TEST_OUT}/gltf-cases-${light}.png
        --size 640 160 --golden ${GOLDEN}/gltf-cases-${light}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(gltf.cases-${light}-image PROPERTIES FIXTURES_REQUIRED gltf-cases-${light})
endforeach()

# Zero normals and tangents under a normal map that decodes to almost nothing: no NaN, no
# infinity, nothing negative in the light output, validation-clean.
chapter_test(gltf.zero-tangent-frame WORKDIR /
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 320 --height 180
            --model ${GLTF}/degenerate/zero_frame.gltf --check-output
    EXPECT_STDOUT "chapter-15: 1 draws, 2 triangles.*light output 320x180: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
set_tests_properties(gltf.zero-tangent-frame PROPERTIES FIXTURES_REQUIRED gltf-cases)

# The same model as .gltf + .bin, .gltf with data: URIs, and .glb: the same image, to the bit; and
# without a scene, whose root nodes are then all drawn.
foreach(form model.gltf model_embedded.gltf model.glb model_no_scene.gltf)
    chapter_test(gltf.same-${form} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 320 --height 180
                --model ${GLTF}/same/${form} --screenshot ${TEST_OUT}/gltf-same-${form}.png
        EXPECT_STDOUT "chapter-15: 3 draws, 6 triangles" QUIET_STDERR)
    set_tests_properties(gltf.same-${form} PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP gltf-same-${form})
endforeach()
foreach(form model_embedded.gltf model.glb model_no_scene.gltf)
    add_test(NAME gltf.same-${form}-image COMMAND image_compare ${TEST_OUT}/gltf-same-${form}.png
        --size 320 180 --golden ${TEST_OUT}/gltf-same-model.gltf.png --max-diff 0 --max-fraction 0)
    set_tests_properties(gltf.same-${form}-image PROPERTIES
        FIXTURES_REQUIRED "gltf-same-${form};gltf-same-model.gltf")
endforeach()

# Hostile files: one line and exit 2 (or one warning), in every chapter that loads models.
set(GH ${GLTF}/hostile)
function(gltf_hostile name exit expected file)
    foreach(chapter 10 14 15)
        hostile_test(gltf-${name}-${chapter} ${chapter} ${exit} "${expected}" --model ${GH}/${file})
        set_tests_properties(hostile.gltf-${name}-${chapter} PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
    endforeach()
endfunction()
gltf_hostile(syntax 2 "${GH}/syntax.gltf: invalid JSON: parse error at line 1, column 41: syntax error" syntax.gltf)
gltf_hostile(version-1 2 "${GH}/version1.gltf: glTF version '1.0'. only glTF 2.0 is read" version1.gltf)
gltf_hostile(index-past-vertices 2
    "${GH}/index_past_vertices.gltf: meshes\\[0\\].primitives\\[0\\] indices \\(accessor 2\\) refers to vertex 7 of 3"
    index_past_vertices.gltf)
gltf_hostile(accessor-past-view 2
    "${GH}/accessor_past_view.gltf: accessors\\[0\\]: 4 elements from byte 0 end at byte 48, past the end of bufferViews\\[0\\] \\(36 bytes\\)"
    accessor_past_view.gltf)
gltf_hostile(view-past-buffer 2 "${GH}/view_past_buffer.gltf: bufferViews\\[0\\] \\(bytes 0..4000\\) runs past the end of buffer 0"
    view_past_buffer.gltf)
gltf_hostile(stride-lies 2
    "${GH}/stride_lies.gltf: accessors\\[0\\]: bufferViews\\[0\\].byteStride 8 is smaller than an element \\(12 bytes\\)"
    stride_lies.gltf)
gltf_hostile(stride-odd 2 "${GH}/stride_odd.gltf: bufferViews\\[0\\].byteStride 6 is not a multiple of 4 from 4 to 252"
    stride_odd.gltf)
gltf_hostile(cycle 2 "${GH}/cycle.gltf: node 1 is on a cycle of the node hierarchy" cycle.gltf)
gltf_hostile(two-parents 2 "${GH}/two_parents.gltf: node 0 has more than one parent or is its own child" two_parents.gltf)
gltf_hostile(deep 2 "${GH}/deep.gltf: the node hierarchy is deeper than 1024" deep.gltf)
gltf_hostile(missing-bin 2 "${GH}/missing_bin.gltf: File not found : missing_bin.bin" missing_bin.gltf)
gltf_hostile(nan-position 2 "${GH}/nan_position.gltf: meshes\\[0\\].primitives\\[0\\] POSITION \\(accessor 2\\) holds a non-finite number"
    nan_position.gltf)
gltf_hostile(huge-count 2
    "${GH}/huge_count.gltf: accessors\\[0\\].count is 2000000000. it must be a whole number from 1 to 33554432"
    huge_count.gltf)
gltf_hostile(huge-buffer 2 "${GH}/huge_buffer.gltf: buffers\\[0\\].byteLength is 1000000000000000000. it must be a whole number from 1 to 2147483647"
    huge_buffer.gltf)
gltf_hostile(absolute-uri 2 "${GH}/absolute_uri.gltf: images\\[0\\].uri '/etc/passwd' is an absolute path \\(a model reads only files in its own directory\\)"
    absolute_uri.gltf)
gltf_hostile(scheme-uri 2 "${GH}/scheme_uri.gltf: images\\[0\\].uri 'https://example.com/texture.png' is not a relative path"
    scheme_uri.gltf)
gltf_hostile(climbing-uri 2 "${GH}/climbing_uri.gltf: images\\[0\\].uri 'textures/../../secret.png' leaves the model's directory"
    climbing_uri.gltf)
gltf_hostile(draco 2 "${GH}/draco.gltf: requires the extension 'KHR_draco_mesh_compression', which this loader does not implement"
    draco.gltf)
gltf_hostile(meshopt 2 "${GH}/meshopt.gltf: requires the extension 'EXT_meshopt_compression'" meshopt.gltf)
gltf_hostile(shell-uri 2 "${GH}/shell_uri.gltf: File not found" shell_uri.gltf)
gltf_hostile(truncated-glb 2 "${GH}/truncated.glb: the GLB header says [0-9]+ bytes, the file has [0-9]+" truncated.glb)
gltf_hostile(lying-chunk-glb 2 "${GH}/lying_chunk.glb: the GLB's JSON chunk \\([0-9]+ bytes\\) runs past the end of the file"
    lying_chunk.glb)
# Offsets, sizes and counts that a wrapping sum would let through, each refused by its JSON
# path; work a small file asks for, refused from its declared sizes before anything is decoded.
gltf_hostile(offset-wrap 2 "${GH}/offset_wrap.gltf: accessors\\[0\\].byteOffset is 18446744073608888320. it must be a whole number from 0 to 2147483647"
    offset_wrap.gltf)
gltf_hostile(view-offset-wrap 2 "${GH}/view_offset_wrap.gltf: bufferViews\\[0\\].byteOffset is 18446744073608888320;"
    view_offset_wrap.gltf)
gltf_hostile(index-offset-wrap 2 "${GH}/index_offset_wrap.gltf: accessors\\[1\\].byteOffset is 18446744073608888320;"
    index_offset_wrap.gltf)
gltf_hostile(stride-count 2
    "${GH}/stride_count.gltf: accessors\\[0\\]: 33554432 elements from byte 0 end at byte 8455716624, past the end of bufferViews\\[0\\] \\(36 bytes\\)"
    stride_count.gltf)
gltf_hostile(sparse-indices-wrap 2 "${GH}/sparse_indices_wrap.gltf: accessors\\[0\\].sparse.indices.byteOffset is 18446744073608888320;"
    sparse_indices_wrap.gltf)
gltf_hostile(sparse-values-wrap 2 "${GH}/sparse_values_wrap.gltf: accessors\\[0\\].sparse.values.byteOffset is 18446744073709551612;"
    sparse_values_wrap.gltf)
gltf_hostile(index-beyond-32-bits 2 "${GH}/index_beyond_32_bits.gltf: nodes\\[1\\].children\\[0\\] is 4294967296, beyond the 32-bit whole numbers glTF uses"
    index_beyond_32_bits.gltf)
gltf_hostile(chain-1025 2 "${GH}/chain_1025.gltf: the node hierarchy is deeper than 1024" chain_1025.gltf)
gltf_hostile(chain-1024 0 "chapter-[0-9]+: 1 draws" chain_1024.gltf)
gltf_hostile(index-budget 2
    "${GH}/index_budget.gltf: the default scene bakes indices: 33600000 \\(in 11200 nodes\\). at most 33554432 are loaded"
    index_budget.gltf)
gltf_hostile(values-budget 2
    "${GH}/values_budget.gltf: the default scene reads accessor values: 436207622 \\(in 1 node\\). at most 134217728 are loaded"
    values_budget.gltf)
gltf_hostile(primitive-product 2
    "${GH}/primitive_product.gltf: the default scene draws primitives: 110000 \\(in 10000 nodes\\). at most 20000 are loaded"
    primitive_product.gltf)
gltf_hostile(newline-extension warn "${GH}/newline_extension.gltf: extension EXT_a[?]b is not used" newline_extension.gltf)
foreach(chapter 10 14)
    hostile_test(gltf-big-numbers-in-extras-${chapter} ${chapter} warn
        "${GH}/big_numbers_in_extras.gltf: extension EXT_example is not used" --model ${GH}/big_numbers_in_extras.gltf)
    set_tests_properties(hostile.gltf-big-numbers-in-extras-${chapter} PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
endforeach()
# chapter-15 reads the translation of 3e9 as the others do, and then refuses it: its G-buffer keeps
# world positions in 16-bit floats (docs/reliability.md).
chapter_test(hostile.gltf-big-numbers-in-extras-15 WORKDIR /
    COMMAND $<TARGET_FILE:chapter-15> ${HOSTILE_RUN} --model ${GH}/big_numbers_in_extras.gltf
    EXPECT_EXIT 2
    EXPECT_STDERR "^warning: ${GH}/big_numbers_in_extras.gltf: extension EXT_example is not used\nchapter-15: error: ${GH}/big_numbers_in_extras.gltf: the scene reaches 3e[+]09 on an axis. the G-buffer keeps world positions in 16-bit floats[^\n]*\n$")
set_tests_properties(hostile.gltf-big-numbers-in-extras-15 PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
gltf_hostile(hdr-image 2 "${GH}/hdr_image.gltf \\(image 0\\): a Radiance HDR image. textures are read from PNG, JPEG, BMP or TGA images"
    hdr_image.gltf)
gltf_hostile(mode-fraction 2 "${GH}/mode_fraction.gltf: meshes\\[0\\].primitives\\[0\\].mode is not written as a whole number \\(it reads as 1.0\\): write it in digits only, as 1 rather than 1.0 or 1e0"
    mode_fraction.gltf)
gltf_hostile(negative-mesh 2 "${GH}/negative_mesh.gltf: nodes\\[0\\].mesh is -5. it must be a whole number of at least 0"
    negative_mesh.gltf)
gltf_hostile(root-twice 2 "${GH}/root_twice.gltf: scenes\\[0\\].nodes lists node 0 twice" root_twice.gltf)
gltf_hostile(huge-scale 2 "${GH}/huge_scale.gltf: a vertex lies at 3e\\+38 on an axis. coordinates from -1e15 to 1e15 are drawn"
    huge_scale.gltf)
gltf_hostile(data-folder-uri 2 "${GH}/data_folder_uri.gltf: images\\[0\\].uri 'data:/../outside.png' is not a relative path"
    data_folder_uri.gltf)
gltf_hostile(missing-newline 2 "${GH}/missing_newline.gltf: images\\[0\\].uri 'missing%0Aline.png' has a control character \\(NUL, a line break, [.][.][.]\\)"
    missing_newline.gltf)
gltf_hostile(webp-fallback warn "${GH}/webp_fallback.gltf: texture extension EXT_texture_webp is skipped"
    webp_fallback.gltf)
gltf_hostile(newline-key 2 "${GH}/newline_key.gltf: meshes\\[0\\].primitives\\[0\\].attributes.a[?]b is 4294967296, beyond the 32-bit whole numbers glTF uses"
    newline_key.gltf)
gltf_hostile(shared-sparse 2
    "${GH}/shared_sparse.gltf: the default scene bakes vertices: 335544300000 \\(in 10000 nodes\\). at most 8388608 are loaded"
    shared_sparse.gltf)
gltf_hostile(strip-flat 2 "${GH}/strip_flat.gltf: the default scene bakes vertices: 100663290 \\(in 1 node\\). at most 8388608"
    strip_flat.gltf)
gltf_hostile(budget-plus-one 2 "${GH}/budget_plus_one.gltf: the default scene bakes vertices: 8388609 \\(in 1 node\\)"
    budget_plus_one.gltf)
gltf_hostile(count-over-limit 2 "${GH}/count_33554433.gltf: accessors\\[2\\].count is 33554433. it must be a whole number from 1 to 33554432"
    count_33554433.gltf)
gltf_hostile(deep-extras 2 "${GH}/deep_extras.gltf: the JSON nests arrays and objects more than 64 deep \\(at byte [0-9]+\\)"
    deep_extras.gltf)
gltf_hostile(deep-glb 2 "${GH}/deep.glb: the JSON nests arrays and objects more than 64 deep" deep.glb)
gltf_hostile(lying-bin-chunk 2 "${GH}/lying_bin_chunk.glb: the GLB's binary chunk runs past the end of the file" lying_bin_chunk.glb)
gltf_hostile(data-uri-short 2 "${GH}/data_uri_short.gltf: Failed to decode 'uri'" data_uri_short.gltf)
gltf_hostile(data-uri-long 2 "${GH}/data_uri_long.gltf: bufferViews\\[0\\] \\(bytes 0..36\\) runs past the end of buffer 0 \\(4 bytes\\)"
    data_uri_long.gltf)
# Legal and within the budget, drawn: an accessor at the count limit that no mesh uses, a name of
# 100,000 '[' (brackets in strings are not nesting), and one 2^25-vertex sparse accessor under
# 1,000 nodes drawn by 3 indices (decoded once, not once per node).
gltf_hostile(count-at-limit 0 "chapter-[0-9]+: 1 draws" count_33554432.gltf)
gltf_hostile(brackets-in-string 0 "chapter-[0-9]+: 1 draws" brackets_in_string.gltf)
hostile_test(gltf-shared-sparse-indexed 15 0 "chapter-15: 1000 draws, 1000 triangles" --model ${GH}/shared_sparse_indexed.gltf)
# A loose timeout: decoded once per node, the accessor would take about 70 s here.
set_tests_properties(hostile.gltf-shared-sparse-indexed PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases" TIMEOUT 40)
hostile_test(gltf-unknown-extension 15 2 "${DATA}/corrupt.png: not a model file we read \\(.obj, .gltf, .glb or the book's converted .json\\)"
    --model ${DATA}/corrupt.png)
# Warnings: a missing image is a missing texture (the default one); BLEND is drawn as MASK.
gltf_hostile(missing-image warn "texture '${GH}/no_such_image.png' not found. using the default texture" missing_image.gltf)
gltf_hostile(blend warn "${GH}/blend.gltf: alphaMode BLEND is drawn as MASK with a cutoff of 0.5 \\(a G-buffer holds one surface per pixel\\)"
    blend.gltf)
gltf_hostile(emissive warn "${GH}/emissive.gltf: emissive light is not drawn" emissive.gltf)
gltf_hostile(vertex-colors warn "${GH}/vertex_colors.gltf: vertex colours \\(COLOR_n\\) are not used" vertex_colors.gltf)
gltf_hostile(skin warn "${GH}/skin.gltf: a skin whose mesh has no JOINTS_0 is not applied" skin.gltf)
gltf_hostile(morph-targets warn "${GH}/morph_targets.gltf: morph targets are not applied \\(drawn in the base shape\\)"
    morph_targets.gltf)
gltf_hostile(camera warn "${GH}/camera.gltf: its cameras are not used \\(the scene's camera is\\)" camera.gltf)
gltf_hostile(animation warn
    "${GH}/animation.gltf: its skins and animations are played by chapter-17 \\(drawn here in its rest pose\\)" animation.gltf)
gltf_hostile(second-uv-set warn
    "${GH}/second_uv_set.gltf: textures read TEXCOORD_0 only \\(a material asks for another set\\)" second_uv_set.gltf)
gltf_hostile(texture-transform warn "${GH}/texture_transform.gltf: texture extension KHR_texture_transform is skipped"
    texture_transform.gltf)
# Points and lines are skipped with a warning; with nothing else, there is nothing to draw.
hostile_test(gltf-lines-only 15 2 "${GH}/lines_only.gltf: the model's default scene has no triangles" --model ${GH}/lines_only.gltf)
set_tests_properties(hostile.gltf-lines-only PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")

# --book-scene on a stand-in for a clone of the book's repository (tools/gltf_cases.cpp, book/):
# Sponza.gltf where the book keeps it, a room of Sponza's extent under a node scaled 0.008. The
# image shows the book's camera (looking along +x, down), its sun (the floor lit, the walls not)
# and the green cube that marks its point light; chapters 10 and 14 open the same scene.
chapter_test(gltf.book-scene WORKDIR /
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 640 --height 360
            --book-scene ${GLTF}/book --screenshot ${TEST_OUT}/gltf-book-scene.png
    EXPECT_STDOUT "chapter-15: 6 draws, 652 triangles.*2 lights" QUIET_STDERR)
set_tests_properties(gltf.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP gltf-book-scene)
add_test(NAME gltf.book-scene-image COMMAND image_compare ${TEST_OUT}/gltf-book-scene.png
    --size 640 360 --golden ${GOLDEN}/gltf-book-scene.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(gltf.book-scene-image PROPERTIES FIXTURES_REQUIRED gltf-book-scene)
foreach(chapter 10 14)
    chapter_test(gltf.book-scene-chapter-${chapter} WORKDIR /
        COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless --width 320 --height 180
                --book-scene ${GLTF}/book/booksamples/chapter-15/resources/models/sponza/Sponza.gltf
        EXPECT_STDOUT "652 triangles" QUIET_STDERR)
    set_tests_properties(gltf.book-scene-chapter-${chapter} PROPERTIES FIXTURES_REQUIRED gltf-cases)
endforeach()
# A path that is neither a clone with Sponza.gltf in it nor a file: one line, exit 2.
hostile_test(book-scene-not-a-clone 15 2
    "${GLTF}/hostile/booksamples/chapter-15/resources/models/sponza/Sponza.gltf: no such file \\(--book-scene takes the book's clone or its Sponza.gltf\\)"
    --book-scene ${GLTF}/hostile)
hostile_test(book-scene-missing 10 2
    "${GLTF}/no-such-clone: no such file \\(--book-scene takes the book's clone or its Sponza.gltf\\)"
    --book-scene ${GLTF}/no-such-clone)
set_tests_properties(hostile.book-scene-not-a-clone hostile.book-scene-missing PROPERTIES
    FIXTURES_REQUIRED "hostile-inputs;gltf-cases")

# The book's converted models (common/model/book_model.cpp): the stand-in tree loads (--model, any
# chapter), and each broken rule is refused in one line naming the file and the rule -- a range
# past its file, one whose offset would wrap a sum, part of a vertex or a triangle, a material id
# no material has, a size that is not a number, no meshes, a factor outside 0..1, materials that
# are not a list, an id twice, a texture path naming no file, 20,001 meshes, a NaN vertex, an
# index past its mesh, a missing .idx -- and 20,000 meshes naming one 50 KB range (18 million
# vertices) are refused by their sum before anything is decoded.
set(BOOK_TREE ${GLTF}/book/booksamples/chapter-16/resources/models/tree/tree.json)
hostile_test(book-model-tree 15 0 "chapter-15: 2 draws, 10 triangles, [0-9]+ textures, 2 materials" --model ${BOOK_TREE})
set_tests_properties(hostile.book-model-tree PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
set(BH ${GLTF}/book-hostile)
foreach(case "vertices_past_end|tree.json: mesh 1's vertices \\(bytes 896 \\+ 56000\\) lie past the end of the .vtx file \\(1120 bytes\\)"
             "offset_wraps|tree.json: mesh 0's vertices \\(bytes 18446744073709551605 \\+ 896\\) lie past the end"
             "partial_vertex|tree.json: mesh 0's vtx_size 55 is not a whole number of 56-byte vertices"
             "partial_triangle|tree.json: mesh 0's idx_size 8 is not a whole number of triangles"
             "unknown_material|tree.json: mesh 0's material_id 'no-such-material' is in none of tree_mat.json"
             "size_not_a_number|tree.json: mesh 0's \"vtx_size\" is not a whole number 0 or more"
             "no_meshes|tree.json: \"meshes\" is not a list of meshes"
             "color_out_of_range|tree_mat.json: material 0's diffuse_color's \"x\" is not a number from 0 to 1"
             "materials_not_a_list|tree_mat.json: not a list of materials"
             "material_id_twice|tree_mat.json: material 1's id 'tree-mat-1' is empty or another material's"
             "texture_names_no_file|tree_mat.json: material 0's texture_path 'resources/models/..' names no file"
             "too_many_meshes|tree.json: 20001 meshes, more than the 20000 our limits allow"
             "vertex_nan|tree.json: mesh 0's vertex 2 has a value that is not finite or beyond 1e15"
             "index_past_vertices|tree.json: mesh 0's index 6 is 4, past its 4 vertices"
             "ranges_repeated|tree.json: its meshes make more than 8388608 vertices, our limit"
             "missing_idx|tree.idx: no such file")
    string(FIND "${case}" "|" bar)
    string(SUBSTRING "${case}" 0 ${bar} name)
    math(EXPR rest "${bar} + 1")
    string(SUBSTRING "${case}" ${rest} -1 message)
    string(REPLACE "_" "-" test ${name})
    hostile_test(book-model-${test} 15 2 "${BH}/${name}/${message}" --model ${BH}/${name}/tree.json)
    set_tests_properties(hostile.book-model-${test} PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases" TIMEOUT 20)
endforeach()
# Accepted: backslashes in the binaries' paths, a mesh without a material id.
hostile_test(book-model-windows-paths 15 0 "chapter-15: 2 draws, 10 triangles, [0-9]+ textures, 3 materials"
    --model ${BH}/windows_paths/tree.json)
set_tests_properties(hostile.book-model-windows-paths PROPERTIES FIXTURES_REQUIRED "hostile-inputs;gltf-cases")
# Not JSON: one line.
hostile_test(book-model-not-json 15 2 "${DATA}/syntax_error.json: not JSON \\(the book's converted model\\)"
    --model ${DATA}/syntax_error.json)
