import os

# pytest (unlike testflo) does not switch OpenMDAO's reports off; hundreds of report
# folders from tests help nobody.
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import pytest  # noqa: E402


@pytest.fixture(autouse=True)
def _run_in_tmp_path(tmp_path, monkeypatch):
    """Run every test in its own folder so OpenMDAO's *_out folders never land in the repo."""
    monkeypatch.chdir(tmp_path)
    # OpenMDAO writes outputs relative to OPENMDAO_WORKDIR when set; keep it in the tmp folder.
    monkeypatch.setenv("OPENMDAO_WORKDIR", str(tmp_path))
