#!/usr/bin/env python3
"""Checks that <proceduray/implementation.hpp> compiles the bodies of every header that has any, and that
bodies live in <header>-inl.hpp files, never in an `#if PROCEDURAY_BODIES` block of a header.

A header whose bodies sit in an `#if PROCEDURAY_BODIES` block (include/proceduray/config.hpp) but is
not reached from implementation.hpp would leave a PROCEDURAY_SEPARATE program with undefined
symbols at link time. The compiler's own dependency list (-M) is the truth of what is reached.

    implementation_check.py -- COMPILER FLAGS...     exit 1 naming each header not reached
"""
import glob
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main(argv):
    if '--' not in argv:
        sys.exit(__doc__)
    compiler = argv[argv.index('--') + 1:]
    include = os.path.join(ROOT, 'include')
    with_bodies = set()
    in_headers = []
    for path in glob.glob(os.path.join(include, 'proceduray', '**', '*.hpp'), recursive=True):
        with open(path, encoding='utf-8') as f:
            if '#if PROCEDURAY_BODIES' in f.read():
                with_bodies.add(os.path.realpath(path))
                if not path.endswith('-inl.hpp') and os.path.basename(path) != 'config.hpp':
                    in_headers.append(os.path.relpath(path, include))
    if in_headers:
        print('bodies belong in <header>-inl.hpp beside the header (config.hpp), not in an `#if PROCEDURAY_BODIES` '
              'block of the header:\n  ' + '\n  '.join(sorted(in_headers)))
        return 1
    if len(with_bodies) < 10:
        sys.exit(f'implementation_check: only {len(with_bodies)} headers have bodies blocks; the search is broken')
    run = subprocess.run(compiler + ['-I' + include, '-M', '-x', 'c++', os.path.join(include, 'proceduray',
                                                                                     'implementation.hpp')],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit('implementation_check: the compiler failed on implementation.hpp:\n' + run.stderr)
    reached = {os.path.realpath(p) for p in run.stdout.replace('\\\n', ' ').split()[1:]}
    missing = sorted(os.path.relpath(p, include) for p in with_bodies - reached)
    if missing:
        print('implementation.hpp does not reach these headers, so PROCEDURAY_SEPARATE programs miss their '
              'bodies; include them from proceduray/proceduray.hpp:\n  ' + '\n  '.join(missing))
        return 1
    print(f'implementation.hpp reaches all {len(with_bodies)} headers with bodies')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
