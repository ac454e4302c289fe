"""The CLI's output and input files as special files (issue 26; docs/CLI.md,
"Output files" and "Reading figure files").

Outputs: a symbolic link is written through (the link stays, its target
holds the output); a character device, a FIFO and /dev/stdout are written
into, never replaced by a regular file; two outputs that are one file, or an
output that is an input, are refused before any work naming both; no failed
run changes an existing file. Inputs: only regular files are read; a FIFO or
a device is refused at once.

Every subprocess runs with a timeout, so a hang fails the test.
"""
import json
import os
import pathlib
import stat
import subprocess
import threading
import time
import xml.etree.ElementTree as ElementTree

import pytest

TIMEOUT_SECONDS = 60


def run(cli, *args, **kwargs):
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=TIMEOUT_SECONDS, **kwargs)


@pytest.fixture()
def pair(data_dir):
    folder = data_dir / "pairs" / "compatible"
    return folder / "letter_a.source.json", folder / "letter_a.target.json"


def assert_refused(result, *fragments):
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert result.stdout == ""
    assert result.stderr.startswith("error: ") and result.stderr.count("\n") == 1, result.stderr
    assert "internal error" not in result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, (fragment, result.stderr)
    return result.stderr


def is_morph_document(text):
    document = json.loads(text)
    return {"edges", "times", "frames"} <= set(document)


@pytest.mark.parametrize("command", ["morph", "triangulate", "correspond"])
def test_dev_null_stays_a_device(cli, pair, command):
    before = os.stat("/dev/null")
    result = run(cli, command, *pair, "-o", "/dev/null")
    assert result.returncode == 0, result.stderr
    after = os.stat("/dev/null")
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev


def test_dev_full_fails_and_stays_a_device(cli, pair):
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full")
    assert_refused(run(cli, "morph", *pair, "-o", "/dev/full"), "/dev/full: cannot write file", "No space left")
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)


def test_dev_stdout_writes_to_the_pipe(cli, pair):
    result = run(cli, "morph", *pair, "-o", "/dev/stdout")
    assert result.returncode == 0, result.stderr
    assert is_morph_document(result.stdout)


def test_dev_stdout_redirected_to_a_file(cli, pair, tmp_path):
    out = tmp_path / "redirected.json"
    with open(out, "w") as stdout:
        result = subprocess.run([str(cli), "morph", *map(str, pair), "-o", "/dev/stdout"], stdout=stdout,
                                stderr=subprocess.PIPE, text=True, timeout=TIMEOUT_SECONDS)
    assert result.returncode == 0, result.stderr
    assert is_morph_document(out.read_text())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["redirected.json"]


def test_fifo_output_is_written_into(cli, pair, tmp_path):
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    received = {}

    def read():
        with open(fifo) as reader:
            received["text"] = reader.read()

    reader = threading.Thread(target=read)
    reader.start()
    result = run(cli, "morph", *pair, "-o", fifo)
    reader.join(TIMEOUT_SECONDS)
    assert result.returncode == 0, result.stderr
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert is_morph_document(received["text"])


def test_fifo_output_without_reader_fails_instead_of_hanging(cli, pair, tmp_path):
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    start = time.monotonic()
    assert_refused(run(cli, "triangulate", *pair, "-o", fifo), "no process opened the FIFO for reading")
    assert time.monotonic() - start < 30
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


@pytest.mark.parametrize("option", ["-o", "--svg"])
def test_symlink_is_written_through(cli, pair, tmp_path, option):
    target = tmp_path / "real" / "file.out"
    target.parent.mkdir()
    target.write_text("before")
    link = tmp_path / "link.out"
    link.symlink_to(os.path.relpath(target, tmp_path))
    other = tmp_path / ("other.svg" if option == "-o" else "other.json")
    arguments = ["-o", link, "--svg", other] if option == "-o" else ["-o", other, "--svg", link]
    result = run(cli, "morph", *pair, *arguments)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and os.readlink(link) == os.path.relpath(target, tmp_path)
    text = target.read_text()
    if option == "-o":
        assert is_morph_document(text)
    else:
        ElementTree.fromstring(text)


def test_dangling_symlink_creates_its_target(cli, pair, tmp_path):
    link = tmp_path / "link.json"
    link.symlink_to("made.json")
    result = run(cli, "morph", *pair, "-o", link)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and is_morph_document((tmp_path / "made.json").read_text())


def test_replaced_file_keeps_its_permissions_and_new_files_follow_the_umask(cli, pair, tmp_path):
    existing = tmp_path / "existing.json"
    existing.write_text("old")
    existing.chmod(0o640)
    assert run(cli, "morph", *pair, "-o", existing).returncode == 0
    assert stat.S_IMODE(existing.stat().st_mode) == 0o640
    fresh = tmp_path / "fresh.json"
    mask = os.umask(0)
    os.umask(mask)
    assert run(cli, "morph", *pair, "-o", fresh).returncode == 0
    assert stat.S_IMODE(fresh.stat().st_mode) == 0o666 & ~mask


@pytest.mark.parametrize("spelling", ["same", "dot-slash", "absolute", "symlink", "hard-link"])
@pytest.mark.parametrize("command", ["morph", "triangulate"])
def test_two_outputs_naming_one_file_are_refused_and_change_nothing(cli, pair, tmp_path, spelling, command,
                                                                    monkeypatch):
    monkeypatch.chdir(tmp_path)
    keep = tmp_path / "keep.json"
    keep.write_text("ORIGINAL\n")
    if spelling == "symlink":
        (tmp_path / "alias.json").symlink_to("keep.json")
        svg = "alias.json"
    elif spelling == "hard-link":
        os.link(keep, tmp_path / "alias.json")
        svg = "alias.json"
    else:
        svg = {"same": "keep.json", "dot-slash": "./keep.json", "absolute": str(keep)}[spelling]
    message = assert_refused(run(cli, command, *pair, "-o", "keep.json", "--svg", svg, cwd=tmp_path),
                             "--svg and --output name the same file")
    assert command + ": " in message
    assert keep.read_text() == "ORIGINAL\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["keep.json"] + (["alias.json"] if spelling in ("symlink", "hard-link") else []))


@pytest.mark.parametrize("which", [0, 1])
@pytest.mark.parametrize("option", ["-o", "--svg"])
def test_output_over_an_input_is_refused(cli, pair, tmp_path, which, option):
    source, target = (tmp_path / "a.json", tmp_path / "b.json")
    source.write_text(pair[0].read_text())
    target.write_text(pair[1].read_text())
    victim = (source, target)[which]
    arguments = ["-o", victim] if option == "-o" else ["-o", tmp_path / "out.json", "--svg", victim]
    name = "--output" if option == "-o" else "--svg"
    assert_refused(run(cli, "morph", source, target, *arguments),
                   f"{name} and {('SOURCE.json', 'TARGET.json')[which]} name the same file")
    assert source.read_text() == pair[0].read_text() and target.read_text() == pair[1].read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.json", "b.json"]


def test_failed_run_changes_no_existing_file(cli, data_dir, tmp_path):
    # An incompatible pair fails after the outputs were prepared: both keep
    # their contents and no temporary is left.
    folder = data_dir / "pairs" / "incompatible"
    out, svg = tmp_path / "out.json", tmp_path / "out.svg"
    out.write_text("previous json")
    svg.write_text("previous svg")
    result = run(cli, "morph", folder / "mirror_image.source.json", folder / "mirror_image.target.json", "-o", out,
                 "--svg", svg)
    assert_refused(result)
    assert out.read_text() == "previous json" and svg.read_text() == "previous svg"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.json", "out.svg"]


def test_device_write_failure_changes_no_regular_output(cli, pair, tmp_path):
    # -o goes to a regular file, --svg to /dev/full: the SVG fails before
    # the JSON's temporary is renamed over the existing file.
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full")
    out = tmp_path / "out.json"
    out.write_text("previous")
    assert_refused(run(cli, "morph", *pair, "-o", out, "--svg", "/dev/full"), "/dev/full")
    assert out.read_text() == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.json"]


@pytest.mark.parametrize("path", ["/proc/stickmorph-out.json", "/proc/self/stickmorph-out.json"])
def test_output_where_no_file_can_be_made_fails_before_the_work(cli, pair, path):
    result = run(cli, "morph", *pair, "-o", path, "--frames", "2000")
    assert_refused(result, path + ": cannot write file")


def test_block_device_and_socket_outputs_are_refused(cli, pair, tmp_path):
    import socket
    sock_path = tmp_path / "s.sock"
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(sock_path))
    try:
        assert_refused(run(cli, "morph", *pair, "-o", sock_path), "is a socket, not a file")
    finally:
        server.close()
    assert stat.S_ISSOCK(os.lstat(sock_path).st_mode)


def test_short_option_joined_with_equals(cli, pair, tmp_path):
    result = run(cli, "morph", *pair, "-o=x.json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.json"]
    assert_refused(run(cli, "morph", *pair, "-o=", cwd=tmp_path), "needs a file name")


# ------------------------------------------------------------------ inputs --

def test_fifo_input_is_refused_at_once(cli, pair, tmp_path):
    fifo = tmp_path / "in.fifo"
    os.mkfifo(fifo)
    for arguments in (["morph", fifo, pair[1], "-o", tmp_path / "o.json"], ["check", pair[0], fifo]):
        start = time.monotonic()
        assert_refused(run(cli, *arguments), f"{fifo}: cannot read file: a FIFO, not a regular file")
        assert time.monotonic() - start < 1.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.fifo"]


def test_device_input_is_refused(cli, pair):
    assert_refused(run(cli, "check", "/dev/zero", pair[1]), "/dev/zero: cannot read file: a character device")


def test_module_refuses_a_fifo(tmp_path):
    import stickmorph
    fifo = tmp_path / "in.fifo"
    os.mkfifo(fifo)
    start = time.monotonic()
    with pytest.raises(stickmorph.FileError, match="a FIFO, not a regular file"):
        stickmorph.load_figure(fifo)
    assert time.monotonic() - start < 1.0


# --------------------------------------------------------------- SVG text --

NASTY_NAMES = ["x\u0007y", "<b>&amp;</b>", "quote \" and ' apostrophe", "tab\tline\nfeed\rreturn",
               "\u0001\u001f\u007f", "snowman \u2603 and \U0001F600", "\ufffe\uffff"]


@pytest.mark.parametrize("name", NASTY_NAMES, ids=range(len(NASTY_NAMES)))
@pytest.mark.parametrize("command", ["morph", "triangulate", "morph-compare", "morph-overlay"])
def test_every_svg_is_valid_xml(cli, pair, tmp_path, name, command):
    source = json.loads(pair[0].read_text())
    source["name"] = name
    named = tmp_path / "named.json"
    named.write_text(json.dumps(source))
    extra = {"morph-compare": ["--svg-compare-linear"], "morph-overlay": ["--svg-triangulation"]}.get(command, [])
    result = run(cli, command.split("-")[0], named, pair[1], "-o", tmp_path / "o.json", "--svg",
                 tmp_path / "o.svg", *extra)
    assert result.returncode == 0, result.stderr
    root = ElementTree.fromstring((tmp_path / "o.svg").read_bytes())
    assert root.tag.endswith("svg")
    json.loads((tmp_path / "o.json").read_text())


def test_svg_title_from_an_odd_file_name(cli, pair, tmp_path):
    # With no "name" the title quotes the path, whatever bytes it holds.
    source = json.loads(pair[0].read_text())
    source.pop("name", None)
    odd = tmp_path / "a<&\x01\".json"
    odd.write_text(json.dumps(source))
    result = run(cli, "morph", odd, pair[1], "-o", tmp_path / "o.json", "--svg", tmp_path / "o.svg")
    assert result.returncode == 0, result.stderr
    title = ElementTree.fromstring((tmp_path / "o.svg").read_bytes()).find("{http://www.w3.org/2000/svg}title")
    assert "a<&\\x01\"" in title.text
