#!/usr/bin/env python3
"""Fuzzer of the study scripts (runs/*.sh): each script driven with hostile settings and
interrupted at a drawn moment, then run again, with the invariants of runs/lib.sh checked after
every step. Runs on the real binary and the real scripts; the drawn moments and settings come
from --seed, so a failure is reproduced by its seed and the case it prints.

Every script, every time (cheap: nothing runs):
  - GBSSN1D_JOBS drawn from hostile values (0, -1, abc, 2000, '1 2', 07, 1e3, ' '): exit 2,
    GBSSN1D_JOBS named, OUT not created;
  - OUT a regular file, a symbolic link to a folder, or a folder holding another command's run
    (an evolve run's config.toml and timeseries.dat): exit 2, OUT named, the file, the link's
    target and the run byte for byte as they were.
Drawn scripts, while the time budget lasts (each a run of seconds):
  - the script started into a fresh relative OUT from another folder (OUT resolved against the
    caller's folder), one SIGINT or SIGTERM at a drawn moment: exit 130 within 20 s, a line
    saying what is kept, no gbssn1d of it left running, and every result in OUT complete (a run
    moved into place is one that completed: `# end: completed` or a stop of its own, or a
    converge verdict; unfinished runs only in OUT/.new-NAME);
  - run again and interrupted again: every result that was complete before is byte for byte
    the same and was not redone (its log untouched).

Usage:
  scripts_fuzz.py --src REPO --work DIR [--seed 1] [--budget 90] [--only SCRIPT]
"""

import argparse
import hashlib
import os
import random
import shutil
import signal
import subprocess
import sys
import time

BAD_JOBS = ["0", "-1", "abc", "2000", "1 2", "07", "1e3", " "]
# the scripts that source runs/lib.sh for their runs, and the first argument each needs before
# OUT (a stage); claims.sh has no OUT (out/claims in the repository) and is driven for its
# GBSSN1D_JOBS check only
STAGES = {
    "z4c.sh": ["damping", "kappa2", "resolution", "hole"],
    "horizon-coarse.sh": ["reproduce", "mechanism"],
    "box-interfaces.sh": ["wormhole", "five"],
    "boxes.sh": ["thesis", "bursts"],
    "refinement.sh": ["onset"],
    "horizon-robustness.sh": ["1"],  # its tmax
    "error-constant.sh": ["table", "upwind"],
}
NO_OUT = {"claims.sh"}
NOT_SCRIPTS = {"lib.sh", "study-helpers.sh"}


class Failure(Exception):
    pass


def scripts(src, only):
    names = sorted(f for f in os.listdir(os.path.join(src, "runs"))
                   if f.endswith(".sh") and f not in NOT_SCRIPTS)
    return [n for n in names if not only or n == only]


def uses_lib(src, name):
    with open(os.path.join(src, "runs", name)) as f:
        text = f.read()
    return "lib_init" in text or "runs/study-helpers.sh" in text


def command(src, name, stage, out):
    cmd = ["bash", os.path.join(src, "runs", name)]
    if stage is not None:
        cmd.append(stage)
    if out is not None and name not in NO_OUT:
        cmd.append(out)
    return cmd


def tree_hash(path):
    """Every file under path (or the file itself) with its bytes, and every link's target."""
    h = hashlib.sha256()
    if os.path.islink(path):
        h.update(b"link:" + os.readlink(path).encode())
        return h.hexdigest()
    if os.path.isfile(path):
        with open(path, "rb") as f:
            h.update(f.read())
        return h.hexdigest()
    for root, dirs, files in sorted(os.walk(path)):
        dirs.sort()
        for name in sorted(files):
            p = os.path.join(root, name)
            h.update(os.path.relpath(p, path).encode())
            if os.path.islink(p):
                h.update(b"link:" + os.readlink(p).encode())
            else:
                with open(p, "rb") as f:
                    h.update(f.read())
    return h.hexdigest()


def run_quick(cmd, cwd, env, timeout=15):
    """A command that must refuse at once: its status and output, or a Failure (its process
    group stopped) when it is still running after `timeout` s (it did not refuse: it ran)."""
    proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        text, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise Failure(f"{' '.join(cmd)}: still running after {timeout} s (not refused: it ran)")
    return proc.returncode, text


def base_env(jobs="1"):
    env = dict(os.environ)
    env["GBSSN1D_JOBS"] = jobs
    return env


def check_bad_jobs(src, work, name, stage, rng):
    jobs = rng.choice(BAD_JOBS)
    out = os.path.join(work, "jobs-out")
    shutil.rmtree(out, ignore_errors=True)
    status, text = run_quick(command(src, name, stage, out), work, base_env(jobs))
    if status != 2 or "GBSSN1D_JOBS" not in text:
        raise Failure(f"GBSSN1D_JOBS={jobs!r}: exit {status}, expected 2 naming GBSSN1D_JOBS:\n"
                      f"{text}")
    if name not in NO_OUT and os.path.lexists(out):
        raise Failure(f"GBSSN1D_JOBS={jobs!r}: OUT was created")


def evolve_run(exe, where):
    subprocess.run([exe, "evolve", "--id", "1log-trumpet", "--grid", "uniform", "--N", "32",
                    "--rmax", "8", "--tmax", "0.5", "--out", where], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def check_hostile_out(src, exe, work, name, stage, rng):
    if name in NO_OUT:
        return
    kind = rng.choice(["file", "link", "foreign"])
    base = os.path.join(work, "hostile")
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(base)
    out = os.path.join(base, "out")
    watched = out
    if kind == "file":
        with open(out, "w") as f:
            f.write("a user's notes\n")
    elif kind == "link":
        target = os.path.join(base, "target")
        os.makedirs(target)
        with open(os.path.join(target, "keep.txt"), "w") as f:
            f.write("kept\n")
        os.symlink(target, out)
        watched = target
    else:
        evolve_run(exe, out)
    before = tree_hash(watched)
    status, text = run_quick(command(src, name, stage, out), work, base_env("1"))
    if status != 2:
        raise Failure(f"OUT a {kind}: exit {status}, expected 2:\n{text}")
    if out not in text and os.path.basename(out) not in text:
        raise Failure(f"OUT a {kind}: the message does not name it:\n{text}")
    if tree_hash(watched) != before:
        raise Failure(f"OUT a {kind}: it was changed")


def results(out):
    """The results in OUT (NAME with NAME.status), each with its tree hash and its log's mtime."""
    found = {}
    if not os.path.isdir(out):
        return found
    for entry in os.listdir(out):
        if entry.endswith(".status"):
            name = entry[:-len(".status")]
            d = os.path.join(out, name)
            log = os.path.join(out, name + ".log")
            found[name] = (tree_hash(d) if os.path.exists(d) else None,
                           os.path.getmtime(log) if os.path.exists(log) else None)
    return found


def complete(d):
    """Whether d holds a completed run, as runs/lib.sh's lib_complete decides it."""
    if os.path.isfile(os.path.join(d, ".lib-complete")):
        return True
    summary = os.path.join(d, "summary.dat")
    if os.path.isfile(summary) and os.path.isdir(os.path.join(d, "logs")):
        # a sweep: every member finished as a result
        col, rows = None, 0
        with open(summary) as f:
            for line in f:
                words = line.split()
                if line.startswith("#"):
                    if col is None and "status" in words[1:]:
                        col = words[1:].index("status")
                    continue
                if not words:
                    continue
                if col is None or col >= len(words) or \
                        words[col] not in ("ok", "invalid", "blew-up"):
                    return False
                rows += 1
        return rows > 0
    conv = os.path.join(d, "convergence.dat")
    if os.path.isfile(conv):
        with open(conv) as f:
            text = f.read()
        return ("\n# verdict" in text and "# verdict: not judged: the study was interrupted"
                not in text)
    ts = os.path.join(d, "timeseries.dat")
    if not os.path.isfile(ts):
        return False
    with open(ts, "rb") as f:
        lines = f.read().decode(errors="replace").rstrip("\n").split("\n")
    last = lines[-1] if lines else ""
    return (last.startswith("# end: completed") or last.startswith("# end: stopped: ")) and \
        "interrupted by" not in last


def check_results_complete(out):
    if not os.path.isdir(out):
        return
    for entry in os.listdir(out):
        d = os.path.join(out, entry)
        if entry.startswith(".") or not os.path.isdir(d):
            continue
        if not os.path.exists(d + ".status"):
            continue  # a folder the script keeps of its own (a table's, a build's)
        if not complete(d):
            raise Failure(f"{d} is in place but did not complete")


def running_under(out):
    p = subprocess.run(["pgrep", "-f", "--", "--out " + out], stdout=subprocess.PIPE, text=True)
    mine = [pid for pid in p.stdout.split() if int(pid) != os.getpid()]
    p2 = subprocess.run(["pgrep", "-f", "--", out + "/.new-"], stdout=subprocess.PIPE, text=True)
    return mine + [pid for pid in p2.stdout.split() if int(pid) != os.getpid()]


def interrupted_run(src, work, name, stage, rel_out, delay, sig):
    caller = os.path.join(work, "caller")
    os.makedirs(caller, exist_ok=True)
    cmd = command(src, name, stage, rel_out)
    proc = subprocess.Popen(cmd, cwd=caller, env=base_env("1"), stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        proc.wait(timeout=delay)
        finished = True
    except subprocess.TimeoutExpired:
        finished = False
        proc.send_signal(sig)  # the script alone, not its process group (as `kill PID` does)
    try:
        text, _ = proc.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        raise Failure(f"{' '.join(cmd)}: still running 20 s after {sig.name}")
    return finished, proc.returncode, text


def check_interrupt(src, work, name, stage, rng, budget_end):
    if name in NO_OUT:
        return False
    rel = f"fuzz-{name[:-3]}{'-' + stage if stage else ''}"
    out = os.path.join(work, "caller", rel)
    shutil.rmtree(out, ignore_errors=True)
    for attempt in range(2):
        if time.time() + 25 > budget_end:
            return attempt > 0
        before = results(out)
        delay = rng.uniform(0.3, 3.0)
        sig = rng.choice([signal.SIGINT, signal.SIGTERM])
        finished, status, text = interrupted_run(src, work, name, stage, rel, delay, sig)
        what = f"{sig.name} after {delay:.2f} s (attempt {attempt + 1})"
        if finished:
            return True  # it ended first: nothing to interrupt (a cheap stage, or all kept)
        if status != 130:
            raise Failure(f"{what}: exit {status}, expected 130:\n{text[-2000:]}")
        if "interrupted" not in text:
            raise Failure(f"{what}: no line saying it was interrupted:\n{text[-2000:]}")
        time.sleep(0.5)
        left = running_under(out)
        if left:
            raise Failure(f"{what}: processes still running for {out}: {left}")
        if not os.path.isdir(out):
            raise Failure(f"{what}: the relative OUT was not made in the caller's folder ({out})")
        check_results_complete(out)
        after = results(out)
        for key, (tree, log_time) in before.items():
            if key in after and after[key] != (tree, log_time):
                raise Failure(f"{what}: {key}, complete before, was redone or changed")
            if key not in after:
                raise Failure(f"{what}: {key}, complete before, is gone")
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True, help="the repository (runs/ and build/gbssn1d)")
    ap.add_argument("--work", required=True, help="a scratch folder (emptied)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--budget", type=float, default=90.0, help="seconds for the drawn runs")
    ap.add_argument("--only", help="one script (its file name)")
    a = ap.parse_args()
    src = os.path.abspath(a.src)
    exe = os.path.join(src, "build", "gbssn1d")
    if not os.access(exe, os.X_OK):
        sys.exit(f"scripts_fuzz.py: {exe} is missing (bash .ci/build)")
    work = os.path.abspath(a.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    rng = random.Random(a.seed)
    names = [n for n in scripts(src, a.only) if uses_lib(src, n)]
    skipped = [n for n in scripts(src, a.only) if not uses_lib(src, n)]
    failures = []
    cases = 0
    for name in names:
        stage = rng.choice(STAGES[name]) if name in STAGES else None
        for check in (check_bad_jobs, check_hostile_out):
            cases += 1
            try:
                if check is check_bad_jobs:
                    check(src, work, name, stage, rng)
                else:
                    check(src, exe, work, name, stage, rng)
            except Failure as e:
                failures.append(f"{name} {stage or ''}: {e} (--seed {a.seed} --only {name})")
    budget_end = time.time() + a.budget
    order = names[:]
    rng.shuffle(order)
    interrupted = []
    for name in order:
        if time.time() + 25 > budget_end:
            break
        stage = rng.choice(STAGES[name]) if name in STAGES else None
        try:
            if check_interrupt(src, work, name, stage, rng, budget_end):
                interrupted.append(name)
                cases += 1
        except Failure as e:
            failures.append(f"{name} {stage or ''}: {e} (--seed {a.seed} --only {name})")
    print(f"scripts_fuzz.py: {len(names)} scripts ({cases} cases): bad GBSSN1D_JOBS and hostile "
          f"OUT each; interrupted and rerun: {', '.join(sorted(interrupted)) or 'none'}"
          + (f"; not on runs/lib.sh (not driven): {', '.join(skipped)}" if skipped else ""))
    if failures:
        print("\n".join("FAIL: " + f for f in failures), file=sys.stderr)
        sys.exit(1)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
