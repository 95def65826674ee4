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

# Quoted includes, and bracketed ones that name a file of ours (common/ and the chapters are on an
# include path, so <common/...> would compile too).
INCLUDE = re.compile(r'^\s*#\s*include\s*(?:"([^"]+)"|<((?:common|chapter-[\w-]+)/[^>]+)>)', re.M)
SOURCE = (".hpp", ".cpp", ".h")


def includes(text):
    return [quoted or bracketed for quoted, bracketed in INCLUDE.findall(text)]


def find_circles(graph, problems):
    """Reports each circle among the modules of `graph` (module -> modules it includes) once."""
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
            for inc in includes(text):
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
    find_circles(graph, problems)
    # Chapters.
    for chapter in sorted(os.listdir(root)):
        cdir = os.path.join(root, chapter)
        if not chapter.startswith("chapter-") or not os.path.isdir(cdir):
            continue
        number = chapter_number(chapter)
        study = not re.fullmatch(r"chapter-\d+", chapter)
        chapter_graph = {}
        for dirpath, dirnames, filenames in os.walk(cdir):
            dirnames.sort()
            for name in sorted(filenames):
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root).replace(os.sep, "/")
                here = os.path.dirname(path)
                if name == "CMakeLists.txt" or name.endswith(".cmake"):
                    text = open(path, encoding="utf-8").read()
                    for m in re.finditer(r"\b(?:target_)?include_directories\(([^)]*)\)", text):
                        dirs = re.split(r"\b(?:PRIVATE|PUBLIC|INTERFACE|SYSTEM|BEFORE|AFTER)\b", m.group(1))[-1]
                        if "chapter-" in dirs or "CHAPTER_" in dirs:
                            problems.append(f"{rel}: puts another chapter's folder on the include path; "
                                            f"include its files as \"chapter-NN/FILE\"")
                    continue
                if not name.endswith(SOURCE):
                    continue
                module = os.path.splitext(rel)[0]
                chapter_graph.setdefault(module, set())
                text = open(path, encoding="utf-8").read()
                for inc in includes(text):
                    ip = inc.split("/")
                    if ip[0] == "common":
                        if not os.path.isfile(os.path.join(root, inc)):
                            problems.append(f"{rel}: includes {inc}, which does not exist")
                        continue
                    if not ip[0].startswith("chapter-"):
                        if not os.path.isfile(os.path.join(here, inc)):
                            problems.append(f'{rel}: includes "{inc}", not a file of {chapter}/: '
                                            f'name the chapter it comes from')
                        else:
                            target = os.path.splitext(os.path.relpath(os.path.join(here, inc), root))[0]
                            if target.replace(os.sep, "/") != module:
                                chapter_graph[module].add(target.replace(os.sep, "/"))
                        continue
                    if not os.path.isfile(os.path.join(root, inc)):
                        problems.append(f"{rel}: includes {inc}, which does not exist")
                        continue
                    other = chapter_number(ip[0])
                    if ip[0] == chapter:
                        problems.append(f"{rel}: includes its own {inc} by the chapter's name")
                    elif not re.fullmatch(r"chapter-\d+", ip[0]):
                        problems.append(f"{rel}: includes {inc}: a chapter never includes a study")
                    elif not study and other is not None and number is not None and other >= number:
                        problems.append(f"{rel}: includes {inc}, a later chapter's")
        find_circles(chapter_graph, problems)
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
        "a directory-wide include path": ({"chapter-16/CMakeLists.txt": "include_directories(../chapter-10)\n"},
                                          "include path"),
        "a bracketed upward include": ({"common/core/g.hpp": "#include <common/vk/b.hpp>\n"}, "comes after"),
        "a circle of three": ({"common/vk/p.hpp": '#include "common/vk/q.hpp"\n',
                               "common/vk/q.hpp": '#include "common/vk/r.hpp"\n',
                               "common/vk/r.hpp": '#include "common/vk/p.hpp"\n'}, "circle"),
        "a missing file in common": ({"common/vk/h.cpp": '#include "common/vk/none.hpp"\n'}, "does not exist"),
        "a folder not in the table": ({"common/vk/i.cpp": '#include "common/extra/x.hpp"\n',
                                       "common/extra/x.hpp": ""}, "not in"),
        "a chapter including a study": ({"chapter-16/j.cpp": '#include "chapter-15-lab/k.hpp"\n',
                                         "chapter-15-lab/k.hpp": ""}, "never includes a study"),
        "a chapter naming itself": ({"chapter-10/l.cpp": '#include "chapter-10/pass.hpp"\n'}, "its own"),
        "a chapter's missing file": ({"chapter-10/m.cpp": '#include "chapter-06/none.hpp"\n'}, "does not exist"),
        "a file in a chapter's subfolder": ({"chapter-10/sub/n.cpp": '#include "pass.hpp"\n'}, "name the chapter"),
        "a circle in a chapter": ({"chapter-10/s.hpp": '#include "t.hpp"\n', "chapter-10/t.hpp": '#include "s.hpp"\n'},
                                  "circle"),
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
