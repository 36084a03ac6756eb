#!/usr/bin/env python3
"""Counts the figures that the prose of README.md and docs/*.md states, and checks those that
say where they come from.

A figure is a number followed by a unit (%, s, ms, min, h, d, MB, GB, m, m^2, km, km^2, cm,
mm, m/s, m/s^2, rad, rad/s, Hz, x), outside tables, code blocks, inline code, HTML tags and comments.
Tables are checked by doc_figures. A figure in prose is checked when a marker follows it
directly (after at most closing emphasis, a parenthesis and spaces) and names its source:

  0.73 m<!-- checked: table="lake-survey" row="lake_30x30" column="trajectory km" -->
      a cell of a figures table (doc_figures: the marker's id=), the row by its first cell
      (or of="min"/"max" over all rows), the cell's number-th number (default 1);
  1 m<!-- checked: yaml="config/default.yaml" key="wall_distance" -->
      a `key: value` line of a repository file (a parameter default, a mission's setting);
  50 km<!-- checked: code="src/output/local_east_north_frame.cpp" name="kMaxExtent" scale="0.001" -->
      the number assigned to a name in a source file (`name = 5e4`, `name{5e4}`).

A document that a command prints whole (doc_figures' document marker, its prose compared
with a fresh print) has its figures checked where its generator computes them: a figure that
stands literally in the generator's source is typed, and needs a marker like any other.

The figure must equal the source's number times scale (default 1) to within half a unit of
its own last digit: prose may round a figure, not change it. Unchecked figures are a debt
that CI keeps from growing.

  prose_figures.py [--list] [--limit N] [--root DIR]

Prints the count per document and in all, checked and unchecked; --list also prints each
unchecked figure with its line; --limit N exits 1 when more than N are unchecked. Exit
status 2: a marker names no figure or a source that does not hold the figure.
"""
import argparse
import glob
import os
import re
import shlex
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_figures  # noqa: E402

# A number (digits, optionally grouped by spaces or commas in threes, optionally with a
# decimal part and an exponent, optionally negative), optional space, a unit, not followed by a letter,
# digit or caret (so "3 max" is no figure and "2 m^2" one figure); "x" is a ratio ("1.6x"),
# not a size ("64 x 64").
FIGURE = re.compile(
    r'(?<![\w.\-+])-?\d+(?:[ ,]\d{3})*(?:\.\d+)?(?:[eE][-+]?\d+)?\s?(?:%|ms|MB|GB|km\^2|km|m\^2|m/s\^2|m/s|m|s|min|h|d|cm|mm|rad/s|rad|Hz|x(?!\s?\d))(?![\w^])')
CHECKED = re.compile(r'<!-- checked: (.*?) -->')
# What may stand between a figure and its marker.
BETWEEN = re.compile(r'[\s*_)]*\x00(\d+)\x00')
COMPUTED = 'computed by the generator, checked against a fresh print'
SOURCES = {'table': {'row', 'column', 'number', 'of'}, 'yaml': {'key'}, 'code': {'name'}}


class MarkerError(Exception):
    """A checked marker that names no figure, or a source that does not hold it (exit 2)."""


def prose_lines(text):
    """(line number, line, markers) of the prose: tables, fenced and indented code blocks and
    HTML comments left out, inline code spans and HTML tags blanked; each checked marker's
    attribute text stands in `markers`, and in the line as \x00index\x00."""
    in_fence = False
    in_comment = False
    previous_blank = True
    in_indented = False
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith('```'):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        if in_comment:
            if '-->' in line:
                in_comment = False
                line = line.split('-->', 1)[1]
            else:
                continue
        markers = []

        def placeholder(match):
            markers.append(match.group(1))
            return f'\x00{len(markers) - 1}\x00'
        line = CHECKED.sub(placeholder, line)
        line = re.sub(r'<!--.*?-->', '', line)
        if '<!--' in line:
            in_comment = True
            line = line.split('<!--', 1)[0]
        # An indented code block starts after a blank line and lasts while lines are
        # indented by four spaces (or blank).
        if line.startswith('    ') and (previous_blank or in_indented) and \
                not stripped.startswith(('-', '*')):
            in_indented = True
            previous_blank = False
            continue
        if stripped:
            in_indented = False
        previous_blank = not stripped
        if stripped.startswith('|'):
            continue
        yield number, re.sub(r'<[^>]*>', '', re.sub(r'`[^`]*`', '', line)), markers


def figures(path):
    """(line number, figure, marker attributes or None) of the prose figures of a document.
    Raises MarkerError for a marker that follows no figure."""
    with open(path, encoding='utf-8') as stream:
        text = stream.read()
    found = []
    for number, line, markers in prose_lines(text):
        used = set()
        for match in FIGURE.finditer(line):
            follows = BETWEEN.match(line, match.end())
            marker = markers[int(follows.group(1))] if follows else None
            if follows:
                used.add(int(follows.group(1)))
            found.append((number, match.group(0), marker))
        for index in set(range(len(markers))) - used:
            raise MarkerError(f'{path}:{number}: a checked marker follows no figure '
                              f'({markers[index]})')
    return found


def figure_value(figure):
    """The number of a figure and one unit of its last printed digit."""
    match = re.match(r'(-?\d+(?:[ ,]\d{3})*(?:\.(\d+))?)(?:[eE]([-+]?\d+))?', figure)
    exponent = int(match.group(3) or 0)
    decimals = len(match.group(2) or '')
    value = float(re.sub(r'[ ,]', '', match.group(1))) * 10.0 ** exponent
    return value, 10.0 ** (exponent - decimals)


def attributes_of(text, where):
    """The attributes of a checked marker, with its source kind checked."""
    attributes = {}
    for word in shlex.split(text):
        key, _, value = word.partition('=')
        attributes[key] = value
    kinds = [kind for kind in SOURCES if kind in attributes]
    if len(kinds) != 1:
        raise MarkerError(f'{where}: a checked marker names one of table=, yaml=, code= ({text})')
    unknown = set(attributes) - {kinds[0], 'scale'} - SOURCES[kinds[0]]
    if unknown:
        raise MarkerError(f'{where}: unknown attributes {sorted(unknown)} ({text})')
    return kinds[0], attributes


def figure_tables(root):
    """The figures tables that have an id: id -> (document, header, rows)."""
    tables = {}
    for path in documents(root):
        with open(path, encoding='utf-8') as stream:
            lines = stream.read().splitlines()
        for index, line in enumerate(lines):
            match = doc_figures.MARKER.match(line)
            if not match:
                continue
            marker = doc_figures.Marker(os.path.relpath(path, root), index, match.group(1))
            if marker.id is None:
                continue
            if marker.id in tables:
                raise MarkerError(f'{marker.where()}: the table id "{marker.id}" is taken')
            _, _, rows = doc_figures.table_after(lines, marker)
            tables[marker.id] = (marker.where(), rows[0], rows[1:])
    return tables


def table_values(attributes, tables, where):
    """The numbers that a table marker points at (one, or a column's for of=)."""
    if attributes['table'] not in tables:
        raise MarkerError(f'{where}: no figures table has id "{attributes["table"]}"')
    table_where, header, rows = tables[attributes['table']]
    if attributes.get('column') not in header:
        raise MarkerError(f'{where}: {table_where} has no column "{attributes.get("column")}"')
    column = header.index(attributes['column'])
    number = int(attributes.get('number', '1'))
    if 'of' in attributes:
        chosen = rows
    else:
        chosen = [row for row in rows if row[0] == attributes.get('row')][:1]
        if not chosen:
            raise MarkerError(f'{where}: {table_where} has no row "{attributes.get("row")}"')
    values = []
    for row in chosen:
        numbers = doc_figures.NUMBER.findall(re.sub(r'(?<=\d) (?=\d{3}\b)', '', row[column]))
        if len(numbers) >= number:
            values.append(float(numbers[number - 1]))
    if not values:
        raise MarkerError(f'{where}: {table_where}, column "{attributes["column"]}" holds no '
                          f'number {number}')
    aggregate = {'min': min, 'max': max, 'median': statistics.median}
    if 'of' in attributes:
        if attributes['of'] not in aggregate:
            raise MarkerError(f'{where}: of= is min, max or median')
        return aggregate[attributes['of']](values)
    return values[0]


def file_value(kind, attributes, root, where):
    """The number that a yaml= or code= marker points at."""
    path = os.path.join(root, attributes[kind])
    if not os.path.isfile(path):
        raise MarkerError(f'{where}: no file {attributes[kind]}')
    with open(path, encoding='utf-8') as stream:
        text = stream.read()
    if kind == 'yaml':
        pattern = rf'^\s*{re.escape(attributes["key"])}:\s*({doc_figures.NUMBER.pattern})\s*(?:#.*)?$'
    else:
        pattern = rf'\b{re.escape(attributes["name"])}\s*(?:=|\{{)\s*({doc_figures.NUMBER.pattern})'
    match = re.search(pattern, text, re.MULTILINE)
    if not match:
        name = attributes.get('key', attributes.get('name'))
        raise MarkerError(f'{where}: {attributes[kind]} assigns no number to {name}')
    return float(match.group(1))


def check_figure(figure, text, tables, root, where):
    """Raises MarkerError unless the source of a checked marker holds `figure`."""
    kind, attributes = attributes_of(text, where)
    if kind == 'table':
        value = table_values(attributes, tables, where)
    else:
        value = file_value(kind, attributes, root, where)
    expected = value * float(attributes.get('scale', '1'))
    documented, unit = figure_value(figure)
    if abs(documented - expected) > 0.5 * unit * (1 + 1e-9) + 1e-12 * abs(expected):
        raise MarkerError(f'{where}: the prose says {figure}, its source ({text}) {expected:g}')


def documents(root):
    return [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))


def survey(root):
    """(document, found figures) per document; every checked marker verified."""
    tables = figure_tables(root)
    result = []
    for path in documents(root):
        found = figures(path)
        name = os.path.relpath(path, root)
        for number, figure, marker in found:
            if marker is not None:
                check_figure(figure, marker, tables, root, f'{name}:{number}')
        generator = generator_text(path, root)
        if generator is not None:
            found = [(number, figure, COMPUTED if marker is None and figure not in generator
                      else marker) for number, figure, marker in found]
        result.append((name, found))
    return result


def generator_text(path, root):
    """The source of the program that prints the document whole, or None."""
    with open(path, encoding='utf-8') as stream:
        lines = stream.read().splitlines()
    generated = doc_figures.document_marker(os.path.relpath(path, root), lines)
    if generated is None:
        return None
    with open(os.path.join(root, generated[1]), encoding='utf-8') as stream:
        return stream.read()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--list', action='store_true', help='print every unchecked figure')
    parser.add_argument('--limit', type=int, help='exit 1 above this many unchecked figures')
    parser.add_argument('--root', default=ROOT, help='the repository (default: this one)')
    arguments = parser.parse_args()
    try:
        surveyed = survey(arguments.root)
    except (MarkerError, doc_figures.DocumentError) as error:
        print(f'prose_figures: {error}', file=sys.stderr)
        return 2
    total = checked = 0
    for name, found in surveyed:
        done = sum(1 for _, _, marker in found if marker is not None)
        total += len(found)
        checked += done
        print(f'{name}: {len(found)} figures, {done} checked, {len(found) - done} unchecked')
        if arguments.list:
            for number, figure, marker in found:
                if marker is None:
                    print(f'  {name}:{number}: {figure}')
    unchecked = total - checked
    print(f'prose figures: {total}, checked {checked}, unchecked {unchecked}')
    if arguments.limit is not None and unchecked > arguments.limit:
        print(f'prose_figures: {unchecked} unchecked figures in prose, more than the limit of '
              f'{arguments.limit}: point to a table instead, or check the figure',
              file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
