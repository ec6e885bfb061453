#!/usr/bin/env python3
"""Checks asan-skip.txt before `make test-asan` runs (one ctest listing per build folder).

Every name must be a test of the ASan build, or a test, in the Release build, of a program the
ASan build leaves unbuilt (kestrel_add_test ASAN_SKIPPED: ASAN_BUILD/asan-unbuilt-tests.txt); and
every test of such a program must be listed, so that a rename or a new test cannot quietly leave
ASan or come back. Without a built Release build those names cannot be checked: a note.
Usage: check_asan_skip.py SKIP_FILE ASAN_BUILD [RELEASE_BUILD]
"""
import json
import os
import subprocess
import sys


def tests_of(build):
    """{test name: the file name of the program it runs}."""
    out = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"], check=True,
                         capture_output=True, text=True).stdout
    return {t["name"]: os.path.basename((t.get("command") or [""])[0]) for t in json.loads(out)["tests"]}


def main(skip_file, asan_build, release_build=None):
    with open(skip_file) as f:
        names = [line.strip() for line in f if line.strip() and not line.startswith("#")]
    asan = tests_of(asan_build)
    unbuilt_file = os.path.join(asan_build, "asan-unbuilt-tests.txt")
    unbuilt = set(open(unbuilt_file).read().split()) if os.path.exists(unbuilt_file) else set()
    release = None
    if unbuilt and release_build and os.path.exists(os.path.join(release_build, "CTestTestfile.cmake")):
        release = tests_of(release_build)
        if not any(program in unbuilt for program in release.values()):
            release = None  # configured, but its test programs are not built (make product)
    errors = []
    for name in names:
        if name in asan:
            continue
        if release is None and unbuilt:
            print(f"check_asan_skip: {name} is not a test of {asan_build}; no Release build to find it in",
                  file=sys.stderr)
        elif release is None or release.get(name) not in unbuilt:
            errors.append(f"asan-skip.txt names no such test: {name}")
    for name, program in sorted((release or {}).items()):
        if program in unbuilt and name not in names:
            errors.append(f"{name} is a test of {program}, which the ASan build does not build "
                          "(ASAN_SKIPPED), but asan-skip.txt does not list it with a reason")
    for error in errors:
        print(f"test-asan: {error}", file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__.strip().splitlines()[-1])
    sys.exit(main(*sys.argv[1:]))
