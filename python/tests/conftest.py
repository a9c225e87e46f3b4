"""pytest setup for pear's Python tests: tests/support on the path (the corpus reader), and the
session's exit status 77 (meson: SKIP) when every test skipped for missing data."""
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tests" / "support"))
import corpus  # noqa: E402 (tests/support)


def pytest_sessionfinish(session, exitstatus):
    stats = session.config.pluginmanager.get_plugin("terminalreporter").stats
    skipped = stats.get("skipped", [])
    ran = [r for key in ("passed", "failed", "error") for r in stats.get(key, [])]
    if exitstatus == 0 and skipped and not ran and all(
            corpus.MISSING_DATA in str(report.longrepr) for report in skipped):
        session.exitstatus = 77


def pytest_report_header(config):
    import pear
    return f"pear {pear.__version__} from {os.path.dirname(pear.__file__)}"
