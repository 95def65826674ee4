#!/usr/bin/env python3
"""shaders.depfiles: the build rebuilds a shader when a file it includes is edited. glslangValidator
writes a dependency file beside each .spv (cmake/VulkanBook.cmake passes --depfile, and the
add_custom_command reads it as its DEPFILE); this checks that every shader's dependency file lists
the shader and every file it includes, directly or through another include, as the GLSL's own
#include lines resolve them (the including file's folder first, then shaders/include); includes
inside #if blocks are left out of the check, since the build's macros may skip them.

  shader_depfiles.py SHADERS_SOURCE_DIR BUILD_SHADERS_DIR
"""
import pathlib
import re
import sys

source, built = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2])


def unconditional(text):
    """The names of the #include lines outside every #if/#ifdef/#ifndef block (those inside may be
    skipped under this build's macros, and then rightly left out of the dependency file)."""
    depth, names = 0, []
    for line in text.split("\n"):
        directive = re.match(r"\s*#\s*(\w+)\s*(.*)", line)
        if not directive:
            continue
        word, rest = directive.groups()
        if word in ("if", "ifdef", "ifndef"):
            depth += 1
        elif word == "endif":
            depth -= 1
        elif word == "include" and depth == 0:
            name = re.match(r'["<]([^">]+)[">]', rest)
            if not name:
                sys.exit(f"an #include we cannot read: {line.strip()}")
            names.append(name.group(1))
    return names


def includes(path, seen):
    for name in unconditional(path.read_text()):
        for folder in (path.parent, source / "include"):
            found = (folder / name).resolve()
            if found.exists():
                if found not in seen:
                    seen.add(found)
                    includes(found, seen)
                break
        else:
            sys.exit(f"{path}: #include \"{name}\" found nowhere")
    return seen


problems = checked = with_includes = 0
for depfile in sorted(built.rglob("*.spv.d")):
    shader = source / depfile.relative_to(built).as_posix()[: -len(".spv.d")]
    if not shader.exists():  # a variant built under another name: its .source file names the GLSL
        described = depfile.with_name(depfile.name[: -len(".spv.d")] + ".source")
        if not described.exists():
            print(f"{depfile}: no shader {shader} and no {described.name} naming its source")
            problems += 1
            continue
        shader = source / described.read_text().split("\n")[0].strip()
    text = depfile.read_text().replace("\\\n", " ")
    listed = {pathlib.Path(p).resolve() for p in text.split(":", 1)[1].split()}
    wanted = {shader.resolve()} | includes(shader, set())
    missing = wanted - listed
    checked += 1
    with_includes += len(wanted) > 1
    if missing:
        problems += 1
        print(f"{depfile}: does not list {', '.join(sorted(str(m) for m in missing))}")
print(f"{checked} dependency files checked ({with_includes} of shaders with includes), {problems} incomplete")
sys.exit(1 if problems or checked == 0 or with_includes == 0 else 0)
