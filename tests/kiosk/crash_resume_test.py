#!/usr/bin/python3
"""The kill -9 test of autosave and resume (docs/kiosk.md, "Autosave and resume").

  crash_resume_test.py STEERSEG WORKDIR

Starts `steerseg kiosk --platform offscreen` on a ball phantom with a script that seeds two
structures, adds a third and runs it, waits until it evolves and autosaves, SIGKILLs it, and
restarts it with --resume:
  - the resumed state and parameters are the autosave's (a run comes back paused), and all
    three structures are back: the label map exported right after the resume holds each one's
    autosaved mask voxel for voxel;
  - at most interval_seconds (+ one frame and the write) of work is lost: the kill time
    against the restored autosave's time;
  - the mask exported right after the resume equals the autosave's mask voxel for voxel;
  - a torn last audit line from the crash is reported and moved to <log>.torn, so the log stays
    valid JSON lines;
  - with the newest autosave corrupted on purpose, the one before it is used (this run
    answers the kiosk's offer from its script instead of --resume);
  - a scan file changed since the autosave is not resumed.
Standard library only (Debian's python3); exit 0 on success, 1 with the reason.
"""
import json
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

INTERVAL = 1.0  # autosave.interval_seconds for the test
# A snapshot is taken at the first frame past the interval and reaches the disk after its
# write: one llvmpipe frame (up to ~0.6 s under load) and the write on top of the interval.
SLACK = 1.5
N = 96  # the phantom: N^3, a bright ball of radius 40 that takes far longer to fill than the test
# eps 1: inside the ball the speed is 1, so the curvature and rescaling terms set the time step
# and the front crosses ~0.13 voxel a step instead of the 0.5 a speed of eps 60 gave. At 0.5 the
# ball filled in ~145 steps, ~10 s on llvmpipe: a faster solver could end the run before the
# kill, which needs three autosaves while it evolves.
EPS = 1


def fail(message):
    print("FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def make_phantom(path):
    c = (N - 1) / 2.0
    data = bytearray(N * N * N)
    for k in range(N):
        for j in range(N):
            row = (k * N + j) * N
            for i in range(N):
                inside = (i - c) ** 2 + (j - c) ** 2 + (k - c) ** 2 <= 40.0 ** 2
                data[row + i] = 200 if inside else 50
    with open(path, "wb") as f:
        f.write(("NRRD0004\ntype: uint8\ndimension: 3\nsizes: %d %d %d\nspacings: 1 1 1\n"
                 "encoding: raw\n\n" % (N, N, N)).encode())
        f.write(data)


def decode_runs(runs, voxels):
    mask = bytearray(voxels)
    at = 0
    for n, length in enumerate(runs):
        if n % 2 == 1:
            mask[at:at + length] = b"\x01" * length
        at += length
    return bytes(mask)


def read_autosave(path):
    """The metadata and the structures' masks (bytes, 0/1, in the list's order; the active
    one's is the snapshot's own) of an autosave file, checked as the kiosk checks it
    (app/autosave/autosave_snapshot.cpp)."""
    raw = open(path, "rb").read()
    if raw[:8] != b"STEERSAV":
        fail(path + ": bad magic")
    version, meta_bytes, run_count, voxels, crc = struct.unpack_from("<IIQQI", raw, 8)
    payload = raw[36:]
    if version != 1 or len(payload) != meta_bytes + 4 * run_count:
        fail(path + ": bad header")
    if zlib.crc32(payload) != crc:
        fail(path + ": CRC mismatch")
    meta = json.loads(payload[:meta_bytes])
    runs = struct.unpack_from("<%dI" % run_count, payload, meta_bytes)
    items = (meta.get("structures") or {}).get("items", [])
    others = sum(item["runs"] for item in items)
    masks = [decode_runs(runs[:run_count - others], voxels)]
    at = run_count - others
    for n, item in enumerate(items):
        if n != meta["structures"]["active"]:
            masks.insert(n, decode_runs(runs[at:at + item["runs"]], voxels))
            at += item["runs"]
    return meta, masks


def read_nifti_labels(path):
    raw = open(path, "rb").read()
    (size,) = struct.unpack_from("<i", raw, 0)
    if size == 348:
        dims = struct.unpack_from("<8h", raw, 40)
        (datatype,) = struct.unpack_from("<h", raw, 70)
        offset = int(struct.unpack_from("<f", raw, 108)[0])
    elif size == 540:
        (datatype,) = struct.unpack_from("<h", raw, 12)
        dims = struct.unpack_from("<8q", raw, 16)
        (offset,) = struct.unpack_from("<q", raw, 168)
    else:
        fail(path + ": not an uncompressed NIfTI file")
    if datatype != 2:  # uint8
        fail(path + ": datatype %d, expected uint8" % datatype)
    count = dims[1] * dims[2] * dims[3]
    return raw[offset:offset + count]


def labels_of(masks):
    """The label map an export of these structures writes: structure n's voxels are n + 1."""
    out = bytearray(len(masks[0]))
    for n, mask in enumerate(masks):
        for v, inside in enumerate(mask):
            if inside:
                out[v] = n + 1
    return bytes(out)


def write_config(path, work, folder, audit):
    with open(path, "w") as f:
        f.write('[frame]\nsolver_share = 0.9\n[audit]\npath = "%s"\n[export]\nfolder = "%s"\n'
                '[autosave]\nfolder = "%s"\ninterval_seconds = %.1f\nkeep = 5\n'
                % (audit, os.path.join(work, "export"), folder, INTERVAL))


def run_kiosk(steerseg, work, name, config, session, extra):
    out = os.path.join(work, name)
    os.makedirs(out, exist_ok=True)
    argv = [steerseg, "kiosk", "--platform", "offscreen", "--size", "480x320", "--config",
            config, "--frames", out, "--script", session, "--max-seconds", "60", "--allow-root"]
    argv += extra
    done = subprocess.run(argv, capture_output=True, text=True, timeout=120)
    log = done.stdout + done.stderr
    with open(os.path.join(work, name + ".log"), "w") as f:
        f.write(log)
    return done.returncode, log, out


def manifest(folder):
    try:
        with open(os.path.join(folder, "manifest.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def main():
    steerseg, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scan = os.path.join(work, "ball.nrrd")
    make_phantom(scan)
    folder = os.path.join(work, "autosave")
    audit = os.path.join(work, "audit.jsonl")
    config = os.path.join(work, "kiosk.toml")
    write_config(config, work, folder, audit)
    grow = os.path.join(work, "grow.session")
    with open(grow, "w") as f:
        # Two structures seeded in the ball, then the third grows around them (they are its
        # barriers) until the kill.
        params = "set T 200\nset eps %d\nset alpha 0.7\n" % EPS
        f.write("load %s\nwait loaded timeout 30\n%sseed 30 48 48 3\nstructure add Two\n%s"
                "seed 66 48 48 3\nstructure add Three\n%sseed 48 48 48 3\nbox 4 5 6 91 90 89\n"
                "run\nwait converged timeout 120\n" % (scan, params, params, params))

    # 1. Seed, run, and kill -9 once it has autosaved a few times while evolving.
    log1 = open(os.path.join(work, "crash.log"), "w")
    kiosk = subprocess.Popen([steerseg, "kiosk", "--platform", "offscreen", "--size", "480x320",
                              "--config", config, "--script", grow, "--max-seconds", "90",
                              "--allow-root"], stdout=log1, stderr=subprocess.STDOUT)
    deadline = time.time() + 60
    while True:
        m = manifest(folder)
        if m and sum(1 for e in m["files"] if e["state"] == "evolving") >= 3:
            break
        if kiosk.poll() is not None:
            fail("the kiosk ended (status %s) before it autosaved while evolving; see %s"
                 % (kiosk.returncode, log1.name))
        if time.time() > deadline:
            kiosk.kill()
            fail("no autosave while evolving within 60 s")
        time.sleep(0.05)
    time.sleep(0.7)  # mid-interval: a kill between autosaves, not just after one
    kiosk.send_signal(signal.SIGKILL)
    killed_at = time.time()
    kiosk.wait()
    log1.close()
    m = manifest(folder)
    newest = m["files"][-1]
    if m["clean"] or newest["state"] != "evolving":
        fail("the manifest after the kill: clean %s, newest state %s" % (m["clean"], newest["state"]))
    lost = killed_at - newest["saved_at_ms"] / 1000.0
    print("killed while evolving; the newest autosave %s is %.2f s older than the kill "
          "(interval %.1f s)" % (newest["file"], lost, INTERVAL))
    if lost > INTERVAL + SLACK:
        fail("%.2f s of work lost, more than the interval %.1f s (+%.1f s)" % (lost, INTERVAL, SLACK))
    saved_meta, saved_masks = read_autosave(os.path.join(folder, newest["file"]))
    if saved_meta["params"].get("box") != {"lo": [4, 5, 6], "hi": [91, 90, 89]}:
        fail("the autosave holds the box %s" % saved_meta["params"].get("box"))
    if len(saved_masks) != 3 or not all(sum(mask) for mask in saved_masks):
        fail("the autosave holds %d structures, %s voxels inside"
             % (len(saved_masks), [sum(mask) for mask in saved_masks]))
    previous = m["files"][-2]
    prev_meta, prev_masks = read_autosave(os.path.join(folder, previous["file"]))
    # The corrupted-newest run below works on a copy taken now, before the resume rotates.
    corrupt = os.path.join(work, "autosave-corrupt")
    shutil.copytree(folder, corrupt)
    changed = os.path.join(work, "autosave-changed")
    shutil.copytree(folder, changed)
    # A crash can tear the audit log's last line: the resumed session must read past it.
    with open(audit, "a") as f:
        f.write('{"event":"action","state":"evol')

    # 2. Resume: state and parameters back, and the mask exported at once equals the autosave's.
    resume = os.path.join(work, "resume.session")
    with open(resume, "w") as f:
        f.write("wait state paused timeout 30\nexpect T == 200\nexpect eps == %d\n"
                "expect alpha > 0.69\nexpect alpha < 0.71\nexpect seeds == 1\nexpect has_box == 1\n"
                "expect structures == 3\nexport resumed.nii\nwait state done timeout 30\n" % EPS)
    status, log, out = run_kiosk(steerseg, work, "resumed", config, resume, ["--resume"])
    if status != 0:
        fail("the resumed kiosk exited %d:\n%s" % (status, log))
    if "resumed " + os.path.join(folder, newest["file"]) not in log:
        fail("the resume did not say it restored %s:\n%s" % (newest["file"], log))
    if "torn last record" not in log:
        fail("the torn audit line was not reported:\n" + log)
    exported = read_nifti_labels(os.path.join(out, "resumed.nii"))
    if exported != labels_of(saved_masks):
        diff = sum(1 for a, b in zip(exported, labels_of(saved_masks)) if a != b)
        fail("the label map after the resume differs from the autosave's masks in %d voxels"
             % diff)
    print("resumed %s: state paused, T 200, eps %d, alpha 0.7, 1 seed; three structures, each "
          "mask identical (%s voxels inside, %d in the grid)"
          % (newest["file"], EPS, [sum(mask) for mask in saved_masks], len(saved_masks[0])))
    lines = open(audit).read().split("\n")
    torn = '{"event":"action","state":"evol'
    records = [json.loads(line) for line in lines if line]  # raises on a bad one
    if not any(r.get("cause") == "resume" for r in records):
        fail("the audit log after the resume: no resume")
    if not os.path.exists(audit + ".torn") or open(audit + ".torn").read() != torn + "\n":
        fail("the torn audit line was not moved to %s.torn" % audit)
    if not manifest(folder)["clean"]:
        fail("the resumed session exported and ended, yet the manifest is not clean")

    # 3. The newest autosave damaged: the previous one is used, and said so.
    with open(os.path.join(corrupt, newest["file"]), "r+b") as f:
        f.seek(60)
        byte = f.read(1)
        f.seek(60)
        f.write(bytes([byte[0] ^ 0x20]))
    config2 = os.path.join(work, "corrupt.toml")
    write_config(config2, work, corrupt, os.path.join(work, "audit-corrupt.jsonl"))
    resume2 = os.path.join(work, "resume-previous.session")
    with open(resume2, "w") as f:
        # No --resume this time: the script answers the kiosk's offer, as an operator would.
        f.write("autosave resume\nwait state paused timeout 30\nexpect seeds == 1\n"
                "export previous.nii\nwait state done timeout 30\n")
    status, log, out = run_kiosk(steerseg, work, "corrupt", config2, resume2, [])
    if status != 0:
        fail("the kiosk with a damaged newest autosave exited %d:\n%s" % (status, log))
    if "CRC mismatch" not in log or "resumed " + os.path.join(corrupt, previous["file"]) not in log:
        fail("the damaged autosave was not reported, or %s not used:\n%s" % (previous["file"], log))
    if read_nifti_labels(os.path.join(out, "previous.nii")) != labels_of(prev_masks):
        fail("the mask resumed from the previous autosave differs from it")
    print("damaged %s: CRC mismatch reported, resumed %s instead, mask identical"
          % (newest["file"], previous["file"]))

    # 4. The scan changed since the autosave: another file's segmentation is not resumed.
    os.utime(scan, (time.time() + 5, time.time() + 5))
    config3 = os.path.join(work, "changed.toml")
    write_config(config3, work, changed, os.path.join(work, "audit-changed.jsonl"))
    nothing = os.path.join(work, "nothing.session")
    with open(nothing, "w") as f:
        f.write("expect state no_scan\n")
    status, log, out = run_kiosk(steerseg, work, "changed", config3, nothing, ["--resume"])
    if status != 0 or "changed since the autosave" not in log or "resumed " in log:
        fail("a changed scan file was resumed or not reported (status %d):\n%s" % (status, log))
    print("scan file changed after the autosave: not resumed, and said why")
    return 0


if __name__ == "__main__":
    sys.exit(main())
