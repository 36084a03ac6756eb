#!/usr/bin/env python3
"""Each parameter is named once: a string literal that is a declared parameter's name (or
the name followed by " = ", as a message about it starts) appears in at most one product
source file, the parameter schema, unless test/repository/parameter_literals_allowlist.txt
lists it with the reason it is not the parameter. A copy of the tree with a second literal
of a name fails the check."""
import os
import re
import shutil
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FOLDERS = ('polygon_coverage_ros_bridge', 'trajectory_generation_tools', 'coverage_system',
           'rviz_plugins')
ALLOWLIST = os.path.join(ROOT, 'test', 'repository', 'parameter_literals_allowlist.txt')
TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|\'(?:\\.|[^\\\'])*\'|"((?:\\.|[^\\"])*)"', re.S)


def parameter_names(root):
    """The keys of config/default.yaml, the schema's output (a gtest keeps them equal)."""
    with open(os.path.join(root, 'config', 'default.yaml')) as stream:
        return [line.split(':')[0] for line in stream if re.match(r'^[a-z_]+:', line)]


def literals(path):
    with open(path, encoding='utf-8') as stream:
        text = stream.read()
    return [match.group(1) for match in TOKEN.finditer(text) if match.group(1) is not None]


def allowed(path):
    entries = set()
    with open(path) as stream:
        for line in stream:
            fields = line.split('#')[0].split()
            if line.strip() and not line.startswith('#'):
                if len(fields) != 2 or '#' not in line:
                    raise ValueError('an allowlist line is "name path  # reason": ' + line)
                entries.add((fields[0], fields[1]))
    return entries


def violations(root, allowlist):
    names = parameter_names(root)
    files = {name: [] for name in names}
    for folder in FOLDERS:
        for directory, _, filenames in os.walk(os.path.join(root, folder)):
            for filename in sorted(filenames):
                if not filename.endswith(('.cpp', '.h')):
                    continue
                path = os.path.join(directory, filename)
                relative = os.path.relpath(path, root)
                found = set()
                for literal in literals(path):
                    name = re.sub(r' = $', '', literal)
                    if name in files and (name, relative) not in allowlist:
                        found.add(name)
                for name in found:
                    files[name].append(relative)
    return {name: paths for name, paths in files.items() if len(paths) > 1}


class ParameterLiteralsTest(unittest.TestCase):
    def test_each_parameter_name_is_a_literal_of_one_file(self):
        found = violations(ROOT, allowed(ALLOWLIST))
        self.assertEqual(found, {}, 'parameter names as literals in several product files '
                         '(take them from the parameter schema, or allowlist a literal that '
                         'is not the parameter, with the reason)')

    def test_a_second_literal_of_a_name_fails(self):
        directory = tempfile.mkdtemp()
        try:
            shutil.copytree(os.path.join(ROOT, 'config'), os.path.join(directory, 'config'))
            for folder in FOLDERS:
                shutil.copytree(os.path.join(ROOT, folder), os.path.join(directory, folder))
            extra = os.path.join(directory, FOLDERS[1], 'trajectory', 'extra.cpp')
            with open(extra, 'w') as stream:
                stream.write('// "v_max" in a comment is no literal\n'
                             'const char* kName = "turning_radius = ";\n')
            self.assertEqual(set(violations(directory, set())) - set(violations(ROOT, set())),
                             {'turning_radius'})
        finally:
            shutil.rmtree(directory)


if __name__ == '__main__':
    unittest.main()
