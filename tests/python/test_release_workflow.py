"""The release workflow (.github/workflows/release.yml) and its description
(docs/RELEASE.md) must stay in step with each other and with the repository.

The workflow cannot run here (no GitHub runner), so these tests check what can
be checked without one:

- it is a GitHub Actions workflow: a mapping with `on` (a `v*` tag push and
  workflow_dispatch) and `jobs`, every job with a runner and steps, every step
  either `uses` an action pinned to a major version or `run`s a script that
  bash can parse;
- every repository file a `run:` script names (build_addon.py,
  native/python/stickmorph_build_backend.py, scripts/..., CMakeLists.txt)
  exists, so that a rename cannot leave the release recipe pointing nowhere;
- the wheels are built for exactly CPython 3.11 and 3.13 (the Pythons
  blender.org Blenders embed: 3.11 in 4.2-5.0, 3.13 from 5.1 on), each checked
  in the Blender series that embeds it, on Linux x86_64, Windows x64, macOS
  arm64 and macOS x86_64;
- docs/RELEASE.md's table names every extension package the workflow uploads;
- the Python snippets the workflow runs (in a venv, inside Blender, the
  Blender download) compile.
"""
import itertools
import pathlib
import re
import subprocess

import pytest
import yaml

REPO = pathlib.Path(__file__).resolve().parents[2]
WORKFLOW = REPO / ".github" / "workflows" / "release.yml"
DOCUMENT = REPO / "docs" / "RELEASE.md"

PYTHONS = {"3.11", "3.13"}
# The blender.org series each Python is checked in: 4.2 LTS (the first with
# extensions) embeds 3.11, 5.1 is the first to embed 3.13.
BLENDER_SERIES = {"3.11": "4.2", "3.13": "5.1"}
PLATFORMS = {"linux-x64", "windows-x64", "macos-arm64", "macos-x64"}

# A path from the repository's root inside a run: script: a top-level folder
# of the repository followed by a path, or one of its top-level files.
TOP_FOLDERS = ("scripts", "native", "tests", "addon", "bench", "docs", "blend_samples")
TOP_FILES = ("build_addon.py", "CMakeLists.txt", "pyproject.toml", "README.md", "BENCHMARKS.md")
REFERENCE = re.compile(r"(?<![\w./$-])((?:" + "|".join(TOP_FOLDERS) + r")/[\w./-]*[\w]|"
                       + "|".join(re.escape(name) for name in TOP_FILES) + r")(?![\w/-])")
# A script run by an interpreter (python build_addon.py, bash scripts/x.sh):
# a relative path there is a file of the repository, at its root or not.
SCRIPT = re.compile(r"(?<![\w./$-])(?:python3?|bash|sh)\s+(?:-[A-Za-z]\s+)*([\w][\w./-]*\.(?:py|sh))(?![\w/-])")
EXPRESSION = re.compile(r"\$\{\{\s*(.*?)\s*\}\}")
MATRIX_VALUE = re.compile(r"\$\{\{\s*matrix\.(\w+)\s*\}\}")


@pytest.fixture(scope="module")
def workflow():
    return yaml.safe_load(WORKFLOW.read_text(encoding="utf-8"))


def triggers(workflow):
    # PyYAML reads YAML 1.1, where the bare key `on` is the boolean True.
    return workflow["on"] if "on" in workflow else workflow.get(True)


def steps(workflow):
    """(job name, job, step) for every step of every job."""
    for name, job in workflow["jobs"].items():
        for step in job.get("steps", []):
            yield name, job, step


def combinations(matrix):
    """The job variants of a strategy.matrix, by GitHub's rules: the product
    of the matrix's lists, minus `exclude`; each `include` entry is added to
    every variant whose original values it does not change, or becomes a
    variant of its own if it fits none."""
    if not matrix:
        return [{}]
    keys = [key for key in matrix if key not in ("include", "exclude")]
    variants = [dict(zip(keys, values)) for values in itertools.product(*(matrix[key] for key in keys))]
    variants = [v for v in variants
                if not any(all(v.get(k) == x for k, x in entry.items()) for entry in matrix.get("exclude", []))]
    originals = [dict(v) for v in variants]
    extra = []
    for entry in matrix.get("include", []):
        fitting = [v for v, original in zip(variants, originals)
                   if all(original[k] == x for k, x in entry.items() if k in original)]
        for variant in fitting:
            variant.update(entry)
        if not fitting:
            extra.append(dict(entry))
    return variants + extra


def job_variants(job):
    return combinations(job.get("strategy", {}).get("matrix"))


def with_matrix(text, variant):
    """text with every ${{ matrix.KEY }} replaced by the variant's value."""
    return MATRIX_VALUE.sub(lambda m: str(variant[m.group(1)]), text)


def wheels_job(workflow):
    """The job whose matrix builds the wheels: the one that sets up Python
    from matrix.python."""
    found = [name for name, job, step in steps(workflow)
             if step.get("uses", "").startswith("actions/setup-python@")
             and "matrix.python" in str(step.get("with", {}).get("python-version", ""))]
    assert len(set(found)) == 1, f"expected one job building wheels per matrix.python, found {found}"
    return workflow["jobs"][found[0]]


def uploaded_packages(workflow):
    """File names (a * for the version) of the Blender packages the workflow
    uploads: every stick_morph-*.zip path of every upload-artifact step, for
    every variant of its job."""
    names = set()
    for _, job, step in steps(workflow):
        if not step.get("uses", "").startswith("actions/upload-artifact@"):
            continue
        for variant in job_variants(job):
            for line in str(step["with"]["path"]).splitlines():
                name = with_matrix(line.strip(), variant).rpartition("/")[2]
                if name.startswith("stick_morph-") and name.endswith(".zip"):
                    names.add(name)
    return names


def test_is_a_workflow(workflow):
    assert isinstance(workflow, dict)
    on = triggers(workflow)
    assert isinstance(on, dict), "the workflow has no `on` mapping"
    assert "v*" in on["push"]["tags"], "a pushed v* tag must start a release"
    assert "workflow_dispatch" in on, "the workflow must be runnable by hand"
    jobs = workflow["jobs"]
    assert isinstance(jobs, dict) and jobs
    for name, job in jobs.items():
        assert "runs-on" in job, f"job {name} has no runner"
        assert job.get("steps"), f"job {name} has no steps"
        for need in [job["needs"]] if isinstance(job.get("needs"), str) else job.get("needs", []):
            assert need in jobs, f"job {name} needs {need}, which is not a job"


def test_every_step_uses_a_pinned_action_or_runs_a_script(workflow):
    for name, _, step in steps(workflow):
        assert ("uses" in step) != ("run" in step), f"a step of {name} must either use an action or run: {step}"
        if "uses" in step:
            assert re.fullmatch(r"[\w.-]+/[\w.-]+@v\d+", step["uses"]), \
                f"{name}: {step['uses']} is not pinned to a major version"


def test_run_scripts_parse_in_bash(workflow, tmp_path):
    assert workflow["defaults"]["run"]["shell"] == "bash"
    for index, (name, job, step) in enumerate(steps(workflow)):
        if "run" not in step:
            continue
        # Expressions are replaced before the shell runs; any word will do.
        script = EXPRESSION.sub("EXPRESSION", step["run"])
        path = tmp_path / f"{name}_{index}.sh"
        path.write_text(script)
        result = subprocess.run(["bash", "-n", str(path)], capture_output=True, text=True)
        assert result.returncode == 0, f"{name}, step {step.get('name', index)}:\n{result.stderr}"


def test_run_steps_name_files_that_exist(workflow):
    named = set()
    for name, _, step in steps(workflow):
        script = step.get("run", "")
        for path in set(REFERENCE.findall(script)) | set(SCRIPT.findall(script)):
            named.add(path)
            assert (REPO / path).exists(), \
                f"job {name}, step {step.get('name', '?')!r} names {path}, which is not in the repository"
    # The parser must find the two entry points of the release recipe.
    assert {"build_addon.py", "native/python/stickmorph_build_backend.py"} <= named, named


def test_reference_patterns():
    text = ("python3 native/python/stickmorph_build_backend.py --out dist && "
            "python build_addon.py --wheel dist/stickmorph-*.whl; bash scripts/x.sh; "
            "ls dist/*.zip; cat 'CMakeLists.txt'; $HOME/docs/not_ours; python -u make_notes.py; "
            "blender --python /tmp/check.py; python -c \"$CODE\"; python -m build; cat > notes.md")
    assert REFERENCE.findall(text) == ["native/python/stickmorph_build_backend.py", "build_addon.py",
                                       "scripts/x.sh", "CMakeLists.txt"]
    assert SCRIPT.findall(text) == ["native/python/stickmorph_build_backend.py", "build_addon.py",
                                    "scripts/x.sh", "make_notes.py"]


def test_matrix_expansion_follows_github():
    matrix = {"python": ["3.11", "3.13"], "os": ["a", "b"],
              "include": [{"os": "a", "arch": "x"}, {"python": "3.11", "cp": "311"},
                          {"python": "3.14", "os": "c"}],
              "exclude": [{"python": "3.13", "os": "b"}]}
    assert combinations(matrix) == [
        {"python": "3.11", "os": "a", "arch": "x", "cp": "311"},
        {"python": "3.11", "os": "b", "cp": "311"},
        {"python": "3.13", "os": "a", "arch": "x"},
        {"python": "3.14", "os": "c"},
    ]


def test_wheels_are_built_for_exactly_python_3_11_and_3_13(workflow):
    variants = job_variants(wheels_job(workflow))
    assert {str(v["python"]) for v in variants} == PYTHONS
    for variant in variants:
        python = str(variant["python"])
        assert str(variant["cp"]) == python.replace(".", ""), variant
        assert str(variant["blender_series"]) == BLENDER_SERIES[python], variant
    # No other job sets up a Python of its own: the Debian jobs use their
    # release's /usr/bin/python3, the one their Blender embeds.
    versions = {str(step["with"]["python-version"]) for _, _, step in steps(workflow)
                if step.get("uses", "").startswith("actions/setup-python@")}
    assert versions == {"${{ matrix.python }}"}, versions


def test_wheels_are_built_for_the_four_platforms(workflow):
    variants = job_variants(wheels_job(workflow))
    assert PLATFORMS <= {v["platform"] for v in variants}
    assert len(variants) == len(PYTHONS) * len({v["platform"] for v in variants})
    for variant in variants:
        assert variant.get("os"), f"no runner for {variant}"
        if variant["platform"].startswith("macos-"):
            assert variant.get("arch") and variant.get("macos_target"), variant


def test_every_extension_is_uploaded(workflow):
    names = uploaded_packages(workflow)
    expected = {f"stick_morph-*-cp{python.replace('.', '')}-{platform}.zip"
                for python in PYTHONS for platform in PLATFORMS}
    assert expected <= names, expected - names


def test_release_document_names_every_package(workflow):
    document = DOCUMENT.read_text(encoding="utf-8")
    table = "\n".join(line for line in document.splitlines() if line.startswith("|"))
    names = uploaded_packages(workflow)
    assert names
    for name in sorted(names):
        shown = name.replace("*", "<version>")
        assert f"`{shown}`" in table, f"docs/RELEASE.md's tables do not name {shown}"


def test_only_the_release_job_writes_and_it_drafts(workflow):
    assert workflow["permissions"] == {"contents": "read"}
    writers = [name for name, job in workflow["jobs"].items() if "write" in str(job.get("permissions", ""))]
    assert writers == ["release"], writers
    release = workflow["jobs"]["release"]
    assert "tag" in release["if"]
    assert set(release["needs"]) == set(workflow["jobs"]) - {"release"}
    script = "\n".join(step.get("run", "") for step in release["steps"])
    assert "gh release create" in script and "--draft" in script


def test_python_snippets_compile(workflow):
    for name in ("SMOKE_MORPH", "BLENDER_CHECK", "BLENDER_FETCH"):
        compile(workflow["env"][name], name, "exec")
