#!/usr/bin/env python3
"""The include order of common/ and the chapters (common/README.md says it).

  include_order.py ROOT          checks the tree at ROOT; one line per break, exit 1 on any
  include_order.py --self-test   checks that each kind of break is found, on small made-up trees

Rules:
- every source of common/ lies in a folder of common/README.md's table (between the
  include-order markers); a file includes files of its own folder and of folders above it in the
  table, always by their full name ("common/vk/device.hpp"), never a chapter;
- no two modules (a .hpp with its .cpp) include each other, directly or round a circle;
- a chapter includes its own files by their bare name and another chapter's by the chapter's
  folder ("chapter-15/scene_pass.hpp"), only an earlier chapter's (the lab may take any);
  no chapter's CMakeLists.txt puts another chapter's folder on an include path.
"""
import os
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SOURCE = (".hpp", ".cpp", ".h")


def folder_order(root):
    text = open(os.path.join(root, "common", "README.md"), encoding="utf-8").read()
    table = text.split("<!-- include-order -->", 1)[1].split("<!-- /include-order -->", 1)[0]
    return [m.group(1) for m in re.finditer(r"^\|\s*`([a-z_]+)/`", table, re.M)]


def chapter_number(name):
    m = re.match(r"chapter-(\d+)", name)
    return int(m.group(1)) if m else None


def check(root):
    problems = []
    order = folder_order(root)
    rank = {folder: i for i, folder in enumerate(order)}
    common = os.path.join(root, "common")
    graph = {}  # module -> modules it includes
    for dirpath, dirnames, filenames in os.walk(common):
        dirnames.sort()
        for name in sorted(filenames):
            if not name.endswith(SOURCE):
                continue
            rel = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")
            parts = rel.split("/")
            if len(parts) != 3 or parts[1] not in rank:
                problems.append(f"{rel}: not in a folder of common/README.md's table")
                continue
            folder = parts[1]
            module = os.path.splitext(rel)[0]
            graph.setdefault(module, set())
            text = open(os.path.join(root, rel), encoding="utf-8").read()
            for inc in INCLUDE.findall(text):
                if inc.startswith("chapter-"):
                    problems.append(f"{rel}: includes {inc}: common never includes a chapter")
                    continue
                ip = inc.split("/")
                if ip[0] != "common" or len(ip) != 3:
                    problems.append(f'{rel}: includes "{inc}": name it from the root, "common/FOLDER/FILE"')
                    continue
                if not os.path.isfile(os.path.join(root, inc)):
                    problems.append(f"{rel}: includes {inc}, which does not exist")
                    continue
                if ip[1] not in rank:
                    problems.append(f"{rel}: includes {inc}, from a folder not in the table")
                elif rank[ip[1]] > rank[folder]:
                    problems.append(f"{rel}: includes {inc}: {ip[1]}/ comes after {folder}/ in the order")
                target = os.path.splitext(inc)[0]
                if target != module:
                    graph[module].add(target)
    # Circles among modules (depth-first search; each circle reported once by its members).
    state, stack, seen_cycles = {}, [], set()

    def visit(m):
        state[m] = 1
        stack.append(m)
        for n in sorted(graph.get(m, ())):
            if state.get(n) == 1:
                cycle = stack[stack.index(n):]
                key = frozenset(cycle)
                if key not in seen_cycles:
                    seen_cycles.add(key)
                    problems.append("include circle: " + " -> ".join(cycle + [n]))
            elif state.get(n) is None:
                visit(n)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if state.get(m) is None:
            visit(m)
    # Chapters.
    for chapter in sorted(os.listdir(root)):
        cdir = os.path.join(root, chapter)
        if not chapter.startswith("chapter-") or not os.path.isdir(cdir):
            continue
        number = chapter_number(chapter)
        study = not re.fullmatch(r"chapter-\d+", chapter)
        for name in sorted(os.listdir(cdir)):
            path = os.path.join(cdir, name)
            if name == "CMakeLists.txt":
                text = open(path, encoding="utf-8").read()
                for m in re.finditer(r"target_include_directories\(([^)]*)\)", text):
                    dirs = re.split(r"\b(?:PRIVATE|PUBLIC|INTERFACE)\b", m.group(1), maxsplit=1)[-1]
                    if "chapter-" in dirs or "CHAPTER_" in dirs:
                        problems.append(f"{chapter}/CMakeLists.txt: puts another chapter's folder on the "
                                        f"include path; include its files as \"chapter-NN/FILE\"")
                continue
            if not name.endswith(SOURCE):
                continue
            text = open(path, encoding="utf-8").read()
            for inc in INCLUDE.findall(text):
                ip = inc.split("/")
                if ip[0] == "common":
                    if not os.path.isfile(os.path.join(root, inc)):
                        problems.append(f"{chapter}/{name}: includes {inc}, which does not exist")
                    continue
                if len(ip) == 1:
                    if not os.path.isfile(os.path.join(cdir, inc)):
                        problems.append(f'{chapter}/{name}: includes "{inc}", not a file of {chapter}/: '
                                        f'name the chapter it comes from')
                    continue
                if ip[0].startswith("chapter-") and os.path.isfile(os.path.join(root, inc)):
                    other = chapter_number(ip[0])
                    if ip[0] == chapter:
                        problems.append(f"{chapter}/{name}: includes its own {inc} by the chapter's name")
                    elif not re.fullmatch(r"chapter-\d+", ip[0]):
                        problems.append(f"{chapter}/{name}: includes {inc}: a chapter never includes a study")
                    elif not study and other is not None and number is not None and other >= number:
                        problems.append(f"{chapter}/{name}: includes {inc}, a later chapter's")
                    continue
                problems.append(f"{chapter}/{name}: includes {inc}, which is neither its own, common's "
                                f"nor an earlier chapter's file")
    return problems


def self_test():
    def tree(files):
        root = tempfile.mkdtemp(prefix="include_order.")
        readme = ("<!-- include-order -->\n| folder | x |\n|---|---|\n| `core/` | a |\n| `vk/` | b |\n"
                  "<!-- /include-order -->\n")
        files = {"common/README.md": readme, **files}
        for rel, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            open(os.path.join(root, rel), "w").write(text)
        return root

    good = {"common/core/a.hpp": "", "common/vk/b.hpp": '#include "common/core/a.hpp"\n',
            "chapter-10/main.cpp": '#include "pass.hpp"\n#include "common/vk/b.hpp"\n',
            "chapter-10/pass.hpp": "", "chapter-16/main.cpp": '#include "chapter-10/pass.hpp"\n'}
    cases = {
        "a clean tree": ({}, None),
        "an upward include": ({"common/core/a.hpp": '#include "common/vk/b.hpp"\n'}, "comes after"),
        "a circle": ({"common/vk/c.hpp": '#include "common/vk/d.hpp"\n',
                      "common/vk/d.cpp": '#include "common/vk/c.hpp"\n', "common/vk/d.hpp": ""}, "circle"),
        "a loose file": ({"common/e.hpp": ""}, "not in a folder"),
        "a bare include in common": ({"common/vk/f.cpp": '#include "b.hpp"\n'}, "from the root"),
        "common including a chapter": ({"common/vk/g.cpp": '#include "chapter-10/pass.hpp"\n'}, "never includes"),
        "a borrowed bare include": ({"chapter-16/x.cpp": '#include "pass.hpp"\n'}, "name the chapter"),
        "a later chapter's file": ({"chapter-10/y.cpp": '#include "chapter-16/main.cpp"\n'}, "later chapter"),
        "an include path": ({"chapter-16/CMakeLists.txt":
                             "target_include_directories(chapter-16 PRIVATE ../chapter-10)\n"}, "include path"),
    }
    failed = 0
    for what, (extra, expect) in cases.items():
        problems = check(tree({**good, **extra}))
        ok = (not problems) if expect is None else any(expect in p for p in problems)
        if not ok:
            failed += 1
            print(f"self-test: {what}: expected {expect or 'no problem'}, got {problems}")
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases right")
    return 1 if failed else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    problems = check(sys.argv[1])
    for p in problems:
        print(p)
    print(f"{len(problems)} include problem(s)" if problems else "includes follow the order")
    sys.exit(1 if problems else 0)
