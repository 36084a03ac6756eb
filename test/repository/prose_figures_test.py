#!/usr/bin/env python3
"""The prose-figure counter (scripts/prose_figures.py) counts a number with a unit in prose
and nothing in tables, code blocks, inline code, HTML tags or comments, and checks a figure
that a marker ties to a table cell, a setting or a source constant: it passes the figure its
source holds and fails a drifted one."""
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
It brakes at 0.2 m/s^2 and turns at 0.5 rad/s, within 1e-9 m.
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
            found = [figure for _, figure, _ in prose_figures.figures(stream.name)]
        finally:
            os.unlink(stream.name)
        self.assertEqual(found, ['1.24 s', '99.9 %', '73 km', '536 km^2', '2 m^2', '0.5 m/s',
                                 '6 min', '2 h', '10 Hz', '0.2 rad', '5 cm', '3 mm', '1.6x',
                                 '1 864 624 s', '0.2 m/s^2', '0.5 rad/s', '1e-9 m', '12 m'])

    def test_line_numbers_point_at_the_figures(self):
        with tempfile.NamedTemporaryFile('w', suffix='.md', delete=False) as stream:
            stream.write(DOCUMENT)
        try:
            lines = sorted({number for number, _, _ in prose_figures.figures(stream.name)})
        finally:
            os.unlink(stream.name)
        self.assertEqual(lines, [3, 4, 5, 22])


BENCHMARKS = '''# Benchmarks

<!-- figures: command="fake_bench" id="lakes" -->
| lake | area km^2 | time s (timing) | seen % | legs m |
|---|---|---|---|---|
| small | 1 864 624 | 0.51 | 99.93 (12 of 13) | 4.5 / 7.25 |
| large | 536.4 | 12.7 | 98.10 (40 of 41) | 3 / 9 |
'''

CONFIG = '''wall_distance: 1.5  # m
trajectory_sampling_distance: 0.1
same_position_tolerance: 1e-9
'''

SOURCE = '''constexpr double kMaxExtentMeters = 5e4;
const double kFoldTolerance{0.0025};
'''


class CheckedMarkerTest(unittest.TestCase):
    """A repository with one figures table, one setting and one constant, and a README whose
    prose points at them."""

    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.root = self.directory.name
        for name, text in {'docs/BENCHMARKS.md': BENCHMARKS, 'config/default.yaml': CONFIG,
                           'src/frame.cpp': SOURCE}.items():
            os.makedirs(os.path.dirname(os.path.join(self.root, name)), exist_ok=True)
            with open(os.path.join(self.root, name), 'w') as stream:
                stream.write(text)

    def tearDown(self):
        self.directory.cleanup()

    def survey(self, prose):
        with open(os.path.join(self.root, 'README.md'), 'w') as stream:
            stream.write('# Readme\n\n' + prose + '\n')
        return dict(prose_figures.survey(self.root))['README.md']

    def assertChecked(self, prose):
        found = self.survey(prose)
        self.assertTrue(found and all(marker for _, _, marker in found), found)

    def assertRefused(self, prose, why):
        with self.assertRaisesRegex(prose_figures.MarkerError, why):
            self.survey(prose)

    def test_a_figure_that_its_cell_holds_passes_rounded_or_not(self):
        self.assertChecked('It sees **99.93 %**<!-- checked: table="lakes" row="small" '
                           'column="seen %" --> of it.')
        self.assertChecked('It sees 99.9 %<!-- checked: table="lakes" row="small" '
                           'column="seen %" --> of it, in 13 s<!-- checked: table="lakes" '
                           'row="large" column="time s (timing)" -->.')
        self.assertChecked('Legs of 7.3 m<!-- checked: table="lakes" row="small" column="legs m" '
                           'number="2" -->... 1 864 624 m^2<!-- checked: table="lakes" '
                           'row="small" column="area km^2" -->.')

    def test_a_drifted_figure_fails(self):
        self.assertRefused('It sees 99.8 %<!-- checked: table="lakes" row="small" '
                           'column="seen %" -->.', 'the prose says 99.8 %')
        self.assertRefused('It sees 99.94 %<!-- checked: table="lakes" row="small" '
                           'column="seen %" -->.', 'the prose says 99.94 %')

    def test_aggregates_over_a_column(self):
        self.assertChecked('At least 98.1 %<!-- checked: table="lakes" column="seen %" of="min" '
                           '--> and at most 99.93 %<!-- checked: table="lakes" column="seen %" '
                           'of="max" -->.')
        self.assertRefused('At least 99.9 %<!-- checked: table="lakes" column="seen %" '
                           'of="min" -->.', 'the prose says')

    def test_settings_and_constants_with_a_scale(self):
        self.assertChecked('A wall distance of 1.5 m<!-- checked: yaml="config/default.yaml" '
                           'key="wall_distance" -->, poses 10 cm<!-- checked: '
                           'yaml="config/default.yaml" key="trajectory_sampling_distance" '
                           'scale="100" --> apart, 50 km<!-- checked: code="src/frame.cpp" '
                           'name="kMaxExtentMeters" scale="0.001" --> and 2.5 mm<!-- checked: '
                           'code="src/frame.cpp" name="kFoldTolerance" scale="1000" -->, '
                           'within 1e-9 m<!-- checked: yaml="config/default.yaml" '
                           'key="same_position_tolerance" -->.')
        self.assertRefused('A wall distance of 1.4 m<!-- checked: yaml="config/default.yaml" '
                           'key="wall_distance" -->.', 'the prose says 1.4 m')

    def test_a_marker_must_name_a_source_that_exists_and_follow_a_figure(self):
        self.assertRefused('It sees 99.9 %<!-- checked: table="rivers" row="small" '
                           'column="seen %" -->.', 'no figures table has id "rivers"')
        self.assertRefused('It sees 99.9 %<!-- checked: table="lakes" row="tiny" '
                           'column="seen %" -->.', 'has no row "tiny"')
        self.assertRefused('It sees 99.9 %<!-- checked: table="lakes" row="small" '
                           'column="seen" -->.', 'has no column "seen"')
        self.assertRefused('1 m<!-- checked: yaml="config/default.yaml" key="v_max" -->',
                           'assigns no number to v_max')
        self.assertRefused('It sees all<!-- checked: table="lakes" row="small" '
                           'column="seen %" -->.', 'follows no figure')
        self.assertRefused('1 m<!-- checked: key="wall_distance" -->', 'one of table=')

    def test_the_limit_counts_unchecked_figures_only(self):
        found = self.survey('A 30 m square, 1.5 m<!-- checked: yaml="config/default.yaml" '
                            'key="wall_distance" --> from its walls.')
        self.assertEqual([(figure, marker is not None) for _, figure, marker in found],
                         [('30 m', False), ('1.5 m', True)])

    def test_a_generated_document_checks_what_its_generator_computes(self):
        with open(os.path.join(self.root, 'report.py'), 'w') as stream:
            stream.write("print(f'the robot took {time:.1f} s in a 30 m square')\n")
        with open(os.path.join(self.root, 'docs', 'REPORT.md'), 'w') as stream:
            stream.write('<!-- document: command="report" source="report.py" -->\n'
                         'The robot took 391.0 s in a 30 m square.\n')
        self.survey('No figure.')
        found = dict(prose_figures.survey(self.root))['docs/REPORT.md']
        self.assertEqual([(figure, marker) for _, figure, marker in found],
                         [('391.0 s', prose_figures.COMPUTED), ('30 m', None)])


if __name__ == '__main__':
    unittest.main()
