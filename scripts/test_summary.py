#!/usr/bin/env python3
"""Closes a ctest run with what a reader of its last lines needs: the tests it skipped or left
disabled, each with its reason; the telling lines of each failed test's output; then the
run's counts on one line ("tests: N passed, N failed, N skipped").

ctest --output-on-failure shows the output of failed tests only, so the line a skipped test
prints (e.g. how to provide Sponza) would never reach the user; and a failed test's output
is printed where the test ended, often thousands of lines above the end of a CI log, which
may keep only its tail. A fuzzer's crash, for one, is reproducible only from the lines
saying what broke and the input that broke it. scripts/test.sh runs ctest with
--output-junit and then this script over the JUnit file.

usage: test_summary.py RESULTS.xml
"""
import re
import sys
import xml.etree.ElementTree as ElementTree

# Lines that say what broke: GoogleTest failures, sanitizer and libFuzzer reports (with the
# crashing input in base64 when it is small, and the stack frames in the project's own
# code), CTest's own timeout.
TELLING = re.compile(
    r"Failure$|^Expected|^  Actual|Which is:|Value of:|==ERROR|^SUMMARY:|runtime error:|"
    r"Test unit written|^Base64:|ALARM|out-of-memory|deadly signal|Timeout|^voxatlas[^:]*:|"
    r"^\s+#\d+ 0x[0-9a-f]+ in .*/(src|tests)/")
MAX_TELLING_LINES = 12
MAX_LINE = 400


def skip_reason(output):
    """The message a GoogleTest GTEST_SKIP() printed: the lines after 'file:line: Skipped'."""
    lines = output.splitlines()
    for index, line in enumerate(lines):
        if line.rstrip().endswith(": Skipped"):
            reason = []
            for following in lines[index + 1:]:
                if following.startswith("[  SKIPPED ]"):
                    break
                reason.append(following.strip())
            return " ".join(part for part in reason if part) or "no reason given"
    return None


def telling_lines(output):
    """The first lines of a failed test's output that say what broke, each cut to MAX_LINE."""
    found = [line.rstrip()[:MAX_LINE] for line in output.splitlines()
             if TELLING.search(line.rstrip())]
    return found[:MAX_TELLING_LINES]


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    try:
        root = ElementTree.parse(argv[1]).getroot()
    except (OSError, ElementTree.ParseError) as error:
        print(f"test_summary: {argv[1]}: {error}", file=sys.stderr)
        return 2
    skipped = []
    failures = []
    passed = 0
    for case in root.iter("testcase"):
        status = case.get("status", "")
        if status == "run":
            passed += 1
        elif status == "fail":
            failures.append((case.get("name"), telling_lines(case.findtext("system-out") or "")))
        if status not in ("notrun", "disabled"):
            continue
        output = case.findtext("system-out") or ""
        reason = skip_reason(output)
        if reason is None:
            marker = case.find("skipped")
            reason = "disabled in its source" if status == "disabled" else (
                marker.get("message") if marker is not None else "not run")
        skipped.append((case.get("name"), reason))
    if skipped:
        print(f"Skipped tests ({len(skipped)}), with their reasons:")
        for name, reason in skipped:
            print(f"  {name}: {reason}")
    else:
        print("Skipped tests: none")
    for name, lines in failures:
        print(f"Failed: {name}")
        for line in lines or ["(no line of its output says what broke; see its full output above)"]:
            print(f"  {line}")
    print(f"tests: {passed} passed, {len(failures)} failed, {len(skipped)} skipped")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
