#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""runExample.py SCRIPT PNG: runs a documentation example (docs/python/) with --output PNG under
the Agg backend and checks only that it wrote a PNG file (the CTest test python.example.*)."""
import os
import pathlib
import subprocess
import sys

script, png = sys.argv[1], pathlib.Path(sys.argv[2])
png.unlink(missing_ok=True)
env = dict(os.environ, MPLBACKEND="Agg")
status = subprocess.run([sys.executable, script, "--output", str(png)], env=env).returncode
if status != 0:
    sys.exit(f"runExample: {script} exited with {status}")
if not png.is_file() or png.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
    sys.exit(f"runExample: {script} did not write the PNG {png}")
print(f"runExample: {png} ({png.stat().st_size} bytes)")
