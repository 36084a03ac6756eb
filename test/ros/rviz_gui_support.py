"""Helpers shared by the GUI rostests: rviz started on a config with a TopDownOrtho view of
known scale, found on the screen and driven with xdotool under Xvfb, a pixel of its render
area mapped to metres of the ground plane and back."""

import os
import re
import shutil
import signal
import subprocess
import sys
import time
import unittest

RVIZ_WINDOW_TIMEOUT_S = 30.0
# rviz first lays out at 640x480, then resizes to the config's geometry.
STABLE_POLLS = 4
POLL_INTERVAL_S = 0.5
# Steps of a drag, so that the tool sees the pointer move before the button is released.
DRAG_STEPS = 5
PLUGIN_ERRORS = ('PluginlibFactory', 'Failed to load library', 'could not be loaded')
GUI_PROGRAMS = ('xdotool', 'xwininfo', 'import')
XML_OUTPUT_FLAG = '--gtest_output=xml:'
# rviz under Xvfb and llvmpipe sometimes aborts while it starts, before its window settles
# ("free(): invalid next size" right after librospack's failed media_export lookup; twice
# in three full ctest runs beside the other tests, never in seven runs alone), and the same
# heap damage may end it with a segmentation fault at that point instead (its log ending
# with librospack's error; once, on a machine running two other test suites): such a start
# is tried again, its log kept; rviz that aborts at every start still fails the test. Only
# those aborts are: any other signal or log, or a log that shows a frame of our plugins'
# library, fails the test at once.
START_ATTEMPTS = 3
KNOWN_START_ABORT = re.compile(r'free\(\): invalid next size')
KNOWN_START_SEGFAULT = re.compile(r'\[librospack\]: error while executing command\s*\Z')
OUR_PLUGIN_LIBRARY = 'libkinematic_coverage_rviz_plugins'


def known_start_abort(returncode, log_text):
    """True for rviz's known start-up abort: SIGABRT with glibc's "free(): invalid next
    size", or SIGSEGV with the log ending at librospack's failed lookup; not for one whose
    log names our plugins' library (a frame of our code)."""
    if OUR_PLUGIN_LIBRARY in log_text:
        return False
    if returncode == -signal.SIGABRT:
        return KNOWN_START_ABORT.search(log_text) is not None
    return returncode == -signal.SIGSEGV and KNOWN_START_SEGFAULT.search(log_text) is not None
XWININFO_LINE = re.compile(
    r'^\s*(0x[0-9a-f]+) (.*?): .*\s(\d+)x(\d+)\+-?\d+\+-?\d+\s+\+(-?\d+)\+(-?\d+)\s*$')


def run(*command):
    return subprocess.run(command, check=True, capture_output=True, text=True,
                          timeout=10).stdout


def move_pointer(pixel):
    """Moves the pointer to a screen pixel and waits until it is there (xdotool's --sync,
    which would wait forever for a move to where the pointer already is)."""
    location = dict(line.split('=', 1) for line in
                    run('xdotool', 'getmouselocation', '--shell').split())
    if (int(location['X']), int(location['Y'])) != tuple(pixel):
        run('xdotool', 'mousemove', '--sync', str(pixel[0]), str(pixel[1]))


def skip_without_display(test_name):
    """Raises unittest.SkipTest (with a line on stderr) when there is no DISPLAY."""
    if not os.environ.get('DISPLAY'):
        message = ('%s: SKIPPED: no DISPLAY. This GUI test drives rviz with xdotool; '
                   'run ctest under xvfb-run -a -s "-screen 0 1280x1024x24".' % test_name)
        print(message, file=sys.stderr)
        raise unittest.SkipTest(message)


class RvizTestCase(unittest.TestCase):
    """A GUI test case: skipped without a DISPLAY, else the subclass's start_rviz() runs once
    for the class. rosunit's result file drops errors raised in setUpClass, so an error there
    is kept in setup_error for the tests to report (check_setup)."""

    TEST_NAME = 'rviz'

    @classmethod
    def setUpClass(cls):
        cls.setup_error = None
        skip_without_display(cls.TEST_NAME)
        try:
            cls.start_rviz()
        except Exception as error:  # reported by every test
            cls.setup_error = '%s: %s' % (type(error).__name__, error)

    def check_setup(self):
        if self.setup_error:
            self.fail(self.setup_error)


def check_gui_programs():
    """Raises RuntimeError naming the programs the GUI tests need that are not installed."""
    missing = [program for program in GUI_PROGRAMS if shutil.which(program) is None]
    if missing:
        raise RuntimeError('missing %s: run scripts/install_dependencies.sh' % ', '.join(missing))


def default_artifact_dir():
    """The directory of the result file rostest asks for (its --gtest_output=xml: argument),
    else ROS_HOME or ~/.ros."""
    for argument in sys.argv:
        if argument.startswith(XML_OUTPUT_FLAG):
            return os.path.dirname(argument[len(XML_OUTPUT_FLAG):])
    return os.environ.get('ROS_HOME', os.path.expanduser('~/.ros'))


def top_down_view(config, config_path):
    """The current view of a parsed rviz config; RuntimeError unless it is TopDownOrtho with
    Angle 0, the view whose pixels map to metres by its scale and focus alone."""
    view = config['Visualization Manager']['Views']['Current']
    if view['Class'] != 'rviz/TopDownOrtho' or float(view['Angle']) != 0.0:
        raise RuntimeError('%s: the test needs a TopDownOrtho view with Angle 0' % config_path)
    return view


class Viewport:
    """The render window's place on the screen and the TopDownOrtho view it shows."""

    def __init__(self, geometry, view):
        self.left, self.top, self.width, self.height = geometry
        self.scale = float(view['Scale'])  # pixels per metre
        self.focus = (float(view['X']), float(view['Y']))

    def pixel(self, point):
        """The screen pixel nearest to a point of the ground plane."""
        return (round(self.left + self.width / 2.0 + (point[0] - self.focus[0]) * self.scale),
                round(self.top + self.height / 2.0 - (point[1] - self.focus[1]) * self.scale))

    def metres(self, pixel):
        """The point of the ground plane a screen pixel shows."""
        return (self.focus[0] + (pixel[0] - self.left - self.width / 2.0) / self.scale,
                self.focus[1] - (pixel[1] - self.top - self.height / 2.0) / self.scale)


def render_window_geometry(rviz_window):
    """(left, top, width, height) on the screen of the rviz window's render area: Ogre's own
    unnamed child window, the largest one, or None before it exists."""
    tree = run('xwininfo', '-tree', '-id', rviz_window)
    best = None
    for line in tree.splitlines():
        match = XWININFO_LINE.match(line)
        if not match or match.group(2) != '(has no name)':
            continue
        width, height, left, top = (int(match.group(i)) for i in range(3, 7))
        if width >= 200 and height >= 200 and (best is None or width * height > best[2] * best[3]):
            best = (left, top, width, height)
    return best


class RvizAborted(RuntimeError):
    """rviz ended on a signal before its render window settled."""

    def __init__(self, message, returncode):
        super().__init__(message)
        self.returncode = returncode


def start_rviz(config_path, log_path, view):
    """An Rviz on `config_path` whose render window settled (wait_for_render_window); a start
    that ended in the known start-up abort (known_start_abort) is tried again, up to
    START_ATTEMPTS, its log kept beside `log_path` with the attempt's number; any other
    abort fails at once. The caller stops the returned Rviz."""
    attempt = 1
    while True:
        rviz = Rviz(config_path, log_path)
        try:
            rviz.wait_for_render_window(view)
            return rviz
        except RvizAborted as error:
            if not known_start_abort(error.returncode, rviz.log()):
                raise RuntimeError('rviz aborted while it started, not in the known start-up '
                                   'abort (%s); see %s' % (error, log_path)) from error
            if attempt == START_ATTEMPTS:
                raise
            os.replace(log_path, '%s.aborted-%d' % (log_path, attempt))
            print('rviz start %d aborted (%s); starting it again' % (attempt, error),
                  file=sys.stderr)
            attempt += 1
        except Exception:
            rviz.stop()
            raise


class Rviz:
    """rviz on a config, in its own process group with its output in `log_path`; once
    `wait_for_render_window` returned, `window` and `viewport` say where it is on the screen
    and the methods below click, drag and type into it."""

    def __init__(self, config_path, log_path):
        self.log_path = log_path
        self.started = time.time()
        self.window = None
        self.viewport = None
        environment = dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1')
        with open(log_path, 'w') as log:
            self.process = subprocess.Popen(['rosrun', 'rviz', 'rviz', '-d', config_path],
                                            stdout=log, stderr=subprocess.STDOUT,
                                            env=environment, start_new_session=True)

    def stop(self):
        """SIGINT to rviz's process group (rosrun execs rviz); SIGKILL after 10 s."""
        if self.process.poll() is not None:
            return
        os.killpg(self.process.pid, signal.SIGINT)
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()

    def log(self):
        with open(self.log_path) as stream:
            return stream.read()

    def wait_for_render_window(self, view):
        """Waits until rviz's render area kept its geometry over STABLE_POLLS polls (the
        splash screen and the first 640x480 layout pass), then sets `window` and `viewport`
        (showing `view`)."""
        deadline = time.time() + RVIZ_WINDOW_TIMEOUT_S
        readings = []
        while time.time() < deadline:
            if self.process.poll() is not None:
                message = 'rviz exited with %d; see %s' % (self.process.returncode,
                                                           self.log_path)
                if self.process.returncode < 0:
                    raise RvizAborted(message, self.process.returncode)
                raise RuntimeError(message)
            readings.append(self.find_render_window())
            recent = readings[-STABLE_POLLS:]
            if (len(recent) == STABLE_POLLS and recent[0] is not None
                    and recent.count(recent[0]) == STABLE_POLLS):
                self.window, geometry = recent[0]
                self.viewport = Viewport(geometry, view)
                return
            time.sleep(POLL_INTERVAL_S)
        raise RuntimeError('no settled rviz render window after %.0f s (last: %s); see %s' % (
            RVIZ_WINDOW_TIMEOUT_S, readings[-STABLE_POLLS:], self.log_path))

    def find_render_window(self):
        """(rviz window id, render area geometry) or None."""
        found = subprocess.run(['xdotool', 'search', '--onlyvisible', '--pid',
                                str(self.process.pid), '--name', 'RViz'],
                               capture_output=True, text=True)
        for window in found.stdout.split():
            try:
                geometry = render_window_geometry(window)
            except subprocess.CalledProcessError:  # the window went away meanwhile
                continue
            if geometry is not None:
                return window, geometry
        return None

    def wait_for_publishers(self, collectors):
        """Waits until every Collector's subscriber is connected to a publisher (rviz's tools
        and panels), so that no click is lost; RuntimeError after RVIZ_WINDOW_TIMEOUT_S from
        rviz's start."""
        for collector in collectors:
            while collector.subscriber.get_num_connections() == 0:
                if time.time() - self.started > RVIZ_WINDOW_TIMEOUT_S:
                    raise RuntimeError('rviz does not publish %s after %.0f s; see %s' % (
                        collector.subscriber.name, RVIZ_WINDOW_TIMEOUT_S, self.log_path))
                time.sleep(0.1)

    def focus(self):
        """Raises rviz and gives its render panel the keyboard focus: a click in the view's
        centre with the default Interact tool."""
        run('xdotool', 'windowraise', self.window)
        run('xdotool', 'windowfocus', '--sync', self.window)
        self.click(self.viewport.focus)

    def move_to(self, point):
        """Moves the pointer over a ground plane point; returns the pixel."""
        pixel = self.viewport.pixel(point)
        move_pointer(pixel)
        return pixel

    def click(self, point, button=1, modifier=None):
        """Clicks `button` on a ground plane point, holding `modifier` (an xdotool key name
        such as 'shift') if given; returns the pixel clicked."""
        pixel = self.move_to(point)
        if modifier:
            run('xdotool', 'keydown', modifier, 'click', str(button), 'keyup', modifier)
        else:
            run('xdotool', 'click', str(button))
        return pixel

    def drag(self, start, end):
        """Drags with the left button from one ground plane point to another, in DRAG_STEPS
        moves; returns the pixel released on."""
        first = self.move_to(start)
        last = self.viewport.pixel(end)
        run('xdotool', 'mousedown', '1')
        for step in range(1, DRAG_STEPS + 1):
            move_pointer((round(first[0] + (last[0] - first[0]) * step / DRAG_STEPS),
                          round(first[1] + (last[1] - first[1]) * step / DRAG_STEPS)))
        run('xdotool', 'mouseup', '1')
        return last

    @staticmethod
    def key(name):
        """Types a key (xdotool's name: 'p', 'alt+a')."""
        run('xdotool', 'key', name)

    @staticmethod
    def screenshot(path):
        run('import', '-window', 'root', path)
        print('screenshot %s' % path)
