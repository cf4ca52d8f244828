#!/usr/bin/env python3
"""Property-based fuzzer of gbssn1d's command line (Debian's python3-hypothesis).

Draws argument vectors for every subcommand (evolve, converge, sweep, resume, and garbled ones)
from the flag table below, which is checked against each subcommand's --help first, so that a
flag added to the program but not here fails the run instead of going undrawn. Values are valid,
boundary (range ends, 0, negative, huge, 1e-400, nan, '', ' 1', '1,5', '0x10', '032', ...) or
invalid words; paths are hostile (spaces, newline, '#', '=', leading '-', names longer than 255
and 4096 bytes, a symlink loop, a FIFO, a directory where a file is expected, a finished run);
flags come in random order, in both --flag=value and --flag value forms, sometimes twice; config
files hold random keys, values, sections and escapes. Every input runs in a fresh scratch folder
with a time limit and a memory limit, and must satisfy:

  - no death by a signal and no hang (the time limit);
  - an exit status the subcommand documents (evolve/resume 0-3, converge 0-6, sweep 0-3);
  - exit status 1 only for a failed write (or `sweep --collect` with members not run yet);
  - no internals on stderr ('terminate called', 'std::', 'what():', 'filesystem error', ...);
  - on a refusal (exit 2): nothing created or changed in the scratch folder, and a message that
    names a flag or parameter;
  - inputs that are refused by rule (a flag given twice, an empty value, a malformed number, no
    subcommand) are refused: exit 2;
  - the finished run `done` is left byte for byte as it was, unless the input asks to write
    into it (--force with --out done, resume done with a later --tmax);
  - every *.dat file a run wrote holds only '#' lines, blank lines and rows of numbers
    (summary.dat, which has words, rows of the header's width);
  - a completed run's timeseries.dat ends with '# end: completed', a stopped one's (exit 3)
    with '# end: stopped';
  - a completed evolve's config.toml repeats the run: `evolve --config OUT/config.toml
    --print-config` prints the same parameters (README: "repeat a run exactly");
  - an --out that is, or lies below, a symbolic link to nothing is not refused as 'File
    exists', and the link's target is not created.

Scenarios (issue 37, round 3) are what one argument vector cannot say. They start from small
finished runs made once (an evolve run to t = 0.5 with a checkpoint and its copy of
--rah-hAH-file, a converge study of N = 32, 40, 48, a sweep of two members; grid uniform, N 32,
rmax 8), copied into a fresh scratch folder, and compare what a command leaves there with what
it leaves on an intact copy (cached; lines and columns with wall times, lock files and logs
left out). Four surfaces:

  concurrent    two writers of one --out started together or a few ms apart (evolve+evolve,
                sweep+sweep, converge+evolve; ko-sigma 0.1 and 0.2, or the same): each ends as
                it does alone or is refused (exit 2) for the folder in use (or, when it ran
                after, for what the other left there); at least one ends as alone; the folder
                then holds exactly what one of them writes alone, never a mix of the two
                (config.toml and the .dat headers of one run, the rows of that run);
  links         a file of a finished run, study member or sweep member (horizon.dat,
                timeseries.dat, config.toml, checkpoint.bin, the lock file, ...) replaced by a
                symbolic link to a file outside (a copy of it, or other bytes), then evolve
                --force, resume, converge or a sweep rerun/--collect: the file outside is left
                byte for byte; a refusal (exit 2) changes nothing; an exit 1 names the link;
                --out a link to nothing (evolve, converge, sweep, --member, --emit-tasks): exit 2
                saying it is a symbolic link, not 'File exists', its target not created;
  resume-files  a checkpoint.bin, converge_samples.bin or rah-hAH-file.dat bit-flipped,
                truncated, deleted, emptied, a link loop, a link to a copy or to another run's
                file (the file --rah-hAH-file names kept, edited or deleted), then resume or the
                converge rerun: refused with exit 2 naming the file and changing nothing, or the
                intact copy's exit status and outputs; never another success;
  sweep-edits   a member's folder deleted, its timeseries.dat emptied or truncated, its
                config.toml edited or deleted, its status file deleted, then --collect and/or a
                rerun: a member whose config.toml was edited is refused by both (exit 2,
                nothing changed); --collect lists a member whose output is gone or cut short as
                missing (exit 1), never ok with nan, and every member it lists ok with the clean
                sweep's numbers; a rerun runs such members again and ends (exit 0) with the clean
                sweep's summary.dat and .dat files.

KNOWN_DEFECTS lists violations the program still has (issue 37): found, they are printed and
counted but do not fail the run; remove an entry once its defect is fixed.

A failure is shrunk by hypothesis to a minimal input, printed with a ready-made row for
tests/cli/hostile_inputs.txt (a scenario: as the shell steps that repeat it). Usage:

  cli_fuzz.py --exe build/gbssn1d          # CI: seed 1, 400 inputs and 250 scenarios, 40-60 s
  cli_fuzz.py --exe build/gbssn1d --examples 10000 --seed 7 --budget 0
  cli_fuzz.py --exe build/gbssn1d --examples 10000 --keep-going    # tally, do not stop
  cli_fuzz.py --exe build/gbssn1d --surface concurrent --scenarios 500 --scenario-budget 0
  cli_fuzz.py --exe build/gbssn1d --check-flags        # only the flag table against --help

--budget S stops drawing new argument vectors after S seconds of wall time, --scenario-budget S
new scenarios (0: no limit); a failure found before then is still shrunk in full. --surface
names what is fuzzed, comma-separated: args (the argument vectors), concurrent, links,
resume-files, sweep-edits (default all); --scenarios N draws at most N scenarios.
"""

import argparse
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
import sys
import tempfile
import time

try:
    import hypothesis
    from hypothesis import strategies as st
except ImportError:  # pragma: no cover
    sys.exit("cli_fuzz.py needs Debian's python3-hypothesis (run it with /usr/bin/python3)")

# ---------------------------------------------------------------------------------------------
# The flag table. Kinds: INT, FLOAT, TEXT (as --help prints them), FLAG (no value), LIST (a
# comma-separated TEXT list), CHOICE (a TEXT of fixed words), PATH (a TEXT naming a file or
# folder). `valid` are values that run quickly; `edge` are range ends of that flag.

INT, FLOAT, TEXT, FLAG = "INT", "FLOAT", "TEXT", "FLAG"


@dataclasses.dataclass(frozen=True)
class Flag:
    kind: str  # INT | FLOAT | TEXT | FLAG, as --help names it
    valid: tuple = ()
    edge: tuple = ()
    choices: tuple = ()  # a TEXT flag of fixed words
    path: bool = False  # a TEXT flag naming a file or folder


EVOLVE = {
    # N: 10000000 (the largest accepted) is valid and needs about 4 GB: not drawn
    "--N": Flag(INT, ("16", "24", "32", "48", "64"), ("0", "-1", "15", "17", "10000001",
                                                     "2147483648", "99999999999", "032")),
    "--rmax": Flag(FLOAT, ("20", "50", "100", "1000"), ("4", "3.999", "8", "8.0000001", "1e6",
                                                        "1000001", "2e9")),
    "--grid": Flag(TEXT, choices=("uniform", "sinh", "boxes")),
    "--levels": Flag(INT, ("1", "2", "3", "4"), ("0", "-3", "30", "31", "2.5")),
    "--time-interp": Flag(TEXT, choices=("rk-stages", "dense", "quadratic")),
    "--no-subcycling": Flag(FLAG),
    "--box-taper": Flag(FLOAT, ("0", "0.25", "0.5"), ("-1e-9", "0.5000001", "1e308")),
    "--box-taper-from": Flag(FLOAT, ("0", "16", "100"), ("-1", "1e308")),
    "--dr-inner": Flag(FLOAT, ("0.02", "0.05", "0.01"), ("1e-30", "1e-300", "2.5", "1e-7")),
    "--id": Flag(TEXT, choices=("wormhole", "maximal-trumpet", "1log-trumpet")),
    "--M": Flag(FLOAT, ("1", "0.5", "2"), ("1e-3", "1e3", "1e-4", "1e308")),
    "--lapse0": Flag(TEXT, choices=("one", "precollapsed")),
    "--formulation": Flag(TEXT, choices=("bssn", "z4c")),
    "--gbssn-volume": Flag(TEXT, choices=("lagrangian", "eulerian")),
    "--kappa1": Flag(FLOAT, ("0", "0.02", "0.1"), ("-1e-300", "1e308")),
    "--kappa1-hole": Flag(FLOAT, ("0", "1", "2"), ("-1", "nan", "1e308")),
    "--kappa2": Flag(FLOAT, ("0", "0.5"), ("-1", "-0.9999999", "1e308")),
    "--z4c-lapse-adm": Flag(FLAG),
    "--eta": Flag(FLOAT, ("0", "1", "2"), ("1e308", "-1e-300")),
    "--advective-shift": Flag(FLAG),
    "--non-advective-lapse": Flag(FLAG),
    "--cfl": Flag(FLOAT, ("0.25", "0.5", "1"), ("1e-4", "9.9e-5", "1.0000001", "4.9e-324",
                                                 "1e-9")),
    "--ko-sigma": Flag(FLOAT, ("0", "0.1", "1"), ("1.0000001", "1.5")),
    "--fd-order": Flag(INT, ("2", "4", "6", "8"), ("3", "10", "4.5")),
    "--chi-floor": Flag(FLOAT, ("0", "1e-5"), ("1", "0.999999", "1e-300")),
    "--driver-advection": Flag(TEXT, choices=("matched", "upwind-gd", "upwind-full", "centred")),
    "--delta-advection": Flag(TEXT, choices=("upwind-full", "upwind-gd", "centred")),
    "--upwind": Flag(TEXT, choices=("lopsided", "biased")),
    "--tmax": Flag(FLOAT, ("0", "0.25", "0.5"), ("1e308", "1e9", "4.9e-324")),
    "--dt-series": Flag(FLOAT, ("0.25", "0.1", "1"), ("4.9e-324", "1e-7", "1e308")),
    "--dt-profiles": Flag(FLOAT, ("0.25", "5"), ("4.9e-324", "1e-5", "1e308")),
    "--checkpoint-every": Flag(FLOAT, ("0", "0.25"), ("1e-17", "1e-300", "1e308")),
    "--out": Flag(TEXT, path=True),
    "--force": Flag(FLAG),
    "--norm-rmin": Flag(FLOAT, ("1", "0"), ("1e308", "1000")),
    "--norm-rmax": Flag(FLOAT, ("10", "5"), ("2000", "1", "1e308")),
    "--norm-Rmin": Flag(FLOAT, ("2.5", "1"), ("12", "1e308")),
    "--norm-Rmax": Flag(FLOAT, ("12", "20"), ("2.5", "1")),
    "--norm-Rint": Flag(FLOAT, ("1.8", "1"), ("1e308",)),
    "--rahA": Flag(FLOAT, ("0", "0.5", "1"), ("-0.5", "1e308", "1e-400")),
    "--rah0": Flag(FLOAT, ("0.89", "0.6", "1.2"), ("1e308", "1e-300")),
    "--rah-width": Flag(FLOAT, ("1", "3"), ("1e308", "1e-300")),
    "--rah-rcut": Flag(FLOAT, ("10", "25"), ("3.5", "7", "1e308")),
    "--rah-taper": Flag(TEXT, choices=("quartic", "step")),
    "--rah-ramp": Flag(FLOAT, ("0", "1"), ("1e308",)),
    "--rah-profile": Flag(TEXT, choices=("auto", "rational", "rational3", "gauss", "gauss3")),
    "--rah-normal": Flag(TEXT, choices=("conformal", "unit", "smooth")),
    "--rah-chi-smooth": Flag(FLOAT, ("0.05",), ("1e308", "1e-300")),
    "--rah-hAH-file": Flag(TEXT, path=True),
    "--ah-every": Flag(TEXT, choices=("substage", "step", "1", "2", "032"),
                       edge=("0", "-3", "99999999999999999999", "1.5")),
    "--ah-interval": Flag(FLOAT, ("1", "0.5"), ("0", "-1", "1e308", "1e-320")),
    "--ah-tmin": Flag(FLOAT, ("0", "0.1"), ("1e308",)),
    "--ah-tmax": Flag(FLOAT, ("1", "0.5"), ("1e308",)),
    "--ah-tol": Flag(FLOAT, ("1e-12", "1e-10"), ("0.01", "1e300", "1e-300")),
    "--rah-variant": Flag(TEXT, choices=(
        "consistent", "no-shift-derivatives", "no-shift-second-derivatives",
        "delta-rhs-from-gd", "driver-full-shift", "midstep-update", "box-substage")),
    "--config": Flag(TEXT, path=True),
    "--print-config": Flag(FLAG),
}

CONVERGE = {
    "--N": Flag(TEXT, ("32,40,48", "32,48,64", "24,32,40,48", "32"),
                ("", "32,,40", "32,", ",32", "32,32,32", "64,48,32", "16,17,18", "032,0x30,64",
                 "32,40", "10000001,2,3")),
    # factors stay small: larger ones are valid and cost what they ask for
    "--factors": Flag(TEXT, ("1,1.5,2", "1,1.25,1.5"),
                      ("1,1.51,2", "x", "0,1,2", "-1,1,2", "1,nan,2", "1,2", "1e-400,1,2")),
    "--jobs": Flag(INT, ("1", "2"), ("0", "-1", "1024", "1025", "1.5")),
    "--out": Flag(TEXT, path=True),
    "--force": Flag(FLAG),
    "--fields": Flag(TEXT, ("alpha,chi,K", "beta", "Delta_r,A_a"),
                     ("", "alpha,bogus", "alpha,,K", "ALPHA")),
    "--scaled-times": Flag(TEXT, ("0.25", "0,0.5"), ("1,nan", "1e308", "-1", "")),
    "--order": Flag(FLOAT, ("4", "2"), ("0", "-4", "1e308")),
    "--expect-order": Flag(FLOAT, ("4", "2.5"), ("0", "30", "30.000001", "1e308")),
}

SWEEP = {
    "--sweep": Flag(TEXT),
    "--jobs": Flag(INT, ("1", "2"), ("0", "-1", "1024", "1025", "1.5")),
    "--out": Flag(TEXT, path=True),
    "--progress-every": Flag(FLOAT, ("0", "60"), ("-1", "1e308", "4.9e-324")),
    "--emit-tasks": Flag(TEXT, path=True),
    "--member": Flag(TEXT),
    "--collect": Flag(FLAG),
}

RESUME = {
    "DIR": Flag(TEXT, path=True),
    "--tmax": Flag(FLOAT, ("1", "1.5"), ("0.25", "0", "1e308", "0.75")),
}

TABLE = {"evolve": EVOLVE, "converge": CONVERGE, "sweep": SWEEP, "resume": RESUME}
# the short form of --jobs (-j, -jN) is drawn where --jobs is
SHORT = {"--jobs": "-j"}

# Text that is no number by the program's grammar (config/numbers.hpp), whatever the flag.
NOT_NUMBERS = ("nan", "NaN", "inf", "-inf", "", " 1", "1 ", "1,5", "0x10", "abc", "1x", "1e999",
               "1e-400", "++1", "-+1", "1e", "e5", "1_000", "\uff11", "9" * 400, "-", "--")
NUMBERS = ("0", "-0", "-1", "1", "+1", "1e308", "-1e308", "4.9e-324", "1.", ".5", "032", "1e+2",
           "2.2250738585072014e-308")
WORDS = ("bogus", "true", "false", "--N", "-", "x" * 300, "a\nb", "\t", "\xff", "caf\u00e9",
         "#", "=", "a=b", "[x]", "'", '"', "\\", "$HOME", "*")


# ---------------------------------------------------------------------------------------------
# The program's --help, parsed: the flags each subcommand lists and their kinds.

# an option line is indented by two spaces (wrapped help text by many more)
HELP_LINE = re.compile(r"^  (?:(-\w),)?(--[\w-]+|[A-Z]+)(?: (INT|FLOAT|TEXT))?(?=[ =]|$)")


def help_flags(exe, sub):
    out = subprocess.run([exe, sub, "--help"], capture_output=True, text=True, check=True).stdout
    flags = {}
    for line in out.splitlines():
        m = HELP_LINE.match(line)
        if not m or m.group(2) in ("--help",):
            continue
        flags[m.group(2)] = m.group(3) or FLAG
    return flags


def check_flag_table(exe):
    """The table above against the program's own --help: every flag listed in both, with the
    same kind. Returns the differences (empty when they agree)."""
    problems = []
    for sub, table in TABLE.items():
        listed = help_flags(exe, sub)
        for name, kind in listed.items():
            if name not in table:
                problems.append(f"{sub}: {name} ({kind}) is listed by --help but not drawn here")
            elif table[name].kind != kind:
                problems.append(f"{sub}: {name} is {kind} in --help, {table[name].kind} here")
        for name in table:
            if name not in listed:
                problems.append(f"{sub}: {name} is drawn here but not listed by --help")
    return problems


# ---------------------------------------------------------------------------------------------
# The scratch folder an input runs in (its working directory), laid out anew for every input.

FRESH_OUT = "out"  # the --out a row may not leave behind when refused: {out} in the catalogue
DONE = "done"  # a finished run with a checkpoint, as tests/cli/test_hostile_inputs.cpp makes it
DAMAGED = "dmg"  # a copy of it with one damage (the case says which)
HAH_FILE = "hAH.dat"  # a valid h_AH(t) file
LONG_NAME = "n" * 300  # a component longer than NAME_MAX
LONG_PATH = "abcdefgh/" * 600 + "x"  # longer than PATH_MAX, in short components
# Hostile paths relative to the scratch folder (which holds each of these before the run).
PATHS = (FRESH_OUT, FRESH_OUT, FRESH_OUT, "new dir", "new\nline", "ha#sh", "eq=ual", "-lead",
         "--lead", LONG_NAME, LONG_PATH, "x" * 5000, "loop", "loop/sub", "dangling",
         "dangling/sub", "fifo", "adir",
         "afile", "afile/sub", DONE, DONE + "/timeseries.dat", DONE + "/config.toml", DAMAGED,
         HAH_FILE, "/dev/null", "/dev/full", "/proc/gbssn1d_cannot", "/", ".", "new/", "a//b",
         "caf\u00e9", "bad\udcffbyte", 'quo"te', "back\\slash", "tab\there", "", "cfg.toml")
DAMAGES = ("none", "checkpoint-truncated", "checkpoint-flipped", "checkpoint-missing",
           "checkpoint-fifo", "checkpoint-loop", "series-truncated", "series-junk",
           "series-no-end", "horizon-missing", "profiles-missing", "config-changed",
           "config-unknown-key", "config-dir", "config-empty", "config-junk")


def make_templates(exe, root):
    """The finished run and the h_AH file every scratch folder gets a copy of."""
    done = os.path.join(root, DONE)
    subprocess.run([exe, "evolve", "--N", "64", "--tmax", "1", "--dt-series", "0.25",
                    "--checkpoint-every", "0.5", "--out", done],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    hah = "# t r_ah\n" + "".join(f"{0.25 * k:g} {0.9 + 0.001 * k:g}\n" for k in range(21))
    with open(os.path.join(root, HAH_FILE), "w") as f:
        f.write(hah)
    return root


def damage(folder, kind):
    def path(name):
        return os.path.join(folder, name)

    if kind == "checkpoint-truncated":
        with open(path("checkpoint.bin"), "r+b") as f:
            f.truncate(os.path.getsize(path("checkpoint.bin")) // 2)
    elif kind == "checkpoint-flipped":
        with open(path("checkpoint.bin"), "r+b") as f:
            f.seek(os.path.getsize(path("checkpoint.bin")) // 3)
            b = f.read(1)
            f.seek(-1, 1)
            f.write(bytes([b[0] ^ 0x40]))
    elif kind == "checkpoint-missing":
        os.remove(path("checkpoint.bin"))
    elif kind == "checkpoint-fifo":
        os.remove(path("checkpoint.bin"))
        os.mkfifo(path("checkpoint.bin"))
    elif kind == "checkpoint-loop":
        os.remove(path("checkpoint.bin"))
        os.symlink("checkpoint.bin", path("checkpoint.bin"))
    elif kind == "series-truncated":
        with open(path("timeseries.dat"), "r+b") as f:
            f.truncate(200)
    elif kind == "series-junk":
        with open(path("timeseries.dat"), "ab") as f:
            f.write(b"junk \xff line\n")
    elif kind == "series-no-end":
        with open(path("timeseries.dat"), "rb") as f:
            lines = f.read().splitlines(keepends=True)
        with open(path("timeseries.dat"), "wb") as f:
            f.writelines(line for line in lines if not line.startswith(b"# end:"))
    elif kind == "horizon-missing":
        os.remove(path("horizon.dat"))
    elif kind == "profiles-missing":
        os.remove(path("profiles.dat"))
    elif kind == "config-changed":
        with open(path("config.toml"), "ab") as f:
            f.write(b"N = 80\n")
    elif kind == "config-unknown-key":
        with open(path("config.toml"), "ab") as f:
            f.write(b"Nn = 80\n")
    elif kind == "config-dir":
        os.remove(path("config.toml"))
        os.mkdir(path("config.toml"))
    elif kind == "config-empty":
        open(path("config.toml"), "wb").close()
    elif kind == "config-junk":
        with open(path("config.toml"), "ab") as f:
            f.write(b"[[[\n\x00\n")


def lay_out(cwd, templates, case):
    """The scratch folder's contents before the run: what the hostile paths name."""
    shutil.copytree(os.path.join(templates, DONE), os.path.join(cwd, DONE), symlinks=True)
    shutil.copytree(os.path.join(templates, DONE), os.path.join(cwd, DAMAGED), symlinks=True)
    damage(os.path.join(cwd, DAMAGED), case.damage)
    shutil.copy(os.path.join(templates, HAH_FILE), os.path.join(cwd, HAH_FILE))
    os.symlink("loop", os.path.join(cwd, "loop"))
    os.symlink("missing-target", os.path.join(cwd, "dangling"))
    os.mkfifo(os.path.join(cwd, "fifo"))
    os.mkdir(os.path.join(cwd, "adir"))
    with open(os.path.join(cwd, "afile"), "w") as f:
        f.write("a file\n")
    for name, content in case.files:
        with open(os.path.join(cwd, name), "wb") as f:
            f.write(content)


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
# Drawing inputs.


@dataclasses.dataclass
class Case:
    args: list  # the arguments after `gbssn1d`
    files: tuple = ()  # (name, bytes) written into the scratch folder first
    damage: str = "none"  # what is wrong with the copy `dmg` of the finished run

    def __repr__(self):
        return "\n" + catalogue_row(self, None, "")


FLOAT_TEXT = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def as_number(text):
    """The value of `text` when it is a plain finite decimal number, else None."""
    if text is None or not FLOAT_TEXT.match(text) or text[:2] in ("+-", "-+"):
        return None
    try:
        v = float(text)
    except ValueError:
        return None
    return v if v == v and abs(v) != float("inf") else None


def malformed(kind, text):
    """Whether `text` is surely no value of a number flag of this kind (a conservative test of
    the grammar in config/numbers.hpp: characters it never accepts, words, integers written
    with a fraction or exponent, integers beyond 32 bits)."""
    if kind not in (INT, FLOAT):
        return False
    if text == "" or re.search(r"[^0-9.eE+-]", text):
        return True
    if kind == INT:
        if re.search(r"[.eE]", text):
            return True
        if re.fullmatch(r"-?\d+", text) and not -(2**31) <= int(text) < 2**31:
            return True
    return False


# Unusual names that are fine folder and file names: a run into them must succeed.
# ('#', quotes and backslashes are recorded in config.toml escaped, and read back exactly)
BENIGN_PATHS = (FRESH_OUT, FRESH_OUT, "new dir", "eq=ual", "caf\u00e9", "new/", "a//b", 'quo"te',
                "ha#sh", "#lead",
                "back\\slash", "sub/deeper/new", "bad\udcffbyte", "x=1,y", " lead", "[x]")


def value_strategy(flag, spec, clean=False):
    """Values of one flag: valid, its range ends, general boundaries, words, paths (clean: valid
    values and benign paths only)."""
    parts = []
    if spec.kind == FLAG:
        return st.none()
    if spec.path:
        return st.sampled_from(BENIGN_PATHS if clean else PATHS)
    if clean and (spec.valid or spec.choices):
        return st.sampled_from(spec.valid + spec.choices)
    if spec.valid:
        parts.append((6, st.sampled_from(spec.valid)))
    if spec.choices:
        parts.append((6, st.sampled_from(spec.choices)))
    if spec.edge:
        parts.append((3, st.sampled_from(spec.edge)))
    parts.append((2, st.sampled_from(NUMBERS + NOT_NUMBERS)))
    parts.append((1, st.sampled_from(WORDS)))
    return st.one_of(*[s for w, s in parts for _ in range(w)])


def flag_forms(draw, flag, value, spec):
    """`--flag value`, `--flag=value` (or the short -j forms) as argument words."""
    name = flag
    if flag in SHORT and draw(st.booleans()):
        name = SHORT[flag]
    if spec.kind == FLAG:
        if draw(st.integers(0, 9)) == 0:
            return [name + "=" + draw(st.sampled_from(("true", "false", "maybe", "")))]
        return [name]
    form = draw(st.integers(0, 3))
    if form == 0:
        return [name + "=" + value]
    if form == 1 and name == "-j":
        return ["-j" + value]
    return [name, value]


# Values under which a run would be slow (many steps, many rows, big grids): an input drawing
# one of them runs to --tmax 0 only. They are valid, so such a run takes the time it asks for.
def risky(flag, text):
    v = as_number(text)
    if v is None:
        return False
    limits = {"--cfl": lambda x: x < 0.05, "--dr-inner": lambda x: x < 0.002,
              "--levels": lambda x: x >= 7, "--N": lambda x: x > 128,
              "--dt-series": lambda x: x < 0.01, "--dt-profiles": lambda x: x < 0.01,
              "--checkpoint-every": lambda x: 0 < x < 0.01, "--M": lambda x: x < 0.1,
              "--rmax": lambda x: x > 1e4, "--ah-every": lambda x: False}
    return limits.get(flag, lambda x: False)(v)


def evolve_pairs(draw, table=EVOLVE, exclude=(), clean=False):
    """A few (flag, value) pairs of evolve flags."""
    names = [f for f in sorted(table) if f not in exclude]
    chosen = draw(st.lists(st.sampled_from(names), max_size=6, unique=True))
    return [(f, draw(value_strategy(f, table[f], clean))) for f in chosen]


def config_file(draw):
    """A TOML-ish config file: known and unknown keys, values of every kind, sections,
    comments, escapes, odd line ends. Returns its bytes and the (flag, value) pairs it sets."""
    keys = [k[2:] for k in EVOLVE if k not in ("--config", "--print-config")]
    lines, pairs = [], []
    for _ in range(draw(st.integers(0, 7))):
        kind = draw(st.integers(0, 11))
        if kind <= 5:
            key = draw(st.sampled_from(keys))
            flag = "--" + key
            value = draw(value_strategy(flag, EVOLVE[flag])) if EVOLVE[flag].kind != FLAG \
                else draw(st.sampled_from(("true", "false", "yes", "1", "")))
            if EVOLVE[flag].kind == FLOAT or EVOLVE[flag].kind == INT:
                if draw(st.integers(0, 3)) == 0:
                    value = '"' + value + '"'
            elif EVOLVE[flag].kind == TEXT:
                q = draw(st.integers(0, 4))
                value = ['"' + value + '"', "'" + value + "'", value, '"' + value,
                         '"""' + value + '"""'][q]
            sep = draw(st.sampled_from((" = ", "=", " =", "\t=\t", " : ")))
            lines.append(key + sep + value)
            pairs.append((flag, value.strip("'\"")))
        elif kind == 6:
            lines.append(draw(st.sampled_from(("Nn", "n", "N N", "", "out.x", "evolve.N",
                                               "[x]", "é"))) + " = 1")
        elif kind == 7:
            lines.append(draw(st.sampled_from(("[evolve]", "[a.b]", "[[x]]", "[", "]", "[]"))))
        elif kind == 8:
            lines.append(draw(st.sampled_from(("# comment", "; comment", "#", "N = 32 # c",
                                               "rah-hAH-file = \"a#b\"", ""))))
        elif kind == 9:
            lines.append(draw(st.sampled_from(('out = "a\\"b"', 'id = "\\u0077ormhole"',
                                               'grid = "sinh\\x"', 'grid = "si\\nh"',
                                               "grid = 'sinh'", 'grid = """sinh\nuniform"""'))))
        elif kind == 10:
            lines.append(draw(st.sampled_from(("force = true", 'out = "out"', 'out = ""',
                                               "N = [32, 48]", "tmax = {a = 1}"))))
        else:
            lines.append(draw(st.sampled_from(("\x00", "\ufeffN = 32", "N = 32\r", "x" * 5000,
                                               "\xff = 1"))))
    end = draw(st.sampled_from(("\n", "\r\n", "")))
    text = "\n".join(lines) + (end if lines else "")
    return text.encode("utf-8", "surrogateescape"), pairs


@st.composite
def evolve_case(draw, clean=False):
    pairs = evolve_pairs(draw, exclude=("--config", "--print-config", "--rah-hAH-file")
                         if clean else ("--config",), clean=clean)
    files = []
    if clean and draw(st.integers(0, 3)) == 0:
        pairs.append(("--rah-hAH-file", HAH_FILE))
    if not clean and draw(st.integers(0, 3)) == 0:
        content, in_file = config_file(draw)
        files.append(("cfg.toml", content))
        if any(risky(f, v) for f, v in in_file):
            pairs.append(("--tmax", "0"))  # the file's own tmax is overridden
        pairs.append(("--config", draw(st.sampled_from(("cfg.toml",) * 6 + PATHS))))
    if not any(f == "--out" for f, _ in pairs) and draw(st.integers(0, 9)) > 0:
        pairs.append(("--out", draw(st.sampled_from(BENIGN_PATHS if clean else PATHS))))
    return pairs, files


@st.composite
def cases(draw):
    sub = draw(st.sampled_from(("evolve",) * 8 + ("converge",) * 3 + ("sweep",) * 3
                               + ("resume",) * 3 + ("top",)))
    files = []
    damage_kind = "none"
    # a third of the inputs have valid values only (and benign paths): they run, and what a
    # run writes is checked
    clean = draw(st.integers(0, 2)) == 0
    if sub == "evolve":
        pairs, files = draw(evolve_case(clean))
        table = EVOLVE
    elif sub == "converge":
        own = [(f, draw(value_strategy(f, CONVERGE[f], clean)))
               for f in draw(st.lists(st.sampled_from(sorted(CONVERGE)), max_size=4, unique=True))]
        if not any(f == "--N" for f, _ in own):
            own.append(("--N", draw(st.sampled_from(CONVERGE["--N"].valid))))
        if not any(f == "--out" for f, _ in own) and draw(st.integers(0, 9)) > 0:
            own.append(("--out", draw(st.sampled_from(PATHS))))
        pairs = own + evolve_pairs(draw, exclude=("--N", "--out", "--force", "--print-config"),
                                   clean=clean)
        table = {**EVOLVE, **CONVERGE}
        if not any(f in ("--rmax", "--grid") for f, _ in pairs):
            pairs.append(("--rmax", "50"))  # small members
    elif sub == "sweep":
        axes = []
        for _ in range(draw(st.integers(0 if draw(st.integers(0, 9)) == 0 else 1, 2))):
            flags = draw(st.lists(st.sampled_from(sorted(f for f in EVOLVE if f not in (
                "--config", "--print-config"))), min_size=1, max_size=2, unique=True))
            point = st.tuples(*[value_strategy(f, EVOLVE[f], clean) for f in flags]).map(
                lambda values: ":".join(v if v is not None else "true" for v in values))
            points = draw(st.lists(point, min_size=1, max_size=2, unique=True))
            axes.append(",".join(f[2:] for f in flags) + "=" + ",".join(points))
        if any(risky(f, v) for f, v in expanded([("--sweep", a) for a in axes])):
            # a swept --tmax would let a slow member run long: its values become 0
            axes = [a if not a.startswith("tmax=") else "tmax=" + ",".join(
                "0" if (as_number(x) or 0) > 0 and as_number(x) < 1e9 else x
                for x in a[5:].split(",")) for a in axes]
        if draw(st.integers(0, 9)) == 0:
            axes.append(draw(st.sampled_from(("N", "=1,2", "N=", "bogus=1,2", "N=32,,40",
                                              "out=a,b", "rah0=0.6,0.8\n9", "N=32 N=40"))))
        own = [("--sweep", a) for a in axes]
        for f in draw(st.lists(st.sampled_from(sorted(f for f in SWEEP if f != "--sweep")),
                               max_size=3, unique=True)):
            if f == "--member":
                own.append((f, draw(st.sampled_from(member_names(axes) + ("", "N=99", "x")))))
            elif f == "--emit-tasks":
                # not a FIFO: opening one for writing waits for a reader, as in every program
                # (and `--emit-tasks >(parallel ...)` relies on it)
                own.append((f, draw(st.sampled_from(tuple(p for p in PATHS if p != "fifo")))))
            else:
                own.append((f, draw(value_strategy(f, SWEEP[f]))))
        if not any(f == "--out" for f, _ in own) and draw(st.integers(0, 9)) > 0:
            own.append(("--out", draw(st.sampled_from(PATHS))))
        if not any(f == "--progress-every" for f, _ in own):
            own.append(("--progress-every", "0"))
        pairs = own + evolve_pairs(draw, exclude=("--out", "--print-config", "--config"),
                                   clean=clean)
        table = {**EVOLVE, **SWEEP}
    elif sub == "resume":
        damage_kind = draw(st.sampled_from(DAMAGES))
        pairs = [("DIR", draw(st.sampled_from((DONE, DONE, DAMAGED, DAMAGED, DAMAGED) + PATHS)))]
        if draw(st.booleans()):
            pairs.append(("--tmax", draw(value_strategy("--tmax", RESUME["--tmax"]))))
        table = RESUME
    else:  # no subcommand, a garbled one, a subcommand out of place, --help, --version
        pairs, _ = draw(evolve_case())
        table = EVOLVE
    pairs = make_cheap(pairs)
    if sub != "resume" and not any(f == "--tmax" for f, _ in pairs):
        pairs.append(("--tmax", draw(st.sampled_from(("0", "0", "0.25")))))
        if any(risky(f, v) for f, v in expanded(pairs)):
            pairs[-1] = ("--tmax", "0")
    if sub != "resume" and not any(f == "--N" for f, _ in pairs):
        pairs.append(("--N", "32"))
    groups = []  # a flag with its value
    for flag, value in pairs:
        if flag == "DIR":
            groups.append([value])
            continue
        spec = table.get(flag, Flag(TEXT))
        groups.append(flag_forms(draw, flag, value, spec))
    # a flag given twice
    if draw(st.integers(0, 14)) == 0 and pairs:
        flag, value = draw(st.sampled_from(pairs))
        if flag != "DIR":
            groups.append(flag_forms(draw, flag, value, table.get(flag, Flag(TEXT))))
    # flags in random order; rarely, words in random order (values parted from their flags)
    order = draw(st.integers(0, 19))
    if order == 0:
        words = draw(st.permutations([w for g in groups for w in g]))
    else:
        groups = draw(st.permutations(groups)) if order > 5 else groups
        words = [w for g in groups for w in g]
    if sub == "top":
        head = draw(st.sampled_from(("", "evolve2", "EVOLVE", "--help", "--version", "-h", "e",
                                     "--out", "help", "resume-x", "evolve --help")))
        words = head.split(" ") + words if head else words
        if draw(st.booleans()):
            words.insert(draw(st.integers(0, len(words))), "evolve")
    else:
        words = [sub] + words
    return Case(args=words, files=tuple(files), damage=damage_kind)


def member_names(axes):
    """The member folder names a sweep with these axes makes (as sweep.cpp names them)."""
    names = [""]
    for a in axes:
        if "=" not in a:
            return ()
        flags, values = a.split("=", 1)
        flags = flags.split(",")
        nxt = []
        for n in names:
            for point in values.split(","):
                vals = point.split(":")
                if len(vals) != len(flags):
                    return ()
                part = "_".join(f + "=" + v for f, v in zip(flags, vals))
                nxt.append((n + "_" if n else "") + part.replace("/", "_").replace(" ", "_"))
        names = nxt
    return tuple(n for n in names if n)[:3]


def expanded(pairs):
    """The (flag, value) pairs, with each --sweep axis as the pairs it sets."""
    out = []
    for f, v in pairs:
        if f == "--sweep" and "=" in v:
            names, values = v.split("=", 1)
            names = names.split(",")
            for point in values.split(","):
                out.extend(("--" + n, x) for n, x in zip(names, point.split(":")))
        else:
            out.append((f, v))
    return out


def make_cheap(pairs):
    """An input whose values would make a run slow runs to --tmax 0 (see `risky`)."""
    if any(risky(f, v) for f, v in expanded(pairs)):
        return [(f, "0" if f == "--tmax" and as_number(v) not in (None,) and as_number(v) > 0
                 and as_number(v) < 1e9 else v) for f, v in pairs]
    return pairs


# ---------------------------------------------------------------------------------------------
# Running one input and checking it.

LEAKS = ("terminate called", "std::", "filesystem error", "basic_string", "bad_alloc", "what():",
         "Assertion", "bad_optional_access", "vector::", "stoi", "stod", "Segmentation",
         "core dumped", "CLI::", "boost::", "Aborted")
# exit status 1 is a failed write (or `sweep --collect` with members not run yet)
WRITE_FAILURE = re.compile(r"cannot write|could not be written|cannot replace|is incomplete|"
                           r"for writing|standard output|did not complete")
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


def subcommand(args):
    return args[0] if args and args[0] in ("evolve", "converge", "sweep", "resume") else None


def resume_dir(args):
    """The DIR of `resume DIR [--tmax T]` (the word that is no flag nor --tmax's value)."""
    rest = []
    k = 1
    while k < len(args):
        if args[k] == "--tmax":
            k += 2
            continue
        if not args[k].startswith("--tmax="):
            rest.append(args[k])
        k += 1
    return rest[0] if len(rest) == 1 else None


def expected_refusals(case):
    """Why the input must be refused (exit 2) by the program's own rules, or []: a flag given
    twice, an empty value, no subcommand first, a malformed number."""
    args = case.args
    why = []
    if any(a in ("--help", "-h", "--version") for a in args):
        return why  # help wins over a malformed number (but not over the checks below)
    sub = subcommand(args)
    if args and not args[0].startswith("-") and sub is None:
        why.append(f"'{args[0]}' is not a subcommand")
    seen = set()
    for k, a in enumerate(args):
        if a == "":
            why.append("an empty argument")
        if len(a) > 2 and a.startswith("--") and a.endswith("="):
            why.append(f"{a} has an empty value")
        if a.startswith("-j") or (a.startswith("--") and a != "--"):
            name = a.split("=", 1)[0]
            name = "-j/--jobs" if a.startswith("-j") or name == "--jobs" else name
            if name != "--sweep" and name in seen:
                why.append(f"{name} is given twice")
            seen.add(name)
    if sub is not None:
        table = {**EVOLVE, **TABLE[sub]} if sub != "resume" else RESUME
        for k, a in enumerate(args[1:], 1):
            name, eq, value = a.partition("=")
            if not eq:
                if k + 1 >= len(args) or args[k + 1].startswith("--"):
                    continue
                value = args[k + 1]
            if name == "-j":
                name = "--jobs"
            elif a.startswith("-j") and not a.startswith("--"):
                name, value = "--jobs", a[2:]
            spec = table.get(name)
            if sub == "resume" and name != "--tmax":
                continue
            if spec and malformed(spec.kind, value):
                why.append(f"{name} = {value!r} is no number of its kind")
    return why


def check_dat(path):
    """A data file holds only '#' lines, blank lines and rows of numbers (summary.dat: rows of
    its header's width). Returns the first offending line, or None."""
    with open(path, "rb") as f:
        data = f.read()
    lines = data.decode("utf-8", "replace").split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    width = None
    for line in lines:
        if line.startswith("#"):
            if width is None and os.path.basename(path) == "summary.dat":
                width = len(line[1:].split())
            continue
        if line.strip() == "":
            continue
        tokens = line.split()
        if os.path.basename(path) == "summary.dat":
            if width is not None and len(tokens) != width:
                return line
            continue
        for t in tokens:
            try:
                float(t)
            except ValueError:
                return line
    return None


def out_dir(case):
    """The --out the command line names (a single one), else None."""
    outs = []
    for k, a in enumerate(case.args):
        if a == "--out" and k + 1 < len(case.args):
            outs.append(case.args[k + 1])
        elif a.startswith("--out="):
            outs.append(a[6:])
    return outs[0] if len(outs) == 1 else None


def may_change_done(case, status):
    """Whether the input asks to write into the finished run: --force with --out done (or a
    folder inside it), resume done with a --tmax after its end. (--emit-tasks never overwrites
    a file of other content, the finished run's included; a new file it names may be added.)"""
    args = case.args
    sub = subcommand(args)
    out = out_dir(case)
    target_done = out is not None and os.path.normpath(out).split(os.sep)[0] == DONE
    if sub == "resume":
        d = resume_dir(args)
        return d is not None and d != "" and os.path.normpath(d) == DONE and status == 0
    if sub == "sweep" and target_done:
        return True  # a sweep's --out is a folder it adds members to (a rerun resumes)
    forced = any(a == "--force" or a.startswith("--force=") for a in args)
    return target_done and (forced or out != DONE)


def check(exe, templates, case):
    """Runs the input in a fresh scratch folder; returns the violated invariants, as
    (kind, detail) pairs."""
    problems = []
    base = tempfile.mkdtemp(prefix="gbssn1d-fuzz-")
    try:
        root = os.path.join(base, "scratch")
        cwd = os.path.join(root, "cwd")
        capture = os.path.join(base, "capture")
        os.makedirs(cwd)
        os.makedirs(capture)
        lay_out(cwd, templates, case)
        before = fingerprint(root)
        status, err, out_text, timed_out = run(exe, case.args, cwd, capture)
        after = fingerprint(root)
        sub = subcommand(case.args)
        if timed_out:
            problems.append(("hang", f"no exit within {TIME_LIMIT:.0f} s"))
        elif status < 0 or status >= 128:
            problems.append(("signal", f"exit {status} (died by a signal)"))
        elif status not in ALLOWED[sub]:
            problems.append(("exit-status", f"exit {status}, not one of {sorted(ALLOWED[sub])}"))
        for leak in LEAKS:
            if leak in err:
                problems.append(("leak", f"stderr holds {leak!r}"))
                break
        if status == 1 and not WRITE_FAILURE.search(err):
            problems.append(("exit-1", "exit 1 without a failed write (a usage error is 2)"))
        if status == 2:
            changed = sorted(set(before) ^ set(after)
                             | {k for k in before if k in after and before[k] != after[k]})
            # documented: `sweep --member M` of an invalid member records its status in
            # OUT/logs/ (for --collect) and exits 2 (study/sweep.cpp, run_one_member)
            out = out_dir(case)
            if sub == "sweep" and out and any(a == "--member" or a.startswith("--member=")
                                              for a in case.args):
                where = os.path.normpath(os.path.join("cwd", out))
                changed = [c for c in changed if c != where and
                           not c.startswith(os.path.join(where, "logs"))]
            if changed:
                problems.append(("refusal-wrote", "refused but changed: "
                                 + ", ".join(repr(c) for c in changed[:4])))
            if not NAMES_A_FLAG.search(err):
                problems.append(("refusal-message", "refused without naming a flag"))
        why = expected_refusals(case)
        if why and status != 2 and not timed_out:
            problems.append(("not-refused", f"exit {status}, but must be refused: {why[0]}"))
        done_before = {k: v for k, v in before.items() if k.startswith("cwd/" + DONE + "/")}
        damaged = [k for k in done_before if after.get(k) != done_before[k]]
        if damaged and not may_change_done(case, status):
            problems.append(("done-changed", "the finished run changed: "
                             + ", ".join(repr(d) for d in damaged[:3])))
        for rel, value in after.items():
            if rel.endswith(".dat") and value.startswith("file:") and before.get(rel) != value:
                bad = check_dat(os.path.join(root, rel))
                if bad is not None:
                    problems.append(("dat-text", f"{rel[4:]} holds {bad[:80]!r}"))
                    break
        out = out_dir(case)
        if sub in ("evolve", "resume") and status in (0, 3) and not timed_out:
            folder = resume_dir(case.args) if sub == "resume" else out
            series = os.path.join(cwd, folder or "", "timeseries.dat")
            printing = any(a.startswith("--print-config") or a in ("--help", "-h")
                           for a in case.args)
            if folder and not printing and os.path.isfile(series):
                with open(series, "rb") as f:
                    last = (f.read().splitlines() or [b""])[-1]
                want = b"# end: completed" if status == 0 else b"# end: stopped"
                if not last.startswith(want):
                    problems.append(("end-line", f"exit {status} but the last line of "
                                     f"timeseries.dat is {last[:60]!r}"))
            if (sub == "evolve" and status == 0 and folder and not printing
                    and os.path.isfile(os.path.join(cwd, folder, "config.toml"))):
                cfg = os.path.join(folder, "config.toml")
                s2, err2, printed, _ = run(exe, ["evolve", "--config", cfg, "--print-config"],
                                           cwd, capture)
                # `force` is recorded but not taken from a config file (on purpose: a recorded
                # force = true must not let a rerun overwrite a finished run), so it is left out
                def params(text):
                    return "".join(line for line in text.splitlines(keepends=True)
                                   if not line.startswith("#") and not line.startswith("force ="))
                with open(os.path.join(cwd, cfg), "rb") as f:
                    recorded = params(f.read().decode("utf-8", "replace"))
                printed = params(printed)
                if s2 != 0 or printed != recorded:
                    diff = [f"{a.strip()!r} -> {b.strip()!r}" for a, b in
                            zip(recorded.splitlines(), printed.splitlines()) if a != b]
                    problems.append(("config-repeat", f"evolve --config {cfg} --print-config: "
                                     f"exit {s2}, " + (diff[0] if diff else err2.strip()[:100])))
        # an --out that is (or lies below) a symbolic link to nothing is refused as one, and
        # the link's target is not created (round 3: it was refused as 'File exists')
        if (sub in ("evolve", "converge", "sweep") and out is not None and not timed_out
                and os.path.normpath(out).split(os.sep)[0] == "dangling"):
            if os.path.lexists(os.path.join(cwd, "missing-target")):
                problems.append(("dangling-out", "the target of the dangling link --out "
                                 f"{out} was created"))
            elif "File exists" in err:
                problems.append(("dangling-out", f"--out {out}, a symbolic link to nothing (or "
                                 "below one), refused as 'File exists': "
                                 + err.strip().splitlines()[-1][:120]))
        case_result = (status, err)
    finally:
        subprocess.run(["chmod", "-R", "u+rwX", base], stderr=subprocess.DEVNULL)
        shutil.rmtree(base, ignore_errors=True)
    return problems, case_result


# ---------------------------------------------------------------------------------------------
# Scenarios (issue 37, round 3): what one argument vector cannot say. Two processes writing one
# folder at once; output files that are symbolic links; a run's resume files corrupted; a
# sweep's folder edited between runs. Each scenario lays out a fresh scratch folder with copies
# of small finished runs (make_references), changes it, runs one or two commands and compares
# what they leave with what the same commands leave on an intact copy (computed once, cached).

TINY = ["--id", "1log-trumpet", "--grid", "uniform", "--N", "32", "--rmax", "8"]
# a run that takes some 0.05-0.3 s, so that two of them overlap
BUSY = ["--id", "1log-trumpet", "--grid", "uniform", "--rmax", "8", "--dt-series", "0.05"]
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
SURFACES = ("concurrent", "links", "resume-files", "sweep-edits")
# the files a run resumes from (not compared as outputs: a refused or finished resume may leave
# a damaged one as it found it)
RESUME_FILES = ("checkpoint.bin", "converge_samples.bin", "rah-hAH-file.dat")
# what a refusal must name for each damaged resume file
NAMES_FILE = {"checkpoint.bin": "checkpoint", "rah-hAH-file.dat": "rah-hAH-file",
              "converge_samples.bin": "converge_samples"}
# exit 2 of one of two writers of a folder: the folder in use, or a documented refusal of what
# the other left there
IN_USE = re.compile(r"being written by another gbssn1d process|already being written")
# (a study or sweep of other inputs: "holds a converge study of other inputs", "holds members
# run with other inputs"; another command's run where a study would go: "is not a converge
# study's folder")
OTHER_REFUSALS = re.compile(r"exists and is not empty|of other inputs|run with other inputs"
                            r"|is not a converge study's folder")


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


# --- resume files corrupted -------------------------------------------------------------------

@st.composite
def resume_files_scenario(draw):
    study = draw(st.integers(0, 2)) == 0
    if study:
        folder = draw(st.sampled_from((STUDY + "/N32", STUDY + "/N40", STUDY + "/N48")))
        name = draw(st.sampled_from(("converge_samples.bin", "checkpoint.bin")))
        action = STUDY_ARGS + (["--force"] if draw(st.booleans()) else [])
        flag_file = "kept"
    else:
        folder = HALF
        name = draw(st.sampled_from(("checkpoint.bin", "rah-hAH-file.dat")))
        action = draw(st.sampled_from((["resume", HALF, "--tmax", "1"], ["resume", HALF],
                                       ["resume", HALF, "--tmax", "0.75"])))
        # the file --rah-hAH-file names, after the run: as it was, edited, or gone
        flag_file = draw(st.sampled_from(("kept", "edited", "edited", "deleted")))
    kind = draw(st.sampled_from(("flip", "flip", "truncate", "delete", "empty", "link-loop",
                                 "link-copy", "link-other")))
    where = draw(st.floats(0, 1))
    mask = draw(st.sampled_from((0x01, 0x40, 0x80, 0x10)))
    path = f"{folder}/{name}"
    step = {"flip": f"flip bit mask {mask:#x} of the byte at {where:.3f} of {path}",
            "truncate": f"truncate {path} to {where:.3f} of its size",
            "delete": f"rm {path}", "empty": f": > {path}",
            "link-loop": f"rm {path}; ln -s {name} {path}",
            "link-copy": f"mv {path} {OUTSIDE}/{name}; ln -s $PWD/{OUTSIDE}/{name} {path}",
            "link-other": f"ln -sf $PWD/{OUTSIDE}/other {path}  # another run's {name}"}[kind]
    steps = (step,)
    if flag_file != "kept":
        steps += (f"{'edit' if flag_file == 'edited' else 'rm'} {HAH_FILE}",)
    steps += (shell_line(action),)
    return Scenario("resume-files", steps, {"folder": folder, "name": name, "kind": kind,
                                            "where": where, "mask": mask,
                                            "flag_file": flag_file, "action": action})


OTHER_HAH = "# t r_ah\n" + "".join(f"{0.25 * k:g} {0.95 + 0.002 * k:g}\n" for k in range(21))


def corrupt(cwd, folder, name, kind, where, mask):
    path = os.path.join(cwd, folder, name)
    outside = os.path.join(cwd, OUTSIDE)
    if kind in ("flip", "truncate"):
        with open(path, "rb") as f:
            data = bytearray(f.read())
        k = min(len(data) - 1, int(where * len(data)))
        if kind == "flip":
            data[k] ^= mask
        else:
            data = data[:k]
        with open(path, "wb") as f:
            f.write(data)
    elif kind == "delete":
        os.remove(path)
    elif kind == "empty":
        open(path, "wb").close()
    elif kind == "link-loop":
        os.remove(path)
        os.symlink(name, path)
    elif kind == "link-copy":
        shutil.move(path, os.path.join(outside, name))
        os.symlink(os.path.join(outside, name), path)
    elif kind == "link-other":
        other = os.path.join(outside, "other")
        if name == "rah-hAH-file.dat":
            with open(other, "w") as f:
                f.write(OTHER_HAH)
        else:  # the same file of another run (another member, or another run's checkpoint)
            donor = {HALF: os.path.join(cwd, STUDY, "N32"), STUDY + "/N32":
                     os.path.join(cwd, STUDY, "N40")}.get(folder, os.path.join(cwd, STUDY, "N32"))
            shutil.copy(os.path.join(donor, name if name != "rah-hAH-file.dat" else
                                     "checkpoint.bin"), other)
        os.remove(path)
        os.symlink(other, path)


def check_resume_files(lab, s):
    """A corrupted resume file: the resume or rerun refuses (exit 2) naming the file, changing
    nothing, or ends as on the intact copy with the same outputs; never another success."""
    p = s.params
    top = p["folder"].split("/")[0]
    # the study's members take another run's checkpoint from the study: both are laid out
    names = (HALF, STUDY) if top == HALF else (STUDY,)
    ref_status, ref_out = lab.reference(names, [p["action"]], top)
    base, cwd = lab.scratch(names)
    problems = []
    try:
        if p["flag_file"] == "edited":
            with open(os.path.join(cwd, HAH_FILE), "w") as f:
                f.write(OTHER_HAH)
        elif p["flag_file"] == "deleted":
            os.remove(os.path.join(cwd, HAH_FILE))
        corrupt(cwd, p["folder"], p["name"], p["kind"], p["where"], p["mask"])
        before = fingerprint(os.path.join(cwd, top))
        outside_before = fingerprint(os.path.join(cwd, OUTSIDE))
        status, err, _, timed_out = run(lab.exe, p["action"], cwd, os.path.join(base, "capture"))
        problems += common_problems(p["action"][0], status, err, timed_out)
        if fingerprint(os.path.join(cwd, OUTSIDE)) != outside_before:
            problems.append(("link-followed", f"{p['folder']}/{p['name']} ({p['kind']}): the "
                             "file outside it points to changed"))
        if status == 2 and ref_status[0] != 2:
            if NAMES_FILE[p["name"]] not in err:
                problems.append(("resume-refusal", f"refused without naming {p['name']}: "
                                 f"{last_line(err)}"))
            if fingerprint(os.path.join(cwd, top)) != before:
                problems.append(("refusal-wrote", f"refused (exit 2) but {top} changed"))
        elif not timed_out and not problems:
            got = outputs(os.path.join(cwd, top))
            if status != ref_status[0] or got != ref_out:
                what = first_difference(got, ref_out) or "the same outputs"
                problems.append(("resume-differs", f"{p['folder']}/{p['name']} {p['kind']}: "
                                 f"exit {status} ({what}); on the intact copy exit "
                                 f"{ref_status[0]}; stderr: {last_line(err)}"))
    finally:
        shutil.rmtree(base, ignore_errors=True)
    return problems, status


# --- a sweep's folder edited between runs -------------------------------------------------------

SWEEP_EDITS = ("folder-deleted", "series-emptied", "series-truncated", "config-edited",
               "config-deleted", "status-deleted")
# edits after which a member is not a result until it runs again
DAMAGING = ("folder-deleted", "series-emptied", "series-truncated", "status-deleted")


@st.composite
def sweep_edits_scenario(draw):
    edits = draw(st.lists(st.tuples(st.sampled_from(SWEEP_MEMBERS), st.sampled_from(SWEEP_EDITS),
                                    st.floats(0, 0.999)),
                          min_size=1, max_size=2, unique_by=lambda e: e[0]))
    actions = draw(st.sampled_from((("collect",), ("rerun",), ("collect", "rerun"))))
    steps = []
    for member, edit, frac in edits:
        m = f"{SWEEP_DIR}/{member}"
        steps.append({"folder-deleted": f"rm -r {m}",
                      "series-emptied": f": > {m}/timeseries.dat",
                      "series-truncated": f"truncate {m}/timeseries.dat to {frac:.3f} of it",
                      "config-edited": f"sed -i s/ko-sigma = .*/ko-sigma = 0.3/ {m}/config.toml",
                      "config-deleted": f"rm {m}/config.toml",
                      "status-deleted": f"rm {SWEEP_DIR}/logs/{member}.status"}[edit])
    steps += [shell_line(SWEEP_ARGS + (["--collect"] if a == "collect" else [])) for a in actions]
    return Scenario("sweep-edits", tuple(steps), {"edits": edits, "actions": actions})


def edit_sweep(cwd, member, edit, frac):
    """Makes the edit; returns whether it cut timeseries.dat within its end line only (every
    row kept, the end line's tail lost)."""
    m = os.path.join(cwd, SWEEP_DIR, member)
    series = os.path.join(m, "timeseries.dat")
    if edit == "folder-deleted":
        shutil.rmtree(m)
    elif edit == "series-emptied":
        open(series, "wb").close()
    elif edit == "series-truncated":
        with open(series, "rb") as f:
            data = f.read()
        cut = int(frac * len(data))
        with open(series, "wb") as f:
            f.write(data[:cut])
        return cut > data.rfind(b"\n", 0, len(data) - 1) + len(b"# end: completed")
    elif edit == "config-edited":
        with open(os.path.join(m, "config.toml"), "rb") as f:
            text = f.read()
        with open(os.path.join(m, "config.toml"), "wb") as f:
            f.write(re.sub(rb"(?m)^ko-sigma = .*$", b"ko-sigma = 0.3", text))
    elif edit == "config-deleted":
        os.remove(os.path.join(m, "config.toml"))
    elif edit == "status-deleted":
        os.remove(os.path.join(cwd, SWEEP_DIR, "logs", member + ".status"))


def check_sweep_edits(lab, s):
    """A sweep folder edited between runs: --collect lists a member whose output is gone or
    cut short as missing (exit 1), never 'ok' (with nan), and every member it lists ok with the
    clean sweep's numbers; a rerun runs such a member again and ends with the clean sweep's
    summary and outputs. A member whose config.toml was edited (to other inputs) is not the
    member's run: --collect and a rerun refuse the folder (exit 2), naming it, and change
    nothing."""
    p = s.params
    _, clean = lab.reference((SWEEP_DIR,), [SWEEP_ARGS], SWEEP_DIR)
    clean = {rel: v for rel, v in clean.items() if rel.endswith(".dat")}
    clean_rows = summary_rows(os.path.join(lab.root, SWEEP_DIR, "summary.dat"))
    base, cwd = lab.scratch((SWEEP_DIR,))
    problems = []
    status = None
    try:
        # members whose timeseries.dat lost only the tail of its end line ('# end: completed
        # at t = 0.' for '... t = 0.5'): reported apart (it was a defect of its own)
        end_cut = {member for member, edit, frac in p["edits"]
                   if edit_sweep(cwd, member, edit, frac)}
        damaged = {member for member, edit, _ in p["edits"] if edit in DAMAGING}
        edited = {member for member, edit, _ in p["edits"] if edit == "config-edited"}
        for action in p["actions"]:
            args = SWEEP_ARGS + (["--collect"] if action == "collect" else [])
            before = fingerprint(os.path.join(cwd, SWEEP_DIR))
            status, err, _, timed_out = run(lab.exe, args, cwd, os.path.join(base, "capture"))
            problems += common_problems("sweep", status, err, timed_out)
            if edited:
                if status != 2 or not any(f"{m} (" in err and "in its folder's config.toml" in err
                                          for m in edited):
                    problems.append(("sweep-config-edited", f"{action}: exit {status}, wanted 2 "
                                     f"naming {', '.join(sorted(edited))}: {last_line(err)}"))
                elif fingerprint(os.path.join(cwd, SWEEP_DIR)) != before:
                    problems.append(("refusal-wrote", f"{action}: refused (exit 2) but "
                                     f"{SWEEP_DIR} changed"))
                if problems:
                    break
                continue
            rows = summary_rows(os.path.join(cwd, SWEEP_DIR, "summary.dat")) or {}
            for member, cols in rows.items():
                name = "ko-sigma=" + member
                if len(cols) > 1 and cols[1] == "ok" and "nan" in cols[3:9]:
                    problems.append(("sweep-ok-nan", f"{action}: {name} listed ok with nan: "
                                     + " ".join(cols[:8])))
                elif len(cols) > 1 and cols[1] == "ok" and cols != clean_rows.get(member):
                    problems.append(("sweep-numbers", f"{action}: {name} listed ok with "
                                     f"{' '.join(cols[2:8])}, the clean sweep's "
                                     f"{' '.join(clean_rows.get(member, ['?'] * 8)[2:8])}"))
            if action == "collect":
                want = 1 if damaged else 0
                for member in damaged:
                    cols = rows.get(member.split("=", 1)[1])
                    if cols is None or len(cols) < 2 or cols[1] != "missing":
                        problems.append(("sweep-end-line-cut" if member in end_cut else
                                         "sweep-not-missing", f"collect: {member} ("
                                         f"{dict((m, e) for m, e, _ in p['edits'])[member]}) "
                                         f"listed {cols[1] if cols and len(cols) > 1 else None}"
                                         ", not missing"))
                if status != want and not problems:
                    problems.append(("sweep-collect-exit", f"collect: exit {status}, wanted "
                                     f"{want}: {last_line(err)}"))
            else:
                # the results (a member's config.toml deleted by hand may stay so: the sweep
                # keeps each member's inputs in logs/)
                got = {rel: v for rel, v in outputs(os.path.join(cwd, SWEEP_DIR)).items()
                       if rel.endswith(".dat")}
                if status != 0 or got != clean:
                    where = first_difference(got, clean) or ""
                    problems.append(("sweep-end-line-cut" if where.split("/")[0] in end_cut
                                     else "sweep-rerun", f"rerun: exit {status} ("
                                     f"{first_difference(got, clean) or 'the same outputs'}); "
                                     f"a clean sweep: exit 0; {last_line(err)}"))
                damaged = set()
            if problems:
                break
    finally:
        shutil.rmtree(base, ignore_errors=True)
    return problems, status


SCENARIO_DRAW = {"concurrent": concurrent_scenario, "links": links_scenario,
                 "resume-files": resume_files_scenario, "sweep-edits": sweep_edits_scenario}
SCENARIO_CHECK = {"concurrent": check_concurrent, "links": check_links,
                  "resume-files": check_resume_files, "sweep-edits": check_sweep_edits}


@st.composite
def scenarios(draw, surfaces):
    return draw(SCENARIO_DRAW[draw(st.sampled_from(surfaces))]())


# Known defects: violations the current program still has, each reported (issue 37); matched
# by the invariant and the input, they are tallied and printed but do not fail the run. Remove
# an entry once its defect is fixed, so that it cannot come back unseen.
KNOWN_DEFECTS = ()


def flag_value(args, flag):
    return args[args.index(flag) + 1] if flag in args[:-1] else None


def known_defect(kind, case):
    for kinds, match, what in KNOWN_DEFECTS:
        try:
            if kind in kinds and match(case):
                return what
        except Exception:  # a matcher that does not apply to this input
            continue
    return None


# ---------------------------------------------------------------------------------------------
# A failure as a row of tests/cli/hostile_inputs.txt.


def short(word):
    """A word as a Python expression, a long repetition as 'unit' * n."""
    if len(word) > 80:
        for n in range(1, 10):
            unit, reps = word[:n], len(word) // n
            if unit * reps == word[:n * reps]:
                tail = word[n * reps:]
                return f"{unit!r} * {reps}" + (f" + {tail!r}" if tail else "")
    return repr(word)


def catalogue_word(word):
    if word == FRESH_OUT:
        return "{out}"
    if word == "--out=" + FRESH_OUT:
        return "--out={out}"
    if word == DONE:
        return "{done}"
    if "'" in word or "\\n" in word:
        return None
    if word == "" or re.search(r"[\s']", word) or "\\n" in word:
        return "'" + word.replace("\n", "\\n") + "'"
    return word


def catalogue_row(case, status, err, problem=""):
    lines = []
    if problem:
        lines.append(f"# fuzz: {problem}")
    if status is not None:
        lines.append(f"# observed: exit {status}; stderr: {err.strip()[:200]!r}")
    notes = []
    if case.damage != "none" and DAMAGED in case.args:
        notes.append(f"'{DAMAGED}' is a copy of {{done}} with damage '{case.damage}'")
    for name in ("loop", "dangling", "fifo", "adir", "afile", HAH_FILE):
        if any(name in a for a in case.args):
            notes.append(f"the scratch folder holds {name} (see cli_fuzz.py lay_out)")
    for name, content in case.files:
        text = content.decode("utf-8", "surrogateescape")
        if "'" in text or "\\n" in text:
            notes.append(f"@file {name} cannot be written as a row: {content!r}")
        else:
            lines.append(f"@file {name} '" + text.replace("\n", "\\n") + "'")
    words = [catalogue_word(w) for w in case.args]
    if None in words:
        notes.append(f"a word holds ' and cannot be a row word: {case.args!r}")
        words = [w if w is not None else "?" for w in words]
    flag = next((m.group(1) for m in [NAMES_A_FLAG.search(err)] if m), "--?") if err else "--?"
    row = f"2 | {flag} | " + " ".join(words)
    if len(row) > 1000:
        notes.append("words abbreviated: the whole row is longer than 1000 characters")
        row = f"2 | {flag} | " + " ".join(w if len(w) <= 80 else "<" + short(w) + ">"
                                          for w in words)
    lines.extend("# note: " + n for n in notes)
    lines.append(row)
    lines.append("# args: [" + ", ".join(short(a) for a in case.args) + "]")
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------


class InvariantFailure(AssertionError):
    pass


_failure_classes = {}


def failure(kind):
    """One exception class per invariant, so that hypothesis shrinks and reports each
    separately."""
    if kind not in _failure_classes:
        _failure_classes[kind] = type("Failure_" + kind.replace("-", "_"), (InvariantFailure,), {})
    return _failure_classes[kind]


def drive(name, strategy, check_one, report, limit, budget, opts, state):
    """Draws up to `limit` inputs from `strategy` (for `budget` seconds) and checks each with
    check_one(input) -> (problems, (label, status, detail)); a failure is shrunk and raised
    (--keep-going: tallied). A violation matched by KNOWN_DEFECTS is tallied apart."""
    start = time.monotonic()
    st_ = state.setdefault(name, {"runs": 0, "stopped": False})

    @hypothesis.settings(max_examples=limit, deadline=None, database=None,
                         print_blob=False, report_multiple_bugs=True,
                         suppress_health_check=list(hypothesis.HealthCheck))
    @hypothesis.seed(opts.seed)
    @hypothesis.given(strategy)
    def fuzz(case):
        over = budget > 0 and time.monotonic() - start > budget
        if over and not state["failed"]:
            st_["stopped"] = True
            return  # the budget is spent: no new inputs (a found failure still shrinks)
        st_["runs"] += 1
        if st_["runs"] % 1000 == 0:
            print(f"cli fuzz: {st_['runs']} {name}, {time.monotonic() - start:.0f} s",
                  flush=True)
        found, (label, status, err) = check_one(case)
        key = f"{label}:{status}"
        state["statuses"][key] = state["statuses"].get(key, 0) + 1
        if opts.only:
            found = [p for p in found if p[0] == opts.only]
        unknown = []
        for kind, detail in found:
            what = known_defect(kind, case)
            if what is None:
                unknown.append((kind, detail))
                continue
            seen = state["known"].setdefault(what, [])
            if not seen:
                print(f"\nknown defect (not failed): {kind}: {detail}\n{report(case, status, err)}",
                      flush=True)
            seen.append(kind)
        if not unknown:
            state["clean"] += 1 if not found else 0
            return
        if opts.keep_going:
            for kind, detail in unknown:
                t = state["tally"].setdefault(kind, [])
                if len(t) < 3:
                    t.append(report(case, status, err, f"{kind}: {detail}"))
                    print(f"\n[{name} {st_['runs']}] {kind}: {detail}\n"
                          + report(case, status, err), flush=True)
                else:
                    t.append(None)
            return
        state["failed"] = True
        kind, detail = unknown[0]
        raise failure(kind)(f"{kind}: {detail}\nreproducer:\n"
                            + report(case, status, err, f"{kind}: {detail}"))

    try:
        fuzz()
    except InvariantFailure:
        import traceback
        traceback.print_exc(limit=0)
        return 1
    except hypothesis.errors.Flaky as e:  # a failure that did not repeat (two processes' timing)
        cause = e.__cause__ or e.__context__
        print(f"\n{name}: a failure that did not repeat when replayed: {cause or e}", flush=True)
        return 1
    except BaseException as e:  # hypothesis' group of several distinct failures
        if not any(isinstance(x, InvariantFailure) for x in getattr(e, "exceptions", ())):
            raise
        for x in e.exceptions:
            print(f"\n{x}", flush=True)
        return 1
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True, help="the gbssn1d executable")
    ap.add_argument("--examples", type=int, default=400,
                    help="argument vectors to draw at most")
    ap.add_argument("--seed", type=int, default=1, help="hypothesis seed")
    ap.add_argument("--budget", type=float, default=40.0,
                    help="seconds after which no new argument vector is drawn (0: none)")
    ap.add_argument("--scenarios", type=int, default=250, help="scenarios to draw at most")
    ap.add_argument("--scenario-budget", type=float, default=20.0,
                    help="seconds after which no new scenario is drawn (0: none)")
    ap.add_argument("--surface", default="all",
                    help="what to fuzz, comma-separated: args, " + ", ".join(SURFACES)
                    + " (all: every one)")
    ap.add_argument("--keep-going", action="store_true",
                    help="tally failures by invariant instead of stopping and shrinking")
    ap.add_argument("--only", help="fail on this invariant only (and shrink it)")
    ap.add_argument("--check-flags", action="store_true", help="only check the flag table")
    ap.add_argument("--show", type=int, default=0, help="print N drawn inputs and exit")
    opts = ap.parse_args()
    exe = os.path.abspath(opts.exe)
    surfaces = ("args",) + SURFACES if opts.surface == "all" else tuple(opts.surface.split(","))
    unknown = [s for s in surfaces if s not in ("args",) + SURFACES]
    if unknown:
        ap.error(f"--surface: unknown {', '.join(unknown)}")
    scenario_surfaces = tuple(s for s in surfaces if s != "args")

    problems = check_flag_table(exe)
    if problems:
        print("the fuzzer's flag table and the program's --help differ:\n  "
              + "\n  ".join(problems))
        return 1
    print("flag table: agrees with --help of evolve, converge, sweep, resume")
    if opts.check_flags:
        return 0
    if opts.show:
        import warnings
        warnings.simplefilter("ignore")
        for _ in range(opts.show):
            if "args" in surfaces:
                print(repr(cases().example()))
            if scenario_surfaces:
                print(repr(scenarios(scenario_surfaces).example()))
        return 0

    start = time.monotonic()
    templates = make_templates(exe, tempfile.mkdtemp(prefix="gbssn1d-fuzz-templates-"))
    state = {"failed": False, "tally": {}, "statuses": {}, "known": {}, "clean": 0}
    status = 0
    try:
        if "args" in surfaces:
            def check_case(case):
                found, (st_, err) = check(exe, templates, case)
                return found, (subcommand(case.args), st_, err)
            status |= drive("inputs", cases(), check_case, catalogue_row, opts.examples,
                            opts.budget, opts, state)
        if scenario_surfaces and not (status and not opts.keep_going):
            make_references(exe, templates)
            lab = Lab(exe, templates)

            def check_scenario(s):
                found, st_ = SCENARIO_CHECK[s.surface](lab, s)
                return found, (s.surface, st_, "")

            def scenario_report(s, st_, err, problem=""):
                return (f"# fuzz: {problem}\n" if problem else "") + describe(s)
            status |= drive("scenarios", scenarios(scenario_surfaces), check_scenario,
                            scenario_report, opts.scenarios, opts.scenario_budget, opts, state)
    finally:
        shutil.rmtree(templates, ignore_errors=True)
    wall = time.monotonic() - start
    summary = ", ".join(f"{k} {v}" for k, v in sorted(state["statuses"].items()))
    runs = {k: v for k, v in state.items() if isinstance(v, dict) and "runs" in v}
    drawn = ", ".join(f"{v['runs']} {k}{' (budget spent)' if v['stopped'] else ''}"
                      for k, v in runs.items())
    print(f"\ncli fuzz: {drawn} run in {wall:.0f} s (seed {opts.seed}); "
          f"{state['clean']} clean; label:exit counts: {summary}")
    for what, seen in state["known"].items():
        print(f"cli fuzz: known defect seen {len(seen)} time(s), not failed: {what}")
    if opts.keep_going:
        for kind, rows in sorted(state["tally"].items()):
            print(f"\n== {kind}: {len(rows)} input(s); the first:")
            print(rows[0])
        status = 1 if state["tally"] else 0
    print(f"cli fuzz: {'FAILED' if status else 'passed'}")
    return status


if __name__ == "__main__":
    sys.exit(main())
