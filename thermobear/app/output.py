"""What the command line writes: JSON, CSV (whole, or streamed row by row), progress, output paths.

Output paths are checked before anything is computed; a whole file is written to a temporary name
and renamed (never half-written); a streamed file (a sweep's rows) holds only complete rows,
flushed one by one, so an interrupted run keeps every finished row.
"""
from __future__ import annotations

import csv
import io
import json
import os
import signal
import sys
import threading
import time
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from thermobear.errors import InputError

__all__ = ["jsonable", "print_json", "check_out_file", "check_out_dir", "write_text", "csv_text", "flatten",
           "RowWriter", "Progress", "wrote"]


def jsonable(x):
    """``x`` with numpy types turned into plain Python (non-finite floats → None)."""
    if isinstance(x, dict):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return jsonable(x.tolist())
    if isinstance(x, (np.floating, float)):
        return None if not np.isfinite(x) else float(x)
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    if isinstance(x, np.str_):
        return str(x)
    return x


def print_json(d):
    print(json.dumps(jsonable(d), indent=2, ensure_ascii=False))


def check_out_file(path, field):
    """An output file must be creatable: its folder exists and is writable, it is not a folder."""
    if path is None:
        return None
    p = Path(path)
    if p.is_dir():
        raise InputError(field, str(path), "is a folder; give a file name")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(field, str(path), f"folder {parent} does not exist")
    if not os.access(parent, os.W_OK) or (p.exists() and not os.access(p, os.W_OK)):
        raise InputError(field, str(path), "not writable")
    return p


def check_out_dir(path, field="--plot"):
    """A plot folder must exist or be creatable: it is made and removed again now (the only reliable
    test on every file system), before anything is computed; the plots create it when they write."""
    if path is None:
        return None
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InputError(field, str(path), "exists and is not a folder")
    made = [q for q in [p, *p.parents] if not q.exists()]
    try:
        p.mkdir(parents=True, exist_ok=True)
        ok = os.access(p, os.W_OK)
    except OSError as exc:
        raise InputError(field, str(path), f"cannot be created ({exc.strerror or exc})") from None
    finally:
        for q in made:                            # deepest first: leave nothing behind
            try:
                q.rmdir()
            except OSError:
                pass
    if not ok:
        raise InputError(field, str(path), "not writable")
    return p


def write_text(path: Path, text: str):
    """Write a whole file: a temporary file, then renamed."""
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def _cell(v):
    return "" if v is None else (f"{v:.10g}" if isinstance(v, (float, np.floating)) else v)


def csv_text(header, rows, comments=()):
    buf = io.StringIO()
    for c in comments:
        buf.write(f"# {c}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in rows:
        w.writerow([_cell(v) for v in r])
    return buf.getvalue()


def flatten(d, pre=""):
    """A nested row as one level (``breakdown_W.rolling``); per-ball arrays are left out, lists of
    text joined by "; "."""
    out = {}
    for k, v in d.items():
        if isinstance(v, dict):
            out.update(flatten(v, f"{pre}{k}."))
        elif isinstance(v, (list, tuple)) and all(isinstance(x, str) for x in v):
            out[f"{pre}{k}"] = "; ".join(v)
        elif isinstance(v, (list, tuple, np.ndarray)) and np.ndim(v) > 0:
            continue
        else:
            out[f"{pre}{k}"] = v.item() if isinstance(v, np.generic) else v
    return out


@contextmanager
def _signals_held():
    """SIGINT and SIGTERM held (delivered on exit) where the platform can block signals (POSIX main thread)."""
    block = getattr(signal, "pthread_sigmask", None)
    held = {signal.SIGINT, signal.SIGTERM}
    if block is None or threading.current_thread() is not threading.main_thread():
        yield
        return
    old = block(signal.SIG_BLOCK, held)
    try:
        yield
    finally:
        block(signal.SIG_SETMASK, old)


class RowWriter:
    """Rows written as they finish: CSV (``index`` column first) and/or JSON lines, each flushed.

    The files are created on the first row (a run refused before computing writes nothing).
    """

    def __init__(self, header, csv_path=None, jsonl_path=None, comment=""):
        self.header = ["index"] + list(header)
        self.csv_path, self.jsonl_path, self.comment = csv_path, jsonl_path, comment
        self._csv = self._jsonl = self._writer = None
        self.count = 0

    def write(self, index: int, row: dict):
        """Write one row and count it as one step: an interrupt (SIGINT, SIGTERM) arriving meanwhile is held until
        both are done, so that ``count`` is always the number of rows in the files."""
        with _signals_held():
            self._write(index, row)

    def _write(self, index: int, row: dict):
        flat = flatten(row)
        if self.csv_path is not None:
            if self._csv is None:
                self._csv = open(self.csv_path, "w", encoding="utf-8", newline="")
                if self.comment:
                    self._csv.write(f"# {self.comment}\n")
                self._writer = csv.writer(self._csv, lineterminator="\n")
                self._writer.writerow(self.header)
            self._writer.writerow([index] + [_cell(flat.get(k)) for k in self.header[1:]])
            self._csv.flush()
        if self.jsonl_path is not None:
            if self._jsonl is None:
                self._jsonl = open(self.jsonl_path, "w", encoding="utf-8")
            self._jsonl.write(json.dumps(jsonable({"index": index, **row}), ensure_ascii=False) + "\n")
            self._jsonl.flush()
        self.count += 1

    def close(self):
        for f in (self._csv, self._jsonl):
            if f is not None:
                f.close()

    @property
    def paths(self) -> list:
        return [str(p) for p in (self.csv_path, self.jsonl_path) if p is not None]


class Progress:
    """Progress on stderr: a bar on a terminal; elsewhere (a log file, a pipe) a line every few
    seconds and one at the end."""

    def __init__(self, enabled=True, stream=None, label="sweep", every_s: float = 5.0):
        self.enabled, self.stream, self.label = enabled, stream or sys.stderr, label
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.every_s, self._last = every_s, time.monotonic()

    def __call__(self, done, total=None, *args, **kw):
        if not self.enabled:
            return
        total = total or 1
        if self.tty:
            k = int(30 * done / total)
            self.stream.write(f"\r{self.label} [{'#' * k}{'.' * (30 - k)}] {done}/{total}")
            if done >= total:
                self.stream.write("\n")
        else:
            now = time.monotonic()
            if done < total and now - self._last < self.every_s:
                return
            self._last = now
            self.stream.write(f"{self.label}: {done}/{total} points\n")
        self.stream.flush()


def wrote(paths):
    for p in paths:
        print(f"wrote {p}", file=sys.stderr)
