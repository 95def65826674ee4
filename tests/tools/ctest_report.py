#!/usr/bin/env python3
"""What a test stage cost, from the JUnit file ctest writes (ctest --output-junit FILE).

    ctest_report.py JUNIT.xml [STAGE]            the stage's test count, the sum of its tests'
                                                 times (the time the cores spent on tests, above
                                                 the stage's wall time under ctest -j) and its 10
                                                 slowest tests (scripts/setup.sh test prints this
                                                 at the end of each test stage)
    ctest_report.py --groups JUNIT.xml           each group's tests, test time and share of the
                                                 whole (a group: the name up to its first '.';
                                                 the standalone builds one group of their own)
"""
import collections
import sys
import xml.etree.ElementTree as ElementTree


def read(path):
    cases = ElementTree.parse(path).getroot().iter('testcase')
    return [(float(case.get('time', 0.0)), case.get('name', '?')) for case in cases]


def groups(path):
    times = read(path)
    total = sum(t for t, _ in times)
    if not times or total <= 0:
        sys.exit(f'ctest_report: no test times in {path}')
    by_group = collections.defaultdict(lambda: [0, 0.0])
    for seconds, name in times:
        group = 'standalone builds' if name.endswith('.standalone-build') else name.split('.')[0]
        by_group[group][0] += 1
        by_group[group][1] += seconds
    print(f'| group | tests | test time | share |\n|---|---|---|---|')
    for group, (count, seconds) in sorted(by_group.items(), key=lambda item: -item[1][1]):
        print(f'| {group} | {count} | {seconds:.0f} s | {100 * seconds / total:.1f}% |')
    print(f'| all | {len(times)} | {total:.0f} s | 100% |')


def main():
    if len(sys.argv) > 2 and sys.argv[1] == '--groups':
        groups(sys.argv[2])
        return
    path = sys.argv[1]
    stage = sys.argv[2] if len(sys.argv) > 2 else 'tests'
    try:
        times = read(path)
    except (OSError, ElementTree.ParseError) as error:
        print(f'setup: {stage}: no test times ({error})')
        return
    times.sort(reverse=True)
    total = sum(t for t, _ in times)
    print(f'setup: {stage}: {len(times)} tests, {total:.0f} s of test time; the 10 slowest:')
    for seconds, name in times[:10]:
        print(f'setup:   {seconds:7.1f} s  {name}')


if __name__ == '__main__':
    main()
