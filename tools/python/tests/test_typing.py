"""typed_use.py (the file mypy checks against the stubs) runs as typed."""
import typed_use
from conftest import SCENES


def test_the_typed_use_runs():
    assert typed_use.main(str(SCENES / "fig1.json")) > 0
