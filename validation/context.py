# SPDX-License-Identifier: GPL-3.0-or-later
"""Where a study finds the build and writes what it makes.

A Context says which command-line tool and Python module (the build's), how many solves run at
once, and where data and generated tables go: the committed ones (validation/data,
docs/validation/generated) or, with quick, a scratch copy under build/validation-quick that the
repository never sees.
"""
import importlib
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Context:
    def __init__(self, quick=False, jobs=None, cli=None, checking=False):
        self.quick = quick
        self.checking = checking  # check: solve nothing, write nothing
        self.jobs = jobs or os.cpu_count() or 1
        self.cli = os.path.realpath(cli or os.environ.get("ROUGHCONTACT_CLI") or
                                    os.path.join(ROOT, "build", "bin", "multiscaleContact"))
        base = os.path.join(ROOT, "build", "validation-quick") if quick else None
        self.data = os.path.join(base, "data") if quick else os.path.join(ROOT, "validation", "data")
        self.generated = (os.path.join(base, "generated") if quick
                          else os.path.join(ROOT, "docs", "validation", "generated"))
        # Surfaces made on the way (spectrum files, height maps): never committed.
        self.scratch = os.path.join(ROOT, "build", "validation-quick" if quick else "validation", "scratch")
        self._rc = None

    def rc(self):
        """The Python module roughcontact of this build (build/python beside the CLI's bin/)."""
        if self._rc is None:
            path = os.path.realpath(os.path.join(os.path.dirname(self.cli), "..", "python"))
            if path not in sys.path:
                sys.path.insert(0, path)
            try:
                self._rc = importlib.import_module("roughcontact")
            except ImportError as e:
                raise SystemExit(f"validation: the Python module roughcontact is not in {path} "
                                 f"(./Allwmake builds it): {e}")
        return self._rc

    def scratch_path(self, *parts):
        path = os.path.join(self.scratch, *parts)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        return path

    def relative(self, path):
        return os.path.relpath(path, ROOT)
