#!/usr/bin/env python3
"""Compiles the documentation's code: every header's usage block and every ```cpp block of README.md.

The text is read from the header or README itself at test time (no copy that can drift) and wrapped
with a prelude from tests/docs/ that declares the names the block uses; all blocks of one batch
(a folder of headers, or the README) go into one translation unit, compiled with -fsyntax-only.
Diagnostics point at the header's or README's own lines (#line), so a failure reads
    include/proceduray/vk/trace.hpp:3:5: error: ...

    check_docs.py --list                          batch names, one a line (CMake and Meson register them)
    check_docs.py --show FILE                     the usage block of FILE as the extractor sees it
    check_docs.py BATCH -- COMPILER FLAGS...      compile one batch; exit 1 with the diagnostics

The usage block is the first run of code lines in a header's top comment: lines indented by two or
more spaces after `//` (`//   code`), with blank `//` lines allowed inside; the first prose line
(`// text`) after it ends it. Inside a block:
  - `...` stands for what the reader fills in; it is dropped (so `Arguments{...}` compiles as `Arguments{}`,
    `f(...)` as `f()`). Write a block so that it still compiles with the dots removed.
  - `#include` lines are moved to the top of the batch; a prelude line `// @skip-include "x.hpp"`
    drops the block's include of a file that exists only in the example (the prelude declares it).
  - lines at the block's own indentation that start a declaration (struct, class, enum, using,
    namespace, template, inline, constexpr, int main, PROCEDURAY_*) go at namespace scope with the lines
    indented under them; every other line is a statement and goes into the prelude's function.
The prelude, tests/docs/<path of the file under include/proceduray or the repository>.hpp (README.md:
tests/docs/README.md.<n>.hpp for its n-th ```cpp block), is C++ with two marker lines:
`// @declarations` (namespace scope) and `// @statements` (inside a function whose parameters are the
objects the block uses, e.g. `void usage(proceduray::Scene& scene) { // @statements }`). Without a
prelude a block gets `#include <the header>` and `void usage() {}`. Each block lives in its own
namespace, so blocks of one batch may reuse names.
A README block right after a line `<!-- same as PATH -->` must equal the file PATH (any fence
language): the readme batch fails, naming both, when they differ. That is how the README's first
scene stays the program tests/consumer builds against the installed package and runs.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOCS = os.path.join(ROOT, 'tests', 'docs')

# Batch name -> the files whose blocks it compiles (globs relative to the repository root).
BATCHES = {
    'shader': ['include/proceduray/shader/*.hpp'],
    'scene': ['include/proceduray/scene/*.hpp'],
    'accuracy': ['include/proceduray/accuracy/*.hpp'],
    'march': ['include/proceduray/march/*.hpp'],
    'mesh': ['include/proceduray/mesh/*.hpp'],
    # scene/ headers whose blocks show the renderer are compiled with vk/ (the scene batch stays pure).
    'vk': ['include/proceduray/vk/*.hpp',
           'include/proceduray/scene/uniform_slot.hpp'],
    'umbrella': ['include/proceduray/*.hpp', 'include/proceduray/image/*.hpp', 'examples/common/*.hpp'],
    'readme': ['README.md'],
}
# Batches whose headers must not pull in Vulkan (scene/, shader/ and accuracy/ stay pure): checked in the same compile.
PURE = {'shader', 'scene', 'accuracy', 'march', 'mesh'}
DECLARATION = re.compile(r'(struct|class|enum|union|using|namespace|template|inline|constexpr|int main'
                         r'|PROCEDURAY_STRUCT|PROCEDURAY_DEFINE_STRUCT)\b')


def files_of(batch):
    """The files of a batch; a file named exactly (no glob) by another batch belongs to that one."""
    named_elsewhere = {os.path.join(ROOT, p) for other, patterns in BATCHES.items() if other != batch
                       for p in patterns if not glob.has_magic(p)}
    out = []
    for pattern in BATCHES[batch]:
        out += [f for f in sorted(glob.glob(os.path.join(ROOT, pattern))) if f not in named_elsewhere]
    return out


def header_block(path):
    """[(line number, code)] of the header's usage block."""
    block = []
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip('\n')
            if not line.startswith('//'):
                break
            body = line[2:]
            if body.startswith('   '):
                block.append((number, body[3:]))
            elif body.strip() == '':
                if block:
                    block.append((number, ''))
            elif block:
                break
    while block and block[-1][1] == '':
        block.pop()
    return block


def readme_blocks(path):
    """[[(line number, code)]] of every ```cpp block."""
    blocks, current = [], None
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip('\n')
            if current is None and line.strip() == '```cpp':
                current = []
            elif current is not None and line.strip() == '```':
                blocks.append(current)
                current = None
            elif current is not None:
                current.append((number, line))
    return blocks


def copy_mismatches(path):
    """Messages for README blocks marked `<!-- same as PATH -->` that differ from PATH."""
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    problems = []
    for i, line in enumerate(lines):
        m = re.match(r'\s*<!-- same as (\S+) -->\s*$', line)
        if not m:
            continue
        start = i + 1
        if start >= len(lines) or not lines[start].startswith('```'):
            problems.append(f'README.md:{i + 1}: the marker for {m.group(1)} is not followed by a ``` block')
            continue
        end = start + 1
        while end < len(lines) and lines[end].strip() != '```':
            end += 1
        shown = '\n'.join(lines[start + 1:end]) + '\n'
        try:
            with open(os.path.join(ROOT, m.group(1)), encoding='utf-8') as f:
                actual = f.read()
        except OSError:
            problems.append(f'README.md:{i + 1}: {m.group(1)} cannot be read')
            continue
        if shown != actual:
            problems.append(f'README.md:{start + 2}: the block differs from {m.group(1)}; copy the file into it')
    return problems


def blocks_of(path):
    """[(block name, prelude path, [(line, code)])] for one documented file."""
    rel = os.path.relpath(path, ROOT)
    if rel == 'README.md':
        return [(f'README.md block {i}', os.path.join(DOCS, f'README.md.{i}.hpp'), b)
                for i, b in enumerate(readme_blocks(path), 1)]
    block = header_block(path)
    if not block:
        return []
    under = os.path.relpath(path, os.path.join(ROOT, 'include', 'proceduray')) if rel.startswith('include/') else rel
    return [(rel, os.path.join(DOCS, under), block)]


def split_block(block, skipped_includes):
    """(includes, declarations, statements), each a list of (line, code), `...` dropped."""
    includes, declarations, statements = [], [], []
    base = min((len(c) - len(c.lstrip()) for _, c in block if c.strip()), default=0)
    target = statements
    for number, code in block:
        code = code.replace('...', '')
        stripped = code.strip()
        indent = len(code) - len(code.lstrip())
        if stripped.startswith('#include'):
            if stripped.split()[1] not in skipped_includes:
                includes.append((number, stripped))
            continue
        if stripped and indent == base and not stripped.startswith('//') and stripped[0] not in '})].,:':
            target = declarations if DECLARATION.match(stripped) else statements
        target.append((number, code))
    return includes, declarations, statements


def default_prelude(doc_file):
    rel = os.path.relpath(doc_file, ROOT)
    include = os.path.relpath(doc_file, os.path.join(ROOT, 'include')) if rel.startswith('include/') else rel
    return f'#include <{include}>\n// @declarations\nvoid usage() {{\n  // @statements\n}}\n'


def translation_unit(batch):
    includes, body = [], []
    for doc_file in files_of(batch):
        for n, (name, prelude_path, block) in enumerate(blocks_of(doc_file)):
            if os.path.exists(prelude_path):
                with open(prelude_path, encoding='utf-8') as f:
                    prelude = f.read()
                prelude_name = os.path.relpath(prelude_path, ROOT)
            else:
                prelude = default_prelude(doc_file)
                prelude_name = os.path.relpath(prelude_path, ROOT) + ' (default prelude: none there)'
            skipped = set(re.findall(r'^\s*// @skip-include (\S+)', prelude, re.M))
            block_includes, declarations, statements = split_block(block, skipped)
            source = os.path.relpath(doc_file, ROOT)
            ident = re.sub(r'\W', '_', name)
            body.append(f'namespace doc_{ident}_{n} {{')
            for number, line in enumerate(prelude.splitlines(), 1):
                marker = line.strip()
                if marker.startswith('#include'):
                    includes.append((prelude_name, number, marker))
                elif marker in ('// @declarations', '// @statements'):
                    last = None
                    for at, code in declarations if marker == '// @declarations' else statements:
                        if at != last:  # only where lines jump: a directive inside a macro call is not portable
                            body.append(f'#line {at} "{source}"')
                        body.append(code)
                        last = at + 1
                else:
                    body += [f'#line {number} "{prelude_name}"', line]
            body.append(f'}}  // namespace doc_{ident}_{n}')
            includes += [(source, at, code) for at, code in block_includes]
    head, seen = [], set()
    for name, number, line in includes:
        if line not in seen:
            seen.add(line)
            head += [f'#line {number} "{name}"', line]
    if batch in PURE:
        head += ['#if defined(VULKAN_CORE_H_) || defined(VULKAN_HPP)',
                 f'#error "a header of {batch}/ includes a Vulkan header: shader/, scene/ and accuracy/ must stay pure"',
                 '#endif']
    return '\n'.join(head + body) + '\n'


def main(argv):
    if argv[1:] == ['--list']:
        print('\n'.join(BATCHES))
        return 0
    if len(argv) == 3 and argv[1] == '--show':
        for name, prelude, block in blocks_of(os.path.abspath(argv[2])):
            print(f'== {name} (prelude {os.path.relpath(prelude, ROOT)})')
            for part, lines in zip(('includes', 'declarations', 'statements'), split_block(block, set())):
                print(f'-- {part}')
                print('\n'.join(f'{n:4} {c}' for n, c in lines))
        return 0
    if len(argv) < 4 or argv[2] != '--' or argv[1] not in BATCHES:
        print(__doc__, file=sys.stderr)
        return 2
    batch, compiler = argv[1], argv[3:]
    if batch == 'readme':
        problems = copy_mismatches(os.path.join(ROOT, 'README.md'))
        if problems:
            print('docs readme: blocks that must equal a file do not:\n' + '\n'.join(problems))
            return 1
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, f'docs_{batch}.cpp')
        with open(source, 'w', encoding='utf-8') as f:
            f.write(translation_unit(batch))
        # Blocks show values (`ctx.name();  // "llvmpipe"`) and declare what they do not use.
        quiet = ['-Wno-unused-value', '-Wno-unused-variable', '-Wno-unused-but-set-variable', '-Wno-unused-result',
                 '-Wno-unused-local-typedefs', '-Wno-unused-parameter', '-Wno-unused-function']
        run = subprocess.run(compiler + quiet + ['-I' + ROOT, '-fsyntax-only', source], cwd=ROOT, capture_output=True, text=True)
        if run.returncode == 0:
            print(f'docs {batch}: the usage blocks of {", ".join(BATCHES[batch])} compile')
            return 0
        run.stderr = run.stderr.replace(ROOT + os.sep, '')
        failed = sorted(set(re.findall(r'^((?:include|examples|tests/docs)/[^:\s]+|README\.md):\d+', run.stderr, re.M)))
        print(f'docs {batch}: the usage blocks of these files do not compile: {", ".join(failed) or "(see below)"}\n'
              f'fix the block in the header (or its prelude in tests/docs/); see tests/docs/check_docs.py\n')
        print(run.stdout + run.stderr)
        return 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
