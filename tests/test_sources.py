"""Every source the project cites is a paper, a standard or a file of the project: no file of it (code,
data, networks, examples, validation scripts and reports, tests, documentation) cites the notebook of
formulas that lives outside the project (each formula is cited to the paper it came from)."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = "PHYSICS" + ".md"                      # spelled apart, so that this file does not cite it
SKIP_DIRS = {".git", ".venv", "__pycache__", ".pytest_cache", ".hypothesis", "build", "dist"}
TEXT = {".py", ".toml", ".md", ".csv", ".txt", ".cfg", ".ini", ".json", ".yml", ".yaml", ""}


def project_files():
    for p in ROOT.rglob("*"):
        if p.is_file() and not SKIP_DIRS & set(p.relative_to(ROOT).parts) and p.suffix in TEXT:
            yield p


def test_no_project_file_cites_the_notebook_outside_the_project():
    files = list(project_files())
    assert any(p.name == "skf_constants.toml" for p in files) and any(p.parent.name == "report" for p in files)
    citing = [str(p.relative_to(ROOT)) for p in files if NOTEBOOK in p.read_text(encoding="utf-8", errors="replace")]
    assert not citing, f"cite the paper (author, year, equation) instead of {NOTEBOOK} in: {', '.join(citing)}"
