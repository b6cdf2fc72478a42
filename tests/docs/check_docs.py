#!/usr/bin/env python3
"""Checks the documentation's code: every header's usage block, and every ```cpp block and command block
of README.md and docs/**/*.md.

The text is read from the header or page itself at test time (no copy that can drift) and wrapped
with a prelude from tests/docs/ that declares the names the block uses; all blocks of one batch
(a folder of headers, the README, or the docs pages) go into one translation unit, compiled with
-fsyntax-only. Diagnostics point at the header's or page's own lines (#line), so a failure reads
    include/proceduray/vk/trace.hpp:3:5: error: ...

    check_docs.py --list                          batch names, one a line (CMake and Meson register them)
    check_docs.py --show FILE                     the usage block (or a page's ```cpp blocks) as the extractor sees it
    check_docs.py --commands BATCH                only the command blocks of a batch's pages (no compiler)
    check_docs.py BATCH -- COMPILER FLAGS...      check one batch; exit 1 with the diagnostics

The usage block is the first run of code lines in a header's top comment: lines indented by two or
more spaces after `//` (`//   code`), with blank `//` lines allowed inside; the first prose line
(`// text`) after it ends it. Inside a block (a header's or a page's ```cpp block):
  - `...` stands for what the reader fills in; it is dropped (so `Arguments{...}` compiles as `Arguments{}`,
    `f(...)` as `f()`). Write a block so that it still compiles with the dots removed.
  - `#include` lines are moved to the top of the batch (a `.glsl` file's stays where it is: GLSL
    compiled as C++ goes inside the scope around it); a prelude line `// @skip-include "x.hpp"`
    drops the block's include of a file that exists only in the example (the prelude declares it).
  - lines at the block's own indentation that start a declaration (struct, class, enum, using,
    namespace, template, inline, constexpr, int main, PROCEDURAY_*) go at namespace scope with the lines
    indented under them; every other line is a statement and goes into the prelude's function.
The prelude is C++ with two marker lines: `// @declarations` (namespace scope) and `// @statements`
(inside a function whose parameters are the objects the block uses, e.g.
`void usage(DocScene& scene) { // @statements }`). Where it lives:
  - a header: tests/docs/<path of the file under include/proceduray, or under the repository>.hpp;
    without one the block gets `#include <the header>` and `void usage() {}`;
  - a page (README.md, docs/guide/meshes.md): tests/docs/<page>.<n>.hpp for its n-th ```cpp block
    (tests/docs/README.md.1.hpp, tests/docs/docs/guide/meshes.md.1.hpp); without one the block gets
    no include and `void usage() {}`, so it must be a whole program. A page prelude whose block is
    gone (tests/docs/README.md.3.hpp when the README has two ```cpp blocks) fails its batch.
Each block lives in its own namespace, so blocks of one batch may reuse names.

Pages are checked for more than C++:
  - A block right after a line `<!-- same as PATH -->` must equal the file PATH (any fence language):
    the batch fails, naming both, when they differ. That is how the README's first scene stays the
    program tests/consumer builds against the installed package and runs. After `<!-- part of PATH -->`
    the block's lines, indentation aside, must be consecutive lines of PATH (an excerpt).
  - A command block is one fenced ```sh, ```bash, ```shell, ```console or bare ``` (output, trees and
    tables of text take ```text). The nearest non-blank line above it must say what the check does
    with it: `<!-- run -->` runs it (bash -e, in the repository root, 60 s at most) and it must exit 0;
    `<!-- not run: REASON -->` skips it, REASON saying why (a build, a GPU, minutes of work). A command
    block without either fails the batch, naming the page and line; so does a marker above a block
    that is not a command block. Mark as run only what is quick and writes nothing.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOCS = os.path.join(ROOT, 'tests', 'docs')

# Batch name -> the files whose blocks it checks (globs relative to the repository root; ** recurses).
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
    'docs': ['docs/**/*.md'],
}
# Batches whose headers must not pull in Vulkan (scene/, shader/ and accuracy/ stay pure): checked in the same compile.
PURE = {'shader', 'scene', 'accuracy', 'march', 'mesh'}
DECLARATION = re.compile(r'(struct|class|enum|union|using|namespace|template|inline|constexpr|int main'
                         r'|PROCEDURAY_STRUCT|PROCEDURAY_DEFINE_STRUCT)\b')
FENCE = re.compile(r'^(\s*)(`{3,}|~{3,})\s*([^`\s]*)')
COMMAND_LANGUAGES = {'', 'sh', 'bash', 'shell', 'console'}
RUN = re.compile(r'^\s*<!--\s*run\s*-->\s*$')
NOT_RUN = re.compile(r'^\s*<!--\s*not run:\s*(.*?)\s*-->\s*$')
RUN_TIMEOUT_S = 60


def rel(path):
    return os.path.relpath(path, ROOT)


def is_page(path):
    return path.endswith('.md')


def files_of(batch):
    """The files of a batch; a file named exactly (no glob) by another batch belongs to that one."""
    named_elsewhere = {os.path.join(ROOT, p) for other, patterns in BATCHES.items() if other != batch
                       for p in patterns if not glob.has_magic(p)}
    out = []
    for pattern in BATCHES[batch]:
        out += [f for f in sorted(glob.glob(os.path.join(ROOT, pattern), recursive=True)) if f not in named_elsewhere]
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


def fenced_blocks(path):
    """[(language, line of the opening fence, [(line number, text)])] of every fenced block of a page."""
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, language = len(m.group(1)), m.group(2), m.group(3).lower()
        body, j = [], i + 1
        while j < len(lines):
            closing = lines[j].strip()
            if closing.startswith(fence[0] * len(fence)) and closing.strip(fence[0]) == '':
                break
            text = lines[j]
            body.append((j + 1, text[indent:] if text[:indent].strip() == '' else text))
            j += 1
        blocks.append((language, i + 1, body))
        i = j + 1
    return blocks


def page_blocks(path):
    """[[(line number, code)]] of every ```cpp block of a page."""
    return [body for language, _, body in fenced_blocks(path) if language in ('cpp', 'c++')]


def marker_above(lines, fence_line):
    """The nearest non-blank line above line `fence_line` (1-based), or ''."""
    i = fence_line - 2
    while i >= 0 and lines[i].strip() == '':
        i -= 1
    return lines[i] if i >= 0 else ''


def copy_mismatches(path):
    """Messages for blocks marked `<!-- same as PATH -->` that differ from PATH, and for blocks marked
    `<!-- part of PATH -->` whose lines are not consecutive lines of PATH."""
    name = rel(path)
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    problems = []
    for i, line in enumerate(lines):
        m = re.match(r'\s*<!-- (same as|part of) (\S+) -->\s*$', line)
        if not m:
            continue
        kind, copied = m.group(1), m.group(2)
        start = i + 1
        if start >= len(lines) or not lines[start].startswith('```'):
            problems.append(f'{name}:{i + 1}: the marker for {copied} is not followed by a ``` block')
            continue
        end = start + 1
        while end < len(lines) and lines[end].strip() != '```':
            end += 1
        try:
            with open(os.path.join(ROOT, copied), encoding='utf-8') as f:
                actual = f.read()
        except OSError:
            problems.append(f'{name}:{i + 1}: {copied} cannot be read')
            continue
        if kind == 'same as':
            if '\n'.join(lines[start + 1:end]) + '\n' != actual:
                problems.append(f'{name}:{start + 2}: the block differs from {copied}; copy the file into it')
            continue
        shown = [text.strip() for text in lines[start + 1:end]]
        whole = [text.strip() for text in actual.split('\n')]
        if not any(whole[k:k + len(shown)] == shown for k in range(len(whole) - len(shown) + 1)):
            problems.append(f'{name}:{start + 2}: the block is not a part of {copied} (its lines, indentation aside, '
                            f'must be consecutive lines there); copy the part again')
    return problems


def command_problems(path):
    """(messages, blocks run, blocks not run) for the command blocks of a page: each must be marked,
    and each marked `<!-- run -->` must exit 0."""
    name = rel(path)
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    problems, ran, skipped = [], 0, 0
    for language, at, body in fenced_blocks(path):
        above = marker_above(lines, at)
        run, not_run = RUN.match(above), NOT_RUN.match(above)
        if language not in COMMAND_LANGUAGES:
            if run or not_run:
                problems.append(f'{name}:{at}: a run marker above a ```{language} block, which is not a command '
                                f'block (```sh, ```bash, ```shell, ```console or bare ```)')
            continue
        if not_run:
            if not not_run.group(1):
                problems.append(f'{name}:{at}: `<!-- not run: -->` without a reason; say why it is not run')
            skipped += 1
            continue
        if not run:
            problems.append(f'{name}:{at}: a command block without a marker: put `<!-- run -->` (quick, writes '
                            f'nothing) or `<!-- not run: REASON -->` on the line above it (text that is not '
                            f'commands takes ```text)')
            continue
        ran += 1
        script = '\n'.join(text for _, text in body) + '\n'
        try:
            done = subprocess.run(['bash', '-e', '-c', script], cwd=ROOT, capture_output=True, text=True,
                                  timeout=RUN_TIMEOUT_S, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            problems.append(f'{name}:{at}: the block marked run did not finish in {RUN_TIMEOUT_S} s')
            continue
        if done.returncode != 0:
            output = (done.stdout + done.stderr).strip()
            tail = '\n'.join(output.splitlines()[-20:])
            problems.append(f'{name}:{at}: the block marked run exited {done.returncode}:\n{tail}')
    return problems, ran, skipped


def page_prelude(path, n):
    """The prelude of a page's n-th ```cpp block: tests/docs/<page>.<n>.hpp."""
    return os.path.join(DOCS, f'{rel(path)}.{n}.hpp')


def orphan_preludes(batch, pages):
    """Messages for page preludes in tests/docs/ whose page, or whose ```cpp block, is gone."""
    preludes = set()
    for pattern in BATCHES[batch]:
        if pattern.endswith('.md'):
            preludes.update(glob.glob(os.path.join(DOCS, pattern) + '.*.hpp', recursive=True))
    counts = {page: len(page_blocks(page)) for page in pages}
    problems = []
    for prelude in sorted(preludes):
        m = re.match(r'(.*)\.(\d+)\.hpp$', prelude)
        if not m:
            continue
        page = os.path.join(ROOT, os.path.relpath(m.group(1), DOCS))
        if page not in counts:
            problems.append(f'{rel(prelude)}: there is no page {rel(page)}; delete the prelude or move it with its page')
        elif int(m.group(2)) > counts[page]:
            problems.append(f'{rel(prelude)}: {rel(page)} has {counts[page]} ```cpp block(s), not {m.group(2)}; '
                            f'delete the prelude or renumber')
    return problems


def blocks_of(path):
    """[(block name, prelude path, [(line, code)])] for one documented file."""
    name = rel(path)
    if is_page(path):
        return [(f'{name} block {i}', page_prelude(path, i), b) for i, b in enumerate(page_blocks(path), 1)]
    block = header_block(path)
    if not block:
        return []
    under = os.path.relpath(path, os.path.join(ROOT, 'include', 'proceduray')) if name.startswith('include/') else name
    return [(name, os.path.join(DOCS, under), block)]


def split_block(block, skipped_includes):
    """(includes, declarations, statements), each a list of (line, code), `...` dropped."""
    includes, declarations, statements = [], [], []
    base = min((len(c) - len(c.lstrip()) for _, c in block if c.strip()), default=0)
    target = statements
    for number, code in block:
        code = code.replace('...', '')
        stripped = code.strip()
        indent = len(code) - len(code.lstrip())
        if stripped.startswith('#include') and stripped.split()[1].rstrip('">').endswith('.glsl'):
            target.append((number, code))  # GLSL compiled as C++: it belongs where it stands (glsl_cpp.hpp)
            continue
        if stripped.startswith('#include'):
            if stripped.split()[1] not in skipped_includes:
                includes.append((number, stripped))
            continue
        if stripped and indent == base and not stripped.startswith('//') and stripped[0] not in '})].,:':
            target = declarations if DECLARATION.match(stripped) else statements
        target.append((number, code))
    return includes, declarations, statements


def default_prelude(doc_file):
    if is_page(doc_file):
        return '// @declarations\nvoid usage() {\n  // @statements\n}\n'
    name = rel(doc_file)
    include = os.path.relpath(doc_file, os.path.join(ROOT, 'include')) if name.startswith('include/') else name
    return f'#include <{include}>\n// @declarations\nvoid usage() {{\n  // @statements\n}}\n'


def translation_unit(batch):
    includes, body = [], []
    for doc_file in files_of(batch):
        for n, (name, prelude_path, block) in enumerate(blocks_of(doc_file)):
            if os.path.exists(prelude_path):
                with open(prelude_path, encoding='utf-8') as f:
                    prelude = f.read()
                prelude_name = rel(prelude_path)
            else:
                prelude = default_prelude(doc_file)
                prelude_name = rel(prelude_path) + ' (default prelude: none there)'
            skipped = set(re.findall(r'^\s*// @skip-include (\S+)', prelude, re.M))
            block_includes, declarations, statements = split_block(block, skipped)
            source = rel(doc_file)
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


def page_problems(batch):
    """(messages, summary) of a batch's pages: copies, command blocks, orphan preludes."""
    pages = [f for f in files_of(batch) if is_page(f)]
    problems, ran, skipped = orphan_preludes(batch, pages), 0, 0
    for page in pages:
        problems += copy_mismatches(page)
        found, r, s = command_problems(page)
        problems += found
        ran, skipped = ran + r, skipped + s
    return problems, f'{ran} command block(s) run, {skipped} marked not run' if pages else ''


def main(argv):
    if argv[1:] == ['--list']:
        print('\n'.join(BATCHES))
        return 0
    if len(argv) == 3 and argv[1] == '--show':
        for name, prelude, block in blocks_of(os.path.abspath(argv[2])):
            print(f'== {name} (prelude {rel(prelude)})')
            for part, lines in zip(('includes', 'declarations', 'statements'), split_block(block, set())):
                print(f'-- {part}')
                print('\n'.join(f'{n:4} {c}' for n, c in lines))
        return 0
    if len(argv) == 3 and argv[1] == '--commands' and argv[2] in BATCHES:
        problems, summary = page_problems(argv[2])
        print('\n'.join(problems) if problems else f'docs {argv[2]}: {summary or "no pages"}')
        return 1 if problems else 0
    if len(argv) < 4 or argv[2] != '--' or argv[1] not in BATCHES:
        print(__doc__, file=sys.stderr)
        return 2
    batch, compiler = argv[1], argv[3:]
    problems, summary = page_problems(batch)
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, f'docs_{batch}.cpp')
        with open(source, 'w', encoding='utf-8') as f:
            f.write(translation_unit(batch))
        # Blocks show values (`ctx.name();  // "llvmpipe"`) and declare what they do not use.
        quiet = ['-Wno-unused-value', '-Wno-unused-variable', '-Wno-unused-but-set-variable', '-Wno-unused-result',
                 '-Wno-unused-local-typedefs', '-Wno-unused-parameter', '-Wno-unused-function']
        run = subprocess.run(compiler + quiet + ['-I' + ROOT, '-fsyntax-only', source], cwd=ROOT, capture_output=True, text=True)
    if problems:
        print(f'docs {batch}: pages that do not pass (see tests/docs/check_docs.py):\n' + '\n'.join(problems) + '\n')
    if run.returncode == 0:
        print(f'docs {batch}: the code blocks of {", ".join(BATCHES[batch])} compile' + (f'; {summary}' if summary else ''))
        return 1 if problems else 0
    run.stderr = run.stderr.replace(ROOT + os.sep, '')
    failed = sorted(set(re.findall(r'^((?:include|examples|tests/docs|docs)/[^:\s]+|[^/:\s]+\.md):\d+', run.stderr, re.M)))
    print(f'docs {batch}: the code blocks of these files do not compile: {", ".join(failed) or "(see below)"}\n'
          f'fix the block in the header or page (or its prelude in tests/docs/); see tests/docs/check_docs.py\n')
    print(run.stdout + run.stderr)
    return 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
