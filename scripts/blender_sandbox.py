"""A Blender whose user folders are temporary, and the add-on installed there.

Used by tests/blender/run_pytest.py, tests/blender/gui/adjust_last_operation.py and
scripts/render_demo.py: all of them install the add-on package, and the real
user configuration (preferences, add-ons, extensions) must never be touched.

In Blender (import this module):
    relaunch_in_sandbox(script, args, prefix)   re-run a script in a new
                                                Blender with temporary user folders
    check_sandboxed()                           fail unless every user folder
                                                Blender uses is in the sandbox
    find_package(dist)                          the dist/ package for this Blender
    install_package(path)                       install + enable it; returns the
                                                add-on's module name

From a shell (any Python 3, no bpy), around any command:
    python3 scripts/blender_sandbox.py [--dir DIR] [--keep] -- COMMAND ...
runs COMMAND with the same environment (a new temporary folder unless --dir)
and removes the folder afterwards unless --keep or --dir.

Which variables: Blender 4.2+ reads BLENDER_USER_RESOURCES (the root of
config/, scripts/, datafiles/ and extensions/) and BLENDER_USER_EXTENSIONS;
3.x has no extensions and takes BLENDER_USER_CONFIG, _SCRIPTS and _DATAFILES
(BLENDER_USER_RESOURCES too). All of them are set, each to its own folder
under the sandbox, and XDG_CONFIG_HOME as well, so that a folder Blender
derives from the default location (~/.config/blender/<version>/) lands in the
sandbox too. check_sandboxed() then asks the running Blender where it really
looks, so a variable a Blender does not honour is an error, not a leak.
"""

import glob
import os
import subprocess
import sys
import tempfile

# Set in the re-launched Blender to the temporary folder.
SANDBOX = "STICKMORPH_BLENDER_SANDBOX"

# The first Blender with extensions; earlier ones install legacy add-ons.
EXTENSIONS_SINCE = (4, 2, 0)
# The extension id (blender_manifest.toml) and the local repository that
# Blender creates by default; an extension's module is bl_ext.<repo>.<id>.
PACKAGE_ID = "stick_morph"
USER_REPOSITORY = "user_default"


def sandbox_env(folder, base=None):
    """The environment of a Blender whose user folders all live in `folder`."""
    env = dict(os.environ if base is None else base)
    env.update({
        "BLENDER_USER_RESOURCES": os.path.join(folder, "resources"),
        "BLENDER_USER_CONFIG": os.path.join(folder, "config"),
        "BLENDER_USER_SCRIPTS": os.path.join(folder, "scripts"),
        "BLENDER_USER_DATAFILES": os.path.join(folder, "datafiles"),
        "BLENDER_USER_EXTENSIONS": os.path.join(folder, "extensions"),
        "XDG_CONFIG_HOME": os.path.join(folder, "xdg-config"),
        SANDBOX: folder,
    })
    return env


def relaunch_in_sandbox(script, args, prefix, background=True, extra_args=()):
    """Runs `script` with `args` in a new Blender (headless unless
    background=False) whose user folders live in a temporary folder, removed
    afterwards; returns its exit code."""
    import bpy
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        command = [bpy.app.binary_path, *(["-b"] if background else []), "--factory-startup",
                   "--python-exit-code", "1", *extra_args, "--python", os.path.abspath(script), "--", *args]
        return subprocess.call(command, env=sandbox_env(tmp))


def _inside(path, folder):
    path, folder = os.path.realpath(path), os.path.realpath(folder)
    return os.path.commonpath([path, folder]) == folder


def uses_extensions():
    import bpy
    return tuple(bpy.app.version) >= EXTENSIONS_SINCE


def addon_module_name():
    """The module name the add-on is enabled under in this Blender:
    stick_morph (legacy add-on) or bl_ext.user_default.stick_morph (extension)."""
    return f"bl_ext.{USER_REPOSITORY}.{PACKAGE_ID}" if uses_extensions() else PACKAGE_ID


def user_folders():
    """(what, path) of every user folder this Blender writes to."""
    import bpy
    kinds = ["CONFIG", "SCRIPTS", "DATAFILES"] + (["EXTENSIONS"] if uses_extensions() else [])
    folders = [(kind, bpy.utils.user_resource(kind)) for kind in kinds]
    folders.append(("user scripts (script_path_user)", bpy.utils.script_path_user()))
    if uses_extensions():
        for repo in bpy.context.preferences.extensions.repos:
            # The system repository is Blender's own read-only one; remote
            # repositories cache their listings in their directory too.
            if getattr(repo, "source", "USER") == "SYSTEM":
                continue
            folders.append((f"extension repository '{repo.module}'", repo.directory))
    return folders


def check_sandboxed():
    """Raises RuntimeError unless this Blender runs in a sandbox and every
    user folder it uses is inside it; returns the sandbox folder."""
    sandbox = os.environ.get(SANDBOX)
    if not sandbox:
        raise RuntimeError(f"not in a sandbox (${SANDBOX} unset): run through scripts/blender_sandbox.py")
    outside = [f"{what}: {path}" for what, path in user_folders() if path and not _inside(path, sandbox)]
    if outside:
        raise RuntimeError("user folders outside the sandbox " + sandbox + ": " + "; ".join(outside))
    return sandbox


def package_pattern():
    """The glob of build_addon.py's package name for this Blender and Python:
    an extension per Python ABI and platform from 4.2, a legacy zip per
    Blender series before."""
    import platform
    import bpy
    machine = {"x86_64": "x64", "amd64": "x64", "aarch64": "arm64"}.get(platform.machine().lower(),
                                                                       platform.machine().lower())
    python = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    if uses_extensions():
        return f"stick_morph-*-{python}-linux-{machine}.zip"
    return f"stick_morph-*-blender{bpy.app.version[0]}.{bpy.app.version[1]}-{python}-linux-{machine}.zip"


def find_package(dist):
    """The newest package in `dist` built for this Blender (by Python and,
    for a legacy add-on, version series). Raises FileNotFoundError naming
    what was looked for."""
    pattern = package_pattern()
    found = glob.glob(os.path.join(dist, pattern))
    if uses_extensions():
        # The extension glob also matches legacy names (...-blender3.4-cp311-...).
        found = [path for path in found if "-blender" not in os.path.basename(path)]
    found.sort(key=os.path.getmtime)
    if not found:
        import bpy
        raise FileNotFoundError(f"no {pattern} in {dist}: build it first with "
                                f"python3 build_addon.py --blender {bpy.app.binary_path}")
    return found[-1]


def _is_extension_package(path):
    import zipfile
    with zipfile.ZipFile(path) as archive:
        return "blender_manifest.toml" in archive.namelist()


def _install_extension_file(path, name):
    """`blender --command extension install-file -r user_default --enable`,
    the command line a farm or a script installs an extension with (issue
    33), run in this sandbox; then this Blender, started before the
    install, reads the repository again, installs the package's wheels into
    its site-packages (extensions/.local) and enables the add-on."""
    import addon_utils
    import bpy
    command = [bpy.app.binary_path, "--command", "extension", "install-file", "-r", USER_REPOSITORY,
               "--enable", path]
    try:
        out = subprocess.run(command, capture_output=True, text=True, timeout=600)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"`{' '.join(command)}` did not finish in 600 s") from None
    if out.returncode != 0:
        raise RuntimeError(f"`{' '.join(command)}` failed (exit {out.returncode}):\n{out.stdout}\n{out.stderr}")
    addon_utils.modules_refresh()
    addon_utils.extensions_refresh(ensure_wheels=True, addon_modules_pending=[name])
    # The wheel is already installed (by the command above), so the refresh
    # has nothing to sync and does not put the extensions' site-packages on
    # sys.path: Blender does that at startup, which a farm's next `blender`
    # command goes through. This Blender started before the folder existed,
    # so it takes that startup step now, with Blender's own function.
    add_site_packages = getattr(addon_utils, "_initialize_extensions_site_packages", None)
    if add_site_packages is None:
        raise RuntimeError(f"Blender {bpy.app.version_string} has no addon_utils._initialize_extensions_site_packages; "
                           "the sandbox cannot make the installed wheel importable without a restart")
    add_site_packages(extensions_directory=bpy.utils.user_resource("EXTENSIONS"))
    return bpy.ops.preferences.addon_enable(module=name)


def engine_module_file():
    """Where `import stickmorph` finds the engine (an extension's wheel
    installs it into the sandbox's extensions/.local site-packages)."""
    import importlib
    return importlib.import_module("stickmorph").__file__


def install_package(path):
    """Installs the package at `path` into the sandbox and enables it, the way
    this Blender installs such a package (legacy add-on: Preferences > Add-ons
    > Install; 4.2+: `blender --command extension install-file` into the
    user_default repository, which installs the engine's wheel). Returns the
    add-on's module name. Raises RuntimeError."""
    import importlib
    import bpy
    sandbox = check_sandboxed()
    path = os.path.abspath(path)
    name = addon_module_name()
    if uses_extensions():
        if not _is_extension_package(path):
            raise RuntimeError(f"{path} is a legacy add-on zip; Blender {bpy.app.version_string} "
                               "needs the extension package (build_addon.py --blender this Blender)")
        result = _install_extension_file(path, name)
    else:
        if _is_extension_package(path):
            raise RuntimeError(f"{path} is an extension; Blender {bpy.app.version_string} installs "
                               "legacy add-on zips")
        result = bpy.ops.preferences.addon_install(filepath=path, overwrite=True)
        if result == {"FINISHED"}:
            result = bpy.ops.preferences.addon_enable(module=name)
    if result != {"FINISHED"}:
        raise RuntimeError(f"installing {path} as {name} failed: {result}")
    if name not in bpy.context.preferences.addons:
        raise RuntimeError(f"{path} was installed but {name} is not enabled "
                           f"(enabled: {sorted(a.module for a in bpy.context.preferences.addons)})")
    module = importlib.import_module(name)
    if not _inside(module.__file__, sandbox):
        raise RuntimeError(f"{name} was loaded from {module.__file__}, not from the sandbox {sandbox}")
    if uses_extensions():
        # The engine must be the wheel the package carries, installed by
        # Blender into the sandbox, not a module from a build tree.
        local = os.path.join(sandbox, "extensions", ".local")
        installed = glob.glob(os.path.join(local, "lib", "python*", "site-packages", "stickmorph.*"))
        if not installed:
            raise RuntimeError(f"installing {path} put no stickmorph module into {local}: the wheel was not installed")
        try:
            engine = engine_module_file()
        except (ImportError, OSError):
            engine = None  # the add-on reports a module that does not load (tests/blender/test_dependencies.py)
        if engine is not None and not _inside(engine, local):
            raise RuntimeError(f"stickmorph was loaded from {engine}, not from the wheel Blender installed "
                               f"into {os.path.join(sandbox, 'extensions', '.local')}")
    return name


def _main(argv):
    """Shell entry: runs a command with the sandbox's environment."""
    import argparse
    import shutil
    parser = argparse.ArgumentParser(prog="blender_sandbox.py",
                                     description="Run COMMAND with Blender's user folders in a temporary folder.")
    parser.add_argument("--dir", help="use this folder (created if missing, kept afterwards)")
    parser.add_argument("--keep", action="store_true", help="keep the temporary folder and print its path")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- COMMAND [ARGS...]")
    args = parser.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("no command given (after --)")
    folder = os.path.abspath(args.dir) if args.dir else tempfile.mkdtemp(prefix="stickmorph-sandbox-")
    os.makedirs(folder, exist_ok=True)
    try:
        return subprocess.call(command, env=sandbox_env(folder))
    finally:
        if args.dir or args.keep:
            print(f"blender_sandbox.py: sandbox kept in {folder}", file=sys.stderr)
        else:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(_main(sys.argv[1:]))
