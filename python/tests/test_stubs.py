"""The type stubs (phongvk/_phongvk.pyi) name exactly what the compiled module defines: every
class with its members, every function with its parameters in order, so they cannot drift."""

import ast
import pathlib
import re

import phongvk
from phongvk import _phongvk

STUBS = pathlib.Path(phongvk.__file__).with_name("_phongvk.pyi")


def stub_tree():
    return ast.parse(STUBS.read_text())


def parameters_of(doc):
    """The parameter names of pybind11's signature line: "name(a: int, b: str = 'x') -> T"."""
    inside = re.match(r"\w+\((.*)\) ->", doc.splitlines()[0]).group(1)
    names = re.findall(r"(?:^|, )(\*|\w+)(?=: |$|,)", inside)
    return [n for n in names if n not in ("self", "*")]


def stub_parameters(function):
    args = function.args
    return [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs if a.arg != "self"]


def test_stubs_and_the_package_are_installed_side_by_side():
    assert STUBS.is_file() and STUBS.with_name("py.typed").is_file()


def test_every_name_of_the_module_has_a_stub_and_no_stub_is_left_over():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    stubbed |= {t.target.id for t in tree.body if isinstance(t, ast.AnnAssign)}
    defined = {n for n in dir(_phongvk) if not n.startswith("__") or n in ("__version__", "__revision__")}
    assert stubbed - {"Vec3", "ArrayLike"} == defined


def test_functions_have_the_modules_parameters():
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            assert stub_parameters(node) == parameters_of(getattr(_phongvk, node.name).__doc__), node.name


def test_classes_have_the_modules_members():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef) or not hasattr(getattr(_phongvk, node.name), "__dict__"):
            continue
        cls = getattr(_phongvk, node.name)
        if issubclass(cls, Exception):
            continue
        members = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} - {"__init__"}
        members |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        assert members == {a for a in cls.__dict__ if not a.startswith("_")}, node.name
        for method in node.body:
            decorators = [getattr(d, "id", "") for d in getattr(method, "decorator_list", [])]
            if isinstance(method, ast.FunctionDef) and "property" not in decorators:
                doc = getattr(cls, method.name).__doc__.strip()
                if method.name == "__init__":  # "__init__(self: phongvk._phongvk.Camera, *, position: ..."
                    doc = doc.replace("__init__(self: phongvk._phongvk.%s, " % node.name, "__init__(", 1)
                assert stub_parameters(method) == parameters_of(doc), f"{node.name}.{method.name}"
