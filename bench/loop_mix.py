#!/usr/bin/env python3
"""The instruction mix of the right-hand side's point loop, counted from the compiled code.

    python3 bench/loop_mix.py [OBJECT] [--symbol REGEX] [--mca [--mcpu CPU]]
    python3 bench/loop_mix.py --check-vectorised OBJECT...

Disassembles OBJECT (default: build/CMakeFiles/gbssn1d_core.dir/src/gbssn/rhs_bssn.cpp.o) with
objdump, takes the function whose mangled name matches REGEX (default: the 4th-order, lopsided,
plain BSSN instance of GbssnRhs::interior), finds its main vectorised loop (the innermost
backward jump whose body is mostly full-width vector instructions) and prints, per iteration and
per grid point (an iteration handles `lanes` points: 8 for 512-bit registers, 4 for 256-bit):
floating-point arithmetic instructions by kind, divisions and square roots, loads by where they
read (the staged block: data; the stack: spilled registers; constants) and stores; and the flops
of one point (an FMA counts two; each vector instruction does one lane's work for each point).
docs/roofline.md reads these counts against the machine's ceilings (gbssn1d_bench --sections
peak).
The loop body is branch-free, so the static count of one iteration is its dynamic count.

--mca: also runs LLVM's machine-code analyser (llvm-mca, Debian package llvm) on the loop body:
its model of the CPU's ports, latencies and out-of-order window (-mcpu, default: this host's
CPU) gives the cycles an iteration takes when every load hits L1 (no line splits, no aliasing)
and the front end keeps up, and the pressure on each port (the busiest ones bound the loop).
Prints those cycles per iteration and per point (the backward jump left out), the loop's bytes
of code, and the busiest ports (--mca-asm FILE: also the assembly given to llvm-mca).

--check-vectorised: for every instance of GbssnRhs::interior and of the loop that writes beta_H
(fill_horizon_shift, one per normal) in the OBJECTs (those without one are skipped; at least one
must hold one), requires that its point loop be vectorised: among the innermost loops holding at least half of the most
floating-point arithmetic (the point loop and its scalar remainder hold the same), one with at
least 90% of it packed (..pd) rather than scalar (..sd); prints one line per instance and exits
1 naming each one that is not. A call left in the loop (an equation GCC did not inline) stops
vectorisation and costs a factor of about 8 (docs/roofline.md, Sec. 6). beta_H's loops must also
hold no division or square root: s^r without the divider (sqrt_quotient) runs 3.5 times faster
(docs/roofline.md, Sec. 4).
"""
import argparse
import collections
import re
import subprocess
import sys

DEFAULT_OBJECT = "build/CMakeFiles/gbssn1d_core.dir/src/gbssn/rhs_bssn.cpp.o"
DEFAULT_SYMBOL = r"interiorINS_4BssnENS_6VacuumELi4ELNS_2fd6UpwindE0ELb0E"

INSTRUCTION = re.compile(r"\s*([0-9a-f]+):\s+(\S+)\s*(.*)")


def disassemble(obj, symbol_regex):
    names = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
    symbols = [line.split()[-1] for line in names.splitlines()
               if re.search(symbol_regex, line) and line.split()[-2] in "tTwW"]
    if not symbols:
        sys.exit(f"loop_mix.py: no function matching {symbol_regex!r} in {obj}")
    text = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-M", "intel",
                           f"--disassemble={symbols[0]}", obj],
                          capture_output=True, text=True, check=True).stdout
    out = []
    for line in text.splitlines():
        m = INSTRUCTION.match(line)
        if m:
            out.append((int(m.group(1), 16), m.group(2), m.group(3)))
    return symbols[0], out


# the mangled names of the loops --check-vectorised checks
CHECKED_LOOPS = ("GbssnRhs8interiorI", "fill_horizon_shift")
DIVIDER = re.compile(r"v?(div|sqrt)(p|s)d$")
FP_ARITHMETIC = re.compile(r"v?(f(n?)m(add|sub)\d+|mul|add|sub|div)(p|s)d$")


def fp_arithmetic(body):
    """(packed, scalar) floating-point arithmetic instructions of a loop body."""
    packed = scalar = 0
    for _, mnemonic, _ in body:
        m = FP_ARITHMETIC.match(mnemonic)
        if m:
            packed += m.group(4) == "p"
            scalar += m.group(4) == "s"
    return packed, scalar


def innermost_loops(ins):
    where = {a: i for i, (a, _, _) in enumerate(ins)}
    loops = []
    for i, (a, mnemonic, operands) in enumerate(ins):
        if mnemonic.startswith("j"):
            target = re.match(r"([0-9a-f]+)", operands)
            if target and int(target.group(1), 16) <= a and int(target.group(1), 16) in where:
                loops.append((where[int(target.group(1), 16)], i))
    return [(b, e) for b, e in loops
            if not any(b <= b2 and e2 <= e and (b2, e2) != (b, e) for b2, e2 in loops)]


def check_vectorised(objects):
    failed = []
    found = 0
    for obj in objects:
        names = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
        symbols = sorted({line.split()[-1] for line in names.splitlines()
                          if any(name in line for name in CHECKED_LOOPS)
                          and line.split()[-2] in "tTwW"})
        found += len(symbols)
        for symbol in symbols:
            _, ins = disassemble(obj, re.escape(symbol) + "$")
            # the point loop and its scalar remainder hold the same arithmetic: the loop is
            # vectorised if one of the loops with at least half of the most arithmetic of one
            # kind is packed (of one kind: with 256-bit vectors GCC lays out a 2-lane epilogue
            # and the scalar remainder inside one backward jump, which holds both kinds, 370
            # packed and 371 scalar instructions beside the point loop's 370 packed)
            counts = [fp_arithmetic(ins[b:e + 1]) for b, e in innermost_loops(ins)]
            most = max((max(c) for c in counts), default=0)
            packed_loops = [c for c in counts if sum(c) >= 0.5 * most and c[0] >= 0.9 * sum(c)]
            ok = most > 0 and bool(packed_loops)
            divider = [m for _, m, _ in ins if DIVIDER.match(m)]
            if "fill_horizon_shift" in symbol and divider:
                ok = False
                print(f"uses the divider: {', '.join(sorted(set(divider)))}")
            packed, scalar = max(packed_loops, key=sum) if ok else max(counts, key=sum,
                                                                         default=(0, 0))
            demangled = subprocess.run(["c++filt", symbol], capture_output=True,
                                       text=True).stdout.strip()
            print(f"{'vectorised' if ok else 'NOT VECTORISED'}: {packed} packed, {scalar} scalar "
                  f"arithmetic instructions: {demangled}")
            if not ok:
                failed.append(demangled)
    if not found:
        sys.exit("loop_mix.py: no instance of GbssnRhs::interior or fill_horizon_shift in "
                 + " ".join(objects))
    if failed:
        print(f"loop_mix.py: {len(failed)} of {found} point loops not vectorised:", *failed,
              sep="\n  ")
        return 1
    print(f"loop_mix.py: all {found} point loops vectorised")
    return 0


def main_loop(ins):
    """The innermost backward-jump loop with the most full-width vector instructions."""
    where = {a: i for i, (a, _, _) in enumerate(ins)}
    loops = []
    for i, (a, mnemonic, operands) in enumerate(ins):
        if mnemonic.startswith("j"):
            target = re.match(r"([0-9a-f]+)", operands)
            if target and int(target.group(1), 16) <= a and int(target.group(1), 16) in where:
                loops.append((where[int(target.group(1), 16)], i))
    innermost = [(b, e) for b, e in loops
                 if not any(b <= b2 and e2 <= e and (b2, e2) != (b, e) for b2, e2 in loops)]
    def width_count(loop, reg):
        return sum(reg in ins[k][2] for k in range(loop[0], loop[1] + 1))
    best = max(innermost, key=lambda lp: max(width_count(lp, "zmm"), width_count(lp, "ymm")))
    lanes = 8 if width_count(best, "zmm") >= width_count(best, "ymm") else 4
    return ins[best[0]:best[1] + 1], lanes


def classify(body):
    kinds = collections.Counter()
    loads = collections.Counter()
    stores = 0
    for _, mnemonic, operands in body:
        if re.match(r"vf(n?)m(add|sub)\d+pd", mnemonic):
            kinds["fma"] += 1
        elif re.match(r"vmulpd", mnemonic):
            kinds["mul"] += 1
        elif re.match(r"v(add|sub)pd", mnemonic):
            kinds["add/sub"] += 1
        elif re.match(r"v(min|max|and|andn|or|xor)pd|vblendm|vcmp", mnemonic):
            kinds["other vector"] += 1
        elif mnemonic == "vdivpd":
            kinds["div"] += 1
        elif mnemonic == "vsqrtpd":
            kinds["sqrt"] += 1
        parts = operands.split(",")
        if "PTR" in parts[0] and not mnemonic.startswith(("lea", "nop", "prefetch")):
            stores += 1
        elif "PTR" in operands and not mnemonic.startswith(("lea", "nop", "prefetch")):
            base = re.search(r"\[(\w+)", operands).group(1)
            loads["stack (spilled registers)" if base == "rsp" else
                  "constants" if base == "rip" else "data"] += 1
    return kinds, loads, stores


def mca(body, mcpu, asm_file=None, iterations=300):
    """llvm-mca's cycles per iteration of the loop body and the pressure on each resource (its
    ports; on some models numbered units of one resource, labelled [12.0], [12.1] ...)."""
    asm = [".intel_syntax noprefix"]
    for _, mnemonic, operands in body[:-1]: # the backward jump is left out
        operands = re.sub(r"<[^>]*>", "", re.sub(r"\s*#.*", "", operands))
        asm.append(f"{mnemonic} {operands}")
    text = "\n".join(asm) + "\n"
    if asm_file:
        with open(asm_file, "w") as f:
            f.write(text)
    try:
        out = subprocess.run(["llvm-mca", f"-mcpu={mcpu}", f"-iterations={iterations}",
                              "-timeline=false", "-instruction-info=false"],
                             input=text, capture_output=True, text=True, check=True).stdout
    except FileNotFoundError:
        sys.exit("loop_mix.py: --mca needs llvm-mca (Debian package llvm)")
    except subprocess.CalledProcessError as e:
        sys.exit(f"loop_mix.py: llvm-mca failed: {e.stderr.strip()}")
    cycles = int(re.search(r"Total Cycles:\s+(\d+)", out).group(1)) / iterations
    names = dict(re.findall(r"^\[([\d.]+)\]\s+- (\S+)", out, re.M))
    lines = out.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("Resource pressure per iter"))
    labels = re.findall(r"\[([\d.]+)\]", lines[at + 1])
    values = lines[at + 2].split()
    if len(labels) != len(values) or any(label not in names for label in labels):
        sys.exit("loop_mix.py: llvm-mca's resource pressure table not understood")
    # a unit of a resource with several keeps its number: Zn3FPP45.0, Zn3FPP45.1
    pressure = {names[label] + (label[label.index("."):] if "." in label else ""):
                (0.0 if value == "-" else float(value)) for label, value in zip(labels, values)}
    return cycles, pressure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("object", nargs="*", default=[DEFAULT_OBJECT])
    parser.add_argument("--symbol", default=DEFAULT_SYMBOL,
                        help="regular expression on the mangled function name")
    parser.add_argument("--check-vectorised", action="store_true",
                        help="require every point-loop instance in the objects to be vectorised")
    parser.add_argument("--mca", action="store_true",
                        help="also llvm-mca's cycles per iteration and port pressure")
    parser.add_argument("--mcpu", default="native", help="llvm-mca's CPU model (with --mca)")
    parser.add_argument("--mca-asm", metavar="FILE",
                        help="with --mca: also write the assembly given to llvm-mca to FILE")
    args = parser.parse_args()
    if args.check_vectorised:
        return check_vectorised(args.object)
    if len(args.object) != 1:
        parser.error("one object without --check-vectorised")
    args.object = args.object[0]
    symbol, ins = disassemble(args.object, args.symbol)
    body, lanes = main_loop(ins)
    kinds, loads, stores = classify(body)
    arithmetic = kinds["fma"] + kinds["mul"] + kinds["add/sub"]
    flops = 2 * kinds["fma"] + kinds["mul"] + kinds["add/sub"] + kinds["div"] + kinds["sqrt"]
    print(f"# {symbol}")
    print(f"# main loop: {len(body)} instructions per iteration, {lanes} points per iteration")
    print("# instructions: per_iteration per_point (issue slots a point takes)")
    rows = [("instructions", len(body)),
            ("fp_arithmetic (fma+mul+add/sub)", arithmetic),
            ("  fma", kinds["fma"]), ("  mul", kinds["mul"]), ("  add/sub", kinds["add/sub"]),
            ("div", kinds["div"]), ("sqrt", kinds["sqrt"]),
            ("other_vector (logic, compare, blend)", kinds["other vector"]),
            ("loads", sum(loads.values()))]
    rows += [(f"  {k}", v) for k, v in sorted(loads.items())]
    rows += [("stores", stores)]
    for name, value in rows:
        print(f"{name:40s} {value:5d} {value / lanes:8.2f}")
    # each vector instruction works on every point of the iteration, one lane each
    print(f"flops_per_point (fma = 2) {flops}")
    # from the loop's first instruction to the one after its backward jump
    after = next((a for a, _, _ in ins if a > body[-1][0]), None)
    if after is not None:
        print(f"code_bytes_per_iteration {after - body[0][0]}")
    if args.mca:
        cycles, pressure = mca(body, args.mcpu, args.mca_asm)
        print(f"mca_cycles_per_iteration ({args.mcpu}) {cycles:.1f} per_point {cycles / lanes:.2f}")
        busiest = sorted(pressure.items(), key=lambda kv: -kv[1])[:4]
        print("mca_port_pressure_per_iteration "
              + " ".join(f"{name}={value:.0f}" for name, value in busiest))

if __name__ == "__main__":
    sys.exit(main())
