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

The code, in this folder: cli_fuzz.py (this file) the driver (the surfaces, KNOWN_DEFECTS,
drawing, shrinking and tallying, main); cli_fuzz_flags.py the flag table, its check against
--help and the scratch folder with its hostile paths; cli_fuzz_cases.py how argument vectors are
drawn and a failure's catalogue row; cli_fuzz_check.py the invariants an argument vector is
checked against; cli_fuzz_common.py running gbssn1d under limits, the invariants every command
keeps and the scenarios' lab (the finished references, cached outcomes on intact copies);
cli_fuzz_scenarios_folders.py the surfaces concurrent and links; cli_fuzz_scenarios_resume.py
resume-files and sweep-edits.
"""

import argparse
import os
import shutil
import sys
import tempfile
import time

try:
    import hypothesis
    from hypothesis import strategies as st
except ImportError:  # pragma: no cover
    sys.exit("cli_fuzz.py needs Debian's python3-hypothesis (run it with /usr/bin/python3)")

# The fuzzer's modules, beside this file (Python puts the folder of the script it runs first on
# sys.path); after the check above, as they import hypothesis.
from cli_fuzz_cases import cases, catalogue_row
from cli_fuzz_check import check, subcommand
from cli_fuzz_common import Lab, describe, make_references
from cli_fuzz_flags import check_flag_table, make_templates
from cli_fuzz_scenarios_folders import (check_concurrent, check_links, concurrent_scenario,
                                        links_scenario)
from cli_fuzz_scenarios_resume import (check_resume_files, check_sweep_edits,
                                       resume_files_scenario, sweep_edits_scenario)

# ---------------------------------------------------------------------------------------------
# The scenario surfaces by name (the argument vectors are the surface `args`), and the known
# defects.

SURFACES = ("concurrent", "links", "resume-files", "sweep-edits")

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


def known_defect(kind, case):
    for kinds, match, what in KNOWN_DEFECTS:
        try:
            if kind in kinds and match(case):
                return what
        except Exception:  # a matcher that does not apply to this input
            continue
    return None


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
