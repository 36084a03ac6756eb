#!/usr/bin/env python3
"""Keeps the tables of README.md and of docs/ARCHITECTURE.md, BENCHMARKS.md, EXPERIMENTS.md
and RELIABILITY.md true.

Every figure table in those documents is preceded by a marker naming the one command that
prints it (the same command stands in the text above the table, for the reader):

    <!-- figures: command="coverage_benchmark --runs 51" ci="coverage_benchmark --runs 1" -->

- command: a program of the build (build/devel/lib/kinematic_coverage/...) or a script
  (scripts/...) with its arguments; its standard output holds the table as Markdown.
- table: which table of that output, counting from 1 (default 1).
- id: a name for the table, unique over the documents, by which a figure in prose points at
  one of its cells (scripts/prose_figures.py checks that the prose agrees with the cell).
- ci: the cheaper command that CI runs instead. It prints some or all of the same rows
  (rows are matched by their first cell, in order); "skip: REASON" leaves the table out of
  CI (the full check still runs it).

A document that a command prints whole (its prose figures computed from the runs) says so
in a first-line marker, and its prose is then checked line by line as a table row is (the
text equal, each number within one unit of its last printed digit):

    <!-- document: command="scripts/run_experiments.sh --print" source="scripts/experiments_report.py" -->

(source: the program that writes the prose; scripts/prose_figures.py counts a figure that
stands literally in it as typed, not computed.)

A table that holds no measured figure (a list of limits, of fuzz targets) is preceded by
`<!-- reference table: WHY -->` instead; a table with neither marker is an error.

Columns whose header says "(timing)" are timings, and "(varies)" marks figures of a run that is
not seeded (a fuzz campaign's coverage): neither is compared nor expected to repeat. A
column whose header says "(at most X)" (a peak memory) is not compared either, but every
number in its cells, documented and fresh, must be at most X: the bound is the claim.
Every other cell is a machine-independent figure: its text must be equal and each number in
it equal to the document's: whole numbers (counts) exactly, decimals within one unit of the
document's last printed digit (they are printed rounded; the unit absorbs a last-digit
rounding flip, nothing more).

    scripts/doc_figures.py check [--ci] [--build-dir DIR] [--only FILE] [--skip PROGRAM]
                                 [--program PROGRAM] [--jobs N]
    scripts/doc_figures.py regenerate [--build-dir DIR] [--only FILE] [--skip PROGRAM]
                                      [--program PROGRAM] [--jobs N]

--only limits the run to one document, --skip leaves out the tables of one program (e.g.
`--skip scripts/run_fuzzers.sh`, hours of fuzzing), --program keeps only the tables of one
program (a change that moves one program's figures regenerates just those); each may be
repeated. --jobs N runs up to
N distinct commands at once (default 1; the tables' timings then share the machine, and
say so only if the prose around them does).

`regenerate` reruns every command in full and writes its tables (timings included) into the
documents; the prose around them is the writer's. Exit status: 0 the figures hold, 1 a
figure drifted or a command failed, 2 a malformed document or call.
"""
import argparse
import concurrent.futures
import os
import re
import shlex
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCUMENTS = ['README.md', 'docs/ARCHITECTURE.md', 'docs/BENCHMARKS.md', 'docs/EXPERIMENTS.md',
             'docs/RELIABILITY.md']
MARKER = re.compile(r'^<!-- figures: (.*) -->\s*$')
DOCUMENT_MARKER = re.compile(r'^<!-- document: (.*) -->\s*$')
REFERENCE_TABLE = re.compile(r'^<!-- reference table: .+ -->\s*$')
ATTRIBUTE = re.compile(r'(\w+)="([^"]*)"|(\w+)=(\S+)')
NUMBER = re.compile(r'[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?')
UNCHECKED = ('(timing)', '(varies)')
BOUND = re.compile(r'\(at most ([0-9.]+)\)')


class DocumentError(Exception):
    """A document or a call that the checker cannot work with (exit 2)."""


class Marker:
    """One figure table of a document: where it stands and the commands that print it."""

    def __init__(self, document, line_index, text):
        self.document = document
        self.line_index = line_index
        attributes = {}
        for match in ATTRIBUTE.finditer(text):
            key = match.group(1) or match.group(3)
            attributes[key] = match.group(2) if match.group(1) else match.group(4)
        if 'command' not in attributes:
            raise DocumentError(f'{document}:{line_index + 1}: a figures marker without command=')
        self.command = attributes['command']
        self.ci = attributes.get('ci', self.command)
        self.table = int(attributes.get('table', '1'))
        self.id = attributes.get('id')
        unknown = set(attributes) - {'command', 'ci', 'table', 'id'}
        if unknown:
            raise DocumentError(f'{document}:{line_index + 1}: unknown attributes {sorted(unknown)}')

    def where(self):
        return f'{self.document}:{self.line_index + 1}'


def read_tables(lines):
    """The Markdown tables of `lines`: (first line index, end index, rows of cells)."""
    tables = []
    index = 0
    while index < len(lines):
        if lines[index].startswith('|'):
            start = index
            while index < len(lines) and lines[index].startswith('|'):
                index += 1
            rows = [split_row(line) for line in lines[start:index]]
            rows = [row for row in rows if not all(re.fullmatch(r':?-+:?', c) for c in row)]
            tables.append((start, index, rows))
        else:
            index += 1
    return tables


def split_row(line):
    return [cell.strip() for cell in line.strip().strip('|').split('|')]


def find_markers(document, lines):
    """The figures markers of a document; every table must have one or a reference marker."""
    for start, _, _ in read_tables(lines):
        before = start - 1
        while before >= 0 and not lines[before].strip():
            before -= 1
        if before < 0 or not (MARKER.match(lines[before]) or REFERENCE_TABLE.match(lines[before])):
            raise DocumentError(f'{document}:{start + 1}: a table names no command (precede it '
                                'with a figures marker, or a reference-table marker)')
    # The reader's text: the document without its markers, which name the commands too.
    text = '\n'.join(line for line in lines if not MARKER.match(line))
    markers = []
    for index, line in enumerate(lines):
        match = MARKER.match(line)
        if match:
            marker = Marker(document, index, match.group(1))
            program = shlex.split(marker.command)[0]
            if program not in text:
                raise DocumentError(f'{marker.where()}: the text does not name {program}')
            markers.append(marker)
    return markers


def document_marker(document, lines):
    """(command, source) of a document printed whole by a command, else None."""
    if not lines or not DOCUMENT_MARKER.match(lines[0]):
        return None
    attributes = dict((m.group(1) or m.group(3), m.group(2) if m.group(1) else m.group(4))
                      for m in ATTRIBUTE.finditer(DOCUMENT_MARKER.match(lines[0]).group(1)))
    if set(attributes) != {'command', 'source'}:
        raise DocumentError(f'{document}:1: a document marker names command= and source=')
    return attributes['command'], attributes['source']


def compare_prose(document, lines, output):
    """The differences between the prose of a generated document and a fresh print of it."""
    ours = [(index, line) for index, line in enumerate(lines) if not line.startswith('|')]
    fresh = [line for line in output.splitlines() if not line.startswith('|')]
    if len(ours) != len(fresh):
        return [f'{document}: the command prints {len(fresh)} lines of prose, the document '
                f'holds {len(ours)}']
    problems = []
    for (index, line), fresh_line in zip(ours, fresh):
        why = compare_cell(line, fresh_line)
        if why:
            problems.append(f'{document}:{index + 1}: the prose drifted ({why}): "{fresh_line}"')
    return problems


def table_after(lines, marker):
    """The table that starts on the first non-blank line after `marker`."""
    index = marker.line_index + 1
    while index < len(lines) and not lines[index].strip():
        index += 1
    if index >= len(lines) or not lines[index].startswith('|'):
        raise DocumentError(f'{marker.where()}: no table right after the figures marker')
    for start, end, rows in read_tables(lines):
        if start == index:
            return start, end, rows
    raise DocumentError(f'{marker.where()}: no table found')


def run_command(command, build_dir, cache):
    """Standard output of `command`, run from the repository root (cached per command)."""
    if command in cache:
        return cache[command]
    words = shlex.split(command)
    if words[0].startswith('scripts/'):
        words[0] = os.path.join(ROOT, words[0])
    else:
        words[0] = os.path.join(build_dir, 'devel', 'lib', 'kinematic_coverage', words[0])
    environment = dict(os.environ, BUILD_DIR=build_dir)
    started = time.monotonic()
    print(f'doc_figures: running {command}', file=sys.stderr, flush=True)
    result = subprocess.run(words, cwd=ROOT, env=environment, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    print(f'doc_figures: {command} took {time.monotonic() - started:.1f} s', file=sys.stderr)
    if result.returncode != 0:
        cache[command] = None
        sys.stderr.write(result.stderr[-4000:])
        print(f'doc_figures: {command} exited with {result.returncode}', file=sys.stderr)
        return None
    cache[command] = result.stdout
    return result.stdout


def run_all(commands, build_dir, cache, jobs):
    """Runs the distinct commands, up to `jobs` at once, into the cache of run_command."""
    distinct = list(dict.fromkeys(command for command in commands if command not in cache))
    if jobs <= 1 or len(distinct) <= 1:
        return
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_command, command, build_dir, results): command
                   for command in distinct}
        for future in concurrent.futures.as_completed(futures):
            future.result()
    cache.update(results)


def commands_of(documents, ci, skip):
    """The commands that check or regenerate would run for the documents."""
    commands = []
    for document in documents:
        generated = document_marker(document, read_lines(document))
        if generated and not skipped_program(generated[0], skip):
            commands.append(generated[0])
        for marker in find_markers(document, read_lines(document)):
            command = marker.ci if ci else marker.command
            if not command.startswith('skip') and not skipped_program(marker.command, skip):
                commands.append(command)
    return commands


def output_table(output, marker, command):
    tables = read_tables(output.splitlines())
    if len(tables) < marker.table:
        raise DocumentError(f'{marker.where()}: `{command}` printed {len(tables)} tables, '
                            f'the marker wants table {marker.table}')
    return tables[marker.table - 1]


def row_name(key):
    return f'"{key[0]}"' + (f' (occurrence {key[1] + 1})' if key[1] else '')


def keyed(rows):
    """Rows by (first cell, occurrence of that first cell)."""
    seen = {}
    result = {}
    for row in rows:
        count = seen.get(row[0], 0)
        seen[row[0]] = count + 1
        result[(row[0], count)] = row
    return result


def last_digit_unit(text):
    """One unit of the last printed decimal of `text`; 0 for a whole number (a count)."""
    mantissa = text.lower().split('e')[0]
    if '.' not in mantissa:
        return 0.0
    unit = 10.0 ** -len(mantissa.split('.')[1])
    return unit * 10.0 ** int(text.lower().split('e')[1]) if 'e' in text.lower() else unit


def compare_cell(documented, fresh):
    """None when `fresh` equals `documented` within the stated tolerance, else why not."""
    if NUMBER.sub('#', documented) != NUMBER.sub('#', fresh):
        return 'text differs'
    for doc_number, fresh_number in zip(NUMBER.findall(documented), NUMBER.findall(fresh)):
        tolerance = max(last_digit_unit(doc_number), 1e-9 * abs(float(doc_number)))
        if abs(float(doc_number) - float(fresh_number)) > tolerance * (1 + 1e-9):
            return f'{doc_number} became {fresh_number}'
    return None


def compare(marker, documented_rows, fresh_rows, subset):
    """The differences between a documented table and a fresh one, as lines."""
    problems = []
    header, fresh_header = documented_rows[0], fresh_rows[0]
    if header != fresh_header:
        return [f'{marker.where()}: header {fresh_header} instead of {header}']
    documented, fresh = keyed(documented_rows[1:]), keyed(fresh_rows[1:])
    for key in fresh:
        if key not in documented:
            problems.append(f'{marker.where()}: row {row_name(key)} is printed but not documented')
    if not subset:
        for key in documented:
            if key not in fresh:
                problems.append(f'{marker.where()}: row {row_name(key)} is documented but not printed')
    for key, row in fresh.items():
        if key not in documented:
            continue
        doc_row = documented[key]
        if len(doc_row) != len(row):
            problems.append(f'{marker.where()}: row {row_name(key)} has {len(row)} cells, '
                            f'the document {len(doc_row)}')
            continue
        for column, (doc_cell, cell) in enumerate(zip(doc_row, row)):
            bound = BOUND.search(header[column])
            if bound:
                problems += bound_problems(marker, key, header[column], float(bound.group(1)),
                                           {'documented': doc_cell, 'printed': cell})
                continue
            if any(word in header[column] for word in UNCHECKED):
                continue
            why = compare_cell(doc_cell, cell)
            if why:
                problems.append(f'{marker.where()}: row {row_name(key)}, column "{header[column]}": '
                                f'documented "{doc_cell}", printed "{cell}" ({why})')
    return problems


def bound_problems(marker, key, column, bound, cells):
    """A line for every number of `cells` (documented and printed) above `bound`."""
    return [f'{marker.where()}: row {row_name(key)}, column "{column}": {which} {number} is '
            f'above its bound {bound:g}'
            for which, cell in cells.items() for number in NUMBER.findall(cell)
            if float(number) > bound]


def programs_of(documents):
    """Every program whose tables or prose the documents hold."""
    programs = set()
    for document in documents:
        lines = read_lines(document)
        generated = document_marker(document, lines)
        if generated:
            programs.add(shlex.split(generated[0])[0])
        programs.update(shlex.split(marker.command)[0] for marker in find_markers(document, lines))
    return programs


def skipped_program(command, skip):
    return shlex.split(command)[0] in skip


def check(documents, build_dir, ci, skip=(), jobs=1):
    cache = {}
    run_all(commands_of(documents, ci, skip), build_dir, cache, jobs)
    problems = []
    checked = skipped = 0
    for document in documents:
        lines = read_lines(document)
        generated = document_marker(document, lines)
        if generated and not skipped_program(generated[0], skip):
            output = run_command(generated[0], build_dir, cache)
            problems += compare_prose(document, lines, output) if output is not None else [
                f'{document}: `{generated[0]}` failed']
        for marker in find_markers(document, lines):
            command = marker.ci if ci else marker.command
            if command.startswith('skip') or skipped_program(marker.command, skip):
                print(f'doc_figures: {marker.where()}: not in CI ({command})', file=sys.stderr)
                skipped += 1
                continue
            output = run_command(command, build_dir, cache)
            if output is None:
                problems.append(f'{marker.where()}: `{command}` failed')
                continue
            _, _, documented = table_after(lines, marker)
            _, _, fresh = output_table(output, marker, command)
            found = compare(marker, documented, fresh, subset=ci and marker.ci != marker.command)
            problems += found
            checked += 1
    for problem in problems:
        print(problem)
    print(f'doc_figures: {checked} tables checked, {skipped} left to the full run, '
          f'{len(problems)} differences')
    if problems:
        print('doc_figures: regenerate with `scripts/doc_figures.py regenerate` and read the '
              'prose around each table, or fix the change that moved the figures')
    return 1 if problems else 0


def regenerate(documents, build_dir, skip=(), jobs=1):
    cache = {}
    run_all(commands_of(documents, False, skip), build_dir, cache, jobs)
    failed = 0
    for document in documents:
        lines = read_lines(document)
        generated = document_marker(document, lines)
        if generated and not skipped_program(generated[0], skip):
            output = run_command(generated[0], build_dir, cache)
            if output is None:
                failed += 1
            else:
                lines = output.splitlines()
        replacements = []
        for marker in find_markers(document, lines):
            if skipped_program(marker.command, skip):
                continue
            output = run_command(marker.command, build_dir, cache)
            if output is None:
                failed += 1
                continue
            start, end, _ = table_after(lines, marker)
            out_start, out_end, _ = output_table(output, marker, marker.command)
            replacements.append((start, end, output.splitlines()[out_start:out_end]))
        for start, end, table in sorted(replacements, reverse=True):
            lines[start:end] = table
        with open(os.path.join(ROOT, document), 'w') as stream:
            stream.write('\n'.join(lines) + '\n')
        print(f'doc_figures: {document}: {len(replacements)} tables written', file=sys.stderr)
    return 1 if failed else 0


def read_lines(document):
    with open(os.path.join(ROOT, document)) as stream:
        return stream.read().splitlines()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('action', choices=['check', 'regenerate'])
    parser.add_argument('--ci', action='store_true', help='run the ci= commands (check only)')
    parser.add_argument('--build-dir', default=os.environ.get('BUILD_DIR',
                                                              os.path.join(ROOT, 'build')))
    parser.add_argument('--only', action='append', help='one document (repeatable)')
    parser.add_argument('--skip', action='append', default=[],
                        help="leave out one program's tables (repeatable)")
    parser.add_argument('--program', action='append', default=[],
                        help="only this program's tables (repeatable)")
    parser.add_argument('--jobs', type=int, default=1, help='commands run at once')
    arguments = parser.parse_args()
    documents = arguments.only or DOCUMENTS
    build_dir = os.path.abspath(arguments.build_dir)
    try:
        if arguments.program:
            arguments.skip += sorted(programs_of(documents) - set(arguments.program))
        if arguments.action == 'check':
            return check(documents, build_dir, arguments.ci, arguments.skip, arguments.jobs)
        return regenerate(documents, build_dir, arguments.skip, arguments.jobs)
    except DocumentError as error:
        print(f'doc_figures: {error}', file=sys.stderr)
        return 2


if __name__ == '__main__':
    sys.exit(main())
