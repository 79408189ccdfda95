"""Runs a unittest.TestCase class and writes a JUnit-style XML report for ctest.

Shared by the Python tests under test/scripts: `junit_runner.main(TestClass, "suite", __doc__)`
gives them the command line `[--xml OUTDIR/suite.xml] [TEST ...]` and the exit status 1 on failure.
"""
import argparse
import os
import sys
import time
import unittest
import xml.etree.ElementTree as ET


class RecordingResult(unittest.TextTestResult):
    """Keeps (test id, outcome, message, seconds) of every test for the XML report."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.records = []
        self.started = time.monotonic()

    def startTest(self, test):
        self.started = time.monotonic()
        super().startTest(test)

    def record(self, test, outcome, message=""):
        self.records.append((test.id(), outcome, message, time.monotonic() - self.started))

    def addSuccess(self, test):
        super().addSuccess(test)
        self.record(test, None)

    def addFailure(self, test, err):
        super().addFailure(test, err)
        self.record(test, "failure", self._exc_info_to_string(err, test))

    def addError(self, test, err):
        super().addError(test, err)
        self.record(test, "error", self._exc_info_to_string(err, test))

    def addSkip(self, test, reason):
        super().addSkip(test, reason)
        self.record(test, "skipped", reason)


def write_junit_xml(path, suite_name, records, seconds):
    suite = ET.Element("testsuite", name=suite_name, tests=str(len(records)),
                       failures=str(sum(r[1] == "failure" for r in records)),
                       errors=str(sum(r[1] == "error" for r in records)),
                       skipped=str(sum(r[1] == "skipped" for r in records)), time=f"{seconds:.3f}")
    for test_id, outcome, message, duration in records:
        classname, _, name = test_id.rpartition(".")
        classname = classname.replace("__main__", suite_name, 1)
        case = ET.SubElement(suite, "testcase", classname=classname, name=name,
                             time=f"{duration:.3f}")
        if outcome:
            element = ET.SubElement(case, outcome, message=message.strip().splitlines()[-1]
                                    if message.strip() else outcome)
            element.text = message
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def main(test_class, suite_name, doc, argv=None, paths=None):
    """paths: {"--option": help} of required path options the tests need (e.g. "--tvd"); each
    sets the test module's global named after it in capitals ("--env-sh" -> ENV_SH) to the
    absolute path."""
    parser = argparse.ArgumentParser(description=(doc or "").split("\n")[0])
    parser.add_argument("--xml", help="write a JUnit-style XML report to this file")
    parser.add_argument("tests", nargs="*", help="test method names (default: all)")
    for option, help_text in (paths or {}).items():
        parser.add_argument(option, required=True, help=help_text)
    args = parser.parse_args(argv)
    module = sys.modules[test_class.__module__]
    for option in paths or {}:
        dest = option.lstrip("-").replace("-", "_")
        setattr(module, dest.upper(), os.path.abspath(getattr(args, dest)))
    loader = unittest.defaultTestLoader
    suite = (loader.loadTestsFromNames([f"{test_class.__name__}.{t}" for t in args.tests], module)
             if args.tests else loader.loadTestsFromTestCase(test_class))
    start = time.monotonic()
    result = unittest.TextTestRunner(resultclass=RecordingResult, verbosity=2).run(suite)
    if args.xml:
        write_junit_xml(args.xml, suite_name, result.records, time.monotonic() - start)
    return 0 if result.wasSuccessful() else 1
