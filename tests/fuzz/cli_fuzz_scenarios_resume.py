"""Scenarios of the command-line fuzzer on what a rerun finds in a folder: a run's or a study's
resume files corrupted (surface resume-files), a sweep's folder edited between runs (surface
sweep-edits)."""

import os
import re
import shutil

from hypothesis import strategies as st

from cli_fuzz_common import (HAH_FILE, HALF, OUTSIDE, STUDY, STUDY_ARGS, SWEEP_ARGS, SWEEP_DIR,
                             SWEEP_MEMBERS, Scenario, common_problems, fingerprint,
                             first_difference, last_line, outputs, run, shell_line,
                             summary_rows)

# what a refusal must name for each damaged resume file
NAMES_FILE = {"checkpoint.bin": "checkpoint", "rah-hAH-file.dat": "rah-hAH-file",
              "converge_samples.bin": "converge_samples"}


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
