#!/usr/bin/env python3
"""The prose-figure counter (scripts/prose_figures.py) counts a number with a unit in prose
and nothing in tables, code blocks, inline code, HTML tags or comments."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), 'scripts'))
import prose_figures  # noqa: E402

DOCUMENT = '''# A document

The lake plans in 1.24 s and sees 99.9 % of it; the 73 km lake, 536 km^2, 2 m^2 and 0.5 m/s.
It took 6 min and 2 h at 10 Hz, a turn of 0.2 rad, 5 cm, 3 mm, a 1.6x speed-up, 1 864 624 s.
A 64 x 64 grid, 3 max, the 2nd lane, version 1.2, 5 minutes: none of these.

| table | 5 m |
|---|---|
| row | 7 s |

    coverage_tool plan --set wall_distance=1 # 3 m

```
fenced 4 m
```

<!-- figures: 9 s -->
<!-- a comment
over 2 lines, 8 m
-->
Inline `--set x=3 m` and <img width="49%"> stay out; 12 m after them counts.
'''


class ProseFiguresTest(unittest.TestCase):
    def test_counts_figures_in_prose_only(self):
        with tempfile.NamedTemporaryFile('w', suffix='.md', delete=False) as stream:
            stream.write(DOCUMENT)
        try:
            found = [figure for _, figure in prose_figures.figures(stream.name)]
        finally:
            os.unlink(stream.name)
        self.assertEqual(found, ['1.24 s', '99.9 %', '73 km', '536 km^2', '2 m^2', '0.5 m/s',
                                 '6 min', '2 h', '10 Hz', '0.2 rad', '5 cm', '3 mm', '1.6x',
                                 '1 864 624 s', '12 m'])

    def test_line_numbers_point_at_the_figures(self):
        with tempfile.NamedTemporaryFile('w', suffix='.md', delete=False) as stream:
            stream.write(DOCUMENT)
        try:
            lines = sorted({number for number, _ in prose_figures.figures(stream.name)})
        finally:
            os.unlink(stream.name)
        self.assertEqual(lines, [3, 4, 21])


if __name__ == '__main__':
    unittest.main()
