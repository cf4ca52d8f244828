"""What the command-line fuzzer's surfaces share (cli_fuzz.py drives them): gbssn1d run under
the fuzzer's limits and the invariants every command keeps, a folder's fingerprint, and the lab
the scenarios run in (small finished runs made once, copied into fresh scratch folders, and what
a command leaves on an intact copy, cached)."""

import dataclasses
import hashlib
import os
import re
import resource
import shlex
import shutil
import signal
import stat
import subprocess
import tempfile

HAH_FILE = "hAH.dat"  # a valid h_AH(t) file (made by make_templates, in every scratch folder)


# ---------------------------------------------------------------------------------------------
# Running gbssn1d under limits, and what every command keeps.

LEAKS = ("terminate called", "std::", "filesystem error", "basic_string", "bad_alloc", "what():",
         "Assertion", "bad_optional_access", "vector::", "stoi", "stod", "Segmentation",
         "core dumped", "CLI::", "boost::", "Aborted")
NAMES_A_FLAG = re.compile(r"(--[A-Za-z][\w-]*|-j\b|\bDIR\b|subcommand|argument)")
ALLOWED = {"evolve": {0, 1, 2, 3}, "resume": {0, 1, 2, 3}, "converge": {0, 1, 2, 3, 4, 5, 6},
           "sweep": {0, 1, 2, 3}, None: {0, 1, 2}}
TIME_LIMIT = 30.0  # seconds: a hang
MEMORY_LIMIT = 3 << 30  # bytes of address space per process
FILE_LIMIT = 256 << 20  # bytes per file


def limits():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_FSIZE, (FILE_LIMIT, FILE_LIMIT))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def encode(word):
    return os.fsencode(word) if isinstance(word, str) else word


def run(exe, args, cwd, capture):
    """Runs gbssn1d with `args` in `cwd`; returns (status, stderr text, timed out)."""
    out_path, err_path = os.path.join(capture, "stdout"), os.path.join(capture, "stderr")
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        p = subprocess.Popen([encode(exe)] + [encode(a) for a in args], cwd=cwd,
                             stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                             preexec_fn=limits, start_new_session=True,
                             env={"PATH": "/usr/bin:/bin", "LANG": "C"})
        timed_out = False
        try:
            p.wait(TIME_LIMIT)
        except subprocess.TimeoutExpired:
            timed_out = True
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    with open(err_path, "rb") as f:
        err_text = f.read().decode("utf-8", "replace")
    with open(out_path, "rb") as f:
        out_text = f.read().decode("utf-8", "replace")
    return p.returncode, err_text, out_text, timed_out


def common_problems(sub, status, err, timed_out):
    """The invariants every command keeps: no hang, no signal, a documented exit, no
    internals on stderr."""
    if timed_out:
        return [("hang", f"no exit within {TIME_LIMIT:.0f} s")]
    if status < 0 or status >= 128:
        return [("signal", f"exit {status} (died by a signal)")]
    problems = []
    if status not in ALLOWED[sub]:
        problems.append(("exit-status", f"exit {status}, not one of {sorted(ALLOWED[sub])}"))
    for leak in LEAKS:
        if leak in err:
            problems.append(("leak", f"stderr holds {leak!r}"))
            break
    return problems


def last_line(err):
    lines = err.strip().splitlines()
    return lines[-1][:160] if lines else ""


def fingerprint(root):
    """Every entry below `root` (symlinks not followed, FIFOs not opened) with its type and, for
    a file, a hash of its bytes."""
    entries = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            rel = os.path.relpath(p, root)
            st_ = os.lstat(p)
            if stat.S_ISLNK(st_.st_mode):
                entries[rel] = "link:" + os.readlink(p)
            elif stat.S_ISDIR(st_.st_mode):
                entries[rel] = "dir"
            elif stat.S_ISREG(st_.st_mode):
                with open(p, "rb") as f:
                    entries[rel] = "file:" + hashlib.sha1(f.read()).hexdigest()
            else:
                entries[rel] = f"other:{stat.S_IFMT(st_.st_mode)}"
    return entries


# ---------------------------------------------------------------------------------------------
# Scenarios (issue 37, round 3): what one argument vector cannot say. Two processes writing one
# folder at once; output files that are symbolic links; a run's resume files corrupted; a
# sweep's folder edited between runs. Each scenario lays out a fresh scratch folder with copies
# of small finished runs (make_references), changes it, runs one or two commands and compares
# what they leave with what the same commands leave on an intact copy (computed once, cached).
# The surfaces: cli_fuzz_scenarios_folders.py (concurrent, links) and
# cli_fuzz_scenarios_resume.py (resume-files, sweep-edits).

TINY = ["--id", "1log-trumpet", "--grid", "uniform", "--N", "32", "--rmax", "8"]
HALF = "half"  # a finished run to t = 0.5, checkpoint at 0.25, with --rah-hAH-file's copy
STUDY = "study"  # a finished converge study (every member with checkpoint and samples)
SWEEP_DIR = "sw"  # a finished sweep of two members
OUTSIDE = "outside"  # a folder outside every run: files that links point to
HALF_ARGS = ["evolve"] + TINY + ["--tmax", "0.5", "--checkpoint-every", "0.25", "--dt-series",
                                 "0.125", "--rahA", "0.5", "--rah-hAH-file", HAH_FILE,
                                 "--out", HALF]
STUDY_ARGS = ["converge", "--N", "32,40,48", "--id", "1log-trumpet", "--grid", "uniform",
              "--rmax", "8", "--tmax", "0.5", "--checkpoint-every", "0.25", "--out", STUDY]
SWEEP_MEMBERS = ("ko-sigma=0.1", "ko-sigma=0.2")
SWEEP_ARGS = ["sweep", "--sweep", "ko-sigma=0.1,0.2"] + TINY + ["--tmax", "0.5",
                                                                "--progress-every", "0",
                                                                "--out", SWEEP_DIR]
# the files a run resumes from (not compared as outputs: a refused or finished resume may leave
# a damaged one as it found it)
RESUME_FILES = ("checkpoint.bin", "converge_samples.bin", "rah-hAH-file.dat")


@dataclasses.dataclass
class Scenario:
    surface: str
    steps: tuple  # (what is done, as a shell-like line) for the report
    params: dict = dataclasses.field(default_factory=dict)

    def __repr__(self):
        return "\n" + describe(self)


def shell_line(args):
    return "gbssn1d " + " ".join(shlex.quote(a) for a in args)


def describe(s):
    """A scenario as the shell steps that reproduce it (in a folder holding the references)."""
    lines = [f"# scenario {s.surface}: " + ", ".join(f"{k}={v!r}" for k, v in s.params.items()
                                                    if k not in ("a", "b", "action"))]
    lines += ["  " + step for step in s.steps]
    return "\n".join(lines)


def make_references(exe, root):
    """The finished runs every scenario starts from, in `root` (the scratch folders copy them to
    the same relative names, so that recorded paths agree)."""
    for args in (HALF_ARGS, STUDY_ARGS, SWEEP_ARGS):
        p = subprocess.run([exe] + args, cwd=root, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True)
        if p.returncode not in (0, 4, 5, 6):
            raise RuntimeError(f"reference {shell_line(args)}: exit {p.returncode}: {p.stderr}")


def summary_rows(path):
    """summary.dat as {member: columns} without the wall_s column (and None if unreadable)."""
    try:
        with open(path, "rb") as f:
            lines = f.read().decode("utf-8", "replace").splitlines()
    except OSError:
        return None
    head = lines[0][1:].split() if lines and lines[0].startswith("#") else []
    wall = head.index("wall_s") if "wall_s" in head else None
    rows = {}
    for line in lines:
        if line.startswith("#") or not line.strip():
            continue
        cols = line.split()
        if wall is not None and wall < len(cols):
            del cols[wall]
        rows[cols[0] if cols else ""] = cols
    return rows


def outputs(folder, keep_resume_files=False):
    """What a run, study or sweep wrote into `folder`, to compare with a reference: every file
    (links followed) but the lock files, the members' logs and status files (they carry wall
    times) and, unless asked, the resume files; summary.dat without its wall_s column."""
    found = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in filenames:
            p = os.path.join(dirpath, name)
            rel = os.path.relpath(p, folder)
            if name.endswith(".lock") or re.search(r"\.(log|status)$", name):
                continue
            if name in RESUME_FILES and not keep_resume_files:
                continue
            if name == "summary.dat":
                found[rel] = repr(summary_rows(p))
                continue
            try:
                with open(p, "rb") as f:
                    found[rel] = hashlib.sha1(f.read()).hexdigest()
            except OSError as e:
                found[rel] = f"unreadable: {e.strerror}"
    return found


def first_difference(got, want):
    for rel in sorted(set(got) | set(want)):
        if got.get(rel) != want.get(rel):
            what = "missing" if rel not in got else "extra" if rel not in want else "differs"
            return f"{rel} {what}"
    return None


class Lab:
    """Runs scenarios: the references, the cache of reference outcomes, scratch folders."""

    def __init__(self, exe, root):
        self.exe, self.root = exe, root
        self.cache = {}

    def scratch(self, names):
        """A fresh scratch folder: its cwd holds hAH.dat, an `outside` folder and copies of
        the named references."""
        base = tempfile.mkdtemp(prefix="gbssn1d-scenario-")
        cwd = os.path.join(base, "cwd")
        os.makedirs(os.path.join(cwd, OUTSIDE))
        os.makedirs(os.path.join(base, "capture"))
        shutil.copy(os.path.join(self.root, HAH_FILE), os.path.join(cwd, HAH_FILE))
        for name in names:
            shutil.copytree(os.path.join(self.root, name), os.path.join(cwd, name), symlinks=True)
        return base, cwd

    def reference(self, names, commands, folder):
        """(exit statuses, outputs of `folder`) of `commands` run one after the other on intact
        copies of the named references (cached)."""
        key = (tuple(names), tuple(tuple(c) for c in commands), folder)
        if key not in self.cache:
            base, cwd = self.scratch(names)
            try:
                statuses = [run(self.exe, c, cwd, os.path.join(base, "capture"))[0]
                            for c in commands]
                self.cache[key] = (statuses, outputs(os.path.join(cwd, folder)))
            finally:
                shutil.rmtree(base, ignore_errors=True)
        return self.cache[key]
