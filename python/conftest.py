"""Doctests of the package's docstrings run from the repository root, with
`wearopt` in their namespace (pyproject.toml runs them with the tests)."""

from pathlib import Path

import pytest

import wearopt

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(autouse=True)
def _doctest_setup(doctest_namespace, monkeypatch):
    doctest_namespace["wearopt"] = wearopt
    monkeypatch.chdir(ROOT)
