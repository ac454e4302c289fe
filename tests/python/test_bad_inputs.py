"""The bad-input catalogue (tests/data/bad_inputs/catalogue.json) at the CLI
and the Python module.

Every kind in the catalogue has, per interface, either an expected answer or
a `skip` saying why it has no form there. The CLI must exit 2 with nothing on
stdout and exactly one `error: ` line on stderr that holds the expected
fragments, leave no output file (and leave an existing one untouched). The
module must raise the named ValueError subclass with the same fragments.
"Never a crash, a hang or a stack trace" is asserted: every CLI run and every
risky module call runs in a child process with a timeout.
"""
import json
import math
import os
import pathlib
import random
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import stickmorph

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"
CATALOGUE = json.loads((DATA / "bad_inputs" / "catalogue.json").read_text())
KINDS = {kind["id"]: kind for kind in CATALOGUE["kinds"]}
TIMEOUT_SECONDS = 60
CRASH_SIGNS = ("Traceback", "terminate called", "Segmentation", "Assertion", "AddressSanitizer",
               "Aborted", "what():", "core dumped")
GOOD_SOURCE = DATA / "pairs" / "compatible" / "letter_a.source.json"
GOOD_TARGET = DATA / "pairs" / "compatible" / "letter_a.target.json"


def ids_with(interface, predicate=lambda kind: True):
    return [k for k, kind in KINDS.items() if "skip" not in kind[interface] and predicate(kind)]


def is_file_kind(kind):
    return "input" in kind and "pair" not in kind["input"]


# ---------------------------------------------------------------- the data --


def test_catalogue_ids_are_unique_and_every_kind_has_each_interface():
    ids = [kind["id"] for kind in CATALOGUE["kinds"]]
    assert len(ids) == len(set(ids))
    for kind in CATALOGUE["kinds"]:
        for interface in ("cli", "python", "blender"):
            entry = kind[interface]
            assert "skip" in entry or "message" in entry or "rejected_by_rna" in entry, (kind["id"], interface)
            if "skip" in entry:
                assert entry["skip"].strip(), (kind["id"], interface)
        assert "skip" not in kind["cli"] or "skip" not in kind["python"] or "skip" not in kind["blender"], kind["id"]


def test_every_malformed_file_and_incompatible_pair_is_catalogued():
    used = {kind["input"]["file"] for kind in KINDS.values() if "file" in kind.get("input", {})}
    on_disk = {f"malformed/{p.name}" for p in (DATA / "malformed").iterdir()}
    assert on_disk == used
    pairs = {kind["input"]["pair"] for kind in KINDS.values() if "pair" in kind.get("input", {})}
    on_disk = {f"incompatible/{p.name[:-len('.source.json')]}"
               for p in (DATA / "pairs" / "incompatible").glob("*.source.json")}
    assert on_disk == pairs


# -------------------------------------------------------------- the inputs --


def materialise(kind, folder):
    """The kind's input as a path (str or bytes) in `folder`."""
    spec = kind["input"]
    if "file" in spec:
        return str(DATA / spec["file"])
    if "sparse_bytes" in spec:
        path = folder / "sparse.json"
        with open(path, "wb") as file:
            file.truncate(spec["sparse_bytes"])
        return str(path)
    if "generate" in spec:
        recipe = spec["generate"]
        path = folder / "generated.json"
        if "random_bytes" in recipe:
            generator = random.Random(recipe["seed"])
            path.write_bytes(bytes(generator.randrange(256) for _ in range(recipe["random_bytes"])))
        else:
            count = recipe["count"]
            text = (recipe.get("head", "") + recipe["repeat"] * count + recipe.get("tail", "")
                    + recipe.get("tail_repeat", "") * count)
            path.write_bytes(text.encode("utf-8"))
        return str(path)
    special = spec["special"]
    if special == "missing":
        return str(folder / "missing.json")
    if special == "directory":
        return str(folder)
    if special == "unreadable":
        path = folder / "locked.json"
        path.write_text(GOOD_SOURCE.read_text())
        path.chmod(0)
        return str(path)
    if special == "dev_zero":
        return "/dev/zero"
    if special == "fifo":
        path = folder / "in.fifo"
        os.mkfifo(path)
        return str(path)
    if special == "empty_name":
        return ""
    if special == "nul_in_name":
        return str(folder / "a\0b.json")
    if special == "line_break_in_name":
        return str(folder / "two\nlines.json")
    raise AssertionError(f"unknown special input {special!r}")


def skip_unless_possible(kind):
    if kind.get("unless_root") and os.geteuid() == 0:
        pytest.skip("root reads files regardless of permissions")


# --------------------------------------------------------------------- CLI --


def run_cli(cli, arguments):
    result = subprocess.run([str(cli), *arguments], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, timeout=TIMEOUT_SECONDS)
    return (result.returncode, result.stdout.decode("utf-8", "replace"),
            result.stderr.decode("utf-8", "replace"))


def assert_one_error_line(outcome, fragments, arguments):
    code, stdout, stderr = outcome
    assert code == 2, (arguments, code, stdout, stderr)
    assert stdout == "", (arguments, stdout)
    assert stderr.startswith("error: ") and stderr.endswith("\n"), (arguments, stderr)
    assert stderr.count("\n") == 1, (arguments, stderr)
    for sign in CRASH_SIGNS:
        assert sign not in stderr, (arguments, stderr)
    message = stderr[len("error: "):-1]
    for fragment in fragments:
        assert fragment in message, (fragment, message)
    return message


def listing(folder):
    return sorted((p.name, p.read_bytes() if p.is_file() else None) for p in folder.iterdir())


@pytest.fixture
def folders(tmp_path):
    inputs, out_dir = tmp_path / "in", tmp_path / "out"
    inputs.mkdir()
    out_dir.mkdir()
    return inputs, out_dir


def cli_file_runs(bad, out):
    good_source, good_target = str(GOOD_SOURCE), str(GOOD_TARGET)
    return [["check", bad, good_target], ["check", good_source, bad],
            ["triangulate", bad, good_target, "-o", str(out)],
            ["morph", good_source, bad, "-o", str(out), "--svg", str(out.with_suffix(".svg"))]]


@pytest.mark.parametrize("kind_id", ids_with("cli", is_file_kind))
def test_cli_file_kind(cli, folders, kind_id):
    kind = KINDS[kind_id]
    skip_unless_possible(kind)
    inputs, out_dir = folders
    bad = materialise(kind, inputs)
    expected = kind["cli"]
    shown = bad.replace("\n", "\\n")
    for arguments in cli_file_runs(bad, out_dir / "OUT.json"):
        message = assert_one_error_line(run_cli(cli, arguments), expected["message"], arguments)
        if expected.get("names_file", True):
            assert message.startswith(f"{shown}: "), message
        assert len(message) <= expected.get("max_message_length", 2000), len(message)
        assert listing(out_dir) == [], listing(out_dir)


@pytest.mark.parametrize("kind_id", ids_with("cli", lambda kind: "pair" in kind.get("input", {})))
def test_cli_pair_kind(cli, folders, kind_id):
    kind = KINDS[kind_id]
    _, out_dir = folders
    source, target = (str(DATA / "pairs" / f"{kind['input']['pair']}.{role}.json") for role in ("source", "target"))
    # check answers: a well-formed incompatible pair is a result, not an error.
    code, stdout, stderr = run_cli(cli, ["check", source, target])
    assert (code, stderr) == (kind["cli"]["check_exit"], "")
    assert stdout.startswith("incompatible: ") and stdout.count("\n") == 1, stdout
    for fragment in kind["cli"]["message"]:
        assert fragment in stdout, (fragment, stdout)
    out = out_dir / "OUT.json"
    for arguments in (["triangulate", source, target, "-o", str(out)],
                      ["morph", source, target, "-o", str(out), "--svg", str(out_dir / "OUT.svg")],
                      ["morph", source, target, "-o", str(out), "--method", "barycentric"],
                      ["morph", source, target, "-o", str(out), "--method", "linear"]):
        message = assert_one_error_line(run_cli(cli, arguments), ["incompatible figures: "] + kind["cli"]["message"],
                                        arguments)
        assert listing(out_dir) == [], message


def substitute(text, names):
    for key, value in names.items():
        text = text.replace("{" + key + "}", value)
    return text


@pytest.mark.parametrize("kind_id", ids_with("cli", lambda kind: "args" in kind["cli"]))
@pytest.mark.parametrize("existing_output", [False, True], ids=["no-output", "existing-output"])
def test_cli_argument_kind(cli, folders, kind_id, existing_output):
    kind = KINDS[kind_id]
    _, out_dir = folders
    names = {"source": str(GOOD_SOURCE), "target": str(GOOD_TARGET), "out_dir": str(out_dir),
             "out": str(out_dir / "OUT.json"), "svg": str(out_dir / "OUT.svg")}
    arguments = [substitute(a, names) for a in kind["cli"]["args"]]
    if existing_output:
        if "{out}" not in kind["cli"]["args"]:
            pytest.skip("writes no OUT.json")
        # A failure must leave what was there before.
        (out_dir / "OUT.json").write_text("previous result")
    before = listing(out_dir)
    fragments = [substitute(f, names) for f in kind["cli"]["message"]]
    assert_one_error_line(run_cli(cli, arguments), fragments, arguments)
    assert listing(out_dir) == before


# ------------------------------------------------------------------ Python --

FIGURE = json.loads(GOOD_SOURCE.read_text())
TARGET_FIGURE = json.loads(GOOD_TARGET.read_text())
PLACEHOLDERS = {"{source_vertices}": FIGURE["vertices"], "{target_vertices}": TARGET_FIGURE["vertices"],
                "{edges}": FIGURE["edges"], "{source_path}": str(GOOD_SOURCE)}


def decode(value):
    """A catalogue value as the Python object it stands for."""
    if isinstance(value, str) and value in PLACEHOLDERS:
        return PLACEHOLDERS[value]
    if isinstance(value, list):
        return [decode(v) for v in value]
    if isinstance(value, dict):
        if "$float" in value:
            return float(value["$float"])
        if "$int" in value:
            return int(value["$int"])
        if "$zeros" in value:
            return np.zeros(tuple(value["$zeros"]))
        if "$array" in value:
            return np.array(value["$array"], dtype=value["dtype"])
        raise AssertionError(f"unknown tagged value {value!r}")
    return value


def call_arguments(kind):
    spec = kind["python"]
    arguments = {name: decode(v) for name, v in CATALOGUE["python_defaults"][spec["call"]].items()}
    arguments.update({name: decode(v) for name, v in spec["args"].items()})
    return arguments


def assert_python_error(error, spec):
    expected_class = getattr(stickmorph, spec["error"])
    assert issubclass(expected_class, ValueError)
    assert type(error) is expected_class, (type(error), error)
    for fragment in spec["message"]:
        assert fragment in str(error), (fragment, str(error))
    if "defect" in spec:
        assert error.defect == spec["defect"]
        for index in (error.vertices or []) + (error.edges or []):
            assert str(index) in str(error)


CHILD = textwrap.dedent("""
    import sys
    sys.path.insert(0, sys.argv[1])
    import stickmorph
    try:
        stickmorph.load_figure(sys.argv[2])
    except stickmorph.StickMorphError as error:
        print(type(error).__name__)
        print(str(error))
    else:
        print("no error")
""")


def load_in_child(path):
    """load_figure in a child process: a crash or a hang fails the test, not pytest."""
    module_dir = pathlib.Path(stickmorph.__file__).parent
    result = subprocess.run([sys.executable, "-c", CHILD, str(module_dir), path], capture_output=True,
                            text=True, stdin=subprocess.DEVNULL, timeout=TIMEOUT_SECONDS)
    assert result.returncode == 0, (result.returncode, result.stderr[-2000:])
    assert result.stderr == ""
    class_name, _, message = result.stdout.partition("\n")
    return class_name, message.rstrip("\n")


@pytest.mark.parametrize("kind_id", ids_with("python", is_file_kind))
def test_python_file_kind(cli, folders, kind_id):
    kind = KINDS[kind_id]
    skip_unless_possible(kind)
    inputs, _ = folders
    path = materialise(kind, inputs)
    spec = kind["python"]
    if spec.get("isolate"):
        class_name, message = load_in_child(path)
        assert class_name == spec["error"], (class_name, message)
        for fragment in spec["message"]:
            assert fragment in message, (fragment, message)
        error_text = message
    else:
        with pytest.raises(stickmorph.StickMorphError) as info:
            stickmorph.load_figure(path)
        assert_python_error(info.value, spec)
        error_text = str(info.value)
    if "skip" not in kind["cli"] and kind["cli"].get("names_file", True):
        # The module and the CLI say the same thing about a file.
        code, _, stderr = run_cli(cli, ["check", path, str(GOOD_TARGET)])
        shown = path.replace("\n", "\\n")
        assert code == 2 and stderr == f"error: {error_text.replace(path, shown)}\n", (stderr, error_text)


@pytest.mark.parametrize("kind_id", ids_with("python", lambda kind: "defect" in kind["python"]
                                             and "file" in kind.get("input", {})))
def test_python_figure_kind_from_arrays(kind_id):
    # The same defect given as arrays: validate() names the same indices.
    document = json.loads((DATA / KINDS[kind_id]["input"]["file"]).read_text())
    with pytest.raises(stickmorph.InvalidFigureError) as info:
        stickmorph.validate(document["vertices"], document["edges"])
    spec = KINDS[kind_id]["python"]
    assert info.value.defect == spec["defect"]
    for fragment in spec["message"]:
        assert fragment in str(info.value)


@pytest.mark.parametrize("kind_id", ids_with("python", lambda kind: "pair" in kind.get("input", {})))
@pytest.mark.parametrize("function, options", [("morph", {}), ("morph", {"method": "barycentric"}),
                                               ("morph", {"method": "linear"}), ("triangulate_figures", {})],
                         ids=["morph", "morph-barycentric", "morph-linear", "triangulate_figures"])
def test_python_pair_kind(kind_id, function, options):
    kind = KINDS[kind_id]
    source, target = (json.loads((DATA / "pairs" / f"{kind['input']['pair']}.{role}.json").read_text())
                      for role in ("source", "target"))
    call = getattr(stickmorph, function)
    with pytest.raises(stickmorph.StickMorphError) as info:
        call(source["vertices"], target["vertices"], source["edges"], target_edges=target["edges"], **options)
    assert_python_error(info.value, kind["python"])
    # check_compatibility answers with a report, and the same reason.
    report = stickmorph.check_compatibility(source["vertices"], target["vertices"], source["edges"],
                                            target["edges"])
    assert not report and str(info.value) == f"incompatible figures: {report.reason}"


@pytest.mark.parametrize("kind_id", ids_with("python", lambda kind: "call" in kind["python"]))
def test_python_argument_kind(kind_id):
    kind = KINDS[kind_id]
    spec = kind["python"]
    function = getattr(stickmorph, spec["call"])
    with pytest.raises(stickmorph.StickMorphError) as info:
        function(**call_arguments(kind))
    assert_python_error(info.value, spec)
    assert "\n" not in str(info.value)


def test_python_calls_with_unknown_keywords_are_type_errors():
    # Deliberately not in the catalogue as a ValueError: a misspelt keyword
    # is a programming error that Python itself reports as TypeError for
    # every function; the message names the keyword.
    with pytest.raises(TypeError, match="framez"):
        stickmorph.morph(FIGURE["vertices"], TARGET_FIGURE["vertices"], FIGURE["edges"], framez=3)


def test_decode_tags():
    assert math.isnan(decode({"$float": "nan"}))
    assert decode({"$int": "99999999999999999999"}) == 99999999999999999999
    assert decode({"$zeros": [2, 3]}).shape == (2, 3)
    assert decode(["{edges}"]) == [FIGURE["edges"]]
