"""How the command-line fuzzer draws argument vectors (`cases`: a subcommand, flags of the table
in cli_fuzz_flags.py with valid, boundary or malformed values, config files, hostile paths, in
random order and forms), and a failing one written as a row of tests/cli/hostile_inputs.txt
(catalogue_row)."""

import dataclasses
import re

from hypothesis import strategies as st

from cli_fuzz_common import HAH_FILE, NAMES_A_FLAG
from cli_fuzz_flags import (CONVERGE, DAMAGED, DAMAGES, DONE, EVOLVE, FLAG, FLOAT, FRESH_OUT, INT,
                            NOT_NUMBERS, NUMBERS, PATHS, RESUME, SHORT, SWEEP, TEXT, WORDS, Flag)

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
            notes.append(f"the scratch folder holds {name} (see cli_fuzz_flags.py lay_out)")
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
