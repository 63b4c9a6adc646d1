"""Running OpenFOAM and project executables from Python: the project
folder, an executable found on PATH (etc/bashrc sourced), and a command
run in a case folder with its log kept."""

import os
import shutil
import subprocess
from pathlib import Path


class CommandError(RuntimeError):
    """A command that could not be found or that failed."""


def project_dir():
    """The project folder: $AGGLO_PROJECT_DIR (set by etc/bashrc), else
    the checkout that holds this package."""
    env = os.environ.get("AGGLO_PROJECT_DIR")
    return Path(env) if env else Path(__file__).resolve().parents[4]


def foam_bin(name):
    """Path of an OpenFOAM or project executable; a clear error if it is
    not on PATH."""
    path = shutil.which(name)
    if path is None:
        raise CommandError(
            f"'{name}' not found on PATH: source etc/bashrc and build the "
            "project (./Allwmake), or run the tests through ./Alltest")
    return path


def run(cmd, cwd, log, check=True, timeout=600):
    """Run cmd in cwd, write stdout+stderr to cwd/log and return the
    CompletedProcess; with check, a non-zero exit raises CommandError
    with the end of the output."""
    env = dict(os.environ, PWD=str(cwd))
    res = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, text=True, timeout=timeout, env=env)
    (Path(cwd) / log).write_text(res.stdout)
    if check and res.returncode != 0:
        raise CommandError(
            f"{' '.join(map(str, cmd))} failed (rc {res.returncode}) in "
            f"{cwd}:\n{res.stdout[-3000:]}")
    return res


def package_command(folder, module, *args):
    """The command that runs a module of the package in folder (python -m
    module args, a tutorial's package) from any working folder: folder
    goes first on the PYTHONPATH of this process, and so of the commands
    it starts (once)."""
    import sys
    paths = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
             if p]
    if str(folder) not in paths:
        os.environ["PYTHONPATH"] = os.pathsep.join([str(folder)] + paths)
    return [sys.executable, "-m", module, *map(str, args)]


def _siblings(path):
    """The scripts of the folder of the script at path that it imports
    (import statements anywhere in it, found by ast)."""
    import ast
    path = Path(path)
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and not node.level \
                and node.module:
            names.add(node.module.split(".")[0])
    found = (path.parent / f"{n}.py" for n in sorted(names))
    return [f for f in found if f.is_file() and f != path]


def _loaded(name, path):
    """The module `name` if it was imported from the file at path."""
    import sys
    module = sys.modules.get(name)
    if getattr(module, "__file__", None) == str(path):
        return module
    return None


def _load(name, path, search=None):
    """The file at path imported as the module `name` and kept in
    sys.modules (a package's __init__.py with search, the folder its
    modules are found in)."""
    import importlib.util
    import sys
    spec = importlib.util.spec_from_file_location(
        name, path, submodule_search_locations=search)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def _script_module(path, name):
    """The Python script at path imported as the module `name` (kept in
    sys.modules: a second call returns the same module), after the
    scripts of its folder that it imports (found in its source: no list
    to keep, no search-path edit; the import graph has no cycle, a test
    checks it)."""
    module = _loaded(name, path)
    if module is not None:
        return module
    for sibling in _siblings(path):
        _script_module(sibling, sibling.stem)
    return _load(name, path)


def tutorial_module(tutorial, name):
    """A tutorial's Python module, for the tests and benchmarks that call
    its functions: a script (tutorials/<tutorial>/<name>.py, imported as
    the module `name`, its siblings found as it imports them) or a module
    of the tutorial's package (a dotted name, "channel.post.report": the
    package tutorials/<tutorial>/channel imported as `channel`, then the
    module as Python imports it)."""
    folder = project_dir() / "tutorials" / tutorial
    if "." in name:
        _package(folder / name.split(".")[0])
        import importlib
        return importlib.import_module(name)
    return _script_module(folder / f"{name}.py", name)


def _package(folder):
    """The package in folder imported under its folder's name (kept in
    sys.modules; its modules found in it, no search-path edit)."""
    name, init = folder.name, folder / "__init__.py"
    module = _loaded(name, init)
    if module is not None:
        return module
    if not init.is_file():
        raise ImportError(f"{folder}: not a package (no __init__.py)")
    return _load(name, init, [str(folder)])


def bench_module(script):
    """A benchmark script (bench/<script>.py of the project) imported as
    the module `script`, for the tests and the benchmarks that use
    another one's functions."""
    return _script_module(project_dir() / "bench" / f"{script}.py", script)
