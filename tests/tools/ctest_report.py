#!/usr/bin/env python3
"""What a test stage cost, from the JUnit file ctest writes (ctest --output-junit FILE).

    ctest_report.py JUNIT.xml [STAGE]

Prints the stage's test count, the sum of its tests' times (the test time the cores spent, above
the stage's wall time under ctest -j) and its 10 slowest tests; scripts/setup.sh test calls it at
the end of each test stage.
"""
import sys
import xml.etree.ElementTree as ElementTree


def main():
    path = sys.argv[1]
    stage = sys.argv[2] if len(sys.argv) > 2 else 'tests'
    try:
        cases = ElementTree.parse(path).getroot().iter('testcase')
        times = [(float(case.get('time', 0.0)), case.get('name', '?')) for case in cases]
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
