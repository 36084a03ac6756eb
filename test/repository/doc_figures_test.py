#!/usr/bin/env python3
"""Tests of scripts/doc_figures.py: it passes a document whose figures its command prints,
and fails one whose machine-independent figure drifted, whatever the timings do."""
import importlib.util
import os
import stat
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SPEC = importlib.util.spec_from_file_location('doc_figures',
                                              os.path.join(ROOT, 'scripts', 'doc_figures.py'))
doc_figures = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(doc_figures)

DOCUMENT = '''# A benchmark

    fake_bench --runs 3

<!-- figures: command="fake_bench --runs 3" ci="fake_bench --runs 1" -->
| map | cells | length m | time ms (timing) |
|---|---|---|---|
| lake | 52 | 7420.70 | 13.2 |
| pond | 3 | 19.34 | 0.2 |
'''


class CompareCellTest(unittest.TestCase):
    def test_equal_cells_pass(self):
        self.assertIsNone(doc_figures.compare_cell('7420.70', '7420.70'))
        self.assertIsNone(doc_figures.compare_cell('21 / 21', '21 / 21'))

    def test_a_last_digit_rounding_flip_passes_and_more_fails(self):
        self.assertIsNone(doc_figures.compare_cell('99.97', '99.98'))
        self.assertIsNotNone(doc_figures.compare_cell('99.97', '99.99'))

    def test_counts_are_exact(self):
        self.assertIsNotNone(doc_figures.compare_cell('753', '754'))
        self.assertIsNotNone(doc_figures.compare_cell('21 / 21', '20 / 21'))

    def test_text_must_match(self):
        self.assertIsNotNone(doc_figures.compare_cell('5 cm, 362404', '10 cm, 362404'))
        self.assertIsNotNone(doc_figures.compare_cell('clean', 'failed'))


class CheckTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.build = self.directory.name
        self.bin = os.path.join(self.build, 'devel', 'lib', 'kinematic_coverage')
        os.makedirs(self.bin)
        self.document = os.path.join(self.directory.name, 'BENCH.md')
        with open(self.document, 'w') as stream:
            stream.write(DOCUMENT)

    def tearDown(self):
        self.directory.cleanup()

    def program(self, rows):
        """fake_bench prints `rows` under the document's header."""
        path = os.path.join(self.bin, 'fake_bench')
        with open(path, 'w') as stream:
            stream.write('#!/bin/sh\necho "| map | cells | length m | time ms (timing) |"\n'
                         'echo "|---|---|---|---|"\n')
            for row in rows:
                stream.write(f'echo "{row}"\n')
        os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)

    def check(self, ci=False):
        return doc_figures.check([self.document], self.build, ci)

    def test_the_same_figures_pass_whatever_the_timings(self):
        self.program(['| lake | 52 | 7420.70 | 99.0 |', '| pond | 3 | 19.34 | 5.1 |'])
        self.assertEqual(self.check(), 0)

    def test_a_drifted_figure_fails(self):
        self.program(['| lake | 52 | 7420.95 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(self.check(), 1)
        self.program(['| lake | 53 | 7420.70 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(self.check(), 1)

    def test_a_missing_or_new_row_fails(self):
        self.program(['| lake | 52 | 7420.70 | 13.2 |'])
        self.assertEqual(self.check(), 1)
        self.program(['| lake | 52 | 7420.70 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |',
                      '| sea | 9 | 1.00 | 0.1 |'])
        self.assertEqual(self.check(), 1)

    def test_ci_may_rerun_some_rows_but_each_must_match(self):
        self.program(['| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(self.check(ci=True), 0)
        self.program(['| pond | 4 | 19.34 | 0.2 |'])
        self.assertEqual(self.check(ci=True), 1)

    def test_a_failing_command_fails(self):
        path = os.path.join(self.bin, 'fake_bench')
        with open(path, 'w') as stream:
            stream.write('#!/bin/sh\nexit 3\n')
        os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
        self.assertEqual(self.check(), 1)

    def test_a_table_without_a_command_is_an_error(self):
        with open(self.document, 'a') as stream:
            stream.write('\n| a | b |\n|---|---|\n| 1 | 2 |\n')
        self.program(['| lake | 52 | 7420.70 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        with self.assertRaises(doc_figures.DocumentError):
            self.check()

    def test_a_bound_column_checks_its_bound_not_its_figures(self):
        bounded = os.path.join(self.directory.name, 'MEMORY.md')
        with open(bounded, 'w') as stream:
            stream.write('    fake_memory\n\n<!-- figures: command="fake_memory" -->\n'
                         '| map | peak MB (at most 100) |\n|---|---|\n| lake | 80 |\n')
        path = os.path.join(self.bin, 'fake_memory')
        for printed, status in (('95', 0), ('120', 1)):
            with open(path, 'w') as stream:
                stream.write('#!/bin/sh\necho "| map | peak MB (at most 100) |"\n'
                             f'echo "|---|---|"\necho "| lake | {printed} |"\n')
            os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
            self.assertEqual(doc_figures.check([bounded], self.build, False), status, printed)

    def test_a_generated_document_is_checked_in_its_prose_too(self):
        generated = os.path.join(self.directory.name, 'REPORT.md')
        text = ('<!-- document: command="fake_report" source="scripts/fake_report.py" -->\n'
                '# Report\n\nThe robot took 391.0 s, 2.3 % less than unsmoothed.\n\n'
                '    fake_report\n\n<!-- figures: command="fake_report" -->\n'
                '| run | time s |\n|---|---|\n| lake | 391.0 |\n')
        with open(generated, 'w') as stream:
            stream.write(text)
        path = os.path.join(self.bin, 'fake_report')
        for printed, status in ((text, 0), (text.replace('391.0 s', '391.1 s'), 0),
                                (text.replace('2.3 %', '2.5 %'), 1),
                                (text.replace('less than', 'more than'), 1),
                                (text.replace('# Report\n', ''), 1)):
            with open(path, 'w') as stream:
                stream.write(f"#!/bin/sh\ncat <<'END'\n{printed}END\n")
            os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
            self.assertEqual(doc_figures.check([generated], self.build, False), status, printed)

    def test_regenerate_writes_the_fresh_table(self):
        self.program(['| lake | 52 | 7420.95 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(doc_figures.regenerate([self.document], self.build), 0)
        self.assertEqual(self.check(), 0)
        with open(self.document) as stream:
            self.assertIn('| lake | 52 | 7420.95 | 13.2 |', stream.read())

    def test_jobs_run_the_commands_at_once_with_the_same_outcome(self):
        with open(self.document, 'a') as stream:
            stream.write('\n    fake_bench --runs 5\n\n'
                         '<!-- figures: command="fake_bench --runs 5" ci="skip: slow" -->\n'
                         '| map | cells | length m | time ms (timing) |\n|---|---|---|---|\n'
                         '| lake | 52 | 7420.70 | 13.2 |\n| pond | 3 | 19.34 | 0.2 |\n')
        self.program(['| lake | 52 | 7420.70 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(doc_figures.check([self.document], self.build, False, jobs=2), 0)
        self.program(['| lake | 52 | 7420.95 | 13.2 |', '| pond | 3 | 19.34 | 0.2 |'])
        self.assertEqual(doc_figures.check([self.document], self.build, False, jobs=2), 1)
        self.assertEqual(doc_figures.regenerate([self.document], self.build, jobs=2), 0)
        with open(self.document) as stream:
            self.assertEqual(stream.read().count('| lake | 52 | 7420.95 | 13.2 |'), 2)


if __name__ == '__main__':
    unittest.main()
