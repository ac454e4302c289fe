"""The engine as a wheel (issue 33): built with Debian's tools from the CMake
project (native/python/stickmorph_build_backend.py through `python3 -m
build`), installed with pip into fresh virtual environments without network
access, and used from there to morph the paper's S into U (Figure 8c).

The wheel is built from the test build folder (-C build-dir), so the module
is not compiled a second time: the backend only checks that the target is up
to date and packs it.
"""
import base64
import csv
import hashlib
import io
import json
import os
import re
import subprocess
import sys
import textwrap
import zipfile

import pytest

from conftest import BUILD, DATA, REPO

BACKEND = REPO / "native" / "python" / "stickmorph_build_backend.py"
STUB = REPO / "native" / "python" / "stickmorph.pyi"
TAG = f"cp{sys.version_info[0]}{sys.version_info[1]}"


def cmake_version():
    text = (REPO / "CMakeLists.txt").read_text()
    return re.search(r"project\(stickmorph VERSION ([0-9.]+)", text).group(1)


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    """The wheel `python3 -m build --wheel --no-isolation` writes."""
    out = tmp_path_factory.mktemp("wheelhouse")
    result = subprocess.run(
        [sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(out),
         f"--config-setting=build-dir={BUILD}", str(REPO)],
        capture_output=True, text=True)
    assert result.returncode == 0, f"python3 -m build failed:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    wheels = sorted(out.glob("*.whl"))
    assert len(wheels) == 1, f"expected one wheel, found {[w.name for w in wheels]}"
    return wheels[0]


def test_name_says_version_python_and_platform(wheel):
    assert re.fullmatch(rf"stickmorph-{re.escape(cmake_version())}-{TAG}-{TAG}-linux_x86_64\.whl", wheel.name), \
        wheel.name


def test_metadata_names_what_it_needs(wheel):
    version = cmake_version()
    with zipfile.ZipFile(wheel) as archive:
        metadata = archive.read(f"stickmorph-{version}.dist-info/METADATA").decode()
        wheel_file = archive.read(f"stickmorph-{version}.dist-info/WHEEL").decode()
    fields = [line.split(": ", 1) for line in metadata.split("\n\n", 1)[0].splitlines()]
    assert ["Name", "stickmorph"] in fields and ["Version", version] in fields
    assert ["Requires-Dist", "numpy>=1.21"] in fields
    external = [value for key, value in fields if key == "Requires-External"]
    # The Debian build links GMP (CGAL's exact number type) and GCC's C++ runtime.
    assert "libgmp.so.10" in external
    assert any(re.fullmatch(r"libstdc\+\+\.so\.6 \(>=3\.4\.\d+\)", entry) for entry in external), external
    assert any(re.fullmatch(r"libc\.so\.6 \(>=2\.\d+\)", entry) for entry in external), external
    assert f"Tag: {TAG}-{TAG}-linux_x86_64" in wheel_file.splitlines()
    assert "Root-Is-Purelib: false" in wheel_file.splitlines()


def test_record_lists_every_file_with_its_hash(wheel):
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
        record_name = next(name for name in names if name.endswith(".dist-info/RECORD"))
        rows = list(csv.reader(io.StringIO(archive.read(record_name).decode())))
        assert {row[0] for row in rows} == names
        for name, digest, size in rows:
            if name == record_name:
                assert digest == "" and size == ""
                continue
            data = archive.read(name)
            expected = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert digest == f"sha256={expected}", name
            assert int(size) == len(data), name


def test_carries_the_module_and_the_stubs(wheel):
    with zipfile.ZipFile(wheel) as archive:
        module = [n for n in archive.namelist() if n.startswith("stickmorph.cpython-") and n.endswith(".so")]
        assert module == [f"stickmorph.cpython-{TAG[2:]}-x86_64-linux-gnu.so"]
        assert archive.read("stickmorph-stubs/__init__.pyi") == STUB.read_bytes()
        assert (archive.getinfo(module[0]).external_attr >> 16) & 0o111, "the module lost its executable bits"


MORPH_S_TO_U = textwrap.dedent("""
    import json, os, sys
    import stickmorph
    data = sys.argv[1]
    source = json.load(open(os.path.join(data, "s_to_u.source.json")))
    target = json.load(open(os.path.join(data, "s_to_u.target.json")))
    result = stickmorph.morph(source["vertices"], target["vertices"], source["edges"], frames=30)
    frames = result["frames"]
    assert frames.shape == (30, len(source["vertices"]), 2), frames.shape
    assert frames[0].tolist() == [[float(x), float(y)] for x, y in source["vertices"]]
    assert frames[-1].tolist() == [[float(x), float(y)] for x, y in target["vertices"]]
    for frame in frames:  # the engine's exact check of each frame
        stickmorph.validate(frame, source["edges"])
    print(json.dumps({"file": stickmorph.__file__, "version": stickmorph.__version__,
                      "frames": frames.tolist()}))
""")


def make_venv(path, system_site_packages):
    command = [sys.executable, "-m", "venv", str(path)]
    if system_site_packages:
        command.insert(3, "--system-site-packages")
    subprocess.run(command, check=True)
    return path / "bin" / "python"


def offline_env():
    """pip without any index or proxy: --no-index is passed too, and a proxy
    that does not exist makes any network attempt fail rather than succeed."""
    env = {key: value for key, value in os.environ.items() if not key.startswith(("PIP_", "PYTHON"))}
    env.update({"PIP_NO_INDEX": "1", "PIP_DISABLE_PIP_VERSION_CHECK": "1", "PIP_NO_CACHE_DIR": "1",
                "http_proxy": "http://127.0.0.1:9", "https_proxy": "http://127.0.0.1:9"})
    return env


def test_installs_offline_into_a_fresh_venv_and_morphs_s_to_u(wheel, tmp_path):
    # numpy, the one Python dependency, comes from Debian (python3-numpy)
    # through --system-site-packages; nothing is downloaded.
    python = make_venv(tmp_path / "venv", system_site_packages=True)
    env = offline_env()
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-index", str(wheel)],
                             capture_output=True, text=True, env=env, cwd=tmp_path)
    assert install.returncode == 0, install.stdout + install.stderr
    run = subprocess.run([str(python), "-c", MORPH_S_TO_U, str(DATA / "paper")],
                         capture_output=True, text=True, env=env, cwd=tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    report = json.loads(run.stdout.strip().splitlines()[-1])
    assert report["file"].startswith(str(tmp_path / "venv")), f"imported from {report['file']}, not the venv"
    assert report["version"] == cmake_version()
    # The installed module is the built one: the same frames, bit for bit.
    sys.path.insert(0, str(BUILD / "python"))
    import stickmorph
    source = json.loads((DATA / "paper" / "s_to_u.source.json").read_text())
    target = json.loads((DATA / "paper" / "s_to_u.target.json").read_text())
    expected = stickmorph.morph(source["vertices"], target["vertices"], source["edges"], frames=30)["frames"]
    assert report["frames"] == expected.tolist()
    # pip's own consistency check: nothing about stickmorph (the system's
    # site-packages may have complaints of their own).
    check = subprocess.run([str(python), "-m", "pip", "check"], capture_output=True, text=True, env=env)
    assert "stickmorph" not in check.stdout + check.stderr
    # ... and the wheel uninstalls cleanly (RECORD is complete).
    subprocess.run([str(python), "-m", "pip", "uninstall", "-y", "stickmorph"], check=True,
                   capture_output=True, env=env)
    leftover = list((tmp_path / "venv").rglob("stickmorph*"))
    assert leftover == [], leftover


def test_a_venv_without_numpy_says_numpy_is_needed(wheel, tmp_path):
    """Without numpy pip refuses offline, naming the requirement; forced in
    with --no-deps, the module imports and morph says numpy is missing."""
    python = make_venv(tmp_path / "bare", system_site_packages=False)
    env = offline_env()
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-index", str(wheel)],
                             capture_output=True, text=True, env=env, cwd=tmp_path)
    assert install.returncode != 0
    assert "numpy" in install.stdout + install.stderr
    subprocess.run([str(python), "-m", "pip", "install", "--no-index", "--no-deps", str(wheel)],
                   check=True, capture_output=True, env=env, cwd=tmp_path)
    run = subprocess.run([str(python), "-c", MORPH_S_TO_U, str(DATA / "paper")],
                         capture_output=True, text=True, env=env, cwd=tmp_path)
    assert run.returncode != 0
    assert "No module named 'numpy'" in run.stderr, run.stderr


def test_backend_refuses_a_bad_setting(tmp_path):
    """A config setting that is not a number is a one-line error, exit 2."""
    result = subprocess.run([sys.executable, str(BACKEND), "--out", str(tmp_path), "--print-name"],
                            capture_output=True, text=True)
    assert result.returncode == 0
    assert result.stdout.strip() == f"stickmorph-{cmake_version()}-{TAG}-{TAG}-linux_x86_64.whl"
    sys.path.insert(0, str(BACKEND.parent))
    import stickmorph_build_backend as backend
    with pytest.raises(backend.BuildError, match="jobs must be a whole number"):
        backend.build_wheel(str(tmp_path), {"jobs": "many", "build-dir": str(BUILD)})


TYPED_USE = textwrap.dedent("""
    import stickmorph
    result = stickmorph.morph([[0.0, 0.0], [1.0, 0.0]], [[0.0, 1.0], [1.0, 1.0]], [[0, 1]], frames=3)
    frames = result["frames"]
    print(frames.shape)
""")
TYPED_MISUSE = TYPED_USE + "stickmorph.morph([[0.0, 0.0]], frames='many')\n"


def test_type_checkers_find_the_stubs_in_the_installed_wheel(wheel, tmp_path):
    """mypy, run in the venv with no stub path of ours, reads the stubs the
    wheel installed (stickmorph-stubs): a correct use passes --strict, a
    wrong call is an error (without stubs mypy would only say the module has
    no type information)."""
    pytest.importorskip("mypy", reason="mypy is not installed (Debian: python3-mypy, scripts/install_deps.sh)")
    python = make_venv(tmp_path / "venv", system_site_packages=True)
    env = offline_env()
    subprocess.run([str(python), "-m", "pip", "install", "--no-index", str(wheel)], check=True,
                   capture_output=True, env=env, cwd=tmp_path)
    results = {}
    for name, text in (("good", TYPED_USE), ("bad", TYPED_MISUSE)):
        script = tmp_path / f"{name}.py"
        script.write_text(text)
        results[name] = subprocess.run(
            [str(python), "-m", "mypy", "--strict", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
             str(script)], capture_output=True, text=True, env=env, cwd=tmp_path)
    good, bad = results["good"], results["bad"]
    assert good.returncode == 0, good.stdout + good.stderr
    assert bad.returncode == 1, bad.stdout + bad.stderr
    assert "bad.py:6: error:" in bad.stdout and "missing library stubs" not in bad.stdout, bad.stdout


def test_pip_builds_the_same_wheel_from_the_source_tree(wheel, tmp_path):
    """`pip wheel .` goes through the same backend (pyproject.toml), offline,
    with the build folder as a config setting."""
    result = subprocess.run([sys.executable, "-m", "pip", "wheel", str(REPO), "--no-build-isolation", "--no-deps",
                             "--no-index", "-w", str(tmp_path), f"--config-settings=build-dir={BUILD}"],
                            capture_output=True, text=True, env=offline_env())
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    built = tmp_path / wheel.name
    assert built.is_file(), sorted(p.name for p in tmp_path.iterdir())
    with zipfile.ZipFile(built) as ours, zipfile.ZipFile(wheel) as reference:
        assert ours.namelist() == reference.namelist()
        for name in reference.namelist():
            assert ours.read(name) == reference.read(name), name
