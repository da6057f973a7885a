"""The type stubs (python/emit/_emit.pyi) and the compiled module name the same things: every class,
function and constant of the stubs is in emit._emit, every public name of the module is in the
stubs, and so is every public method and property of each class, both ways."""

import ast
import inspect

import emit._emit as compiled
from conftest import SOURCE_DIR

STUBS = ast.parse((SOURCE_DIR / "python" / "emit" / "_emit.pyi").read_text())
# Names the stubs define for their own annotations, not the module's.
ALIASES = {"FloatArray", "ArrayLike"}


def stub_names(body):
    names = set()
    for node in body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return names


def public(names):
    return {n for n in names if not n.startswith("_") or n in ("__init__", "__version__", "__iter__", "__next__")}


def test_the_module_and_its_stubs_name_the_same_things():
    stubbed = stub_names(STUBS.body) - ALIASES
    assert stubbed, "the stubs define nothing"
    in_module = public(n for n in dir(compiled) if not inspect.ismodule(getattr(compiled, n)))
    assert stubbed - in_module == set(), "in the stubs, not in the module"
    assert in_module - stubbed == set(), "in the module, not in the stubs"


def test_each_class_has_the_members_its_stubs_give_it():
    classes = [node for node in STUBS.body if isinstance(node, ast.ClassDef)]
    for node in classes:
        cls = getattr(compiled, node.name)
        if issubclass(cls, Exception):
            continue
        stubbed = public(stub_names(node.body))
        # pybind11 gives every class an __init__ (one without a constructor raises): not a member
        # the stubs need to name.
        own = public(n for n in vars(cls) if not n.startswith("__") or n in ("__iter__", "__next__"))
        assert stubbed - set(dir(cls)) == set(), f"{node.name}: in the stubs, not in the class"
        assert own - stubbed == set(), f"{node.name}: in the class, not in its stubs"
