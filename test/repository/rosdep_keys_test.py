#!/usr/bin/env python3
"""Every dependency key of package.xml is one that `rosdep install --from-paths src
--ignore-src` resolves for Noetic on Ubuntu 20.04 (focal) and on Debian 12 (bookworm)
(but for the keys whose rule misses bookworm, which scripts/install_dependencies.sh installs):
a package released in Noetic, or a system key of rosdep/base.yaml or rosdep/python.yaml
with packages for both. Checked against test/repository/data/rosdep_keys.yaml, an extract
of ros/rosdistro (its commit is recorded there) written by scripts/extract_rosdep_keys.py."""
import importlib.util
import os
import re
import unittest

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SPEC = importlib.util.spec_from_file_location(
    'extract_rosdep_keys', os.path.join(ROOT, 'scripts', 'extract_rosdep_keys.py'))
extract_rosdep_keys = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(extract_rosdep_keys)

PLATFORMS = (('ubuntu', 'focal'), ('debian', 'bookworm'))
# Keys whose rosdep rule names no package for bookworm although Debian 12 has one: on
# Debian 12 scripts/install_dependencies.sh installs it (README, In a catkin workspace).
BOOKWORM_BY_INSTALL_SCRIPT = {'polyclipping-dev': 'libpolyclipping-dev'}
INSTALL_SCRIPT = os.path.join(ROOT, 'scripts', 'install_dependencies.sh')
INSTALLERS = ('apt', 'pip', 'source')


def resolve(rule, platform, codename):
    """The packages a rosdep rule installs on `platform` `codename` (REP 111: a list for
    every release, or per codename with '*' for the others, each a list, an installer's
    entry, or null where the key is not available); None when it does not resolve."""
    value = rule.get(platform)
    if isinstance(value, dict) and not any(installer in value for installer in INSTALLERS):
        value = value[codename] if codename in value else value.get('*')
    if value is None:
        return None
    if isinstance(value, list):
        return value
    for installer in INSTALLERS:
        if installer in value:
            entry = value[installer]
            return entry.get('packages', []) if isinstance(entry, dict) else entry
    return value.get('packages')


class ResolveTest(unittest.TestCase):
    def test_a_list_holds_for_every_release(self):
        self.assertEqual(resolve({'debian': ['libgmp-dev']}, 'debian', 'bookworm'),
                         ['libgmp-dev'])

    def test_a_codename_wins_over_the_wildcard(self):
        rule = {'ubuntu': {'*': ['libqt5widgets5t64'], 'focal': ['libqt5widgets5']}}
        self.assertEqual(resolve(rule, 'ubuntu', 'focal'), ['libqt5widgets5'])
        self.assertEqual(resolve(rule, 'ubuntu', 'noble'), ['libqt5widgets5t64'])

    def test_null_or_a_missing_release_or_platform_does_not_resolve(self):
        self.assertIsNone(resolve({'ubuntu': {'focal': None, '*': ['x']}}, 'ubuntu', 'focal'))
        self.assertIsNone(resolve({'ubuntu': {'jammy': ['x']}}, 'ubuntu', 'focal'))
        self.assertIsNone(resolve({'ubuntu': ['x']}, 'debian', 'bookworm'))

    def test_an_installer_entry_resolves(self):
        self.assertEqual(resolve({'debian': {'pip': {'packages': ['y']}}}, 'debian', 'bookworm'),
                         ['y'])
        self.assertEqual(
            resolve({'ubuntu': {'focal': {'apt': {'packages': ['z']}}}}, 'ubuntu', 'focal'), ['z'])


class PackageKeysTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(extract_rosdep_keys.EXTRACT) as stream:
            cls.extract = yaml.safe_load(stream)
        cls.keys = extract_rosdep_keys.package_keys()

    def test_the_extract_names_its_rosdistro_commit(self):
        self.assertRegex(self.extract['rosdistro_commit'], re.compile('^[0-9a-f]{40}$'))

    def test_the_extract_covers_every_key_of_package_xml(self):
        known = set(self.extract['noetic_packages']) | set(self.extract['system_keys']) | set(
            self.extract['unknown_keys'])
        missing = sorted(set(self.keys) - known)
        self.assertEqual(missing, [], 'package.xml has keys the extract does not know: rerun '
                         'scripts/extract_rosdep_keys.py with a clone of ros/rosdistro')

    def test_every_key_is_a_rosdep_key(self):
        self.assertEqual(self.extract['unknown_keys'], [],
                         'not a Noetic package nor a key of rosdep/base.yaml or python.yaml')

    def test_every_system_key_resolves_for_focal_and_bookworm(self):
        for key in self.keys:
            rule = self.extract['system_keys'].get(key)
            if rule is None:
                continue
            for platform, codename in PLATFORMS:
                if codename == 'bookworm' and key in BOOKWORM_BY_INSTALL_SCRIPT:
                    continue
                with self.subTest(key=key, platform=codename):
                    self.assertTrue(resolve(rule, platform, codename),
                                    f'{key} has no packages for {platform} {codename}')

    def test_the_install_script_installs_what_rosdep_cannot_on_bookworm(self):
        with open(INSTALL_SCRIPT) as stream:
            script_packages = stream.read().split()
        for key, package in BOOKWORM_BY_INSTALL_SCRIPT.items():
            with self.subTest(key=key):
                self.assertIn(key, self.keys, 'an exception for a key package.xml does not use')
                self.assertIsNone(resolve(self.extract['system_keys'][key], 'debian', 'bookworm'),
                                  'rosdep resolves it for bookworm now: drop the exception')
                self.assertIn(package, script_packages)


if __name__ == '__main__':
    unittest.main()
