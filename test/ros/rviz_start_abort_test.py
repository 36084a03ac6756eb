#!/usr/bin/env python3
"""The GUI tests start rviz again only after its known start-up abort (rviz_gui_support's
known_start_abort): SIGABRT with glibc's "free(): invalid next size", or SIGSEGV with the
log ending at librospack's failed lookup, and no frame of our plugins' library in its log."""
import os
import signal
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rviz_gui_support  # noqa: E402

KNOWN_LOG = ('[ INFO] rviz version 1.14.20\n'
             '[rospack] Error: package/stack depends on non-existent package\n'
             'free(): invalid next size (normal)\n')


SEGFAULT_LOG = ('[ INFO] rviz version 1.14.19\n'
                '[rospack] Error: no such package media_export\n'
                '[librospack]: error while executing command\n')


class RvizStartAbortTest(unittest.TestCase):
    def test_the_known_abort_is_started_again(self):
        self.assertTrue(rviz_gui_support.known_start_abort(-signal.SIGABRT, KNOWN_LOG))

    def test_a_segfault_at_the_failed_lookup_is_started_again(self):
        self.assertTrue(rviz_gui_support.known_start_abort(-signal.SIGSEGV, SEGFAULT_LOG))
        later = SEGFAULT_LOG + '[ INFO] Stereo is NOT SUPPORTED\n'
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGSEGV, later))
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGABRT, SEGFAULT_LOG))

    def test_another_signal_or_message_fails(self):
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGSEGV, KNOWN_LOG))
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGABRT,
                                                            'double free or corruption\n'))
        self.assertFalse(rviz_gui_support.known_start_abort(1, KNOWN_LOG))

    def test_a_frame_of_our_plugins_fails(self):
        log = KNOWN_LOG + ('#3 0x7f in kinematic_coverage::rviz::PolygonTool::onInitialize() '
                           'from /ws/devel/lib/libkinematic_coverage_rviz_plugins.so\n')
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGABRT, log))
        segfault = SEGFAULT_LOG.replace('[librospack]', log.splitlines()[-1] + '\n[librospack]')
        self.assertFalse(rviz_gui_support.known_start_abort(-signal.SIGSEGV, segfault))


if __name__ == '__main__':
    unittest.main()
