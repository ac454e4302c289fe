"""Every link in README.md and docs/ must resolve inside the repository.

The documents once linked the CLI contract and the paper outside the
repository (../shared/...), which dangles in any clone that is not next to
that folder. So, for README.md, bench/README.md and every docs/**/*.md:

- each Markdown link or image target ([text](target), [ref]: target, and the
  href/src of inline HTML) is a relative path to a file or folder that git
  tracks in this repository (or that exists, where git is unavailable),
  optionally with an #anchor that matches a heading of the Markdown file it
  names;
- no target is an absolute URL or an absolute path: the paper is cited by
  title, everything else lives in the repository;
- no text, code spans included, mentions a ../ path that leaves the
  repository, read from the document's folder or from the repository's root.
"""
import pathlib
import re
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]

# [text](target "title") and ![alt](target); the text may hold one level of
# brackets (`[`a`](b)` does not, but [a [b] c](d) would).
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>]*>|[^)\s]+)(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
REFERENCE_DEFINITION = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)", re.MULTILINE)
HTML_ATTRIBUTE = re.compile(r"<[a-zA-Z][^>]*?\b(?:href|src)\s*=\s*[\"']([^\"']*)[\"']")
FENCE = re.compile(r"^ {0,3}(```|~~~).*?^ {0,3}\1[^\n]*$", re.MULTILINE | re.DOTALL)
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.DOTALL)
URL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")
# A relative path climbing out of its folder, anywhere in the text.
PARENT_PATH = re.compile(r"(?<![\w./-])((?:\.\./)+[\w./-]*)")


def documents():
    return [REPO / "README.md", REPO / "bench" / "README.md", *sorted((REPO / "docs").rglob("*.md"))]


def tracked_paths():
    """Every path git tracks (files and their folders), or None without git."""
    try:
        result = subprocess.run(["git", "-C", str(REPO), "ls-files", "-z"], stdout=subprocess.PIPE,
                                stderr=subprocess.DEVNULL, check=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return None
    paths = set()
    for name in result.stdout.decode("utf-8", "surrogateescape").split("\0"):
        if not name:
            continue
        path = pathlib.PurePosixPath(name)
        paths.add(path)
        paths.update(path.parents)
    return paths


def without_code(text):
    """The text with fenced blocks and code spans blanked (same length, so
    offsets still give line numbers): `[a](b)` in code is not a link."""
    blank = lambda match: re.sub(r"[^\n]", " ", match.group(0))
    return CODE_SPAN.sub(blank, FENCE.sub(blank, text))


def link_targets(text):
    """(line, target) for every link target outside code."""
    prose = without_code(text)
    found = []
    for pattern in (INLINE_LINK, REFERENCE_DEFINITION, HTML_ATTRIBUTE):
        for match in pattern.finditer(prose):
            target = match.group(1)
            if target.startswith("<") and target.endswith(">"):
                target = target[1:-1]
            found.append((prose.count("\n", 0, match.start(1)) + 1, target))
    return sorted(found)


def heading_anchors(markdown_text):
    """The anchors GitHub gives the headings: lower case, punctuation other
    than - and _ dropped, spaces to hyphens, -1, -2, ... for repeats."""
    anchors, seen = set(), {}
    for line in FENCE.sub("", markdown_text).splitlines():
        match = re.match(r"^ {0,3}#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not match:
            continue
        slug = re.sub(r"[^\w\- ]", "", match.group(1).lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        anchors.add(slug if count == 0 else f"{slug}-{count}")
    return anchors


def problems(document, text, tracked):
    """Yields one message per link of `document` (a path in REPO) that does
    not resolve inside the repository."""
    where = document.relative_to(REPO)
    reported = set()  # (line, target): a bad link is not reported again as a ../ path
    for line, target in link_targets(text):
        place = f"{where}:{line}: link {target!r}"
        reported.add((line, target.partition("#")[0]))
        if target.startswith("#"):
            if target[1:] not in heading_anchors(text):
                yield f"{place}: {where} has no heading with anchor {target}"
            continue
        if URL.match(target) or target.startswith("//"):
            yield f"{place} points outside the repository (cite the paper by title, link files in the repo)"
            continue
        path_part, _, anchor = target.partition("#")
        if path_part.startswith("/"):
            yield f"{place} is an absolute path; use a path relative to {where.parent}/"
            continue
        resolved = (document.parent / path_part).resolve()
        try:
            relative = pathlib.PurePosixPath(resolved.relative_to(REPO).as_posix())
        except ValueError:
            yield f"{place} points outside the repository"
            continue
        exists = resolved.exists() if tracked is None else (relative in tracked or relative == pathlib.PurePosixPath("."))
        if not exists:
            yield f"{place}: {relative} is not a file of the repository" + (
                "" if tracked is None else " (not tracked by git)")
            continue
        if anchor and resolved.suffix == ".md" and resolved.is_file():
            if anchor not in heading_anchors(resolved.read_text(encoding="utf-8")):
                yield f"{place}: {relative} has no heading with anchor #{anchor}"
    for match in PARENT_PATH.finditer(text):
        # Prose and commands often give paths from the repository's root
        # rather than from the document's folder: either reading must stay in.
        line = text.count("\n", 0, match.start(1)) + 1
        outside = any(resolved != REPO and REPO not in resolved.parents
                      for resolved in ((document.parent / match.group(1)).resolve(),
                                       (REPO / match.group(1)).resolve()))
        if outside and (line, match.group(1)) not in reported:
            yield f"{where}:{line}: {match.group(1)!r} names a path outside the repository"


@pytest.fixture(scope="module")
def tracked():
    return tracked_paths()


@pytest.mark.parametrize("document", documents(), ids=lambda p: str(p.relative_to(REPO)))
def test_links_resolve_inside_the_repository(document, tracked):
    found = list(problems(document, document.read_text(encoding="utf-8"), tracked))
    assert not found, "\n".join(found)


def test_documents_have_links():
    # Guards the parser: if it stopped finding links, every document would
    # pass unchecked. README.md and docs/ARCHITECTURE.md link other files.
    for name in ("README.md", "docs/ARCHITECTURE.md"):
        assert link_targets((REPO / name).read_text(encoding="utf-8")), f"no links found in {name}"


def test_problems_are_found(tmp_path, monkeypatch):
    # The checker must be able to fail: a document in docs/ with each kind of
    # bad link, checked against the real repository.
    document = REPO / "docs" / "EXAMPLE.md"
    text = "\n".join([
        "# Title",
        "[contract](../../shared/FORMAT.md)",        # 2: leaves the repository
        "[paper](https://example.org/paper.pdf)",    # 3: a URL
        "[gone](NO_SUCH_FILE.md)",                   # 4: missing
        "[anchor](CLI.md#no-such-heading)",          # 5: missing anchor
        "![picture](/etc/passwd)",                   # 6: absolute path
        "see `../shared/paper/x.md`",                # 7: outside path in a code span
        "[ok](CLI.md#exit-codes) [ok](../README.md) [self](#title) `[not a link](nowhere)`",
        "```",
        "[in a fence](nowhere.md)",
        "```",
    ])
    found = list(problems(document, text, tracked_paths()))
    lines = sorted(int(message.split(":")[1]) for message in found)
    assert lines == [2, 3, 4, 5, 6, 7], found
