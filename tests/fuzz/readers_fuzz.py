#!/usr/bin/env python3
"""Fuzzer of gbssn1d's two readers of untrusted bytes: the checkpoint (resume DIR) and the
config file (--config FILE). Meant for the sanitizer build (tests/sanitize.sh), where a read past
an end, an overflow or any undefined behaviour stops the process with a report.

The checkpoint mutations know the format (src/evolution/checkpoint.cpp, format 3): the file is
parsed into its fields, one to three of them are changed (a count set to 0, n +- 1, 2^32, 2^63 or
2^64 - 1; a double to nan, inf, -0, 1e308 or a denormal; a flag byte to 2 or 255; the embedded
config text mutated as below; random bytes flipped, inserted or deleted; the file truncated; the
magic line of format 2), and the checksum is recomputed most of the time, so that the reader gets
past it to the fields. Sometimes the run folder's config.toml is mutated instead. The config
mutations are textual: lines deleted, repeated or swapped, values replaced by boundary and
malformed ones ('', '"', '"a\\', 1e400, nan, 0x10, [1, 2], strings with escapes, 5000 characters,
NUL), sections, stray bytes, CRLF line ends, a byte-order mark.

Every input must satisfy:
  - resume DIR [--tmax T]: exit 0, 2 or 3 (1 is a failed write, which nothing here causes); on a
    refusal (2) the folder is byte for byte as it was;
  - evolve --config FILE --print-config: exit 0 or 2; on 0 the printed configuration is a
    fixed point (printed again from itself, it is the same text);
  - no sanitizer report (ASAN_OPTIONS/UBSAN_OPTIONS log_path, set by tests/sanitize.sh, or a
    report on stderr), no death by a signal, no hang (60 s), no internals on stderr
    ('terminate called', 'what():', 'std::', 'filesystem error', 'Assertion').
A failing input is kept in the work folder with a file saying how to rerun it.

Usage:
  readers_fuzz.py --exe build-sanitize/gbssn1d --seconds 60 --seed 1    # as CI
  readers_fuzz.py --exe build-sanitize/gbssn1d --seconds 3600 --seed 7  # by hand
"""

import argparse
import filecmp
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

LEAKS = ("terminate called", "what():", "std::", "filesystem error", "Assertion",
         "runtime error:", "AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer")
MAGIC3 = b"gbssn1d checkpoint 4\n"  # the format written (the name kept: the magic's length)
MAGIC2 = b"gbssn1d checkpoint 2\n"
TIMEOUT = 60


def fnv1a(data):
    h = 14695981039346656037
    for c in data:
        h ^= c
        h = (h * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


class Layout:
    """The fields of a format-4 checkpoint: (offset, size, kind, name), kind one of
    'u64' (a count), 'i64', 'f64', 'u8' (a flag), 'bytes' (config text or a state's values)."""

    def __init__(self, data):
        self.fields = []
        self.pos = len(MAGIC3)
        self.data = data
        n_config = self.take(8, "u64", "config size")
        self.take(n_config, "bytes", "config")
        self.take(8, "i64", "step")
        for name in ("t", "dt"):
            self.take(8, "f64", name)
        for name in ("k_series", "k_profiles"):
            self.take(8, "i64", name)
        self.take(1, "u8", "h_AH flag")
        self.take(8, "f64", "h_AH")
        self.take(1, "u8", "horizon flag")
        self.take(1, "u8", "report flag")
        self.take(8, "u64", "evaluations")
        for name in ("series", "profiles", "horizons", "series header", "profiles header",
                     "horizons header", "series hash", "profiles hash", "horizons hash"):
            self.take(8, "u64", "mark " + name)
        self.state("u")
        for i in range(self.take(8, "u64", "finer count")):
            self.state(f"finer {i}")
        for i in range(self.take(8, "u64", "level h_AH count")):
            self.take(1, "u8", f"level h_AH flag {i}")
            self.take(8, "f64", f"level h_AH {i}")
        self.take(1, "u8", "shared h_AH flag")
        self.take(8, "f64", "shared h_AH")
        for i in range(self.take(8, "u64", "h_AH history count")):
            self.take(16, "bytes", f"h_AH history {i}")
        for i in range(self.take(8, "u64", "history count")):
            for j in range(self.take(8, "u64", f"history {i} levels")):
                self.take(8, "f64", f"history {i} {j} t")
                self.state(f"history {i} {j}")
        if self.pos != len(data) - 8:
            raise ValueError(f"checkpoint layout: {len(data) - 8 - self.pos} bytes left over")

    def take(self, size, kind, name):
        self.fields.append((self.pos, size, kind, name))
        value = None
        if kind == "u64":
            value = struct.unpack_from("<Q", self.data, self.pos)[0]
        self.pos += size
        return value

    def state(self, name):
        n = self.take(8, "u64", name + " count")
        self.take(8 * n, "bytes", name + " values")


COUNTS = [0, 1, 2, 3, 7, 8, 2**31, 2**32, 2**32 + 1, 2**61, 2**63, 2**64 - 1]
DOUBLES = [float("nan"), float("inf"), -float("inf"), -0.0, 0.0, 1e308, -1e308, 5e-324, -1.0,
           1e-300, 2.0**53]
VALUES = ['', '"', '"a\\', '"\\q"', '"\\u0041"', '"\\n#"', "1e400", "-1e400", "nan", "inf",
          "-0", "0x10", "032", "1_000", "[1, 2]", "{a = 1}", "true", "false", "1 2", "1,5",
          "9" * 400, '"' + "x" * 5000 + '"', "\x00", '"\x00"', "'single'", "1e-400", "-1",
          "0", "4294967297", "18446744073709551617", '"boxes"', '"uniform"', '"dense"',
          '"quadratic"', '"step"', '"7"', '"rah"', "2.5e2", "+3", ".5", "5.", "1e", "--1"]


def mutate_config(text, rng):
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        op = rng.randrange(11)
        i = rng.randrange(len(lines)) if lines else 0
        if op == 0 and lines:
            del lines[i]
        elif op == 1 and lines:
            lines.insert(i, lines[i])  # a key given twice
        elif op == 2 and lines and "=" in lines[i]:
            key = lines[i].split("=", 1)[0]
            lines[i] = key + "= " + rng.choice(VALUES)
        elif op == 3:
            lines.insert(i, rng.choice(["[evolve]", "[", "[[a]]", "= 1", "key", "a.b = 1",
                                        "N = 1 # c", "N=1=2", " \t", "#", "x = \"\"\"a"]))
        elif op == 4 and lines:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif op == 5 and lines and "=" in lines[i]:
            key, value = lines[i].split("=", 1)
            lines[i] = rng.choice([key.upper(), key + "x", "", key.strip() + " \t"]) + "=" + value
        elif op == 6:
            return "\ufeff" + "\n".join(lines) if rng.random() < 0.5 else "\r\n".join(lines)
        elif op == 7 and lines:
            line = bytearray(lines[i].encode("utf-8", "surrogateescape"))
            for _ in range(rng.randint(1, 4)):
                if line:
                    line[rng.randrange(len(line))] = rng.randrange(256)
            lines[i] = line.decode("utf-8", "surrogateescape")
        elif op == 8 and lines and "=" in lines[i]:
            lines[i] = lines[i] + rng.choice([" x", " # ok", "\"", " =", "\\"])
        elif op == 9:
            lines = lines[: rng.randrange(len(lines) + 1)]
        elif op == 10 and lines and '"' in lines[i]:
            key = lines[i].split("=", 1)[0]
            s = "".join(rng.choice(['\\"', "\\\\", "\\n", "\\t", "\\", "#", "'", "é", "\x7f",
                                    "a"]) for _ in range(rng.randint(1, 6)))
            lines[i] = f'{key}= "{s}"'
    return "\n".join(lines)


def mutate_checkpoint(data, rng):
    """A mutated checkpoint, and a word on what was done."""
    layout = Layout(data)
    body = bytearray(data[:-8])
    done = []
    for _ in range(rng.randint(1, 3)):
        off, size, kind, name = rng.choice(layout.fields)
        op = rng.randrange(10)
        if op <= 2 and kind == "u64":
            v = rng.choice(COUNTS + [struct.unpack_from("<Q", body, off)[0] + rng.choice([-1, 1])])
            struct.pack_into("<Q", body, off, v % 2**64)
            done.append(f"{name} = {v}")
        elif op <= 2 and kind in ("f64", "i64"):
            if kind == "f64":
                struct.pack_into("<d", body, off, rng.choice(DOUBLES))
            else:
                struct.pack_into("<q", body, off, rng.choice([-1, 0, 2**62, -2**63, 2**63 - 1]))
            done.append(f"{name} changed")
        elif op <= 2 and kind == "u8":
            body[off] = rng.choice([2, 255])
            done.append(f"{name} = {body[off]}")
        elif op == 3 and name == "config":
            text = mutate_config(bytes(body[off:off + size]).decode("utf-8", "surrogateescape"), rng)
            new = text.encode("utf-8", "surrogateescape")
            body[off:off + size] = new
            struct.pack_into("<Q", body, off - 8, len(new))
            done.append("embedded config mutated")
            layout = Layout(bytes(body) + b"\0" * 8)  # offsets moved
        elif op == 4 and len(body) > len(MAGIC3):
            for _ in range(rng.randint(1, 8)):
                body[rng.randrange(len(MAGIC3), len(body))] ^= 1 << rng.randrange(8)
            done.append("bits flipped")
            break  # the layout no longer holds
        elif op == 5:
            at = rng.randrange(len(MAGIC3), len(body) + 1)
            body[at:at] = bytes(rng.randrange(256) for _ in range(rng.choice([1, 7, 8, 9, 64])))
            done.append("bytes inserted")
            break
        elif op == 6 and len(body) > len(MAGIC3) + 1:
            at = rng.randrange(len(MAGIC3), len(body) - 1)
            del body[at:at + rng.choice([1, 8, 9, 100])]
            done.append("bytes deleted")
            break
        elif op == 7:
            del body[rng.randrange(len(body) + 1):]
            done.append("truncated")
            break
        elif op == 8:
            body[: len(MAGIC2)] = MAGIC2
            done.append("format 2 magic")
        elif op == 9 and kind == "bytes" and size:
            at = off + rng.randrange(size)
            body[at] = rng.randrange(256)
            done.append(f"a byte of {name}")
    if rng.random() < 0.85:
        body += struct.pack("<Q", fnv1a(body))
        done.append("checksum recomputed")
    else:
        body += data[-8:]
    return bytes(body), ", ".join(done)


def snapshot(folder):
    return {name: open(os.path.join(folder, name), "rb").read()
            for name in sorted(os.listdir(folder))}


class Fuzzer:
    def __init__(self, exe, work, logs):
        self.exe = exe
        self.work = work
        self.logs = logs
        self.failures = 0

    def run(self, args, cwd):
        try:
            p = subprocess.run([self.exe] + args, cwd=cwd, capture_output=True,
                               timeout=TIMEOUT, stdin=subprocess.DEVNULL)
            return p.returncode, p.stdout.decode("utf-8", "replace"), \
                p.stderr.decode("utf-8", "replace")
        except subprocess.TimeoutExpired:
            return None, "", f"(no exit within {TIMEOUT} s)"

    def sanitizer_reports(self):
        if not self.logs or not os.path.isdir(self.logs):
            return []
        return sorted(os.listdir(self.logs))

    def judge(self, case, args, status, err, allowed, extra=None):
        problems = []
        if status is None:
            problems.append(err)
        elif status < 0:
            problems.append(f"killed by signal {-status}")
        elif status not in allowed:
            problems.append(f"exit {status}, expected one of {sorted(allowed)}")
        for word in LEAKS:
            if word in err:
                problems.append(f"stderr holds {word!r}")
        reports = self.sanitizer_reports()
        if reports:
            problems.append("sanitizer reports: " + ", ".join(reports))
        if extra:
            problems.append(extra)
        if problems:
            self.failures += 1
            with open(os.path.join(case, "FAILED.txt"), "w") as f:
                f.write("rerun: (cd {} && {} {})\n".format(case, self.exe, " ".join(args)))
                f.write("\n".join(problems) + "\n--- stderr:\n" + err)
            print(f"FAILED {case}: " + "; ".join(problems), flush=True)
            print("  stderr: " + err.strip().replace("\n", "\n  ")[:2000], flush=True)
            for name in reports:  # keep the reports with the case, so the next input starts clean
                shutil.move(os.path.join(self.logs, name), os.path.join(case, name))
            return False
        return True


def make_bases(fz):
    """Short runs whose checkpoints are the seeds: a single grid with beta_H, boxes in each
    time interpolation, a shrinking horizon with the h_AH history."""
    specs = {
        "sinh-rah": ["--N", "40", "--rahA", "0.5", "--rah0", "1.2"],
        "boxes-rk": ["--grid", "boxes", "--rmax", "32", "--N", "16", "--rahA", "0.5"],
        "boxes-quadratic": ["--grid", "boxes", "--rmax", "32", "--N", "16",
                            "--time-interp", "quadratic"],
        "boxes-dense-step": ["--grid", "boxes", "--rmax", "16", "--N", "16",
                             "--time-interp", "dense", "--rahA", "1", "--rah0", "0.7",
                             "--ah-every", "step"],
    }
    bases = {}
    for name, flags in specs.items():
        out = os.path.join(fz.work, "base-" + name)
        args = ["evolve", "--id", "1log-trumpet", "--tmax", "1", "--checkpoint-every", "0.5",
                "--dt-series", "0.25", "--out", out] + flags
        status, _, err = fz.run(args, fz.work)
        if status != 0 or not os.path.isfile(os.path.join(out, "checkpoint.bin")):
            sys.exit(f"readers_fuzz: the base run {name} failed (exit {status}): {err}")
        Layout(open(os.path.join(out, "checkpoint.bin"), "rb").read())  # the format as known
        bases[name] = out
    if fz.sanitizer_reports():
        sys.exit("readers_fuzz: the base runs themselves gave sanitizer reports: "
                 + ", ".join(fz.sanitizer_reports()))
    return bases


def checkpoint_case(fz, bases, rng, case):
    base = bases[rng.choice(sorted(bases))]
    shutil.copytree(base, case)
    cp = os.path.join(case, "checkpoint.bin")
    data = open(cp, "rb").read()
    if rng.random() < 0.2:
        cfg = os.path.join(case, "config.toml")
        text = mutate_config(open(cfg, encoding="utf-8").read(), rng)
        open(cfg, "w", encoding="utf-8", errors="surrogateescape").write(text)
    else:
        new, _ = mutate_checkpoint(data, rng)
        open(cp, "wb").write(new)
    before = snapshot(case)
    args = ["resume", case] + (["--tmax", "1.25"] if rng.random() < 0.5 else [])
    status, _, err = fz.run(args, fz.work)
    extra = None
    if status == 2 and snapshot(case) != before:
        extra = "refused (exit 2), yet the folder changed"
    return fz.judge(case, args, status, err, {0, 2, 3}, extra), status


def config_case(fz, bases, rng, case):
    os.makedirs(case)
    base = bases[rng.choice(sorted(bases))]
    text = mutate_config(open(os.path.join(base, "config.toml"), encoding="utf-8").read(), rng)
    cfg = os.path.join(case, "in.toml")
    open(cfg, "w", encoding="utf-8", errors="surrogateescape").write(text)
    args = ["evolve", "--config", cfg, "--print-config"]
    status, out, err = fz.run(args, case)
    extra = None
    if status == 0:
        again = os.path.join(case, "printed.toml")
        open(again, "w").write(out)
        s2, out2, err2 = fz.run(["evolve", "--config", again, "--print-config"], case)
        if s2 != 0 or out2 != out:
            extra = f"the printed configuration is not a fixed point (exit {s2}): {err2.strip()}"
    if sorted(os.listdir(case)) not in (["in.toml"], ["in.toml", "printed.toml"]):
        extra = "files created: " + ", ".join(sorted(os.listdir(case)))
    return fz.judge(case, args, status, err, {0, 2}, extra), status


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--seconds", type=float, default=60, help="wall-clock budget")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--work", help="work folder (kept); default a temporary one, removed if "
                                   "nothing failed")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="readers-fuzz-")
    os.makedirs(work, exist_ok=True)
    logs = None
    for var in ("ASAN_OPTIONS", "UBSAN_OPTIONS"):
        m = re.search(r"log_path=([^:]+)", os.environ.get(var, ""))
        if m:
            logs = os.path.dirname(m.group(1))
    fz = Fuzzer(exe, work, logs)
    bases = make_bases(fz)
    rng = random.Random(args.seed)
    start = time.time()
    counts = {"checkpoint": {}, "config": {}}  # exit statuses, for each kind of input
    i = 0
    while time.time() - start < args.seconds:
        kind = "checkpoint" if i % 3 != 2 else "config"
        case = os.path.join(work, f"case-{i:05d}")
        run_case = checkpoint_case if kind == "checkpoint" else config_case
        ok, status = run_case(fz, bases, rng, case)
        counts[kind][status] = counts[kind].get(status, 0) + 1
        if ok:
            shutil.rmtree(case, ignore_errors=True)
        i += 1
    took = time.time() - start
    tally = {kind: ", ".join(f"{n} exit {s}" for s, n in sorted(c.items(), key=str))
             for kind, c in counts.items()}
    print(f"readers fuzz: {sum(counts['checkpoint'].values())} checkpoints "
          f"({tally['checkpoint']}) and {sum(counts['config'].values())} config files "
          f"({tally['config']}) in {took:.0f} s (seed {args.seed}), {fz.failures} failing"
          + (f", kept in {work}" if fz.failures else ""))
    if not fz.failures and not args.work:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if fz.failures else 0


if __name__ == "__main__":
    sys.exit(main())
