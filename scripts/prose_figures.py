#!/usr/bin/env python3
"""Counts the figures that the prose of README.md and docs/*.md states: a number followed by
a unit (%, s, ms, min, h, d, MB, GB, m, m^2, km, km^2, cm, mm, m/s, rad, Hz, x), outside tables, code blocks, inline code, HTML tags
and comments. Tables are checked by doc_figures; a figure in prose is checked by nothing, so
their count is a debt that CI keeps from growing.

  prose_figures.py [--list] [--limit N] [--root DIR]

Prints the count per document and in all; --list also prints each figure with its line;
--limit N exits 1 when there are more than N.
"""
import argparse
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# A number (digits, optionally grouped by spaces or commas in threes, optionally with a
# decimal part, optionally negative), optional space, a unit, not followed by a letter,
# digit or caret (so "3 max" is no figure and "2 m^2" one figure); "x" is a ratio ("1.6x"),
# not a size ("64 x 64").
FIGURE = re.compile(
    r'(?<![\w.])-?\d+(?:[ ,]\d{3})*(?:\.\d+)?\s?(?:%|ms|MB|GB|km\^2|km|m\^2|m/s|m|s|min|h|d|cm|mm|rad|Hz|x(?!\s?\d))(?![\w^])')


def prose_lines(text):
    """(line number, line) of the prose: tables, fenced and indented code blocks and HTML
    comments left out, inline code spans and HTML tags blanked."""
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
        yield number, re.sub(r'<[^>]*>', '', re.sub(r'`[^`]*`', '', line))


def figures(path):
    """(line number, figure) of the prose figures of one document."""
    with open(path, encoding='utf-8') as stream:
        text = stream.read()
    found = []
    for number, line in prose_lines(text):
        for match in FIGURE.finditer(line):
            found.append((number, match.group(0)))
    return found


def documents(root):
    return [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--list', action='store_true', help='print every figure')
    parser.add_argument('--limit', type=int, help='exit 1 above this many figures')
    parser.add_argument('--root', default=ROOT, help='the repository (default: this one)')
    arguments = parser.parse_args()
    total = 0
    for path in documents(arguments.root):
        found = figures(path)
        total += len(found)
        name = os.path.relpath(path, arguments.root)
        print(f'{name}: {len(found)}')
        if arguments.list:
            for number, figure in found:
                print(f'  {name}:{number}: {figure}')
    print(f'prose figures: {total}')
    if arguments.limit is not None and total > arguments.limit:
        print(f'prose_figures: {total} figures in prose, more than the limit of {arguments.limit}: '
              'point to a table instead, or check the figure', file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
