"""Shared fixtures. Paths: the repository (tools/python/tests/../../..), the
build tree ($MODESPLIT_BUILD, else <repo>/build) holding bin/modesplit.

A skip is a case that cannot run here; with MS_TEST_NO_SKIP=1 (.ci/run) a
skip fails instead, as for the C suites (tests/support.h)."""
import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]
BUILD = pathlib.Path(os.environ.get("MODESPLIT_BUILD", ROOT / "build"))
SCENES = ROOT / "data" / "scenes"


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def tool():
    t = BUILD / "bin" / "modesplit"
    if not t.exists():
        pytest.skip("no modesplit tool at %s (make)" % t)
    return t


def pytest_configure(config):
    config.addinivalue_line("markers", "no_asan: not run by `make check-python SAN=asan`")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    rep = outcome.get_result()
    if rep.skipped and os.environ.get("MS_TEST_NO_SKIP") == "1":
        rep.outcome = "failed"
        rep.longrepr = "skipped, and MS_TEST_NO_SKIP=1 makes a skip fail: %s" % (rep.longrepr,)
