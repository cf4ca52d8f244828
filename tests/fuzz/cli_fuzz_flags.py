"""The command-line fuzzer's vocabulary: the flag table (checked against each subcommand's
--help by check_flag_table), the values drawn besides a flag's own, and the scratch folder an
argument vector runs in, with the hostile paths it names (lay_out)."""

import dataclasses
import os
import re
import shutil
import subprocess

from cli_fuzz_common import HAH_FILE

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
    "--id": Flag(TEXT, choices=("wormhole", "maximal-trumpet", "1log-trumpet", "flat")),
    "--M": Flag(FLOAT, ("1", "0.5", "2"), ("1e-3", "1e3", "1e-4", "1e308")),
    "--lapse0": Flag(TEXT, choices=("one", "precollapsed")),
    "--matter": Flag(TEXT, choices=("none", "scalar")),
    "--scalar-amp": Flag(FLOAT, ("0.01", "0.001", "-0.01"), ("1e308", "-1e308", "10")),
    "--scalar-r0": Flag(FLOAT, ("10", "5", "0"), ("-1", "1e308", "1e-300")),
    "--scalar-width": Flag(FLOAT, ("2", "1", "3"), ("0", "-1", "1e308", "1e-300")),
    "--flux-R": Flag(TEXT, ("5", "5,20", "2.5, 30"), ("", "0", "-1", "5,5", "5,,3", "nan", "1e308",
                                                    "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17")),
    "--formulation": Flag(TEXT, choices=("bssn", "z4c")),
    "--gbssn-volume": Flag(TEXT, choices=("lagrangian", "eulerian")),
    "--kappa1": Flag(FLOAT, ("0", "0.02", "0.1"), ("-1e-300", "1e308")),
    "--kappa1-hole": Flag(FLOAT, ("0", "1", "2"), ("-1", "nan", "1e308")),
    "--kappa2": Flag(FLOAT, ("0", "0.5"), ("-1", "-0.9999999", "1e308")),
    "--z4c-lapse-adm": Flag(FLAG),
    "--eta": Flag(FLOAT, ("0", "1", "2"), ("1e308", "-1e-300")),
    "--advective-shift": Flag(FLAG),
    "--non-advective-lapse": Flag(FLAG),
    "--shift": Flag(TEXT, choices=("gamma-driver", "zero")),
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
# (and HAH_FILE, in cli_fuzz_common.py: the scenarios copy it too)
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
