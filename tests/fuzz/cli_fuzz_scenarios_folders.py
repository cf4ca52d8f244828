"""Scenarios of the command-line fuzzer on an output folder while it is written: two writers of
one --out at once (surface concurrent), and files of a finished run, study or sweep replaced by
symbolic links, or --out a link to nothing (surface links)."""

import os
import re
import shutil
import signal
import subprocess
import time

from hypothesis import strategies as st

from cli_fuzz_common import (HALF, HALF_ARGS, OUTSIDE, STUDY, STUDY_ARGS, SWEEP_ARGS, SWEEP_DIR,
                             SWEEP_MEMBERS, TIME_LIMIT, TINY, Scenario, common_problems, encode,
                             fingerprint, first_difference, last_line, limits, outputs, run,
                             shell_line)

# a run that takes some 0.05-0.3 s, so that two of them overlap
BUSY = ["--id", "1log-trumpet", "--grid", "uniform", "--rmax", "8", "--dt-series", "0.05"]
# exit 2 of one of two writers of a folder: the folder in use, or a documented refusal of what
# the other left there
IN_USE = re.compile(r"being written by another gbssn1d process|already being written")
# (a study or sweep of other inputs: "holds a converge study of other inputs", "holds members
# run with other inputs"; another command's run where a study would go: "is not a converge
# study's folder")
OTHER_REFUSALS = re.compile(r"exists and is not empty|of other inputs|run with other inputs"
                            r"|is not a converge study's folder")


# --- two writers of one folder ---------------------------------------------------------------

@st.composite
def concurrent_scenario(draw):
    pair = draw(st.sampled_from(("evolve+evolve", "sweep+sweep", "converge+evolve")))
    n = draw(st.sampled_from(("200", "300", "400")))
    tmax = draw(st.sampled_from(("1", "2")))
    sigma = ("0.1", draw(st.sampled_from(("0.2", "0.1"))))  # the same inputs, now and then

    def evolve(k, force):
        return (["evolve"] + BUSY + ["--N", n, "--tmax", tmax, "--ko-sigma", sigma[k], "--out",
                                     "busy"] + (["--force"] if force else []))

    if pair == "evolve+evolve":
        a, b = evolve(0, draw(st.booleans())), evolve(1, draw(st.booleans()))
    elif pair == "sweep+sweep":
        a, b = [["sweep", "--sweep", "rahA=0,0.5", "--progress-every", "0"] + BUSY
                + ["--N", n, "--tmax", tmax, "--ko-sigma", sigma[k], "--out", "busy"]
                + (["--jobs", "2"] if draw(st.booleans()) else []) for k in (0, 1)]
    else:  # a study and a run: --force would let a run after the study add its files to it
        a = ["converge", "--N", "100,150,200"] + BUSY + ["--tmax", tmax, "--ko-sigma", sigma[0],
                                                          "--out", "busy"]
        b = evolve(1, False)
    if draw(st.booleans()):
        a, b = b, a
    delay = draw(st.sampled_from((0.0, 0.0, 0.005, 0.02, 0.08)))
    steps = (f"{shell_line(a)} &", f"sleep {delay}; {shell_line(b)} &", "wait")
    return Scenario("concurrent", steps, {"pair": pair, "delay": delay, "a": a, "b": b})


def spawn(exe, args, cwd, capture, tag):
    err = open(os.path.join(capture, tag + ".err"), "wb")
    p = subprocess.Popen([encode(exe)] + [encode(a) for a in args], cwd=cwd,
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                         preexec_fn=limits, start_new_session=True,
                         env={"PATH": "/usr/bin:/bin", "LANG": "C"})
    return p, err


def reap(p, err, started):
    timed_out = False
    try:
        p.wait(max(1.0, TIME_LIMIT - (time.monotonic() - started)))
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
    err.close()
    with open(err.name, "rb") as f:
        return p.returncode, f.read().decode("utf-8", "replace"), timed_out


def check_concurrent(lab, s):
    """Of two writers of one folder, each ends as it would alone or is refused (the folder in
    use, or what the other left there); at least one ends as alone; the folder then holds what
    one of them writes alone, never a mix."""
    a, b = s.params["a"], s.params["b"]
    base, cwd = lab.scratch(())
    problems = []
    try:
        capture = os.path.join(base, "capture")
        started = time.monotonic()
        pa = spawn(lab.exe, a, cwd, capture, "a")
        if s.params["delay"]:
            time.sleep(s.params["delay"])
        pb = spawn(lab.exe, b, cwd, capture, "b")
        results = [reap(*pa, started), reap(*pb, started)]
        found = outputs(os.path.join(cwd, "busy"))
        alone = []
        for args, (status, err, timed_out) in zip((a, b), results):
            tag = args[0]
            problems += [(k, f"{tag}: {d}") for k, d in
                         common_problems(args[0], status, err, timed_out)]
            solo_status, solo_out = lab.reference((), [args], "busy")
            solo_status = solo_status[0]
            if status == solo_status:
                alone.append(solo_out)
            elif status == 2:
                if not (IN_USE.search(err) or OTHER_REFUSALS.search(err)):
                    problems.append(("concurrent-refusal", f"{tag} refused (exit 2) but not "
                                     f"for the folder in use: {last_line(err)}"))
            elif not timed_out:
                problems.append(("concurrent-exit", f"{tag} ended with exit {status}; alone it "
                                 f"ends with {solo_status}, refused with 2: {last_line(err)}"))
        if not alone and not problems:
            problems.append(("concurrent-none", "both writers were refused: "
                             + " / ".join(last_line(r[1]) for r in results)))
        elif alone and all(found != want for want in alone):
            diffs = "; ".join(first_difference(found, want) for want in alone)
            problems.append(("concurrent-mix", "the folder holds neither writer's output as "
                             f"written alone ({diffs}); exits {results[0][0]} and "
                             f"{results[1][0]}" + config_vs_headers(os.path.join(cwd, "busy"))))
    finally:
        shutil.rmtree(base, ignore_errors=True)
    return problems, (results[0][0], results[1][0])


def config_vs_headers(folder):
    """', config.toml says ko-sigma = X, timeseries.dat's header Y' when they differ."""
    def sigma(path, prefix):
        try:
            with open(path, "rb") as f:
                for line in f.read().decode("utf-8", "replace").splitlines():
                    if line.startswith(prefix + "ko-sigma = "):
                        return line.split("=", 1)[1].strip()
        except OSError:
            return None
        return None
    said = {name: sigma(os.path.join(folder, name), "# ") for name in
            ("timeseries.dat", "horizon.dat", "profiles.dat", "convergence.dat")}
    said["config.toml"] = sigma(os.path.join(folder, "config.toml"), "")
    said = {k: v for k, v in said.items() if v is not None}
    if len(set(said.values())) > 1:
        return "; ko-sigma by file: " + ", ".join(f"{k} {v}" for k, v in said.items())
    return ""


# --- symbolic links where a command writes -----------------------------------------------------

LINK_NAMES = ("horizon.dat", "timeseries.dat", "profiles.dat", "config.toml", "checkpoint.bin",
              "rah-hAH-file.dat", ".gbssn1d.lock", "notes.txt")


@st.composite
def links_scenario(draw):
    where = draw(st.sampled_from(("run", "run", "study-member", "sweep-member", "dangling-out")))
    if where == "dangling-out":
        target = draw(st.sampled_from(("missing-target", "missing-dir/target")))
        below = draw(st.sampled_from(("", "", "/sub")))
        out = "link" + below
        cmd = draw(st.sampled_from((
            ["evolve"] + TINY + ["--tmax", "0", "--out", out],
            ["converge", "--N", "32,40,48"] + TINY[:4] + ["--rmax", "8", "--tmax", "0", "--out",
                                                          out],
            ["sweep", "--sweep", "ko-sigma=0.1,0.2"] + TINY + ["--tmax", "0", "--out", out],
            ["sweep", "--sweep", "ko-sigma=0.1,0.2"] + TINY + ["--tmax", "0", "--out", out,
                                                              "--member", "ko-sigma=0.1"],
            ["sweep", "--sweep", "ko-sigma=0.1,0.2"] + TINY + ["--tmax", "0", "--out", out,
                                                              "--emit-tasks", "tasks.txt"])))
        steps = (f"ln -s {target} link", shell_line(cmd))
        return Scenario("links", steps, {"where": where, "target": target, "out": out,
                                         "action": cmd})
    if where == "run":
        folder, name = HALF, draw(st.sampled_from(LINK_NAMES))
        cmd = draw(st.sampled_from((
            HALF_ARGS + ["--force"],
            ["evolve"] + TINY + ["--tmax", "0.25", "--checkpoint-every", "0.25", "--force",
                                 "--out", HALF],
            ["resume", HALF, "--tmax", "1"],
            ["resume", HALF])))
    elif where == "study-member":
        folder = draw(st.sampled_from((STUDY + "/N32", STUDY + "/N40", STUDY)))
        name = draw(st.sampled_from(LINK_NAMES + ("converge_samples.bin", "convergence.dat",
                                                  "scaled_H.dat")))
        cmd = STUDY_ARGS + (["--force"] if draw(st.booleans()) else [])
    else:
        folder = draw(st.sampled_from([SWEEP_DIR + "/" + m for m in SWEEP_MEMBERS]
                                      + [SWEEP_DIR]))
        name = draw(st.sampled_from(LINK_NAMES + ("summary.dat",)))
        cmd = SWEEP_ARGS + (["--collect"] if draw(st.booleans()) else [])
    content = draw(st.sampled_from(("copy", "other")))  # the linked file: a copy, or not
    # a member whose status file is gone runs again (into the folder that holds the link)
    rerun = folder.startswith(SWEEP_DIR + "/") and draw(st.booleans())
    steps = ((f"cp {folder}/{name} {OUTSIDE}/precious" if content == "copy" else
              f"echo precious > {OUTSIDE}/precious"),
             f"rm -f {folder}/{name}; ln -s $PWD/{OUTSIDE}/precious {folder}/{name}")
    if rerun:
        steps += (f"rm {SWEEP_DIR}/logs/{folder.split('/')[-1]}.status",)
    steps += (shell_line(cmd),)
    return Scenario("links", steps, {"where": where, "folder": folder, "name": name,
                                     "content": content, "rerun": rerun, "action": cmd})


def check_links(lab, s):
    """No file is written through a symbolic link: the file a link in the folder points to is
    left byte for byte; a refusal (exit 2) changes nothing in the folder; a failed write (exit
    1) names the link; a dangling --out is refused as a link (not 'File exists'), its target not
    created."""
    p = s.params
    problems = []
    if p["where"] == "dangling-out":
        base, cwd = lab.scratch(())
        try:
            os.symlink(p["target"], os.path.join(cwd, "link"))
            status, err, _, timed_out = run(lab.exe, p["action"], cwd,
                                            os.path.join(base, "capture"))
            problems += common_problems(p["action"][0], status, err, timed_out)
            made = [t for t in ("missing-target", "missing-dir")
                    if os.path.lexists(os.path.join(cwd, t))]
            if made:
                problems.append(("link-followed", f"the dangling link's target {made[0]} was "
                                 "created"))
            if status != 2 or "symbolic link" not in err or "File exists" in err:
                problems.append(("dangling-out", f"--out {p['out']} (a link to nothing, or "
                                 f"below one): exit {status}, {last_line(err)!r}; wanted a "
                                 "refusal (exit 2) saying it is a symbolic link"))
        finally:
            shutil.rmtree(base, ignore_errors=True)
        return problems, status
    top = p["folder"].split("/")[0]
    base, cwd = lab.scratch((top,))
    try:
        link = os.path.join(cwd, p["folder"], p["name"])
        precious = os.path.join(cwd, OUTSIDE, "precious")
        if p["content"] == "copy" and os.path.isfile(link):
            shutil.copy(link, precious)
        else:
            with open(precious, "wb") as f:
                f.write(b"precious\n")
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(precious, link)
        if p["rerun"]:
            os.remove(os.path.join(cwd, SWEEP_DIR, "logs",
                                   p["folder"].split("/")[-1] + ".status"))
        outside_before = fingerprint(os.path.join(cwd, OUTSIDE))
        before = fingerprint(os.path.join(cwd, top))
        status, err, _, timed_out = run(lab.exe, p["action"], cwd, os.path.join(base, "capture"))
        problems += common_problems(p["action"][0], status, err, timed_out)
        if fingerprint(os.path.join(cwd, OUTSIDE)) != outside_before:
            problems.append(("link-followed", f"{p['folder']}/{p['name']}, a link to "
                             f"{OUTSIDE}/precious: the file it points to changed (exit "
                             f"{status})"))
        if status == 2 and fingerprint(os.path.join(cwd, top)) != before:
            problems.append(("refusal-wrote", f"refused (exit 2) but {top} changed: "
                             f"{last_line(err)}"))
        # exit 1: a write refused at the link, or --collect with members not (any more) done
        if status == 1 and "link" not in err and not ("--collect" in p["action"]
                                                      and "missing" in err):
            problems.append(("exit-1", f"exit 1 not naming the link: {last_line(err)}"))
    finally:
        shutil.rmtree(base, ignore_errors=True)
    return problems, status
