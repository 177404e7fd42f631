# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared paths of the Python tests (tests/python, run by CTest with the label python).

CTest sets PYTHONPATH to the module's directory (<build>/python), ROUGHCONTACT_SOURCE_DIR and
ROUGHCONTACT_CLI (build/bin/multiscaleContact); by hand:
    PYTHONPATH=build/python ROUGHCONTACT_CLI=build/bin/multiscaleContact python3 -m pytest tests/python
"""
import csv
import io
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ROUGHCONTACT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
STANDIN = str(SOURCE_DIR / "data" / "standin-2454.csv")
DEKTAK = str(SOURCE_DIR / "data" / "dektak-1.csv")
X3P = str(SOURCE_DIR / "data" / "x3p-2.x3p")
# The seed's steel against a rigid flat (docs/install.md: "A first result from the core").
STEEL = dict(E=179.52e9, nu=0.32, Sy=0.2e9)
STEEL_ARGS = ["--E", "179.52e9", "--nu", "0.32", "--Sy", "0.2e9"]


class CliResult:
    def __init__(self, status, out, err):
        self.status, self.out, self.err = status, out, err

    def columns(self):
        """The CSV on stdout as {column: [float or None]}."""
        rows = list(csv.reader(io.StringIO(self.out)))
        header, body = rows[0], rows[1:]
        return {name: [float(r[i]) if r[i] != "" else None for r in body] for i, name in enumerate(header)}

    def error(self):
        """The message after 'multiscaleContact: error: ' (the core's what())."""
        prefix = "multiscaleContact: error: "
        assert self.err.startswith(prefix), self.err
        return self.err[len(prefix):].rstrip("\n")


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("ROUGHCONTACT_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("ROUGHCONTACT_CLI (build/bin/multiscaleContact) is not set")

    def run(*args):
        r = subprocess.run([path, *map(str, args)], capture_output=True, text=True, timeout=600)
        return CliResult(r.returncode, r.stdout, r.stderr)

    return run
