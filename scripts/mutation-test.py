#!/usr/bin/python3
"""Mutation testing: plants each catalogued bug in turn and checks the tests catch it.

The catalogue is tests/mutants/<area>/<name>.patch: a few header lines, then
a unified diff against the tree.

    Bug: what the planted bug does, in one line
    Tests: materials_tests:MicrofacetAlbedo.*:Microfacet.*  integrators_tests
    Equivalent: why no expected value can change (such mutants are listed, not run)

Each test is a test executable, optionally with a GoogleTest filter after
the first colon, or mpi:PATTERN for the tests/mpi tests whose names contain
PATTERN, run under mpirun against the mutant's caustica. The script keeps a scratch copy of the tree in
build-mutants/tree, builds it incrementally in build-mutants/build, applies
each patch there, rebuilds the named executables, runs them, reverts the
patch, and prints caught or survived with the tests that failed, then the
score. It is not part of the test command: it takes about a minute per
mutant on two cores after a first full build.

    scripts/mutation-test.py                 # the whole catalogue
    scripts/mutation-test.py materials/      # the mutants whose name starts so
    scripts/mutation-test.py --refresh       # rewrite the patches against the tree
    scripts/mutation-test.py --add NAME FILE --bug TEXT --tests TESTS  # OLD on stdin, then a line '====', then NEW

Documentation checks never catch a mutant: tests that compare parameter
defaults or descriptions as text (DOC_CHECKS below) are left out of every
run, so a bug they alone would notice counts as survived.

Patches apply by their context, so they survive code moving around them;
--refresh rewrites them with the tree's line numbers and context, and names
those whose lines have changed so much that they no longer apply.
"""

import argparse
import difflib
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CATALOGUE = ROOT / "tests" / "mutants"
SCRATCH = ROOT / "build-mutants"
TREE = SCRATCH / "tree"
BUILD = SCRATCH / "build"
# GoogleTest patterns of documentation checks: docs/plugins.md's tables
# against the declarations, and every declaration having its text.
DOC_CHECKS = ["ParameterTables.*"]


class Mutant:
    def __init__(self, path):
        self.path = path
        self.name = str(path.relative_to(CATALOGUE).with_suffix(""))
        text = path.read_text()
        head, sep, diff = text.partition("\ndiff ")
        if not sep:
            head, sep, diff = text.partition("\n--- ")
            diff = "--- " + diff
        else:
            diff = "diff " + diff
        self.diff = diff
        self.header = head.strip() + "\n"
        fields = dict(re.findall(r"^(\w+):[ \t]*(.*)$", head, re.M))
        self.bug = fields.get("Bug", "")
        self.tests = fields.get("Tests", "").split()
        self.equivalent = fields.get("Equivalent")
        self.files = re.findall(r"^\+\+\+ b/(\S+)", diff, re.M)
        if not self.bug or not self.files or not (self.tests or self.equivalent):
            sys.exit(f"{path}: needs Bug:, Tests: (or Equivalent:) and a diff")


def tracked_files():
    out = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT, check=True,
                         capture_output=True).stdout
    return [f for f in out.decode().split("\0") if f and not f.startswith("tests/mutants/")]


def sync_tree():
    """Copies into the scratch tree only what differs, so builds stay incremental."""
    wanted = set(tracked_files())
    for rel in wanted:
        src, dst = ROOT / rel, TREE / rel
        if src.is_symlink() or not src.is_file():
            continue
        if dst.is_file() and dst.read_bytes() == src.read_bytes():
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(src, dst)  # a fresh time stamp: whatever was built from this path is rebuilt
    for dst in list(TREE.rglob("*")):
        if dst.is_file() and str(dst.relative_to(TREE)) not in wanted:
            dst.unlink()


def apply(mutant):
    # Offsets are fine; fuzz could plant the bug on a similar line elsewhere.
    args = ["patch", "-p1", "--forward", "--silent", "--fuzz=0", "--no-backup-if-mismatch", "-r", "-", "-d", str(TREE)]
    return subprocess.run(args, input=mutant.diff, text=True, capture_output=True).returncode == 0


def saved(mutant):
    return {f: (TREE / f).read_bytes() for f in mutant.files}


def restore(files):
    """Writes the files back as they were before the mutant; the fresh time
    stamps make the next build recompile them."""
    for f, data in files.items():
        (TREE / f).write_bytes(data)


class SpecRun:
    def __init__(self, failing, failed, tests_run):
        self.failing, self.failed, self.tests_run = failing, failed, tests_run


def target_of(spec):
    """The build target a test selection needs: its executable, or caustica for mpi:NAME (tests/mpi, under mpirun)."""
    exe = spec.partition(":")[0]
    return "caustica" if exe == "mpi" else exe


def run_python_tests(pattern, timeout):
    """Runs the tests/mpi tests whose names contain `pattern` against the mutant's caustica."""
    cmd = ["/usr/bin/python3", "-m", "unittest", "discover", "-s", str(TREE / "tests" / "mpi"), "-p", "*_test.py",
           "-k", pattern]
    env = dict(os.environ, CAUSTICA_BINARY=str(BUILD / "caustica"))
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=TREE, env=env)
    except subprocess.TimeoutExpired:
        return SpecRun(True, [f"mpi:{pattern} (timed out)"], 0)
    ran = re.search(r"^Ran (\d+) tests?", r.stderr, re.M)
    names = re.findall(r"^(?:FAIL|ERROR): (\w+)", r.stderr, re.M)
    return SpecRun(r.returncode != 0, sorted(set(names)) or ([f"mpi (exit {r.returncode})"] if r.returncode else []),
                   int(ran.group(1)) if ran else 0)


def without_doc_checks(gtest_filter):
    """The filter with DOC_CHECKS excluded (added to its negative part, if it has one)."""
    positive, _, negative = (gtest_filter or "*").partition("-")
    return positive + "-" + ":".join(([negative] if negative else []) + DOC_CHECKS)


def run_tests_spec(spec, timeout):
    """Runs one executable[:filter] (or mpi:PATTERN): whether it failed, what failed, how many tests ran."""
    exe, _, gtest_filter = spec.partition(":")
    if exe == "mpi":
        return run_python_tests(gtest_filter, timeout)
    cmd = [str(BUILD / "tests" / exe), "--gtest_filter=" + without_doc_checks(gtest_filter)]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=TREE)
    except subprocess.TimeoutExpired:
        return SpecRun(True, [f"{exe} (timed out)"], 0)
    ran = re.search(r"^\[==========\] (\d+) tests? from .* ran\.", r.stdout, re.M)
    tests_run = int(ran.group(1)) if ran else 0
    if r.returncode == 0:
        return SpecRun(False, [], tests_run)
    names = re.findall(r"^\[  FAILED  \] ([\w/.]+)(?:,|$| \()", r.stdout, re.M)
    return SpecRun(True, sorted(set(names)) or [f"{exe} (exit {r.returncode})"], tests_run)


def run_tests(mutant, timeouts):
    failed, caught = [], False
    for spec in mutant.tests:
        run = run_tests_spec(spec, timeouts[spec])
        caught |= run.failing
        failed += run.failed
    return caught, failed


def build(targets, jobs):
    r = subprocess.run(["cmake", "--build", str(BUILD), "--parallel", str(jobs), "--target", *targets],
                       capture_output=True, text=True)
    return r.returncode == 0, r.stdout + r.stderr


def refresh(mutants):
    stale = []
    sync_tree()
    for m in mutants:
        original = saved(m)
        applied = apply(m)
        after = {f: (TREE / f).read_text() for f in m.files}
        restore(original)
        if not applied:
            stale.append(m.name)
            continue
        before = {f: data.decode() for f, data in original.items()}
        diff = "".join(
            "".join(difflib.unified_diff(before[f].splitlines(True), after[f].splitlines(True), f"a/{f}", f"b/{f}"))
            for f in m.files)
        m.path.write_text(m.header + "\n" + diff)
    return stale


def add(name, file, bug, tests):
    old, sep, new = sys.stdin.read().partition("\n====\n")
    if not sep:
        sys.exit("stdin: the original text, a line '====', then the mutated text")
    text = (ROOT / file).read_text()
    if text.count(old) != 1:
        sys.exit(f"{file}: the original text occurs {text.count(old)} times, not once")
    mutated = text.replace(old, new.rstrip("\n") + ("\n" if old.endswith("\n") else ""))
    diff = "".join(difflib.unified_diff(text.splitlines(True), mutated.splitlines(True), f"a/{file}", f"b/{file}"))
    path = CATALOGUE / (name + ".patch")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"Bug: {bug}\nTests: {tests}\n\n{diff}")
    print(path.relative_to(ROOT))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("prefix", nargs="*", help="run only mutants whose name starts with one of these")
    ap.add_argument("--refresh", action="store_true")
    ap.add_argument("--add", nargs=2, metavar=("NAME", "FILE"))
    ap.add_argument("--bug")
    ap.add_argument("--tests")
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--timeout", type=int, default=900, help="seconds for each test selection's unmutated run")
    args = ap.parse_args()
    if args.add:
        if not args.bug or not args.tests:
            ap.error("--add needs --bug and --tests")
        return add(*args.add, args.bug, args.tests)

    mutants = [Mutant(p) for p in sorted(CATALOGUE.rglob("*.patch"))]
    if args.prefix:
        mutants = [m for m in mutants if any(m.name.startswith(p) for p in args.prefix)]
    TREE.mkdir(parents=True, exist_ok=True)
    if args.refresh:
        stale = refresh(mutants)
        print(f"refreshed {len(mutants) - len(stale)} patches" + (f"; no longer apply: {', '.join(stale)}" if stale else ""))
        return 1 if stale else 0

    sync_tree()
    subprocess.run(["cmake", "-S", str(TREE), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release"], check=True,
                   capture_output=True)
    runnable = [m for m in mutants if not m.equivalent]
    targets = sorted({target_of(t) for m in runnable for t in m.tests})
    ok, log = build(targets, args.jobs)
    if not ok:
        sys.exit("the unmutated tree does not build:\n" + log[-3000:])
    specs = sorted({t for m in runnable for t in m.tests})
    print(f"running the {len(specs)} named test selections without any mutant", flush=True)
    # A mutant may make tests slower, or hang them: each selection gets five
    # times its unmutated time, and half a minute.
    timeouts = {}
    for spec in specs:
        start = time.time()
        run = run_tests_spec(spec, args.timeout)
        if run.failing:
            sys.exit(f"{spec} fails without any mutant: {', '.join(run.failed)}")
        if run.tests_run == 0:
            sys.exit(f"{spec} runs no test: its filter matches nothing")
        timeouts[spec] = 5 * (time.time() - start) + 30

    results = []
    for m in runnable:
        start = time.time()
        original = saved(m)
        if not apply(m):
            status, detail = "does not apply", "run --refresh, or rewrite the patch"
        else:
            ok, log = build(sorted({target_of(t) for t in m.tests}), args.jobs)
            if not ok:
                status, detail = "does not compile", ""
            else:
                caught, failed = run_tests(m, timeouts)
                status, detail = ("caught", ", ".join(failed)) if caught else ("SURVIVED", "")
        restore(original)
        results.append((m, status, detail))
        print(f"{status:16} {m.name:48} {time.time() - start:5.0f} s  {detail}", flush=True)

    counted = [r for r in results if r[1] in ("caught", "SURVIVED")]
    caught = sum(r[1] == "caught" for r in counted)
    print()
    for m in mutants:
        if m.equivalent:
            print(f"equivalent       {m.name:48} {m.equivalent}")
    for m, status, _ in results:
        if status == "SURVIVED":
            print(f"survived         {m.name:48} {m.bug}")
    print(f"\nscore: {caught} of {len(counted)} non-equivalent mutants caught"
          + (f" ({100.0 * caught / len(counted):.0f} %)" if counted else "")
          + f"; {sum(1 for m in mutants if m.equivalent)} equivalent"
          + (f"; {len(results) - len(counted)} did not apply or compile" if len(results) > len(counted) else ""))
    return 0 if caught == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
