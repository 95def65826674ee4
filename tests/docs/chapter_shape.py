#!/usr/bin/env python3
"""The shape of the chapters from 15 on (docs/chapter-15.md, "Main, Render and the frame loop").

    chapter_shape.py REPO         checks the tree; exit 1 with a line per break
    chapter_shape.py --self-test  shows that each kind of break is found

Each chapter-NN/ with NN >= 15, and chapter-15-lab/, is the book's Main (main.cpp) and Render
(render.cpp), and runs on the frame loop of common/app/frame_loop.cpp: none of its files acquires,
submits or presents a frame itself (the calls below), and its main.cpp hands the loop its steps.
Chapters 06, 10 and 14 write their loop out and are not checked. chapter-20 writes its own, on two
threads, where that is the lesson: in frame_threads.cpp only, and its main.cpp runs it.
"""
import os
import re
import sys
import tempfile

# What only the frame loop calls from chapter 15 on: the frame's acquire, submit and present.
LOOP_CALLS = re.compile(r'\b(acquireTargetImage|presentTargetImage|QueueSubmit2?|vkAcquireNextImageKHR|'
                        r'vkQueuePresentKHR|beginFrame|endFrame)\s*\(')


# A chapter whose own loop is its lesson: the file that holds it, and what its main.cpp calls.
OWN_LOOPS = {'chapter-20': ('frame_threads.cpp', 'runThreadedFrameLoop(')}


def chapters(repo):
    for name in sorted(os.listdir(repo)):
        match = re.fullmatch(r'chapter-(\d+)(-lab)?', name)
        if match and int(match.group(1)) >= 15 and os.path.isdir(os.path.join(repo, name)):
            yield name


def check(repo):
    problems = []
    found = False
    for chapter in chapters(repo):
        found = True
        folder = os.path.join(repo, chapter)
        for part in ('main.cpp', 'render.cpp', 'render.hpp'):
            if not os.path.isfile(os.path.join(folder, part)):
                problems.append(f'{chapter}: no {part} (the book\'s Main is main.cpp, its Render render.cpp)')
        for name in sorted(os.listdir(folder)):
            if not name.endswith(('.cpp', '.hpp')):
                continue
            with open(os.path.join(folder, name), encoding='utf-8') as f:
                for number, line in enumerate(f, 1):
                    code = line.split('//', 1)[0]
                    call = LOOP_CALLS.search(code)
                    if call and OWN_LOOPS.get(chapter, ('',))[0] != name:
                        problems.append(f'{chapter}/{name}:{number}: calls {call.group(1)}: the frame loop is '
                                        'common/app/frame_loop.cpp\'s from chapter 15 on')
        main = os.path.join(folder, 'main.cpp')
        if os.path.isfile(main):
            with open(main, encoding='utf-8') as f:
                text = f.read()
            loop = OWN_LOOPS.get(chapter, (None, 'common::runFrameLoop('))[1]
            if loop not in text:
                problems.append(f'{chapter}/main.cpp: does not run {loop.rstrip("(")}')
    if not found:
        problems.append('no chapter from 15 on found')
    return problems


def self_test():
    good_main = 'int run() { common::runFrameLoop(c.context, steps); }\n'
    cases = {
        'a good chapter': ({'chapter-15/main.cpp': good_main, 'chapter-15/render.cpp': '',
                            'chapter-15/render.hpp': ''}, None),
        'no render.cpp': ({'chapter-15/main.cpp': good_main, 'chapter-15/render.hpp': ''}, 'no render.cpp'),
        'a loop of its own': ({'chapter-18/main.cpp': good_main, 'chapter-18/render.hpp': '',
                               'chapter-18/render.cpp': 'VK_CHECK(common::vk13.QueueSubmit2(q, 1, &s, f));\n'},
                              'calls QueueSubmit2'),
        'a present of its own': ({'chapter-15-lab/main.cpp': good_main, 'chapter-15-lab/render.hpp': '',
                                  'chapter-15-lab/render.cpp': '',
                                  'chapter-15-lab/study.cpp': 'presentTargetImage(t, d, i, f);\n'},
                                 'calls presentTargetImage'),
        'no frame loop': ({'chapter-16/main.cpp': 'int main() {}\n', 'chapter-16/render.cpp': '',
                           'chapter-16/render.hpp': ''}, 'does not run common::runFrameLoop'),
        'a comment is not a call': ({'chapter-17/main.cpp': good_main + '// acquireTargetImage(...) is the loop\'s\n',
                                     'chapter-17/render.cpp': '', 'chapter-17/render.hpp': ''}, None),
        'chapter-14 writes its loop out': ({'chapter-14/main.cpp': 'acquireTargetImage(t);\n',
                                            'chapter-15/main.cpp': good_main, 'chapter-15/render.cpp': '',
                                            'chapter-15/render.hpp': ''}, None),
        'chapter-20 writes its threads\' loop out': ({'chapter-20/main.cpp': 'runThreadedFrameLoop(c, s);\n',
                                                     'chapter-20/render.cpp': '', 'chapter-20/render.hpp': '',
                                                     'chapter-20/frame_threads.cpp': 'presentImage(t);\n'
                                                                                     'QueueSubmit2(q);\n'}, None),
        'chapter-20 submits from its Render': ({'chapter-20/main.cpp': 'runThreadedFrameLoop(c, s);\n',
                                                'chapter-20/render.hpp': '',
                                                'chapter-20/render.cpp': 'QueueSubmit2(q);\n'}, 'calls QueueSubmit2'),
        'chapter-20 without its loop': ({'chapter-20/main.cpp': good_main, 'chapter-20/render.cpp': '',
                                         'chapter-20/render.hpp': ''}, 'does not run runThreadedFrameLoop'),
    }
    failures = 0
    for title, (files, expected) in cases.items():
        with tempfile.TemporaryDirectory() as repo:
            for path, text in files.items():
                os.makedirs(os.path.dirname(os.path.join(repo, path)), exist_ok=True)
                with open(os.path.join(repo, path), 'w', encoding='utf-8') as f:
                    f.write(text)
            problems = check(repo)
            ok = not problems if expected is None else any(expected in p for p in problems)
            print(f'{"ok  " if ok else "FAIL"} {title}: {problems or "clean"}')
            failures += not ok
    return 1 if failures else 0


def main():
    if sys.argv[1:] == ['--self-test']:
        return self_test()
    problems = check(sys.argv[1])
    for problem in problems:
        print(problem)
    print(f'{len(list(chapters(sys.argv[1])))} chapters checked, {len(problems)} problem(s)')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
