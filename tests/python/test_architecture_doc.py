"""docs/ARCHITECTURE.md must stay in step with the source tree.

- every .h, .cpp, .py and .sh file under native/, addon/stick_morph/,
  scripts/ and bench/ is named in it by its path from the repository root (in a code
  span, e.g. `native/stickmorph/morph.h`);
- every repository path it names in a code span exists (a `*` in a path must
  match at least one file).

So a file added, moved or removed without a line in the document fails here
instead of leaving the document silently wrong.
"""
import pathlib
import re

REPO = pathlib.Path(__file__).resolve().parents[2]
DOCUMENT = REPO / "docs" / "ARCHITECTURE.md"

# Folders whose sources the document must list, and the suffixes that count.
LISTED_FOLDERS = ("native", "addon/stick_morph", "scripts", "bench")
LISTED_SUFFIXES = {".h", ".cpp", ".py", ".sh"}
SKIPPED_PARTS = {"__pycache__"}

# A code span that is a path from the repository root: it starts with one of
# the repository's top-level folders or files.
TOP_LEVEL = ("native/", "addon/", "scripts/", "bench/", "tests/", "docs/", "blend_samples/", "build_addon.py",
             "CMakeLists.txt", "README.md", "BENCHMARKS.md")
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.DOTALL)
PATH = re.compile(r"^[\w./*+-]+$")


def document_text():
    return DOCUMENT.read_text(encoding="utf-8")


def named_paths(text):
    """Every code span of the text that is a repository path."""
    paths = set()
    for match in CODE_SPAN.finditer(text):
        span = match.group(2).strip()
        if PATH.match(span) and span.startswith(TOP_LEVEL):
            paths.add(span.rstrip("/") if span != "/" else span)
    return paths


def source_files():
    files = []
    for folder in LISTED_FOLDERS:
        for path in sorted((REPO / folder).rglob("*")):
            if not path.is_file() or path.suffix not in LISTED_SUFFIXES:
                continue
            if SKIPPED_PARTS.intersection(path.relative_to(REPO).parts):
                continue
            files.append(path.relative_to(REPO).as_posix())
    return files


def test_the_document_names_paths():
    # Guards the parsing below: a document without any path would pass the
    # existence check vacuously.
    assert len(named_paths(document_text())) > 50


def test_every_source_file_is_named():
    named = named_paths(document_text())
    missing = [path for path in source_files() if path not in named]
    assert not missing, ("docs/ARCHITECTURE.md does not name these files (one line each, by their path "
                         "from the repository root): " + ", ".join(missing))


def test_every_named_path_exists():
    absent = []
    for path in sorted(named_paths(document_text())):
        if "*" in path:
            if not any(REPO.glob(path)):
                absent.append(path)
        elif not (REPO / path).exists():
            absent.append(path)
    assert not absent, "docs/ARCHITECTURE.md names paths that do not exist: " + ", ".join(absent)


def test_named_paths_parsing():
    text = "`native/cli/main.cpp`, `tests/python/test_addon_*.py`, `stickmorph morph`, `out.json`, `tests/data/`"
    assert named_paths(text) == {"native/cli/main.cpp", "tests/python/test_addon_*.py", "tests/data"}
