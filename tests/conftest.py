import os

# pytest (unlike testflo) does not switch OpenMDAO's reports off; hundreds of report
# folders from tests help nobody.
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import pytest  # noqa: E402


def _have_ipopt():
    try:
        import cyipopt  # noqa: F401
    except ImportError:
        return False
    return True


#: Whether IPOPT (the ``cyipopt`` module, ``pip install 'lpc-mdo[ipopt]'``) can be imported.
HAVE_IPOPT = _have_ipopt()


# A test that runs IPOPT is marked ``@pytest.mark.requires_ipopt``: it alone is skipped when
# cyipopt is missing, and the other tests of its module still run. A fixture that runs IPOPT
# requests the ``ipopt`` fixture instead (a marker on a fixture has no effect).
def pytest_configure(config):
    config.addinivalue_line(
        "markers",
        "requires_ipopt: runs IPOPT; skipped when the cyipopt module is missing "
        "(pip install 'lpc-mdo[ipopt]')",
    )


def pytest_runtest_setup(item):
    if item.get_closest_marker("requires_ipopt") is not None and not HAVE_IPOPT:
        pytest.skip("needs IPOPT: the cyipopt module is missing (pip install 'lpc-mdo[ipopt]')")


@pytest.fixture(scope="session")
def ipopt():
    """Skip the test (or a fixture that uses this one) unless cyipopt imports."""
    if not HAVE_IPOPT:
        pytest.skip("needs IPOPT: the cyipopt module is missing (pip install 'lpc-mdo[ipopt]')")


@pytest.fixture(autouse=True)
def _run_in_tmp_path(tmp_path, monkeypatch):
    """Run every test in its own folder so OpenMDAO's *_out folders never land in the repo."""
    monkeypatch.chdir(tmp_path)
    # OpenMDAO writes outputs relative to OPENMDAO_WORKDIR when set; keep it in the tmp folder.
    monkeypatch.setenv("OPENMDAO_WORKDIR", str(tmp_path))
