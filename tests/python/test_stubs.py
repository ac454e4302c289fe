"""The type stub native/python/stickmorph.pyi against the built module.

The stub is written by hand, so nothing keeps it in step with the bindings
(native/python/*.cpp) but this test. It reads the stub with `ast` (it is
never imported) and checks it against `stickmorph` as imported:

- names: every public name of the module is in the stub, and the stub
  adds none (its helper types start with "_");
- signatures: parameter names, order, kinds (keyword-only, *args) and which
  have defaults, for every function and every method, against the
  signature pybind11 writes on the first line of each docstring (one per
  overload for overloaded functions);
- classes: bases as at runtime (so the same __mro__: every StickMorphError
  a ValueError, FileError also an OSError), properties as properties, and
  the attributes stickmorph sets on the exceptions it raises declared;
- values: the functions are called on small figures and what they return
  (dict keys, NotRequired keys, ndarray dtypes, Literal names) is checked
  against the stub's annotations, and the Literal name sets against
  the module's tables and the bindings' name switches;
- mypy, when it is installed: a small typed script passes `mypy --strict`
  with the stub, and misuses of the API are reported.
"""
import ast
import builtins
import collections
import functools
import importlib.util
import inspect
import os
import re
import runpy
import shutil
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import stickmorph
from conftest import DATA, REPO

STUB = REPO / "native" / "python" / "stickmorph.pyi"

# Small figures the value checks call the module with: a unit square, the
# same square stretched (compatible with it), and a pentagon (the square
# with its top edge subdivided) for correspond="auto".
SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
STRETCHED = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.5]]
EDGES = [[0, 1], [1, 2], [2, 3], [3, 0]]
PENTAGON = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.5, 1.2], [0.0, 1.0]]
PENTAGON_EDGES = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]]


# ---------------------------------------------------------------------------
# The stub, parsed


def parse_stub():
    # feature_version: the stub must read on the oldest Python the module
    # supports (3.11), whatever Python runs the test.
    return ast.parse(STUB.read_text(encoding="utf-8"), filename=str(STUB), feature_version=(3, 11))


class Stub:
    """The stub's top-level definitions, by name."""

    def __init__(self, tree):
        self.functions = collections.defaultdict(list)  # name -> [FunctionDef], several if @overload
        self.classes = {}  # name -> ClassDef
        self.variables = {}  # name -> annotation: the annotated module attributes
        self.aliases = {}  # name -> the aliased type expression
        self.reexports = set()  # `import x as x`: a stub's only way to re-export an import
        for node in tree.body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self.functions[node.name].append(node)
            elif isinstance(node, ast.ClassDef):
                self.classes[node.name] = node
            elif isinstance(node, ast.AnnAssign):
                name = node.target.id
                if _is_name(node.annotation, "TypeAlias"):
                    self.aliases[name] = node.value
                else:
                    self.variables[name] = node.annotation
            elif isinstance(node, ast.Assign):
                for target in node.targets:
                    # Plain `X = <type>` is an implicit alias in a stub.
                    self.aliases[target.id] = node.value
            elif isinstance(node, (ast.Import, ast.ImportFrom)):
                # Plain imports are not re-exported by a stub (PEP 484).
                self.reexports |= {a.asname for a in node.names if a.asname and a.asname == a.name}
        self.typeddicts = {name: node for name, node in self.classes.items() if self._is_typeddict(node)}

    def _is_typeddict(self, node):
        return any(_is_name(base, "TypedDict") or (isinstance(base, ast.Name) and base.id in self.classes
                                                   and self._is_typeddict(self.classes[base.id]))
                   for base in node.bases)

    def names(self):
        """Every name the stub exports (public or not)."""
        return (set(self.functions) | set(self.classes) | set(self.variables) | set(self.aliases)
                | self.reexports)

    def class_members(self, name):
        """Functions (by name, a list for overloads/setters) and annotated
        attributes of one stub class, without its bases."""
        functions, attributes = collections.defaultdict(list), {}
        for node in self.classes[name].body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                functions[node.name].append(node)
            elif isinstance(node, ast.AnnAssign):
                attributes[node.target.id] = node.annotation
        return functions, attributes

    def stub_ancestors(self, name):
        """name and the stub classes it derives from, nearest first."""
        result = [name]
        for base in self.classes[name].bases:
            if isinstance(base, ast.Name) and base.id in self.classes:
                result += [a for a in self.stub_ancestors(base.id) if a not in result]
        return result

    def typeddict_fields(self, name):
        """{key: (annotation, required)} of a TypedDict, its bases' included."""
        node = self.typeddicts[name]
        fields = {}
        for base in node.bases:
            if isinstance(base, ast.Name) and base.id in self.typeddicts:
                fields.update(self.typeddict_fields(base.id))
        total = all(not (k.arg == "total" and isinstance(k.value, ast.Constant) and k.value.value is False)
                    for k in node.keywords)
        for item in node.body:
            if isinstance(item, ast.AnnAssign):
                annotation, required = item.annotation, total
                if isinstance(annotation, ast.Subscript) and _is_name(annotation.value, "NotRequired"):
                    annotation, required = annotation.slice, False
                elif isinstance(annotation, ast.Subscript) and _is_name(annotation.value, "Required"):
                    annotation, required = annotation.slice, True
                fields[item.target.id] = (annotation, required)
        return fields

    def literal_values(self, alias):
        """The strings of a Literal[...] alias."""
        node = self.aliases[alias]
        assert isinstance(node, ast.Subscript) and _is_name(node.value, "Literal"), f"{alias} is not a Literal"
        elements = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
        return [e.value for e in elements]


def _is_name(node, name):
    return (isinstance(node, ast.Name) and node.id == name) or (isinstance(node, ast.Attribute) and node.attr == name)


def _decorators(function):
    return [ast.unparse(d) for d in function.decorator_list]


STUB_TREE = parse_stub()
STUBS = Stub(STUB_TREE)


def runtime_public_names():
    names = {name for name in dir(stickmorph) if not name.startswith("_")}
    if hasattr(stickmorph, "__version__"):
        names.add("__version__")
    return names


def runtime_classes():
    return sorted(name for name in runtime_public_names() if isinstance(getattr(stickmorph, name), type))


def runtime_functions():
    return sorted(name for name in runtime_public_names()
                  if callable(getattr(stickmorph, name)) and not isinstance(getattr(stickmorph, name), type))


def runtime_constants():
    return sorted(name for name in runtime_public_names() if not callable(getattr(stickmorph, name)))


# ---------------------------------------------------------------------------
# Signatures

# One parameter: its name, kind ("positional_only", "positional", "vararg",
# "keyword_only", "varkw") and whether it has a default.
Param = collections.namedtuple("Param", "name kind default")


def _top_level(text):
    """(index, char, depth) of every character of text outside quotes, the
    depth of brackets before it (a default's repr may hold commas and
    brackets: "= (1, 2)", "= 'a, b'")."""
    depth, quote = 0, None
    for i, char in enumerate(text):
        if quote:
            if char == quote and text[i - 1] != "\\":
                quote = None
        elif char in "'\"":
            quote = char
        else:
            yield i, char, depth
            depth += (char in "([{") - (char in ")]}")


def _split_top_level(text, separator):
    """text split at `separator` outside brackets and quotes."""
    cuts = [i for i, char, depth in _top_level(text) if char == separator and depth == 0]
    bounds = [-1, *cuts, len(text)]
    return [text[a + 1:b].strip() for a, b in zip(bounds, bounds[1:])]


def parse_pybind_signature(line, name):
    """The parameters of one pybind11 signature line, "name(a: object, *, b: object = 1) -> dict"."""
    assert line.startswith(name + "("), f"{line!r} is not a signature of {name}"
    end = next(i for i, char, depth in _top_level(line) if i > len(name) and char == ")" and depth == 1)
    inner = line[len(name) + 1:end]
    params, keyword_only = [], False
    for piece in (p for p in _split_top_level(inner, ",") if p):
        if piece == "*":
            keyword_only = True
        elif piece == "/":
            params = [p._replace(kind="positional_only") for p in params]
        elif piece.startswith("**"):
            params.append(Param(piece[2:].split(":")[0].strip(), "varkw", False))
        elif piece.startswith("*"):
            params.append(Param(piece[1:].split(":")[0].strip(), "vararg", False))
            keyword_only = True
        else:
            has_default = len(_split_top_level(piece, "=")) > 1
            params.append(Param(piece.split(":")[0].split("=")[0].strip(),
                                "keyword_only" if keyword_only else "positional", has_default))
    return params


def runtime_signatures(obj, name):
    """Each overload's parameters, or None where the object has no signature
    (a slot wrapper such as the __init__ of a class without constructor).

    pybind11 writes "name(...) -> ret" on the docstring's first line; an
    overloaded function has "name(*args, **kwargs)", "Overloaded function."
    and then one "k. name(...) -> ret" line per overload. Functions defined
    in Python (FileError.__str__) have an inspect.signature instead."""
    if inspect.isfunction(obj):
        kinds = {inspect.Parameter.POSITIONAL_ONLY: "positional_only",
                 inspect.Parameter.POSITIONAL_OR_KEYWORD: "positional",
                 inspect.Parameter.VAR_POSITIONAL: "vararg", inspect.Parameter.KEYWORD_ONLY: "keyword_only",
                 inspect.Parameter.VAR_KEYWORD: "varkw"}
        return [[Param(p.name, kinds[p.kind], p.default is not inspect.Parameter.empty)
                 for p in inspect.signature(obj).parameters.values()]]
    lines = (getattr(obj, "__doc__", None) or "").splitlines()
    if not lines or not lines[0].startswith(name + "("):
        return None
    if lines[0].startswith(name + "(*args, **kwargs)") and "Overloaded function." in lines[1:3]:
        return [parse_pybind_signature(m.group(1), name) for line in lines
                if (m := re.match(rf"\d+\. ({re.escape(name)}\(.*)$", line))]
    return [parse_pybind_signature(lines[0], name)]


def stub_signature(function):
    a = function.args
    positional = a.posonlyargs + a.args
    first_default = len(positional) - len(a.defaults)
    params = [Param(arg.arg, "positional_only" if i < len(a.posonlyargs) else "positional", i >= first_default)
              for i, arg in enumerate(positional)]
    if a.vararg:
        params.append(Param(a.vararg.arg, "vararg", False))
    params += [Param(arg.arg, "keyword_only", default is not None) for arg, default in zip(a.kwonlyargs, a.kw_defaults)]
    if a.kwarg:
        params.append(Param(a.kwarg.arg, "varkw", False))
    return params


def signature_differences(where, runtime, stub):
    """What differs between two parameter lists, each naming `where` and the parameter."""
    problems = []
    runtime_names, stub_names = [p.name for p in runtime], [p.name for p in stub]
    for name in runtime_names:
        if name not in stub_names:
            problems.append(f"{where}: parameter {name!r} is in the module but not in the stub")
    for name in stub_names:
        if name not in runtime_names:
            problems.append(f"{where}: parameter {name!r} is in the stub but not in the module")
    if not problems and runtime_names != stub_names:
        problems.append(f"{where}: parameters in another order: module {runtime_names}, stub {stub_names}")
    stub_by_name = {p.name: p for p in stub}
    for p in runtime:
        s = stub_by_name.get(p.name)
        if s is None:
            continue
        if s.kind != p.kind:
            problems.append(f"{where}: parameter {p.name!r} is {p.kind} in the module but {s.kind} in the stub")
        if s.default != p.default:
            says = {True: "has a default", False: "has no default"}
            problems.append(f"{where}: parameter {p.name!r} {says[p.default]} in the module but "
                            f"{says[s.default]} in the stub")
    return problems


def compare_callable(where, runtime_object, runtime_name, stub_defs):
    runtime = runtime_signatures(runtime_object, runtime_name)
    assert runtime is not None, f"{where}: the module's docstring carries no signature to compare with"
    overloads = [d for d in stub_defs if "overload" in _decorators(d)]
    if len(runtime) == 1:
        assert not overloads and len(stub_defs) == 1, (
            f"{where}: one signature in the module, {len(stub_defs)} definitions in the stub")
        return signature_differences(where, runtime[0], stub_signature(stub_defs[0]))
    assert len(overloads) == len(runtime), (
        f"{where}: {len(runtime)} overloads in the module, {len(overloads)} @overload definitions in the stub")
    problems = []
    for k, (params, stub_def) in enumerate(zip(runtime, overloads), start=1):
        problems += signature_differences(f"{where} (overload {k})", params, stub_signature(stub_def))
    return problems


# ---------------------------------------------------------------------------
# Names


def test_stub_parses_as_python_3_11():
    # parse_stub() ran at import; this names the check and its file.
    assert STUB_TREE.body, f"{STUB} is empty"
    header = STUB.read_text(encoding="utf-8").splitlines()[:2]
    assert "Surazhsky & Gotsman 2001" in " ".join(header), "the stub's first lines cite the paper"


def test_stub_defines_every_public_name_and_no_other():
    stub_public = {n for n in STUBS.names() if not n.startswith("_")}
    if "__version__" in STUBS.names():
        stub_public.add("__version__")
    missing = sorted(runtime_public_names() - stub_public)
    extra = sorted(stub_public - runtime_public_names())
    assert not missing, f"public names of the module missing from {STUB.name}: {missing}"
    assert not extra, f"{STUB.name} defines public names the module lacks: {extra}"


@pytest.mark.parametrize("name", sorted(runtime_public_names()))
def test_each_name_is_the_same_kind_of_thing(name):
    value = getattr(stickmorph, name)
    if isinstance(value, type):
        assert name in STUBS.classes, f"{name} is a class in the module but not a class in the stub"
    elif callable(value):
        assert name in STUBS.functions, f"{name} is a function in the module but not a def in the stub"
    else:
        assert name in STUBS.variables, f"{name} is a {type(value).__name__} in the module but not an " \
                                        f"annotated variable in the stub"


# ---------------------------------------------------------------------------
# Signatures of the functions and methods


@pytest.mark.parametrize("name", runtime_functions())
def test_function_signature(name):
    problems = compare_callable(name, getattr(stickmorph, name), name, STUBS.functions[name])
    assert not problems, "\n".join(problems)


# Members classes get from Python itself, not API (3.13 and 3.14 add some
# to classes defined in Python, as FileError is).
IGNORED_MEMBERS = {"__doc__", "__module__", "__weakref__", "__dict__", "__qualname__", "__firstlineno__",
                   "__static_attributes__", "__annotations__", "__annotate__", "__annotate_func__",
                   "__annotations_cache__", "__type_params__"}


def runtime_members(cls):
    """The members a class defines itself, without the internals above and
    without private names (pybind11 adds e.g. _pybind11_conduit_v1_)."""
    return {name: member for name, member in vars(cls).items()
            if name not in IGNORED_MEMBERS and not (name.startswith("_") and not name.startswith("__"))}


def method_cases():
    cases = []
    for class_name in runtime_classes():
        for name, member in runtime_members(getattr(stickmorph, class_name)).items():
            if callable(member) and not isinstance(member, property):
                cases.append((class_name, name))
    return cases


@pytest.mark.parametrize("class_name, name", method_cases(), ids=[f"{c}.{n}" for c, n in method_cases()])
def test_method_signature(class_name, name):
    cls = getattr(stickmorph, class_name)
    member = vars(cls)[name]
    functions, _ = STUBS.class_members(class_name)
    where = f"{class_name}.{name}"
    if name == "__init__" and runtime_signatures(member, name) is None:
        # No py::init: pybind11 leaves a slot that raises, so Python cannot
        # construct the class and the stub must not say it can.
        with pytest.raises(TypeError, match="No constructor defined"):
            cls()
        assert name not in functions, f"{where}: {class_name} cannot be constructed from Python, " \
                                      f"so the stub must not declare __init__"
        return
    assert name in functions, f"{where} is in the module but not in the stub"
    defs = [d for d in functions[name] if not any(dec.endswith((".setter", ".deleter")) for dec in _decorators(d))]
    problems = compare_callable(where, member, name, defs)
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("class_name", runtime_classes())
def test_class_members(class_name):
    """Properties are @property in the stub (with a setter only where the
    module has one), plain class attributes are annotated, and the stub
    declares nothing the class lacks."""
    cls = getattr(stickmorph, class_name)
    functions, attributes = STUBS.class_members(class_name)
    problems = []
    for name, member in runtime_members(cls).items():
        if isinstance(member, property):
            defs = functions.get(name, [])
            decorators = [dec for d in defs for dec in _decorators(d)]
            if "property" not in decorators:
                problems.append(f"{class_name}.{name} is a property in the module but not an @property in the stub")
            has_setter = f"{name}.setter" in decorators
            if (member.fset is not None) != has_setter:
                problems.append(f"{class_name}.{name}: the module's property is "
                                f"{'writable' if member.fset else 'read-only'}, the stub's "
                                f"{'has' if has_setter else 'has no'} setter")
        elif not callable(member) and not name.startswith("__") and name not in attributes:
            problems.append(f"{class_name}.{name} is a class attribute in the module but not declared in the stub")
    for name, defs in functions.items():
        decorators = [dec for d in defs for dec in _decorators(d)]
        if not hasattr(cls, name):
            problems.append(f"{class_name}.{name} is in the stub but not in the module")
        elif "property" in decorators and not isinstance(inspect.getattr_static(cls, name), property):
            problems.append(f"{class_name}.{name} is an @property in the stub but not a property in the module")
    for name in attributes:
        if not hasattr(cls, name):
            problems.append(f"{class_name}.{name} is declared in the stub but the module's class has no such attribute")
    assert not problems, "\n".join(problems)


# ---------------------------------------------------------------------------
# Bases and exception attributes


def resolve_base(node):
    """The runtime class a stub base names: one of the module's, or a builtin."""
    name = ast.unparse(node)
    if name in STUBS.classes:
        return getattr(stickmorph, name)
    assert hasattr(builtins, name), f"stub base {name} is neither a stickmorph class nor a builtin"
    return getattr(builtins, name)


@functools.cache
def stub_class(class_name):
    """A stand-in class built from the stub alone: its stub bases are
    stand-ins too, so that a base changed anywhere up the stub's hierarchy
    shows in the __mro__ of every class below it."""
    bases = tuple(stub_class(ast.unparse(b)) if ast.unparse(b) in STUBS.classes else resolve_base(b)
                  for b in STUBS.classes[class_name].bases)
    return type(class_name, bases or (object,), {})


def stub_mro_names(class_name):
    """The __mro__ the stub's classes give, as names (object left out)."""
    return [c.__name__ for c in stub_class(class_name).__mro__ if c is not object]


@pytest.mark.parametrize("class_name", runtime_classes())
def test_class_bases_match_runtime_mro(class_name):
    cls = getattr(stickmorph, class_name)
    # pybind11 classes derive from pybind11_builtins.pybind11_object, an
    # implementation detail: in the stub they derive from object.
    runtime_bases = tuple(b for b in cls.__bases__ if b.__module__ != "pybind11_builtins" and b is not object)
    stub_bases = tuple(resolve_base(b) for b in STUBS.classes[class_name].bases)
    assert stub_bases == runtime_bases, (
        f"{class_name}: bases in the module {[b.__name__ for b in runtime_bases]}, "
        f"in the stub {[b.__name__ for b in stub_bases]}")
    # The whole __mro__ from the stub's classes alone: a base changed higher
    # up (StickMorphError no longer a ValueError) fails every class below.
    runtime_mro = [c.__name__ for c in cls.__mro__ if c is not object and c.__module__ != "pybind11_builtins"]
    stub_mro = stub_mro_names(class_name)
    assert stub_mro == runtime_mro, (
        f"{class_name}: __mro__ in the module {runtime_mro}, from the stub {stub_mro} "
        f"(only in the module: {[n for n in runtime_mro if n not in stub_mro]}, "
        f"only in the stub: {[n for n in stub_mro if n not in runtime_mro]})")


def raised(call):
    try:
        call()
    except Exception as error:  # noqa: BLE001 - the error is what the case wants
        return error
    raise AssertionError("the call raised nothing")


# One instance of each exception class that carries attributes, as stickmorph
# raises it (errors.cpp sets them on the instance).
RAISED_ERRORS = {
    "InvalidFigureError": lambda: stickmorph.validate([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
                                                      [[0, 1], [2, 3]]),
    "InvalidDrawingError": lambda: stickmorph.clean_drawing([[[0.0, 0.0]]]),
    "IncompatibleFiguresError": lambda: stickmorph.morph(SQUARE, [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]],
                                                         EDGES),  # a mirror image
    "FigureFileNotFoundError": lambda: stickmorph.load_figure(REPO / "tests" / "data" / "no such figure.json"),
}


@pytest.mark.parametrize("class_name", sorted(RAISED_ERRORS))
def test_raised_exception_attributes_are_declared(class_name):
    error = raised(RAISED_ERRORS[class_name])
    assert type(error).__name__ == class_name, f"the case raised {type(error).__name__}: {error}"
    declared = {}
    for ancestor in STUBS.stub_ancestors(class_name):
        declared = {**STUBS.class_members(ancestor)[1], **declared}
    # Attributes set on the instance, and the ones the class says it has
    # (None on the class, errors.cpp).
    names = set(vars(error)) | {n for c in type(error).__mro__ if c.__module__ == "stickmorph"
                                for n, v in vars(c).items() if not n.startswith("__") and not callable(v)}
    problems = []
    for name in sorted(names):
        if name in declared:
            problems += check_value(getattr(error, name), declared[name], f"{class_name}().{name}")
        elif not any(hasattr(base, name) for base in type(error).__mro__ if base.__module__ == "builtins"):
            problems.append(f"{class_name}.{name} is set on the instances stickmorph raises but not declared")
    if isinstance(error, OSError):
        # FileError's errno, strerror and filename are OSError's (declared by
        # typeshed); the binding must still set them.
        assert error.errno and error.strerror and isinstance(error.filename, str)
    assert not problems, "\n".join(problems)


# ---------------------------------------------------------------------------
# Values against annotations


def check_value(value, node, where):
    """Problems of `value` against the stub annotation `node` ([] if it fits).

    Understands what the stub uses for results: int, float, str, bool,
    None, Literal, X | Y, list[X], tuple[X, ...], tuple[X, Y], dict[K, V],
    NDArray[dtype], the stub's TypedDicts, aliases and classes. Anything
    else is reported rather than passed, so that a new construct in the
    stub gets a check here."""
    if isinstance(node, ast.Constant) and node.value is None:
        return [] if value is None else [f"{where}: {type(value).__name__}, the stub says None"]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        branches = []
        for branch in (node.left, node.right):
            problems = check_value(value, branch, where)
            if not problems:
                return []
            branches.append(problems)
        return min(branches, key=len)
    if isinstance(node, ast.Name):
        name = node.id
        simple = {"int": int, "float": float, "str": str, "bool": bool}
        if name in simple:
            # bool is an int, but an int where the stub says bool (or the
            # reverse) is a wrong promise.
            ok = isinstance(value, simple[name]) and (name == "bool") == isinstance(value, bool)
            return [] if ok else [f"{where}: {type(value).__name__} {value!r:.60}, the stub says {name}"]
        if name in ("Any", "object"):
            return []
        if name in STUBS.aliases:
            return check_value(value, STUBS.aliases[name], where)
        if name in STUBS.typeddicts:
            return check_typeddict(value, name, where)
        if name in STUBS.classes:
            cls = getattr(stickmorph, name)
            return [] if isinstance(value, cls) else [f"{where}: {type(value).__name__}, the stub says {name}"]
    if isinstance(node, ast.Subscript):
        base = ast.unparse(node.value)
        arguments = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
        if base == "Literal":
            allowed = [a.value for a in arguments]
            return [] if value in allowed else [f"{where}: {value!r} is not one of the stub's {allowed}"]
        if base == "NDArray":
            if not isinstance(value, np.ndarray):
                return [f"{where}: {type(value).__name__}, the stub says {ast.unparse(node)}"]
            dtype = ast.unparse(arguments[0])
            if dtype != "Any" and value.dtype != np.dtype(getattr(np, dtype.split(".")[-1])):
                return [f"{where}: an ndarray of {value.dtype}, the stub says {ast.unparse(node)}"]
            return []
        if base == "list":
            if not isinstance(value, list):
                return [f"{where}: {type(value).__name__}, the stub says {ast.unparse(node)}"]
            return [p for i, item in enumerate(value) for p in check_value(item, arguments[0], f"{where}[{i}]")]
        if base == "tuple":
            if not isinstance(value, tuple):
                return [f"{where}: {type(value).__name__}, the stub says {ast.unparse(node)}"]
            if len(arguments) == 2 and isinstance(arguments[1], ast.Constant) and arguments[1].value is Ellipsis:
                arguments = [arguments[0]] * len(value)
            if len(arguments) != len(value):
                return [f"{where}: a tuple of {len(value)}, the stub says {ast.unparse(node)}"]
            return [p for i, (item, a) in enumerate(zip(value, arguments))
                    for p in check_value(item, a, f"{where}[{i}]")]
        if base == "dict":
            if not isinstance(value, dict):
                return [f"{where}: {type(value).__name__}, the stub says {ast.unparse(node)}"]
            return [p for k, v in value.items()
                    for p in check_value(k, arguments[0], f"{where} key")
                    + check_value(v, arguments[1], f"{where}[{k!r}]")]
    return [f"{where}: the test cannot check the annotation {ast.unparse(node)}: teach check_value"]


def check_typeddict(value, name, where):
    if not isinstance(value, dict):
        return [f"{where}: {type(value).__name__}, the stub says the TypedDict {name}"]
    fields = STUBS.typeddict_fields(name)
    problems = [f"{where}: key {key!r} is in the module's dict but not in the stub's {name}"
                for key in value if key not in fields]
    problems += [f"{where}: the stub's {name} requires key {key!r}, missing from the module's dict"
                 for key, (_, required) in fields.items() if required and key not in value]
    for key, (annotation, _) in fields.items():
        if key in value:
            problems += check_value(value[key], annotation, f"{where}[{key!r}]")
    return problems


def stub_annotation(target):
    """The stub's annotation of what `target` gives: "f" a function's return,
    "C.m" a method's return or a property's type, "C.__init__" the class,
    "x" a module variable."""
    if "." not in target:
        if target in STUBS.variables:
            return STUBS.variables[target]
        (function,) = STUBS.functions[target]
        return function.returns
    class_name, member = target.split(".")
    if member == "__init__":
        return ast.Name(id=class_name)
    functions, attributes = STUBS.class_members(class_name)
    if member in attributes:
        return attributes[member]
    (function,) = [d for d in functions[member] if not any(x.endswith(".setter") for x in _decorators(d))]
    # typing.Self in a method is the class (no subclasses of these in Python).
    return ast.Name(id=class_name) if _is_name(function.returns, "Self") else function.returns


def _read(obj, name):
    """A property's value, or what a method returns called without arguments."""
    value = getattr(obj, name)
    return value() if callable(value) else value


def _solvers():
    triangulation = stickmorph.triangulate_figures(SQUARE, STRETCHED, EDGES)
    return (stickmorph.MorphSolver(triangulation, EDGES), stickmorph.RigidMorphSolver(SQUARE, STRETCHED, EDGES),
            stickmorph.KeyPoseMorphSolver([SQUARE, STRETCHED, SQUARE], EDGES, frames=5))


def _progress_after_a_call():
    progress = stickmorph.Progress()
    stickmorph.morph(SQUARE, STRETCHED, EDGES, frames=3, progress=progress)
    return progress


def _drawing_with_changes():
    # Two strokes crossing, and a third whose end is near the first stroke:
    # a crossing, a merge or snap, entries with None in them.
    return stickmorph.clean_drawing([[[0.0, 0.0], [1.0, 1.0]], [[0.0, 1.0], [1.0, 0.0]],
                                     [[0.0, 0.0], [0.001, 0.5]]])


# (what the value is, the stub target its annotation is read from, how to
# get it). Every function, method and property of the stub is covered: a
# new one needs a case here (test_every_stub_target_has_a_value_case).
VALUE_CASES = [
    ("morph rigid", "morph", lambda: stickmorph.morph(SQUARE, STRETCHED, EDGES, frames=3)),
    ("morph rigid eased ccw", "morph",
     lambda: stickmorph.morph(SQUARE, STRETCHED, EDGES, frames=3, rotation="ccw", easing="in-out", turns=1,
                              steiner="aronov", weights="floater")),
    ("morph barycentric", "morph", lambda: stickmorph.morph(SQUARE, STRETCHED, EDGES, frames=3, method="barycentric")),
    ("morph linear", "morph", lambda: stickmorph.morph(SQUARE, STRETCHED, EDGES, frames=3, method="linear")),
    ("morph correspond=auto", "morph",
     lambda: stickmorph.morph(SQUARE, PENTAGON, EDGES, target_edges=PENTAGON_EDGES, frames=3, correspond="auto")),
    ("morph_key_poses", "morph_key_poses",
     lambda: stickmorph.morph_key_poses([SQUARE, STRETCHED, SQUARE], EDGES, frames=5)),
    ("morph_key_poses correspond=auto", "morph_key_poses",
     lambda: stickmorph.morph_key_poses([SQUARE, PENTAGON], [EDGES, PENTAGON_EDGES], frames=5, correspond="auto")),
    ("triangulate_figures", "triangulate_figures", lambda: stickmorph.triangulate_figures(SQUARE, STRETCHED, EDGES)),
    ("compatible_triangulation", "compatible_triangulation",
     lambda: stickmorph.compatible_triangulation(SQUARE, STRETCHED)),
    ("correspond", "correspond",
     lambda: stickmorph.correspond(SQUARE, PENTAGON, EDGES, target_edges=PENTAGON_EDGES)),
    ("decompose", "decompose", lambda: stickmorph.decompose(SQUARE, EDGES)),
    ("rotation_system", "rotation_system", lambda: stickmorph.rotation_system(SQUARE, EDGES)),
    ("figure_parts", "figure_parts", lambda: stickmorph.figure_parts(5, [[0, 1], [2, 3]])),
    ("edge_set_difference", "edge_set_difference", lambda: stickmorph.edge_set_difference(EDGES, [[0, 1], [1, 3]])),
    ("check_pins ok", "check_pins", lambda: stickmorph.check_pins(4, EDGES, 4, EDGES, [[0, 0]])),
    ("check_pins refused", "check_pins", lambda: stickmorph.check_pins(4, EDGES, 4, EDGES, [[0, 7]])),
    ("validate", "validate", lambda: stickmorph.validate(SQUARE, EDGES)),
    ("check_compatibility yes", "check_compatibility",
     lambda: stickmorph.check_compatibility(SQUARE, STRETCHED, EDGES)),
    ("load_figure", "load_figure",
     lambda: stickmorph.load_figure(DATA / "pairs" / "compatible" / "glyph_7_to_L.source.json")),
    ("clean_drawing", "clean_drawing", _drawing_with_changes),
    ("clean_figure", "clean_figure", lambda: stickmorph.clean_figure(SQUARE, EDGES)),
]
# The report of a mirror image: not compatible, so kind, reason and vertices say something.
MIRRORED = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]
for _name in ("compatible", "kind", "reason", "vertices", "__bool__", "__repr__"):
    VALUE_CASES.append((f"CompatibilityReport.{_name}", f"CompatibilityReport.{_name}",
                        lambda n=_name: _read(stickmorph.check_compatibility(SQUARE, MIRRORED, EDGES), n)))
for _name in ("vertices", "edges", "stroke_vertices", "point_vertex", "cyclic", "tolerance", "junctions_made",
              "ends_snapped", "points_merged", "changes", "summary", "__repr__"):
    VALUE_CASES.append((f"CleanedDrawing.{_name}", f"CleanedDrawing.{_name}",
                        lambda n=_name: _read(_drawing_with_changes(), n)))
VALUE_CASES += [
    ("MorphSolver()", "MorphSolver.__init__", lambda: _solvers()[0]),
    ("MorphSolver.solve", "MorphSolver.solve", lambda: _solvers()[0].solve(0.5)),
    ("MorphSolver.solve all_nodes", "MorphSolver.solve", lambda: _solvers()[0].solve(0.5, all_nodes=True)),
    ("MorphSolver.weights", "MorphSolver.weights", lambda: _solvers()[0].weights),
    ("MorphSolver.stats", "MorphSolver.stats", lambda: _solvers()[0].stats),
    ("RigidMorphSolver()", "RigidMorphSolver.__init__", lambda: _solvers()[1]),
    ("RigidMorphSolver.solve", "RigidMorphSolver.solve", lambda: _solvers()[1].solve(0.5, verify=False)),
    ("RigidMorphSolver.triangulation", "RigidMorphSolver.triangulation", lambda: _solvers()[1].triangulation),
    ("RigidMorphSolver.similarity", "RigidMorphSolver.similarity", lambda: _solvers()[1].similarity),
    ("KeyPoseMorphSolver()", "KeyPoseMorphSolver.__init__", lambda: _solvers()[2]),
    ("KeyPoseMorphSolver.solve", "KeyPoseMorphSolver.solve", lambda: _solvers()[2].solve(0.3)),
    ("KeyPoseMorphSolver.frame", "KeyPoseMorphSolver.frame", lambda: _solvers()[2].frame(2)),
    ("KeyPoseMorphSolver.frame_count", "KeyPoseMorphSolver.frame_count", lambda: _solvers()[2].frame_count),
    ("KeyPoseMorphSolver.keys_at", "KeyPoseMorphSolver.keys_at", lambda: _solvers()[2].keys_at),
    ("KeyPoseMorphSolver.edges", "KeyPoseMorphSolver.edges", lambda: _solvers()[2].edges),
    ("KeyPoseMorphSolver.places", "KeyPoseMorphSolver.places", lambda: _solvers()[2].places),
    ("KeyPoseMorphSolver.segments", "KeyPoseMorphSolver.segments", lambda: _solvers()[2].segments),
    ("Progress()", "Progress.__init__", stickmorph.Progress),
    ("Progress.stage before", "Progress.stage", lambda: stickmorph.Progress().stage),
    ("Progress.fraction before", "Progress.fraction", lambda: stickmorph.Progress().fraction),
    ("Progress.cancel", "Progress.cancel", lambda: stickmorph.Progress().cancel()),
    ("Progress.begin_stage", "Progress.begin_stage", lambda: stickmorph.Progress().begin_stage("reading", 3)),
    ("Progress.set_progress", "Progress.set_progress", lambda: stickmorph.Progress().set_progress(1, 3)),
    ("Progress.finish", "Progress.finish", lambda: stickmorph.Progress().finish()),
]
for _name in ("cancelled", "stage", "done", "total", "fraction", "stages", "summary"):
    VALUE_CASES.append((f"Progress.{_name} after a morph", f"Progress.{_name}",
                        lambda n=_name: _read(_progress_after_a_call(), n)))


def _fraction_while_counted():
    progress = stickmorph.Progress()
    progress.begin_stage("reading", 4)
    progress.set_progress(1, 4)
    return progress.fraction  # a float now, None before


def _enter_and_exit():
    """What __enter__ and __exit__ return. Both are called: an entered
    Progress stays installed on this thread until its __exit__."""
    progress = stickmorph.Progress()
    entered = progress.__enter__()
    return entered, progress.__exit__(None, None, None)


VALUE_CASES += [("Progress.fraction counted", "Progress.fraction", _fraction_while_counted),
                ("Progress.__enter__", "Progress.__enter__", lambda: _enter_and_exit()[0]),
                ("Progress.__exit__", "Progress.__exit__", lambda: _enter_and_exit()[1])]
VALUE_CASES += [(name, name, lambda n=name: getattr(stickmorph, n)) for name in runtime_constants()]


@pytest.mark.parametrize("target, call", [(t, c) for _, t, c in VALUE_CASES],
                         ids=[label for label, _, _ in VALUE_CASES])
def test_value_fits_the_stub_annotation(target, call):
    value = call()
    problems = check_value(value, stub_annotation(target), target)
    assert not problems, "\n".join(problems)


def test_every_stub_target_has_a_value_case():
    """So that a function or property added to the stub (and the module)
    gets its annotation checked against a real value too."""
    targets = set(STUBS.functions) | set(STUBS.variables)
    for class_name in runtime_classes():
        functions, _ = STUBS.class_members(class_name)
        if not issubclass(getattr(stickmorph, class_name), BaseException):
            targets |= {f"{class_name}.{name}" for name in functions}
    missing = sorted(targets - {target for _, target, _ in VALUE_CASES})
    assert not missing, f"no VALUE_CASES entry checks these against a real value: {missing}"


# ---------------------------------------------------------------------------
# Literal name sets

# Alias -> the module's tuple of the same names.
NAME_TABLES = {
    "_MethodName": ("METHOD_NAMES", "method"),
    "_RotationName": ("ROTATION_NAMES", "rotation"),
    "_EasingName": ("EASING_NAMES", "easing"),
    "_SteinerName": (None, "steiner"),
    "_WeightsName": (None, "weights"),
    "_FrameCheckName": (None, "frame_check"),
    "_CorrespondName": (None, "correspond"),
}


@pytest.mark.parametrize("alias", sorted(NAME_TABLES))
def test_option_name_literals_match_the_module(alias):
    constant, option = NAME_TABLES[alias]
    stub = STUBS.literal_values(alias)
    choices = stickmorph.option_rules[option]["choices"]
    assert sorted(stub) == sorted(choices), f"{alias}: stub {stub}, option_rules[{option!r}]['choices'] {choices}"
    if constant:
        assert sorted(stub) == sorted(getattr(stickmorph, constant)), f"{alias}: stub {stub}, {constant}"


def test_every_option_with_choices_has_a_literal():
    options = {option for _, option in NAME_TABLES.values()}
    with_choices = {name for name, rule in stickmorph.option_rules.items() if "choices" in rule}
    assert with_choices <= options, (
        f"options with names but no Literal alias in the stub: {sorted(with_choices - options)}")


# Alias -> (source file, function): the switch that names the engine's enum
# values for Python ("case X: return \"name\";"). The names reach Python only
# when something fails, so the sources are read instead of the module.
ENUM_TABLES = {
    "_FigureDefect": ("native/python/errors.cpp", "defect_name", set()),
    "_DrawingDefect": ("native/python/errors.cpp", "drawing_defect_name", set()),
    "_Incompatibility": ("native/python/errors.cpp", "incompatibility_name", set()),
    # check_pins returns None instead of a dict with defect "none".
    "_PinDefect": ("native/python/bind_figures.cpp", "pin_defect_name", {"none"}),
    "_DrawingChangeKind": ("native/stickmorph/drawing_cleaning.cpp", "drawing_change_name", set()),
}


@pytest.mark.parametrize("alias", sorted(ENUM_TABLES))
def test_enum_name_literals_match_the_bindings(alias):
    path, function, left_out = ENUM_TABLES[alias]
    source = (REPO / path).read_text(encoding="utf-8")
    start = re.search(rf"\b{function}\([^)]*\)\s*\{{", source)
    assert start, f"{path} has no function {function}: update ENUM_TABLES"
    body = source[start.end():source.index("\n}\n", start.end())]
    names = set(re.findall(r'case [\w:]+:\s*return "([^"]+)";', body)) - left_out
    assert names, f"{path}: no names found in {function}"
    stub = set(STUBS.literal_values(alias))
    assert stub == names, (f"{alias}: only in the bindings ({path} {function}) {sorted(names - stub)}, "
                           f"only in the stub {sorted(stub - names)}")


def test_typed_dicts_of_module_constants_have_the_module_keys():
    """limits and option_rules: every key, not just the ones a TypedDict
    requires (they are all required, and the values are checked above)."""
    assert set(STUBS.typeddict_fields("_Limits")) == set(stickmorph.limits)
    assert set(STUBS.typeddict_fields("_OptionRules")) == set(stickmorph.option_rules)


# ---------------------------------------------------------------------------
# mypy

mypy_missing = pytest.mark.skipif(
    importlib.util.find_spec("mypy") is None,
    reason="mypy is not installed (Debian: python3-mypy); the stub's names, signatures and types are "
           "still checked by the other tests of this file")

# A typed use of the module: morph two small figures, read the result.
TYPED_EXAMPLE = '''
import numpy as np
import numpy.typing as npt

import stickmorph

SOURCE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
TARGET = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.5]]
EDGES = [[0, 1], [1, 2], [2, 3], [3, 0]]


def mean_position(frames: npt.NDArray[np.float64]) -> float:
    return float(frames.mean())


def main() -> None:
    result = stickmorph.morph(SOURCE, TARGET, EDGES, frames=5, method="rigid", rotation="ccw")
    frames: npt.NDArray[np.float64] = result["frames"]
    times = result["times"]
    assert frames.shape == (5, 4, 2) and float(times[-1]) == 1.0
    steiner: int = result["stats"]["steiner_vertices"]
    method: str = result["stats"]["method"]
    rigid = result["stats"].get("rigid")
    if rigid is not None:
        angle: float = rigid["similarity"]["angle_degrees"]
        assert isinstance(angle, float)
    # MorphSolver scrubs a barycentric morph's triangulation (the rigid
    # method's enclosure moves); linear has none, hence the None check.
    triangulation = stickmorph.morph(SOURCE, TARGET, EDGES, frames=3, method="barycentric")["triangulation"]
    if triangulation is not None:
        solver = stickmorph.MorphSolver(triangulation, EDGES, weights="mvc")
        middle = solver.solve(0.5, verify=True)
        assert middle.shape == (4, 2)
    report = stickmorph.check_compatibility(SOURCE, TARGET, EDGES)
    if not report:
        print(report.kind, report.reason, report.vertices)
    try:
        stickmorph.validate([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]], [[0, 1], [2, 3]])
    except stickmorph.InvalidFigureError as error:
        edges: list[int] | None = error.edges
        assert error.defect == "crossing_edges", edges
    with stickmorph.Progress() as progress:
        stickmorph.morph(SOURCE, TARGET, EDGES, frames=3, progress=progress)
    stages: list[tuple[str, float]] = progress.stages
    rounds: int = stickmorph.limits["max_frames"]
    print(mean_position(frames), steiner, method, stages, rounds, stickmorph.__version__)


main()
'''

# Misuses mypy must report with the stub, one per line marked "# error".
# Without them, a stub of Any everywhere would pass TYPED_EXAMPLE.
MISUSE_EXAMPLE = '''
import stickmorph

SOURCE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
EDGES = [[0, 1], [1, 2], [2, 3], [3, 0]]

result = stickmorph.morph(SOURCE, SOURCE, EDGES, method="rigidd")  # error: not a method name
stickmorph.morph(SOURCE, SOURCE, EDGES, frame=5)  # error: no such keyword
stickmorph.correspond(SOURCE, SOURCE, EDGES, EDGES)  # error: target_edges is keyword-only
result2 = stickmorph.morph(SOURCE, SOURCE, EDGES)
result2["stats"]["rigid_stats"]  # error: no such key
count: str = result2["stats"]["triangles"]  # error: an int
result2["triangulation"]["triangles"]  # error: may be None
solver = stickmorph.RigidMorphSolver(SOURCE, SOURCE, EDGES)
solver.solve(0.5, True)  # error: all_nodes is keyword-only
stickmorph.Progress().begin_stage(3)  # error: a name is a str
text: str = stickmorph.limits["max_coordinate_magnitude"]  # error: a float
'''


def run_mypy(tmp_path, script):
    stubs = tmp_path / "stubs"
    stubs.mkdir()
    shutil.copy(STUB, stubs / "stickmorph.pyi")
    (tmp_path / "example.py").write_text(textwrap.dedent(script), encoding="utf-8")
    environment = {**os.environ, "MYPYPATH": str(stubs)}
    # The oldest supported Python, strict, the cache kept out of the tree.
    command = [sys.executable, "-m", "mypy", "--strict", "--python-version", "3.11", "--no-color-output",
               "--cache-dir", str(tmp_path / "mypy_cache"), "example.py"]
    return subprocess.run(command, cwd=tmp_path, env=environment, capture_output=True, text=True, timeout=600)


@mypy_missing
def test_typed_example_passes_mypy_strict(tmp_path):
    run = run_mypy(tmp_path, TYPED_EXAMPLE)
    assert run.returncode == 0, f"mypy --strict with the stub:\n{run.stdout}{run.stderr}"
    # And it is a real use of the module: it runs.
    runpy.run_path(str(tmp_path / "example.py"), run_name="__example__")


@mypy_missing
def test_mypy_reports_misuses(tmp_path):
    run = run_mypy(tmp_path, MISUSE_EXAMPLE)
    lines = textwrap.dedent(MISUSE_EXAMPLE).splitlines()
    expected = {number for number, line in enumerate(lines, start=1) if "# error" in line}
    reported = {int(m.group(1)) for m in re.finditer(r"^example\.py:(\d+): error:", run.stdout, re.MULTILINE)}
    assert run.returncode == 1, f"mypy should fail on the misuses:\n{run.stdout}{run.stderr}"
    missed = [lines[n - 1].strip() for n in sorted(expected - reported)]
    unexpected = [lines[n - 1].strip() for n in sorted(reported - expected)]
    assert not missed, "mypy accepted these misuses (the stub is too loose):\n" + "\n".join(missed) + \
        f"\n\nmypy said:\n{run.stdout}"
    assert not unexpected, "mypy reported lines not marked as misuses:\n" + "\n".join(unexpected) + \
        f"\n\nmypy said:\n{run.stdout}"
