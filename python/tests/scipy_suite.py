"""Runs SciPy's own tests of ``scipy.stats.qmc`` against nyquist.

The test file is ``scipy/stats/tests/test_qmc.py`` from the installed SciPy wheel, run as
shipped (never copied or edited). Before pytest collects it, the names nyquist provides are
replaced in ``scipy.stats.qmc`` and ``scipy.stats._qmc`` by nyquist's (``PATCHED``), so the
tests, and SciPy's own classes that build engines (``MultivariateNormalQMC``,
``MultinomialQMC``), call nyquist. Only the tests of what nyquist replaces are run
(``APPLICABLE``); the others would test SciPy against itself.

Every applicable test must pass, or be listed in ``scipy_expected.txt`` (one node id per line,
then `` # `` and the reason it cannot pass); a listed test that passes is an error too, so the
list stays true. Prints the counts; exits 1 on a mismatch.

    python python/tests/scipy_suite.py [pytest arguments]
"""

import pathlib
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent

# What nyquist replaces: the names in scipy.stats.qmc and scipy.stats._qmc.
PATCHED = [
    "Sobol",
    "Halton",
    "LatinHypercube",
    "PoissonDisk",
    "discrepancy",
    "update_discrepancy",
    "geometric_discrepancy",
    "scale",
]

# The tests of what nyquist replaces: pytest -k expressions over the test ids.
APPLICABLE = " or ".join(
    [
        "TestSobol",
        "TestHalton",
        "TestLHS",
        "TestPoisson",
        "test_deterministic",
        "TestMultinomialQMC",
        "TestNormalQMC",
        "TestMultivariateNormalQMC",
        "(TestUtils and (scale or discrepancy))",
    ]
)


def patch():
    import scipy.stats._qmc as private
    import scipy.stats.qmc as public

    from nyquist import qmc

    for name in PATCHED:
        setattr(public, name, getattr(qmc, name))
        setattr(private, name, getattr(qmc, name))


class Recorder:
    """Patches SciPy at configuration, before collection, and records each test's outcome."""

    def __init__(self):
        self.outcomes = {}

    def pytest_configure(self, config):
        patch()

    def pytest_runtest_logreport(self, report):
        key = report.nodeid.split("::", 1)[1]
        if report.when == "call" or report.outcome != "passed":
            if report.outcome == "skipped":
                self.outcomes.setdefault(key, "skipped")
            else:
                previous = self.outcomes.get(key)
                if previous != "failed":
                    self.outcomes[key] = report.outcome


def expected_failures():
    out = {}
    for line in (HERE / "scipy_expected.txt").read_text().splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        test, _, reason = line.partition(" # ")
        if not reason.strip():
            raise SystemExit(f"scipy_expected.txt: {test} has no reason")
        out[test.strip()] = reason.strip()
    return out


def main(args):
    import scipy
    import scipy.stats.tests as tests

    path = pathlib.Path(tests.__file__).parent / "test_qmc.py"
    recorder = Recorder()
    pytest.main([str(path), "-q", "-p", "no:cacheprovider", "-k", APPLICABLE, *args],
                plugins=[recorder])
    expected = expected_failures()
    outcomes = recorder.outcomes
    passed = [t for t, o in outcomes.items() if o == "passed"]
    failed = [t for t, o in outcomes.items() if o == "failed"]
    skipped = [t for t, o in outcomes.items() if o == "skipped"]
    unexpected = [t for t in failed if t not in expected]
    stale = [t for t in expected if outcomes.get(t) == "passed"]
    missing = [t for t in expected if t not in outcomes]
    run = len(passed) + len(failed)
    print(
        f"SCIPY_SUITE scipy {scipy.__version__}: {run} applicable tests run, {len(passed)} passed"
        f" ({100 * len(passed) / max(run, 1):.1f} %), {len(failed)} failed"
        f" ({len(failed) - len(unexpected)} listed in scipy_expected.txt), {len(skipped)} skipped"
    )
    for t in unexpected:
        print(f"  failed and not listed: {t}")
    for t in stale:
        print(f"  listed but passed: {t}")
    for t in missing:
        print(f"  listed but not run: {t}")
    return 1 if unexpected or stale or missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
