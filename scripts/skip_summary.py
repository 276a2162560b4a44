#!/usr/bin/env python3
"""Lists the tests a ctest run skipped or left disabled, each with its reason, then the run's
counts on one closing line ("tests: N passed, N failed, N skipped").

ctest --output-on-failure shows the output of failed tests only, so the line a skipped test
prints (e.g. how to provide Sponza) would never reach the user. scripts/test.sh runs ctest
with --output-junit and then this script over the JUnit file.

usage: skip_summary.py RESULTS.xml
"""
import sys
import xml.etree.ElementTree as ElementTree


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


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    try:
        root = ElementTree.parse(argv[1]).getroot()
    except (OSError, ElementTree.ParseError) as error:
        print(f"skip_summary: {argv[1]}: {error}", file=sys.stderr)
        return 2
    skipped = []
    passed = failed = 0
    for case in root.iter("testcase"):
        status = case.get("status", "")
        if status == "run":
            passed += 1
        elif status == "fail":
            failed += 1
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
    print(f"tests: {passed} passed, {failed} failed, {len(skipped)} skipped")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
