#!/usr/bin/python3
"""The kill -9 soak (issue 25): cycles of start, random scripted work, SIGKILL, resume.

  kill9_soak.py STEERSEG WORKDIR [--cycles N] [--seed S] [--figures FILE]

Each cycle starts `steerseg kiosk --platform offscreen` on the built-in sample with a script of
random operator work (seeds, erasures, runs, pauses, parameters, undo, review), kills it with
SIGKILL at a random moment, and starts the next cycle with --resume when the autosave folder
holds an unfinished session. After each cycle:
  - the audit log is valid JSON lines, a torn last line (the kill's) aside, and that torn line
    is gone (moved to <log>.torn) once the next kiosk has started;
  - every autosave the manifest lists reads back whole (magic, size, CRC), and no file under
    the kiosk's folders is half-written under its own name (temporaries are hidden names);
  - the resumed session equals the last autosave: its script checks the seed count and the
    parameters, and exports at once; that mask equals the autosave's voxel for voxel.
The work lost per kill is the kill's time against the newest autosave's, counted where the
session was evolving (so an autosave was due every interval). Standard library only.
CI runs 5 cycles (CTest kiosk_kill9_soak); tools/soak-kill9.sh runs the long form.
"""
import argparse
import glob
import json
import os
import random
import shutil
import signal
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crash_resume_test import fail, labels_of, manifest, read_autosave, read_nifti_labels  # noqa: E402

INTERVAL = 1.0  # autosave.interval_seconds
DIMS = (128, 128, 96)  # the built-in sample (app/core/sample_phantom.cpp)


def write_config(path, work, folder, audit):
    with open(path, "w") as f:
        f.write('[frame]\nsolver_share = 0.9\n[audit]\npath = "%s"\n[export]\nfolder = "%s"\n'
                '[autosave]\nfolder = "%s"\ninterval_seconds = %.1f\nkeep = 3\n'
                % (audit, os.path.join(work, "export"), folder, INTERVAL))


def voxel(rng):
    return "%d %d %d" % (rng.randint(44, 84), rng.randint(44, 84), rng.randint(32, 64))


def random_work(rng):
    """Operator steps in a plausible order; a step the state refuses is refused and logged,
    as an operator's would be, and the script goes on."""
    steps = ["probe %s" % voxel(rng), "seed %s %d" % (voxel(rng), rng.randint(3, 6)), "run",
             "wait seconds %.1f" % rng.uniform(0.3, 1.5)]
    for _ in range(rng.randint(3, 8)):
        kind = rng.random()
        if kind < 0.3:
            steps.append("seed %s %d" % (voxel(rng), rng.randint(3, 6)))
        elif kind < 0.4:
            steps.append("erase %s %d" % (voxel(rng), rng.randint(2, 4)))
        elif kind < 0.55:
            steps.append(rng.choice(["set alpha %.2f" % rng.uniform(0.5, 0.9),
                                     "nudge T %d" % rng.randint(-5, 5),
                                     "nudge eps %d" % rng.randint(-5, 5)]))
        elif kind < 0.65:
            steps.append(rng.choice(["undo", "redo", "pause", "finish", "resume"]))
        steps.append("run")
        steps.append("wait seconds %.1f" % rng.uniform(0.3, 2.5))
    return steps


def audit_lines(path):
    """The records, and whether the last line is torn. Fails on a damaged line before it."""
    if not os.path.exists(path):
        return [], False
    text = open(path, "rb").read().decode("utf-8", "replace")
    lines = text.split("\n")
    records = []
    torn = False
    for n, line in enumerate(lines):
        if not line:
            continue
        try:
            records.append(json.loads(line))
        except ValueError:
            if n == len(lines) - 1:
                torn = True  # the kill's, no newline yet
            else:
                fail("%s: line %d is not JSON: %r" % (path, n + 1, line[:80]))
    return records, torn


def check_files(work, folder):
    """Every listed autosave whole; no half-written file under a visible name. Returns the
    number of files checked and of hidden temporaries a kill left behind."""
    checked = 0
    m = manifest(folder)
    for entry in (m or {}).get("files", []):
        path = os.path.join(folder, entry["file"])
        if os.path.exists(path):
            read_autosave(path)  # fails on bad magic, size or CRC
            if os.path.getsize(path) != entry["bytes"]:
                fail("%s: %d bytes, the manifest says %d" % (path, os.path.getsize(path),
                                                             entry["bytes"]))
            checked += 1
    temporaries = 0
    for path in glob.glob(os.path.join(work, "**", "*"), recursive=True):
        name = os.path.basename(path)
        if ".tmp-" in name and not name.startswith("."):
            fail("a temporary under a visible name: " + path)
        if name.endswith(".nii") and os.path.isfile(path):
            with open(path, "rb") as f:
                header = f.read(348)
            if len(header) < 348:
                fail(path + ": a half-written export")
            checked += 1
    for path in glob.glob(os.path.join(work, "**", ".*.tmp-*"), recursive=True):
        temporaries += 1
        os.remove(path)  # what the kill left; the next write makes its own
    return checked, temporaries


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("steerseg")
    ap.add_argument("work")
    ap.add_argument("--cycles", type=int, default=5)
    ap.add_argument("--seed", type=int, default=25)
    ap.add_argument("--figures")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    work = args.work
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    folder = os.path.join(work, "autosave")
    audit = os.path.join(work, "audit.jsonl")
    config = os.path.join(work, "kiosk.toml")
    write_config(config, work, folder, audit)
    out = os.path.join(work, "out")
    os.makedirs(out)

    lost = []
    early = 0
    resumes = compared = checked = temporaries = repaired = 0
    started = time.time()
    pending = None  # (cycle, export path, autosave mask) of the last resume
    for cycle in range(args.cycles):
        m = manifest(folder)
        # What the kiosk offers to resume (kiosk/session_autosave.cpp): an unfinished session.
        resume = bool(m and not m["clean"] and m["files"]
                      and m["files"][-1]["state"] not in ("no_scan", "loading", "done"))
        exported = None
        _, torn_before = audit_lines(audit)
        aside_before = os.path.getsize(audit + ".torn") if os.path.exists(audit + ".torn") else 0
        steps = []
        if resume:
            meta, masks = read_autosave(os.path.join(folder, m["files"][-1]["file"]))
            mask = labels_of(masks)
            params = meta["params"]
            steps += ["wait loaded timeout 60", "expect seeds == %d" % meta["seeds"]]
            for p in ("T", "eps", "alpha"):
                steps += ["expect %s > %.6f" % (p, params[p] - 1e-3),
                          "expect %s < %.6f" % (p, params[p] + 1e-3)]
            if any(mask):
                exported = os.path.join(out, "resumed-%d.nii" % cycle)
                steps += ["finish", "export " + exported, "wait state done timeout 60",
                          "back", "resume"]
                pending = (cycle, exported, mask)
        else:
            steps += ["load builtin:sample", "wait loaded timeout 60"]
        steps += random_work(rng) + ["wait seconds 600"]
        script = os.path.join(work, "cycle.session")
        with open(script, "w") as f:
            f.write("\n".join(steps) + "\n")
        log_path = os.path.join(work, "cycle.log")
        log = open(log_path, "w")
        argv = [args.steerseg, "kiosk", "--platform", "offscreen", "--size", "320x240",
                "--config", config, "--script", script, "--max-seconds", "120", "--allow-root"]
        if resume:
            argv.append("--resume")
        records_before = len(audit_lines(audit)[0])
        started_cycle = time.time()
        kiosk = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT)

        def alive():
            if kiosk.poll() is not None:
                log.close()
                fail("cycle %d: the kiosk ended (status %d) before the kill:\n%s"
                     % (cycle, kiosk.returncode, open(log_path).read()))

        ready = started_cycle
        if rng.random() < 0.1:
            early += 1  # killed while it starts, loads or resumes
            delay = rng.uniform(0.0, 1.5)
        else:
            # Ready: the scan loaded (or the session resumed) and, after a resume, the export
            # of the restored mask written; the kill comes at a random moment of the work.
            cause = "resume" if resume else "load"
            deadline = time.time() + 90
            while True:
                alive()
                new = audit_lines(audit)[0][records_before:]
                if any(r.get("cause") == cause and r.get("event") == "transition"
                       and r.get("to") != "loading" for r in new) and (
                           exported is None or os.path.exists(exported)):
                    break
                if time.time() > deadline:
                    kiosk.kill()
                    fail("cycle %d: not ready within 90 s:\n%s" % (cycle, open(log_path).read()))
                time.sleep(0.02)
            ready = time.time()
            delay = rng.uniform(0.5, 5.0)
        deadline = time.time() + delay
        while time.time() < deadline:
            alive()
            time.sleep(0.02)
        kiosk.send_signal(signal.SIGKILL)
        killed_at = time.time()
        kiosk.wait()
        log.close()
        text = open(log_path).read()
        resumes += 1 if resume else 0
        records, torn_after = audit_lines(audit)  # fails on a damaged line before the last
        if torn_before:
            aside = os.path.getsize(audit + ".torn") if os.path.exists(audit + ".torn") else 0
            if aside > aside_before:
                repaired += 1  # the kiosk says so unless the kill came before its first line
            elif not torn_after:
                fail("cycle %d: the torn audit line vanished without being moved aside:\n%s"
                     % (cycle, text))
            # else: killed before the log was opened; the tear waits for the next start
        if not records:
            fail("cycle %d: an empty audit log" % cycle)
        if not torn_after and rng.random() < 0.3:
            # A kill rarely lands inside the write of a line; a power cut's tear, made here,
            # gives the next start one to repair.
            with open(audit, "a") as f:
                f.write('{"event":"action","state":"evol')
        if pending and pending[0] == cycle and os.path.exists(pending[1]):
            if read_nifti_labels(pending[1]) != pending[2]:
                fail("cycle %d: the mask exported after the resume differs from the autosave's"
                     % cycle)
            compared += 1
        print("cycle %d: %s%s, killed %.1f s after %s" % (
            cycle, "resumed" if resume else "fresh",
            " (mask %d voxels, %s)" % (sum(pending[2]), "compared" if pending[0] == cycle
                                       and os.path.exists(pending[1]) else "not exported")
            if resume and pending and pending[0] == cycle else "",
            killed_at - ready, "start" if ready == started_cycle else "ready"), flush=True)
        n, t = check_files(work, folder)
        checked += n
        temporaries += t
        m = manifest(folder)
        # Work lost: counted where this cycle's session was evolving and had autosaved, so an
        # autosave was due every interval (an older one would count earlier cycles' time).
        if m and m["files"] and not m["clean"] and m["files"][-1]["state"] == "evolving":
            saved = m["files"][-1]["saved_at_ms"] / 1000.0
            if saved >= ready:
                lost.append(killed_at - saved)
    elapsed = time.time() - started
    if not lost:
        fail("no kill came while evolving in %d cycles" % args.cycles)
    figures = {
        "cycles": args.cycles,
        "resumes": resumes,
        "masks_compared": compared,
        "torn_audit_lines_repaired": repaired,
        "files_checked": checked,
        "temporaries_left_by_kills": temporaries,
        "kills_during_start_up": early,
        "kills_while_evolving": len(lost),
        "lost_seconds_median": statistics.median(lost),
        "lost_seconds_max": max(lost),
        "autosave_interval_seconds": INTERVAL,
        "seconds": elapsed,
    }
    print(json.dumps(figures, indent=1))
    if args.figures:
        with open(args.figures, "w") as f:
            json.dump(figures, f, indent=1)
    # A kill can land right after a frame's autosave began: one interval, one frame, the write.
    if max(lost) > INTERVAL + 1.5:
        fail("%.2f s of work lost by a kill, more than the interval %.1f s (+1.5 s)"
             % (max(lost), INTERVAL))
    return 0


if __name__ == "__main__":
    sys.exit(main())
