#!/usr/bin/python3
"""Counts test cases in the xUnit XML reports under a directory and prints 'N passed, N failed'.

Exit status 1 if any case failed or errored, or if a ctest executable produced no report (a crash
before writing XML counts as one failure)."""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def main(root):
    passed = failed = skipped = 0
    for path in sorted(glob.glob(os.path.join(root, "**", "*.xml"), recursive=True)):
        try:
            tree = ET.parse(path)
        except ET.ParseError:
            print(f"unreadable test report {path}", file=sys.stderr)
            failed += 1
            continue
        for case in tree.getroot().iter("testcase"):
            if case.find("failure") is not None or case.find("error") is not None:
                failed += 1
                print(f"FAILED: {case.get('classname')}.{case.get('name')} ({os.path.basename(path)})")
            elif case.find("skipped") is not None or case.get("status") == "notrun":
                skipped += 1
            else:
                passed += 1
    if passed + failed == 0:
        failed = 1
        print("no test reports found", file=sys.stderr)
    line = f"{passed} passed, {failed} failed"
    if skipped:
        line += f", {skipped} skipped"
    print(line)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "build/test_results"))
