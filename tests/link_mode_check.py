#!/usr/bin/env python3
"""Checks that one program uses one body mode (include/proceduray/config.hpp), at link time:

  header-only files alone, or separate files with implementation.hpp's file: they link;
  a separate file without implementation.hpp's file: undefined reference to
      proceduray_separate_mode_needs_implementation_hpp_in_one_file
  a header-only file with implementation.hpp's file (each defines every body): multiple definition of
      proceduray_header_only_and_separate_modes_mixed_in_one_program

The files include config.hpp only (the markers live there), so the check takes a second.

    link_mode_check.py -- COMPILER FLAGS...     exit 1 naming the case that did not behave
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE = '#include <proceduray/config.hpp>\nint {name}() {{ return 1; }}\n'
MAIN = '#include <proceduray/config.hpp>\nint main() { return 0; }\n'


def main(argv):
    if '--' not in argv:
        sys.exit(__doc__)
    compiler = argv[argv.index('--') + 1:]
    include = '-I' + os.path.join(ROOT, 'include')
    with tempfile.TemporaryDirectory() as tmp:
        def obj(name, text, defines):
            src = os.path.join(tmp, name + '.cpp')
            with open(src, 'w') as f:
                f.write(text)
            out = os.path.join(tmp, name + '.o')
            run = subprocess.run(compiler + [include] + defines + ['-c', src, '-o', out], capture_output=True, text=True)
            if run.returncode != 0:
                sys.exit(f'link_mode_check: {name}.cpp did not compile:\n{run.stderr}')
            return out

        header_only = [obj('main_h', MAIN, []), obj('a_h', SOURCE.format(name='a'), [])]
        separate = [obj('main_s', MAIN, ['-DPROCEDURAY_SEPARATE']),
                    obj('a_s', SOURCE.format(name='a'), ['-DPROCEDURAY_SEPARATE'])]
        # What implementation.hpp does, without the bodies: define PROCEDURAY_IMPLEMENTATION first.
        implementation = obj('impl', '#include <proceduray/config.hpp>\n',
                             ['-DPROCEDURAY_SEPARATE', '-DPROCEDURAY_IMPLEMENTATION'])
        cases = [
            ('header-only files alone', header_only, None),
            ('separate files with the implementation file', separate + [implementation], None),
            ('a separate file without the implementation file', separate,
             'proceduray_separate_mode_needs_implementation_hpp_in_one_file'),
            ('a header-only file with the implementation file', header_only + [implementation],
             'proceduray_header_only_and_separate_modes_mixed_in_one_program'),
        ]
        failed = 0
        for what, objects, expected in cases:
            run = subprocess.run(compiler + objects + ['-o', os.path.join(tmp, 'program')], capture_output=True,
                                 text=True)
            if expected is None and run.returncode != 0:
                print(f'{what}: should link but did not:\n{run.stderr}')
                failed += 1
            elif expected is not None and (run.returncode == 0 or expected not in run.stderr):
                print(f'{what}: should fail to link naming {expected}, but ' +
                      ('linked' if run.returncode == 0 else 'said:\n' + run.stderr))
                failed += 1
            else:
                print(f'{what}: ' + ('links' if expected is None else f'refused, naming {expected}'))
        return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
