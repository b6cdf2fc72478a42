#!/usr/bin/env python3
"""The test list, derived from the sources: Meson registers what this prints; CMake globs the same files.

    list_tests.py meson LAYER          lines `source<TAB>file`, `case<TAB>name`, `check<TAB>name` for
                                       tests/LAYER: its *_test.cpp, their TEST_CASE names, compile_fail/*.cpp
    list_tests.py verify LAYER EXE     exit 1 unless EXE --list-test-cases names exactly the cases read here
    list_tests.py compare CMAKE MESON  exit 1 unless `ctest -N` in build dir CMAKE and `meson test --list`
                                       in build dir MESON register the same tests

A new test file is found by CMake at the next build (CONFIGURE_DEPENDS) and by Meson at the next
`meson setup --reconfigure` (tools/test.sh runs one); a new TEST_CASE in an existing file re-runs
Meson's configure by itself (the sources are read with fs.read, which Meson watches).
A comma in a name becomes `?` in the --test-case filter (doctest splits filters on commas); Meson shows a\ncolon in a test name as `_`, so the comparison reads them alike.
"""
import glob
import os
import re
import subprocess
import sys

TESTS = os.path.dirname(os.path.abspath(__file__))
CASE = re.compile(r'\bTEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)"')


def sources(layer):
    return sorted(glob.glob(os.path.join(TESTS, layer, '*_test.cpp')))


def cases(source):
    with open(source, encoding='utf-8') as f:
        text = f.read()
    names = [m.replace('\\"', '"').replace('\\\\', '\\') for m in CASE.findall(text)]
    for name in names:
        if ';' in name:  # CMake splits a test name on it, so the two build systems would disagree
            sys.exit(f'{source}: test case "{name}" has a semicolon; CMake splits names on it: use a comma')
    return names


def case_filter(name):
    """A --test-case filter matching exactly `name`: doctest splits filters on commas, so they become `?`."""
    return name.replace(',', '?')


def checks(layer):
    return [os.path.splitext(os.path.basename(p))[0]
            for p in sorted(glob.glob(os.path.join(TESTS, layer, 'compile_fail', '*.cpp')))]


def meson(layer):
    for source in sources(layer):
        print(f'source\t{os.path.relpath(source, os.path.join(TESTS, layer))}')
        for name in cases(source):
            print(f'case\t{name}\t{case_filter(name)}')
    for name in checks(layer):
        print(f'check\t{name}')


def verify(layer, exe):
    out = subprocess.run([exe, '--list-test-cases', '--no-version'], capture_output=True, text=True, check=True).stdout
    listed = [line for line in out.splitlines() if line and not line.startswith('[doctest]') and set(line) != {'='}]
    read = [name for source in sources(layer) for name in cases(source)]
    if sorted(listed) == sorted(read):
        print(f'{layer}: the {len(read)} test cases read from the sources are the binary\'s')
        return 0
    print(f'{layer}: test cases the binary has but tests/list_tests.py did not read: {sorted(set(listed) - set(read))}')
    print(f'{layer}: test cases read from the sources but not in the binary: {sorted(set(read) - set(listed))}')
    print('Meson registers only what list_tests.py reads: write TEST_CASE("name") on one line')
    return 1


def compare(cmake_dir, meson_dir):
    ctest = subprocess.run(['ctest', '--test-dir', cmake_dir, '-N'], capture_output=True, text=True, check=True).stdout
    # CTest shows doctest cases as "layer:name" (doctest_discover_tests drops the prefix's space); Meson
    # shows a colon inside a name as "_".
    cmake = set()
    for m in re.finditer(r'^\s*Test\s+#\d+: (.*)$', ctest, re.M):
        suite, _, name = m.group(1).partition(':')
        cmake.add(f'{suite}: {name.lstrip().replace(":", "_")}')
    mtest = subprocess.run(['meson', 'test', '-C', meson_dir, '--list'], capture_output=True, text=True,
                           check=True).stdout
    names = set()
    for line in mtest.splitlines():
        m = re.match(r'^[^:]+:(\S+) / (.*)$', line)
        if not m:
            continue
        suite, name = m.groups()
        # Meson's own tests are "<suite> compile-fail x" where CMake's are "<suite>: compile-fail x";
        # a doctest case may itself start with the suite's name ("scene tables ...").
        candidates = [f'{suite}: {name}']
        if name.startswith(suite + ' '):
            candidates.append(f'{suite}: {name[len(suite) + 1:]}')
        names.add(next((c for c in candidates if c in cmake), candidates[-1]))
    # Each public header compiled alone is checked once, by CMake (tests/CMakeLists.txt).
    cmake_only = {n for n in cmake if n.startswith('headers: ')}
    missing, extra = sorted(cmake - cmake_only - names), sorted(names - cmake)
    if not missing and not extra:
        print(f'CMake and Meson register the same {len(names)} tests (and CMake {len(cmake_only)} header checks)')
        return 0
    print('only in CMake:\n  ' + '\n  '.join(missing) if missing else '', 'only in Meson:\n  ' + '\n  '.join(extra)
          if extra else '', sep='\n')
    return 1


def main(argv):
    if len(argv) == 3 and argv[1] == 'meson':
        meson(argv[2])
        return 0
    if len(argv) == 4 and argv[1] == 'verify':
        return verify(argv[2], argv[3])
    if len(argv) == 4 and argv[1] == 'compare':
        return compare(argv[2], argv[3])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == '__main__':
    sys.exit(main(sys.argv))
