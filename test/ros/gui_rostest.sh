#!/usr/bin/env bash
# Runs a GUI rostest (the command after RESULT), or, without a DISPLAY, reports it skipped:
# writes RESULT, the JUnit file run_tests.py checks, with one skipped test (which
# catkin_test_results counts as skipped) and exits 77 (ctest's SKIP_RETURN_CODE for it).
#   test/ros/gui_rostest.sh RESULT rostest ARGUMENTS...
set -euo pipefail
result=$1
shift
if [ -n "${DISPLAY:-}" ]; then exec "$@"; fi
message="no DISPLAY: this GUI test drives rviz with xdotool; run it under xvfb-run -a -s \"-screen 0 1280x1024x24\""
mkdir -p "$(dirname "$result")"
cat >"$result" <<XML
<?xml version="1.0" encoding="utf-8"?>
<testsuite name="$(basename "$result" .xml)" tests="1" errors="0" failures="0" skipped="1">
  <testcase classname="rostest" name="$(basename "$result" .xml)"><skipped message="no DISPLAY"/></testcase>
</testsuite>
XML
echo "SKIPPED: $message" >&2
exit 77
