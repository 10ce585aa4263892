"""Where the data files live, and reading them.

Data (materials, lubricants, bearing catalog, thermal networks) are TOML files
in the repository's top-level ``materials/`` and ``networks/`` folders.  A wheel
carries them as ``thermobear/_data/``; an editable install reads them from the
repository.  The package never reads anything outside these two places.
"""
from __future__ import annotations

import os
import tomllib
from functools import lru_cache
from pathlib import Path

from thermobear.errors import InputError

_PKG = Path(__file__).resolve().parent


def data_dir(kind: str) -> Path:
    """Folder of a data kind: ``"materials"`` or ``"networks"``."""
    for base in (_PKG / "_data" / kind, _PKG.parent / kind):
        if base.is_dir():
            return base
    raise FileNotFoundError(f"thermobear data folder '{kind}' not found next to the package")


def read_toml(path: str) -> dict:
    """Read a TOML file, turning a syntax error into an InputError naming the file.

    Cached per file and version: a file edited since its last read (another modification time or
    size) is read again, so a scene, network or catalog file changed during a session is seen.  The
    returned dict is shared between callers: copy it before changing it.

    >>> import thermobear
    >>> read_toml(thermobear.example_path("seed004_oil_jet_7210.toml"))["operation"]["n_rpm"]
    3200.0
    """
    p = Path(path)
    try:
        st = os.stat(p)
    except (FileNotFoundError, NotADirectoryError):
        raise InputError(str(p), None, "file not found") from None
    return _read_toml(str(p), st.st_mtime_ns, st.st_size)


@lru_cache(maxsize=256)
def _read_toml(path: str, mtime_ns: int, size: int) -> dict:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(path, None, f"is not valid TOML: {exc}") from None
    except FileNotFoundError:
        raise InputError(path, None, "file not found") from None


def names_in(folder: Path) -> list[str]:
    """Sorted stems of the ``*.toml`` files in a folder."""
    return sorted(p.stem for p in folder.glob("*.toml"))


def lookup(kind: str, sub: str, name: str, what: str) -> dict:
    """Load ``<kind>/<sub>/<name>.toml`` or raise an InputError listing the known names."""
    folder = data_dir(kind) / sub
    path = folder / f"{name}.toml"
    if not path.is_file():
        known = ", ".join(names_in(folder))
        raise InputError(what, name, f"unknown name; known: {known}")
    return read_toml(str(path))


def example_path(name: str) -> str:
    """Path of a bundled example scene (``examples/<name>``).

    >>> example_path("seed004_oil_jet_7210.toml").endswith("seed004_oil_jet_7210.toml")
    True
    """
    p = data_dir("examples") / name
    if not p.is_file():
        known = ", ".join(sorted(q.name for q in data_dir("examples").glob("*.toml")))
        raise InputError("example", name, f"unknown example; known: {known}")
    return str(p)
