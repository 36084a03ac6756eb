#!/usr/bin/env python3
"""Writes test/repository/data/rosdep_keys.yaml: what ros/rosdistro says about every
dependency key of package.xml, so that test/repository/rosdep_keys_test.py can check,
without a network, that `rosdep install --from-paths src --ignore-src` resolves them for
Noetic on Ubuntu 20.04 (focal) and on Debian 12 (bookworm).

    scripts/extract_rosdep_keys.py ROSDISTRO

ROSDISTRO is a clone of https://github.com/ros/rosdistro (a working tree, or a bare git
directory, whose HEAD is read). Per key, the extract holds the Noetic repository that
releases it (noetic/distribution.yaml) or its rules in rosdep/base.yaml or
rosdep/python.yaml; a key found in none of them is listed as unknown. Rerun it after adding
a dependency to package.xml.
"""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE_XML = os.path.join(ROOT, 'package.xml')
EXTRACT = os.path.join(ROOT, 'test', 'repository', 'data', 'rosdep_keys.yaml')
DEPENDENCY_TAGS = ('depend', 'build_depend', 'build_export_depend', 'buildtool_depend',
                   'exec_depend', 'test_depend', 'doc_depend')


def package_keys(path=PACKAGE_XML):
    """The dependency keys of a package.xml, sorted and without repeats."""
    root = ElementTree.parse(path).getroot()
    return sorted({element.text.strip() for tag in DEPENDENCY_TAGS
                   for element in root.findall(tag)})


class Rosdistro:
    """Files of a rosdistro clone at its HEAD (working tree or bare git directory)."""

    def __init__(self, location):
        self.location = location
        self.tree = os.path.isfile(os.path.join(location, 'rosdep', 'base.yaml'))
        self.commit = self._git('rev-parse', 'HEAD').strip()
        self.date = self._git('show', '-s', '--format=%cs', 'HEAD').strip()

    def _git(self, *arguments):
        flag = ['-C', self.location] if self.tree else ['--git-dir', self.location]
        return subprocess.run(['git', *flag, *arguments], check=True, stdout=subprocess.PIPE,
                              universal_newlines=True).stdout

    def read_yaml(self, path):
        if self.tree:
            with open(os.path.join(self.location, path)) as stream:
                return yaml.safe_load(stream)
        return yaml.safe_load(self._git('show', 'HEAD:' + path))


def noetic_packages(distribution):
    """Package name -> the Noetic repository that releases it."""
    packages = {}
    for name, repository in distribution['repositories'].items():
        release = repository.get('release')
        if not release:
            continue
        for package in release.get('packages', [name]):
            packages[package] = name
    return packages


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('rosdistro', help='a clone of ros/rosdistro')
    arguments = parser.parse_args()
    rosdistro = Rosdistro(arguments.rosdistro)
    released = noetic_packages(rosdistro.read_yaml('noetic/distribution.yaml'))
    rules = {}
    for path in ('rosdep/base.yaml', 'rosdep/python.yaml'):
        rules.update(rosdistro.read_yaml(path))

    noetic, system, unknown = {}, {}, []
    for key in package_keys():
        if key in released:
            noetic[key] = released[key]
        elif key in rules:
            system[key] = {platform: rules[key][platform] for platform in ('debian', 'ubuntu')
                           if platform in rules[key]}
        else:
            unknown.append(key)
    extract = {'rosdistro_commit': rosdistro.commit, 'rosdistro_date': rosdistro.date,
               'noetic_packages': noetic, 'system_keys': system, 'unknown_keys': unknown}
    os.makedirs(os.path.dirname(EXTRACT), exist_ok=True)
    with open(EXTRACT, 'w') as stream:
        stream.write('# Written by scripts/extract_rosdep_keys.py from ros/rosdistro: the rosdep\n'
                     '# keys of package.xml, from noetic/distribution.yaml, rosdep/base.yaml and\n'
                     '# rosdep/python.yaml. Checked by test/repository/rosdep_keys_test.py.\n')
        yaml.safe_dump(extract, stream, default_flow_style=None, sort_keys=False)
    print(f'extract_rosdep_keys: {len(noetic)} Noetic packages, {len(system)} system keys, '
          f'{len(unknown)} unknown ({rosdistro.commit}) -> {os.path.relpath(EXTRACT, ROOT)}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
