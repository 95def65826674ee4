#!/usr/bin/env python3
"""The interface changes tests/chapters/live_reload.sh makes under a running chapter (scenario 'rule').

    live_reload_rules.py SHADERS RULE

Edits the copy of the shader sources SHADERS as the rule says, saving each file as many editors
do (a new file renamed over the old one, included files first), and prints the message the
chapter must refuse the change with (an extended regular expression). Each rule is one thing the
C++ relies on that a reload must not change (docs/live-shaders.md, "What a reload cannot change");
the rules named accept-* are safe changes, which must be reloaded (the script prints ACCEPTED).
"""
import os
import sys

INPUTS = 'chapter-15/light_inputs.glsl'
GBUFFER = 'chapter-15/gbuffer_read.glsl'

# rule: ([(file, old text, new text)], message). "END" as the old text puts the new line before
# the file's last '}'; "ALL text" replaces every occurrence of text.
RULES = {
    # The issue a reader hits first: a uniform block grown past what the C++ binds.
    'block-grown': ([(INPUTS, '    ShaderSceneInfo scene;\n};', '    ShaderSceneInfo scene;\n    vec4 extraTint[64];\n};'),
                     ('chapter-15/light.frag', 'END', '    outColor += extraTint[63];')],
                    r'set 2 binding 0 \(uniform block Scene\): member extraTint \(vec4\[64\], bytes [0-9]+\.\.[0-9]+\) '
                    r'lies past the [0-9]+ bytes the shader its pipeline was made for declares'),
    'member-moved': ([(INPUTS, 'uniform Scene {\n', 'uniform Scene {\n    vec4 movedBy;\n')],
                     r'\(uniform block Scene\): member scene \(struct ShaderSceneInfo, bytes 16\.\.'),
    'image-type': ([(GBUFFER, 'uniform sampler2D depthAttachment;', 'uniform sampler2DArray depthAttachment;'),
                    (GBUFFER, 'textureLod(depthAttachment, uv, 0.0)', 'textureLod(depthAttachment, vec3(uv, 0.0), 0.0)')],
                   r'set 0 binding 4 \(depthAttachment\) is a sampler2DArray now; the shader its pipeline was made '
                   r'for has a sampler2D'),
    'array-size': ([(GBUFFER, 'uniform sampler2D depthAttachment;', 'uniform sampler2D depthAttachment[2];'),
                    (GBUFFER, 'textureLod(depthAttachment, uv, 0.0)', 'textureLod(depthAttachment[1], uv, 0.0)')],
                   r'set 0 binding 4 \(depthAttachment\) is an array of 2 now; the shader its pipeline was made '
                   r'for declares 1'),
    'push-grown': ([(INPUTS, '    LightView show;  // gpu_types.glsl\n', '    LightView show;\n    vec4 pushedTint;\n'),
                    ('chapter-15/light.frag', 'END', '    outColor += pushedTint;')],
                   r'push constants \(LightViewBlock\): member pushedTint \(vec4, bytes [0-9]+\.\.[0-9]+\) lies past'),
    'output-moved': ([('chapter-15/light.frag', 'layout(location = 0) out vec4 outColor;',
                       'layout(location = 1) out vec4 outColor;')],
                     r'it no longer writes output location 0 \(outColor, vec4\)'),
    # The C++ sets a VkBool32: read as an int it is the same number, as a float it is not.
    'constant-type': ([('chapter-15/scene_surface.glsl', 'layout(constant_id = 0) const bool ALPHA_TEST = true;',
                        'layout(constant_id = 0) const float ALPHA_TEST_VALUE = 1.0;\n'
                        'const bool ALPHA_TEST = true;')],
                      r'specialization constant 0 \(ALPHA_TEST_VALUE\) is float now; the C\+\+ sets it as bool'),
    'capability': ([('chapter-15/light.frag', 'END', '    outColor.r += float(double(outColor.g));')],
                   r'it needs the Float64 capability, which the shader its pipeline was made for does not'),
    'readonly-lost': ([(INPUTS, 'readonly buffer Lights', 'buffer Lights'),
                       ('chapter-15/light.frag', 'END', '    lights[0].intensity *= 1.0;')],
                      r'set 1 binding 0 \(storage block Lights\) is written now; the shader its pipeline was made '
                      r'for only reads it'),
    'aliased-binding': ([('chapter-15/light.frag', 'layout(location = 0) out vec4 outColor;',
                          'layout(set = 1, binding = 0) uniform LightsAsUniform { vec4 firstLight; } lightsAsUniform;\n'
                          'layout(location = 0) out vec4 outColor;'),
                         ('chapter-15/light.frag', 'END', '    outColor += lightsAsUniform.firstLight * 0.0;')],
                        r'set 1 binding 0 \([A-Za-z]+\) is a uniform block now; the shader its pipeline was made for '
                        r'has a storage block'),
    'local-size': ([('chapter-15-lab/light.comp', 'local_size_x = 8, local_size_y = 8',
                     'local_size_x = 4, local_size_y = 4')],
                   r'local size is 4 x 4 x 1 now; the dispatch is sized for 8 x 8 x 1'),
    # Refused although the specification would allow them (docs/live-shaders.md): a vertex input
    # read with more components, and a value passed between two stages, whatever the order their
    # files are seen in (the vertex shader's new output and the fragment shader's new input are
    # each refused: the message is the fragment shader's, printed once its file is compiled).
    'input-components': ([('chapter-15/scene.vert', 'layout(location = 0) in vec3 inPosition;',
                           'layout(location = 0) in vec4 inPosition;'),
                          ('chapter-15/scene.vert', 'vec4(inPosition, 1.0)',
                           'vec4(inPosition.xyz + vec3(inPosition.w * 0.0), 1.0)')],
                         r'input location 0 \(inPosition\) is vec4 now; the shader its pipeline was made for '
                         r'reads vec3'),
    # A vertex shader saved with a new output before the fragment shader that reads it (a reader
    # saving one file, then the other): refused alone, never live with an output no stage reads.
    'new-output': ([('chapter-15/scene.vert', 'layout(location = 4) out vec2 outUv;',
                     'layout(location = 4) out vec2 outUv;\nlayout(location = 7) out float outExtra;'),
                    ('chapter-15/scene.vert', 'END', '    outExtra = 1.0;')],
                   r'it writes output location 7 \(outExtra, float\), which the shader its pipeline was made for '
                   r'does not declare'),
    'new-varying': ([('chapter-15/scene.vert', 'layout(location = 4) out vec2 outUv;',
                      'layout(location = 4) out vec2 outUv;\nlayout(location = 7) out float outExtra;'),
                     ('chapter-15/scene.vert', 'END', '    outExtra = 1.0;'),
                     ('chapter-15/scene.frag', 'layout(location = 0) out vec4 outPosition;',
                      'layout(location = 7) in float inExtra;\nlayout(location = 0) out vec4 outPosition;'),
                     ('chapter-15/scene.frag', 'END', '    outAlbedo.a *= inExtra;')],
                    r'it reads input location 7 \(inExtra, float\), which the shader its pipeline was made for '
                    r'does not declare'),
    # Accepted (message None): the edit's magenta line, with interface changes that are safe.
    'accept-unused-member': ([(INPUTS, '    ShaderSceneInfo scene;\n};', '    ShaderSceneInfo scene;\n    vec4 unusedTint[64];\n};'),
                              ('chapter-15/light.frag', 'END', '    outColor = vec4(1.0, 0.0, 1.0, 1.0);')],
                             None),
    # Renamed: the output variable (locations and types are the interface, names are not).
    'accept-renamed': ([('chapter-15/light.frag', 'ALL outColor', 'fragmentColor'),
                        ('chapter-15/light.frag', 'END', '    fragmentColor = vec4(1.0, 0.0, 1.0, 1.0);')],
                       None),
    # A specialization constant the C++ does not set: it keeps its default.
    'accept-new-constant': ([('chapter-15/light.frag', 'layout(location = 0) out vec4 outColor;',
                              'layout(constant_id = 7) const int UNSET_CONSTANT = 3;\n'
                              'layout(location = 0) out vec4 outColor;'),
                             ('chapter-15/light.frag', 'END',
                              '    outColor = vec4(1.0, 0.0, float(UNSET_CONSTANT) / 3.0, 1.0);')],
                            None),
    # Capabilities every Vulkan 1.1 device has: ImageQuery (textureSize), DerivativeControl (dFdxFine).
    'accept-capabilities': ([('chapter-15/light.frag', 'END',
                              '    outColor = vec4(1.0, 0.0, 1.0, 1.0) + vec4(0.0 * float(textureSize(depthAttachment, 0).x)'
                              ' + 0.0 * dFdxFine(inUv.x));')],
                            None),
    'accept-fewer-resources': ([('chapter-15/light.frag', 'END', '    outColor = vec4(1.0, 0.0, 1.0, 1.0);'),
                                ('chapter-15/light.frag', 'outColor = shadePixel(readGBuffer(inUv), ivec2(gl_FragCoord.xy), 1.0);',
                                 'outColor = vec4(0.0);')],
                               None),
}


def main():
    root, rule = sys.argv[1], sys.argv[2]
    edits, message = RULES[rule]
    texts = {}
    for name, old, new in edits:
        text = texts.get(name) or open(os.path.join(root, name)).read()
        if old.startswith('ALL '):  # every occurrence
            if old[4:] not in text:
                sys.exit(f'live_reload_rules: {name} has no {old[4:]!r}')
            text = text.replace(old[4:], new)
        elif old == 'END':
            end = text.rindex('}')
            start = text.rindex('\n', 0, end) + 1
            text = text[:start] + new + '\n' + text[start:]
        else:
            if old not in text:
                sys.exit(f'live_reload_rules: {name} has no {old!r}')
            text = text.replace(old, new, 1)
        texts[name] = text
    for name, text in sorted(texts.items(), key=lambda item: item[0].endswith(('.frag', '.comp', '.vert'))):
        path = os.path.join(root, name)
        with open(path + '.new', 'w') as out:
            out.write(text)
        os.replace(path + '.new', path)
    print(message if message is not None else 'ACCEPTED')


if __name__ == '__main__':
    main()
