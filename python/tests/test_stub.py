"""The type stub swingsim/__init__.pyi names every public name of the package, and is
installed beside it."""
import ast
import pathlib

import swingsim


def _stub_names(stub):
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names.add(node.name)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return names


def test_every_public_name_is_in_the_stub():
    stub = pathlib.Path(swingsim.__file__).with_suffix(".pyi")
    assert stub.exists(), "the build copies __init__.pyi beside __init__.py"
    public = {n for n in dir(swingsim) if not n.startswith("_")}
    modules = {n for n in public if type(getattr(swingsim, n)).__name__ == "module"}
    assert set(swingsim.__all__) <= public
    missing = (public - modules) - _stub_names(stub)
    assert not missing, f"public names not in {stub}: {sorted(missing)}"


def test_every_public_function_has_a_docstring_with_units():
    for name in swingsim.__all__:
        doc = getattr(swingsim, name).__doc__
        assert doc and len(doc) > 40, name
    for name in ("simulate", "swings", "import_osim", "export_osim", "diagnose"):
        doc = getattr(swingsim, name).__doc__
        assert any(unit in doc for unit in (" m", " s", " N", " kg", " deg")), name
