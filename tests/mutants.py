#!/usr/bin/env python3
"""Mutation score of the test suite on randomly drawn single-point mutants of src/.

Not hand-picked, unlike tests/mistakes.sh: the mutants are drawn at random (with a seed) from
every site in src/**/*.cpp and src/**/*.hpp where one of these mutations applies, outside
comments, string and character literals and preprocessor lines:

  arith    a binary + - * / (written with a blank on each side) swapped for another of them
  compare  a comparison < <= > >= == != (blanks on each side) swapped for another of them
  constant a number: an integer +1 or -1, a floating-point one doubled or negated
  index    an index expression [e + 1] or [e - 1] made [e]
  logical  && and || swapped

A kind is drawn first (uniformly among the kinds that have sites), then a site of that kind and
the replacement, so that the many arithmetic sites do not crowd out the rarer kinds. The same
seed and the same HEAD give the same mutants.

Each mutant is applied to a scratch copy of the repository, never to the working tree: a
`git worktree` of HEAD (committed work only: the sites are drawn from HEAD's files too) in a
temporary folder, built in its own build
folder (Release, ccache when installed). For each mutant the mutated file is written, gbssn1d
and gbssn1d_tests are built, the tests run with a time limit, and the file is put back:

  not compilable  the build fails (excluded from the score)
  caught          a test fails, crashes or runs out of time
  survived        every test passes
  likely equivalent
                  survived, and every reference run (below) writes output bit-identical to the
                  unmutated build's: the report names the runs that show it. A survived mutant
                  whose reference output differs is reported as survived, naming the first run
                  and file that differ (a difference the tests do not see).

score = caught / (caught + survived + likely equivalent); the score without the likely
equivalent ones is printed as well.

Tests run (--suite):
  doctest (default)  every doctest case (ctest -LE script: the cases of tests/*/test_*.cpp), in
                     parallel with -j, stopping at the first failure
  ctest              the whole ctest suite, scripts included (the CLI fuzzer, the README
                     examples, the plot scripts: several minutes more per mutant)
  --filter PATTERN   only the doctest cases whose name matches ctest's -R PATTERN (for a quick
                     look; a score from a subset says little)

Reference runs: three short evolutions (the 1+log trumpet on a uniform grid with the horizon
shift, wormhole data on boxes with quadratic time interpolation, the maximal trumpet with
--upwind biased at 6th order), each compared file by file with the unmutated build's output.

Usage:
  tests/mutants.py [--seed 1] [--count 60] [--suite doctest|ctest] [--filter PATTERN]
                   [--jobs N] [--timeout SECONDS] [--report FILE] [--keep] [--list]

  --list       only draw and print the mutants (nothing is built)
  --report     the report (default: mutants-seed<seed>.txt in the current folder); written
               after each mutant, so that an interrupted run keeps what it has
  --keep       keep the scratch worktree (its path is printed)
  --scratch DIR  the scratch worktree's folder (default: a fresh temporary one). ccache keys on
               the source paths, so a run in the same DIR as an earlier one compiles from the
               cache; DIR is made afresh (a worktree of HEAD) and removed at the end unless --keep

Time (measured on 2 cores, seed 1, 8 mutants: 660 s in all): the first build of the scratch
copy about 6 minutes (less when ccache holds its objects, e.g. a second run with the same
--scratch), the unmutated doctest suite and reference runs about 1 minute. Then per mutant
4-60 s: the rebuild (4-20 s for a .cpp file or a small header, about 40 s for the point loop's
rhs_loop.hpp, more for a header that most of the library includes), plus the tests: a caught
mutant stops at the first failing case (0-30 s), a survived one runs every doctest case (about
40 s) and the reference runs (about 10 s). A 60-mutant run: about 1 hour with --suite doctest,
several hours with --suite ctest.
"""

import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent

ARITH = ["+", "-", "*", "/"]
COMPARE = ["<", "<=", ">", ">=", "==", "!="]

REFERENCE_RUNS = [
    ("trumpet, uniform grid, horizon shift",
     ["evolve", "--id", "1log-trumpet", "--grid", "uniform", "--N", "120", "--rmax", "24",
      "--tmax", "2", "--dt-series", "0.5", "--dt-profiles", "1", "--rahA", "0.5", "--rah0", "1"]),
    ("wormhole on boxes, quadratic time interpolation",
     ["evolve", "--id", "wormhole", "--grid", "boxes", "--levels", "3", "--N", "24", "--rmax",
      "24", "--time-interp", "quadratic", "--cfl", "0.25", "--tmax", "2", "--dt-series", "0.5",
      "--dt-profiles", "1"]),
    ("maximal trumpet, --upwind biased, 6th order",
     ["evolve", "--id", "maximal-trumpet", "--grid", "sinh", "--dr-inner", "0.05", "--N", "120",
      "--rmax", "30", "--fd-order", "6", "--upwind", "biased", "--tmax", "2", "--dt-series",
      "0.5", "--dt-profiles", "1"]),
]


def masked(text):
    """The text with comments, string and character literals and preprocessor lines replaced
    by blanks (newlines kept), so that mutation sites are searched in code only."""
    out = list(text)
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":  # a preprocessor line, with its continuations
            j = i
            while j < n and not (text[j] == "\n" and text[j - 1] != "\\"):
                j += 1
            for k in range(i, j):
                if out[k] != "\n":
                    out[k] = " "
            i = j
            continue
        if c == "\n":
            line_start = True
            i += 1
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j += 1
        else:
            i += 1
            continue
        for k in range(i, min(j, n)):
            if out[k] != "\n":
                out[k] = " "
        i = j
    return "".join(out)


def sites(path, text):
    """Every (kind, start, end, original, [replacements]) of one file."""
    code = masked(text)
    found = []
    # binary operators written with a blank on each side (clang-format's spacing); not part of
    # a longer operator (+=, ->, <<, >>, <=>)
    for m in re.finditer(r"(?<=[\w)\]]) ([-+*/]) (?=[\w(.!-])", code):
        op = m.group(1)
        found.append(("arith", m.start(1), m.end(1), op, [o for o in ARITH if o != op]))
    for m in re.finditer(r"(?<=[\w)\]]) (<=|>=|==|!=|<|>) (?=[\w(.!-])", code):
        op = m.group(1)
        found.append(("compare", m.start(1), m.end(1), op, [o for o in COMPARE if o != op]))
    for m in re.finditer(r"(?<![\w.])(\d+\.\d*(?:[eE][-+]?\d+)?|\d+[eE][-+]?\d+|\.\d+(?:[eE][-+]?\d+)?|\d+)([uUlLfF]*)(?![\w.])", code):
        lit = m.group(1)
        if re.fullmatch(r"\d+", lit):
            v = int(lit)
            if len(lit) > 1 and lit[0] == "0":
                continue  # octal: leave alone
            reps = [str(v + 1)] + ([str(v - 1)] if v > 0 else [])
        else:
            v = float(lit)
            reps = [repr(2.0 * v), "-" + lit] if v != 0.0 else ["1.0"]
        found.append(("constant", m.start(1), m.end(1), lit, reps))
    for m in re.finditer(r"\[([^\[\]\n]+?) ([-+]) 1\]", code):
        found.append(("index", m.start(0), m.end(0), text[m.start(0):m.end(0)],
                      ["[" + text[m.start(1):m.end(1)] + "]"]))
    for m in re.finditer(r" (&&|\|\|) ", code):
        op = m.group(1)
        found.append(("logical", m.start(1), m.end(1), op, ["||" if op == "&&" else "&&"]))
    return found


def draw(repo, seed, count):
    """`count` distinct mutants drawn with `seed`: (file, line, kind, start, end, original,
    replacement)."""
    # HEAD's files (the scratch copy is HEAD: uncommitted edits are not drawn from)
    listed = subprocess.run(["git", "-C", str(repo), "ls-tree", "-r", "--name-only", "HEAD",
                             "src"], check=True, capture_output=True, text=True).stdout.split()
    files = sorted(f for f in listed if f.endswith((".cpp", ".hpp")))
    by_kind = {}
    texts = {}
    for rel in files:
        texts[rel] = subprocess.run(["git", "-C", str(repo), "show", "HEAD:" + rel], check=True,
                                    capture_output=True, text=True).stdout
        for s in sites(rel, texts[rel]):
            by_kind.setdefault(s[0], []).append((rel,) + s)
    rng = random.Random(seed)
    kinds = sorted(by_kind)
    chosen, seen = [], set()
    while len(chosen) < count and len(seen) < sum(len(v) for v in by_kind.values()) * 2:
        kind = rng.choice(kinds)
        rel, _, start, end, original, reps = rng.choice(by_kind[kind])
        replacement = rng.choice(reps)
        key = (rel, start, replacement)
        seen.add(key)
        if key in {(c[0], c[3], c[6]) for c in chosen}:
            continue
        line = texts[rel].count("\n", 0, start) + 1
        chosen.append((rel, line, kind, start, end, original, replacement))
    return chosen, texts, {k: len(v) for k, v in by_kind.items()}


def run(cmd, cwd, timeout=None, log=None):
    """(returncode, seconds, output); returncode None on timeout."""
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, timeout=timeout, errors="replace")
        return p.returncode, time.time() - t0, p.stdout
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        return None, time.time() - t0, out


def build(work, jobs):
    code, secs, out = run(["cmake", "--build", "build", "-j", str(jobs), "--target", "gbssn1d",
                           "gbssn1d_tests"], work)
    return code == 0, secs, out


def test(work, args):
    """(caught, seconds, why)."""
    cmd = ["ctest", "--test-dir", "build", "-j", str(args.jobs), "--timeout", str(args.timeout),
           "--stop-on-failure", "--output-on-failure"]
    if args.suite == "doctest":
        cmd += ["-LE", "script"]
    if args.filter:
        cmd += ["-R", args.filter]
    # the whole suite's time limit: the per-test limit is ctest's --timeout
    code, secs, out = run(cmd, work, timeout=args.timeout * 4 + 600)
    if code is None:
        return True, secs, "timeout of the suite"
    if code == 0:
        return False, secs, ""
    failed = re.findall(r"^\s*\d+ - (.*) \((Failed|Timeout|SEGFAULT|Subprocess aborted|[^()]*)\)$",
                        out, re.M)
    why = "; ".join(f"{name} ({how})" for name, how in failed[:3]) or out.strip()[-300:]
    return True, secs, why


def reference_outputs(work, tag):
    """Runs the reference evolutions with the scratch build's binary into build/ref/ (the same
    folders for the unmutated and the mutated binary, whose paths the outputs record; `tag` only
    names the runs in errors): {run name: (exit status, {file: bytes})}."""
    exe = work / "build" / "gbssn1d"
    results = {}
    for name, argv in REFERENCE_RUNS:
        out = work / "build" / "ref" / re.sub(r"\W+", "_", name)
        shutil.rmtree(out, ignore_errors=True)
        code, _, text = run([str(exe)] + argv + ["--out", str(out), "--force"], work, timeout=300)
        files = {}
        if out.is_dir():
            for f in sorted(out.rglob("*")):
                # the run's own facts (wall times, dates, versions) are not its results
                if f.is_file() and f.name not in (".gbssn1d.lock", "checkpoint.bin"):
                    data = f.read_bytes()
                    files[str(f.relative_to(out))] = b"\n".join(
                        l for l in data.split(b"\n")
                        if not re.match(rb"#\s*(wall|date|host|gbssn1d |elapsed|speed)", l))
        results[name] = (code, files)
    return results


def compare(reference, mutant):
    """None if every reference run is bit-identical, else the first difference."""
    for name, (code, files) in reference.items():
        mcode, mfiles = mutant[name]
        if mcode != code:
            return f"{name}: exit {mcode} (unmutated {code})"
        for f in sorted(set(files) | set(mfiles)):
            if files.get(f) != mfiles.get(f):
                return f"{name}: {f} differs"
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=60)
    ap.add_argument("--suite", choices=["doctest", "ctest"], default="doctest")
    ap.add_argument("--filter", default="")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--timeout", type=int, default=900, help="per test, seconds")
    ap.add_argument("--report", default="")
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--scratch", default="")
    args = ap.parse_args()
    report = Path(args.report or f"mutants-seed{args.seed}.txt").resolve()

    mutants, texts, counts = draw(REPO, args.seed, args.count)
    print(f"sites per kind: {counts}")
    for k, (rel, line, kind, _, _, orig, rep) in enumerate(mutants, 1):
        print(f"{k:3d} {rel}:{line} {kind}: {orig} -> {rep}")
    if args.list:
        return 0

    if args.scratch:
        tmp = Path(args.scratch).resolve()
        subprocess.run(["git", "-C", str(REPO), "worktree", "remove", "--force", str(tmp / "src")],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        shutil.rmtree(tmp, ignore_errors=True)
        tmp.mkdir(parents=True)
    else:
        tmp = Path(tempfile.mkdtemp(prefix="gbssn1d-mutants-"))
    work = tmp / "src"
    subprocess.run(["git", "-C", str(REPO), "worktree", "add", "-q", "--detach", str(work), "HEAD"],
                   check=True)
    rows, counts_by_class = [], {}
    started = time.time()
    try:
        for rel in texts:  # the drawn sites are of HEAD's files, as the worktree holds them
            assert (work / rel).read_text() == texts[rel], rel
        launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
        subprocess.run(["cmake", "-S", ".", "-B", "build", "-DCMAKE_BUILD_TYPE=Release"]
                       + launcher, cwd=work, check=True, stdout=subprocess.DEVNULL)
        ok, secs, out = build(work, args.jobs)
        if not ok:
            sys.exit("the unmutated copy does not build:\n" + out[-3000:])
        print(f"unmutated build: {secs:.0f} s", flush=True)
        caught, secs, why = test(work, args)
        if caught:
            sys.exit(f"the unmutated copy fails its tests: {why}")
        print(f"unmutated tests: {secs:.0f} s", flush=True)
        reference = reference_outputs(work, "unmutated")
        for name, (code, files) in reference.items():
            print(f"reference run '{name}': exit {code}, {len(files)} files", flush=True)

        for k, (rel, line, kind, start, end, orig, rep) in enumerate(mutants, 1):
            t0 = time.time()
            text = texts[rel]
            (work / rel).write_text(text[:start] + rep + text[end:])
            detail = ""
            try:
                ok, build_s, out = build(work, args.jobs)
                if not ok:
                    cls, test_s = "not compilable", 0.0
                    errors = [l for l in out.splitlines() if "error" in l]
                    detail = errors[0].strip()[:200] if errors else ""
                else:
                    caught, test_s, why = test(work, args)
                    if caught:
                        cls, detail = "caught", why
                    else:
                        diff = compare(reference, reference_outputs(work, "mutant"))
                        if diff is None:
                            cls = "likely equivalent"
                            detail = "bit-identical output: " + ", ".join(
                                n for n, _ in REFERENCE_RUNS)
                        else:
                            cls, detail = "survived", diff
            finally:
                (work / rel).write_text(text)
            counts_by_class[cls] = counts_by_class.get(cls, 0) + 1
            secs = time.time() - t0
            rows.append(f"{k:3d} | {rel}:{line} | {kind} | {orig} -> {rep} | {cls} | "
                        f"build {build_s:.0f} s, tests {test_s:.0f} s, total {secs:.0f} s | "
                        f"{detail}")
            print(rows[-1], flush=True)
            write_report(report, args, rows, counts_by_class, started, k)
    finally:
        if args.keep:
            print(f"scratch worktree kept: {work}")
        else:
            subprocess.run(["git", "-C", str(REPO), "worktree", "remove", "--force", str(work)],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            shutil.rmtree(tmp, ignore_errors=True)
    print(f"report: {report}")
    return 0


def write_report(path, args, rows, counts, started, done):
    caught = counts.get("caught", 0)
    survived = counts.get("survived", 0)
    equivalent = counts.get("likely equivalent", 0)
    judged = caught + survived + equivalent
    score = f"{caught}/{judged} = {caught / judged:.2f}" if judged else "n/a"
    strict = (f"{caught}/{caught + survived} = {caught / (caught + survived):.2f}"
              if caught + survived else "n/a")
    elapsed = time.time() - started
    lines = [
        f"# gbssn1d mutation score: seed {args.seed}, {done} of {args.count} mutants, suite "
        f"{args.suite}{' -R ' + args.filter if args.filter else ''}, timeout {args.timeout} s",
        f"# classes: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())),
        f"# score caught / (caught + survived + likely equivalent): {score}",
        f"# score without the likely equivalent: {strict}",
        f"# time: {elapsed:.0f} s in all, {elapsed / max(done, 1):.0f} s per mutant (the "
        f"unmutated build and tests included)",
        "# n | file:line | kind | original -> mutant | class | time | detail",
    ]
    path.write_text("\n".join(lines + rows) + "\n")


if __name__ == "__main__":
    sys.exit(main())
