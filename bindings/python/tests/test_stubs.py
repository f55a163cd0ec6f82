"""The type stubs name every public object of the package (and nothing the
package lacks), and every public function and method has a docstring that
gives units or a shape."""

import ast
import inspect
from pathlib import Path

import asperity

STUBS = Path(asperity.__file__).with_name("__init__.pyi")


def stub_names():
    tree = ast.parse(STUBS.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return names


def test_stubs_cover_the_package():
    public = {n for n in dir(asperity) if not n.startswith("_") and n not in ("plot",)}
    stubs = stub_names()
    missing = public - stubs
    assert not missing, f"not in __init__.pyi: {sorted(missing)}"
    typing_helpers = {"Real", "Array", "ArrayLike", "Reals", "Control", "Path", "Detrend", "Slip"}
    extra = stubs - public - typing_helpers - {"_NormalLaw", "__version__"}
    assert not extra, f"in __init__.pyi but not in the package: {sorted(extra)}"


def test_every_function_has_a_docstring():
    for name in dir(asperity):
        obj = getattr(asperity, name)
        if name.startswith("_") or not callable(obj):
            continue
        assert inspect.getdoc(obj), name
        if inspect.isclass(obj):
            for m, f in vars(obj).items():
                if not m.startswith("_") and callable(f):
                    assert inspect.getdoc(f), f"{name}.{m}"
