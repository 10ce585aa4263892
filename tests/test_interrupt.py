"""An interrupted run keeps what it finished: Ctrl-C (SIGINT) or SIGTERM during ``thermobear sweep``
exits with 130, leaves a valid CSV of the finished rows and no worker process; during
``thermobear transient`` it keeps what was integrated."""
import csv
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import thermobear as tb

EXE = [sys.executable, "-m", "thermobear.app.cli"]
SCENE = tb.example_path("seed004_oil_jet_7210.toml")


def _children(pid):
    out = subprocess.run(["ps", "-o", "pid=", "--ppid", str(pid)], capture_output=True, text=True).stdout
    return [int(x) for x in out.split()]


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:                                    # a zombie still answers kill(0): read its state
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().split()[2] != "Z"
    except OSError:
        return False


def _wait_for_rows(path, n, proc, timeout=120):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        if proc.poll() is not None:
            pytest.fail(f"the sweep ended before it was interrupted: {proc.stderr.read()}")
        if path.exists():
            rows = [r for r in path.read_text().splitlines() if r and not r.startswith("#")]
            if len(rows) > n:
                return
        time.sleep(0.05)
    pytest.fail("no rows written in time")


@pytest.mark.parametrize("processes,sig", [(1, signal.SIGINT), (2, signal.SIGINT), (2, signal.SIGTERM)])
def test_interrupted_sweep_keeps_its_rows_and_leaves_no_worker(tmp_path, processes, sig):
    out = tmp_path / "sweep.csv"
    proc = subprocess.Popen(EXE + ["sweep", SCENE, "--n-rpm", "2000:8000:40", "--Fa", "225:675:10",
                                   "--csv", str(out), "--processes", str(processes), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _wait_for_rows(out, 1, proc)
    workers = _children(proc.pid)
    proc.send_signal(sig)
    try:
        proc.wait(timeout=60)                   # a guard against a hang, not a timing check
    finally:
        proc.kill()
    err = proc.stderr.read()
    assert proc.returncode == 130, err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("interrupted: kept ") and str(out) in lines[0], err
    assert "Traceback" not in err
    with open(out, newline="") as fh:
        rows = [r for r in csv.reader(line for line in fh if not line.startswith("#"))]
    header, data = rows[0], rows[1:]
    assert 0 < len(data) < 400 and f"kept {len(data)} of 400 rows" in lines[0]
    assert all(len(r) == len(header) for r in data)                      # every row complete
    assert all(r[header.index("status")] == "ok" for r in data)
    time.sleep(0.2)
    assert not [w for w in workers if _alive(w)], "a worker process outlived the sweep"


def test_interrupted_transient_keeps_what_was_integrated(tmp_path):
    sched = tmp_path / "steps.toml"             # many speed steps: a long integration to interrupt
    sched.write_text("".join(f"[[step]]\nt_s = {10.0 * k}\nn_rpm = {3000.0 + 500.0 * (k % 2)}\n\n"
                             for k in range(1, 3000)))
    out = tmp_path / "heatup.csv"
    proc = subprocess.Popen(EXE + ["transient", SCENE, "--t-end", "30000", "--points", "301", "--schedule", str(sched),
                                   "--csv", str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(15.0)                            # imports, schedule check, then integrating (a busy machine)
    assert proc.poll() is None, proc.stderr.read()
    proc.send_signal(signal.SIGINT)
    proc.wait(timeout=60)                       # a guard against a hang, not a timing check
    err = proc.stderr.read()
    assert proc.returncode == 130, err
    assert "interrupted at t = " in err and "Traceback" not in err
    rows = [r for r in out.read_text().splitlines() if r and not r.startswith("#")]
    assert len(rows) > 2
    t = [float(r.split(",")[0]) for r in rows[1:]]
    assert t == sorted(t) and t[0] == 0.0 and t[-1] < 30000.0


def test_a_stopped_transient_returns_what_it_integrated():
    s = tb.load_scene(SCENE)
    calls = {"n": 0}

    def stop():
        calls["n"] += 1
        return calls["n"] > 40
    run = tb.transient(s, 3600.0, t_eval=[0.0, 10.0, 100.0, 1000.0, 3600.0], stop=stop)
    assert not run.completed and 0 < run.t_s.size < 5 and run.t_s[-1] < 3600.0
    assert all(np.all(np.isfinite(v)) for v in run.T_C.values()) and np.all(np.isfinite(run.P_W))


def test_sweep_interrupted_before_its_first_row_says_nothing_was_written(tmp_path, monkeypatch, capsys):
    """A Ctrl-C while the sweep still builds its points: exit 130, no file, and the line says so (it said
    'kept 0 of N rows in out.csv', a file that was never created)."""
    from thermobear.app import verbs
    from thermobear.app.cli import main

    def interrupted(*args, **kw):
        raise KeyboardInterrupt
    monkeypatch.setattr(verbs, "run_sweep", interrupted)
    out = tmp_path / "sweep.csv"
    assert main(["sweep", SCENE, "--n-rpm", "2000:8000:4", "--csv", str(out), "--quiet"]) == 130
    err = capsys.readouterr().err
    assert not out.exists() and "interrupted before the first of 4 rows finished: nothing written" in err


def test_a_heat_up_stopped_before_its_first_output_time_returns_empty():
    """stop() at once: a machine with a seal node (its seal temperature is asked of the output times) returns its
    run, empty and not completed, instead of failing on an empty array."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    r = tb.transient(s, 30.0, t_eval=[10.0, 30.0], stop=lambda: True)
    assert not r.completed and r.t_s.size == 0
