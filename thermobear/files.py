"""Where the data files live, and reading them: the one module that reads TOML.

Bundled data (materials, lubricants, bearing catalogue, thermal networks) are TOML files
in the repository's top-level ``materials/`` and ``networks/`` folders.  A wheel
carries them as ``thermobear/_data/``; an editable install reads them from the
repository.  Users' scene, network and schedule files are read here too, so every
way a file can be unreadable (missing, a folder, not UTF-8, not TOML) is one
:class:`~thermobear.errors.InputError` naming the file.
"""
from __future__ import annotations

import difflib
import hashlib
import tomllib
from pathlib import Path

from thermobear.errors import InputError

_PKG = Path(__file__).resolve().parent


def data_dir(kind: str) -> Path:
    """Folder of a data kind: ``"materials"`` or ``"networks"`` (found once per process: the package does not
    move while it runs; part of the file catalogue, as :data:`_PARSED`)."""
    got = _DIRS.get(kind)
    if got is None:
        got = next((b for b in (_PKG / "_data" / kind, _PKG.parent / kind) if b.is_dir()), None)
        if got is None:
            raise FileNotFoundError(f"thermobear data folder '{kind}' not found next to the package")
        _DIRS[kind] = got
    return got


#: The data folders found, by kind (:func:`data_dir`).
_DIRS: dict = {}


def read_toml(path: str) -> dict:
    """Read a TOML file, turning every way it can be unreadable into an InputError naming the file.

    Cached on the file's content (a hash of its bytes): a file edited during a session is read
    again, an unchanged one is parsed once.  The returned dict is shared between callers: copy it
    before changing it.

    >>> import thermobear
    >>> read_toml(thermobear.example_path("seed004_oil_jet_7210.toml"))["operation"]["n_rpm"]
    3200.0
    """
    p = Path(path)
    try:
        data = p.read_bytes()
    except (FileNotFoundError, NotADirectoryError):
        raise InputError(str(p), None, "file not found") from None
    except IsADirectoryError:
        raise InputError(str(p), None, "is a folder, not a TOML file") from None
    except OSError as exc:
        raise InputError(str(p), None, f"cannot be read ({exc.strerror or exc})") from None
    return _parse_toml(hashlib.blake2b(data, digest_size=16).digest(), data, str(p))


def _parse_toml(digest: bytes, data: bytes, path: str) -> dict:
    hit = _PARSED.get(digest)
    if hit is None:
        try:
            text = data.decode("utf-8-sig")        # (a byte-order mark first, as some editors write it: skipped)
        except UnicodeDecodeError as exc:
            raise InputError(path, None, f"is not UTF-8 text (TOML files are UTF-8; byte {exc.start} is "
                                         f"0x{data[exc.start]:02x})") from None
        try:
            hit = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise InputError(path, None, f"is not valid TOML: {exc}") from None
        if len(_PARSED) >= 256:
            _PARSED.pop(next(iter(_PARSED)))
        _PARSED[digest] = hit
    return hit


#: Parsed files by the hash of their content (the file catalogue's one cache).
_PARSED: dict = {}


def names_in(folder: Path) -> list[str]:
    """Sorted stems of the ``*.toml`` files in a folder."""
    return sorted(p.stem for p in folder.glob("*.toml"))


def lookup(kind: str, sub: str, name: str, what: str) -> dict:
    """Load ``<kind>/<sub>/<name>.toml`` or raise an InputError naming the closest known names first, then all.

    >>> try:
    ...     lookup("materials", "lubricants", "iso-vg-68-minral", "lubricant")
    ... except InputError as e:
    ...     print(str(e)[:76])
    lubricant = 'iso-vg-68-minral' — unknown name; close: iso-vg-68-mineral, iso
    """
    folder = data_dir(kind) / sub
    path = folder / f"{name}.toml"
    if not path.is_file():
        names = names_in(folder)
        close = difflib.get_close_matches(str(name), names, n=3, cutoff=0.6)
        raise InputError(what, name, "unknown name; " + (f"close: {', '.join(close)}; " if close else "")
                         + f"known: {', '.join(names)}")
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
