# SPDX-License-Identifier: GPL-3.0-or-later
"""The exact (boundary-element) solves of a study and their tidy table.

A Solve is one run of the CLI's boundaryElement model: its key (the variables that name the
surface solved: surface, regime, period, grid, seed, variant, ...) and its arguments, loads
included. Its rows in the study's table are the CLI's curve, one row a load:

    <key columns>, load (F/(A_n E') = p/E'), area_fraction, separation_m, h_per_k_per_m,
    iterations, residual

`solve` runs the solves whose rows are not in the table yet, several at once (one thread each),
and adds their rows as each ends, so that an interrupted run keeps what it solved; `check` finds
every solve's rows there (and solves nothing).
"""
import concurrent.futures
import csv
import io
import os
import subprocess
import sys
import time

from . import tables

VALUES = ["load", "area_fraction", "separation_m", "h_per_k_per_m", "iterations", "residual"]
# The CLI's columns of a boundaryElement curve, as the tidy table names them.
CLI_COLUMNS = {"nominal_pressure_per_Eprime": "load", "area_fraction": "area_fraction", "separation": "separation_m",
               "h_per_k": "h_per_k_per_m", "iterations": "iterations", "residual": "residual"}
# The same of the joint that has carried a peak (the CLI's --unload-from columns).
UNLOADING_COLUMNS = {"nominal_pressure_per_Eprime": "load", "unloading_area_fraction": "area_fraction",
                     "unloading_separation": "separation_m", "unloading_h_per_k": "h_per_k_per_m",
                     "unloading_iterations": "iterations", "unloading_residual": "residual"}
# A curve's contact spots besides (a store whose values are VALUES + SPOT_VALUES).
SPOT_VALUES = ["spots", "mean_spot_radius_m"]
SPOT_COLUMNS = {**CLI_COLUMNS, "spots": "spots", "mean_spot_radius": "mean_spot_radius_m"}
UNLOADING_SPOT_COLUMNS = {**UNLOADING_COLUMNS, "unloading_spots": "spots",
                          "unloading_mean_spot_radius": "mean_spot_radius_m"}


class Solve:
    def __init__(self, key, arguments, loads, columns=None):
        self.key = dict(key)
        self.loads = list(loads)  # p/E' as the arguments give them
        self.arguments = list(arguments) + ["--loads", ",".join(f"{pe:.6g}" for pe in self.loads)]
        self.columns = columns or CLI_COLUMNS  # which of the CLI's columns are the table's values

    def name(self):
        return ", ".join(f"{k} {v}" for k, v in self.key.items() if v not in (None, ""))


def run_cli(ctx, arguments, what):
    """The CLI's CSV output (its # lines left out) as rows of text."""
    r = subprocess.run([ctx.cli] + arguments, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"validation: {what} failed:\n  {' '.join([ctx.cli] + arguments)}\n{r.stderr}")
    lines = [ln for ln in r.stdout.splitlines() if ln and not ln.startswith("#")]
    return list(csv.DictReader(io.StringIO("\n".join(lines))))


class Store:
    """A study's table of exact solves (validation/data/NAME.csv), its key columns first, then
    `values`; `study`: the study that remakes it (NAME when None)."""

    def __init__(self, ctx, name, keys, values=VALUES, study=None):
        self.ctx = ctx
        self.name = name
        self.study = study or name
        self.keys = list(keys)
        self.path = os.path.join(ctx.data, name + ".csv")
        self.table = tables.Table.read(self.path, self.keys + list(values))
        self._index = None

    def index(self):
        if self._index is None:
            self._index = {}
            for r in self.table.rows:
                self._index.setdefault(tuple(r[k] for k in self.keys), []).append(r)
        return self._index

    def curve(self, key):
        """The rows of the solve `key` (a dict of the key columns), in load order; [] when unsolved."""
        return self.index().get(tuple(tables.format_key(key.get(k)) for k in self.keys), [])

    def has(self, solve):
        rows = self.curve(solve.key)
        return all(any(abs(tables.number(r["load"]) / pe - 1) < 1e-5 for r in rows) for pe in solve.loads)

    def add(self, solve, cli_rows):
        key = {k: tables.format_key(solve.key.get(k)) for k in self.keys}
        old = self.index().get(tuple(key[k] for k in self.keys), [])
        for r in old:
            self.table.rows.remove(r)
        for r in cli_rows:
            self.table.rows.append({**key, **{solve.columns[c]: r[c] for c in solve.columns}})
        self._index = None

    def save(self):
        self.table.sort(self.keys + ["load"])
        self.table.write(self.path)
        if not self.ctx.quick:
            tables.record(self.ctx.data, self.name + ".csv", f"python3 -m validation run {self.study}")

    def solve(self, solves):
        """Runs the solves not in the table, ctx.jobs at a time (each on one thread: solves that
        share the cores each on all of them wait on each other), saving after each."""
        todo = [s for s in solves if not self.has(s)]
        if self.ctx.checking:
            if todo:
                raise SystemExit(f"validation: {len(todo)} solves of {self.ctx.relative(self.path)} are missing "
                                 f"(the first: {todo[0].name()}); python3 -m validation run {self.study} solves them")
            return 0
        if not todo:
            return 0
        print(f"{self.name}: {len(todo)} solve{'' if len(todo) == 1 else 's'}, {self.ctx.jobs} at a time", flush=True)
        started = time.time()

        def one(s):
            args = s.arguments + (["--threads", "1"] if self.ctx.jobs > 1 else [])
            return s, run_cli(self.ctx, args, s.name())
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.ctx.jobs) as pool:
            for i, (s, rows) in enumerate(pool.map(one, todo)):
                self.add(s, rows)
                self.save()
                print(f"  [{i + 1}/{len(todo)}, {time.time() - started:.0f} s] {s.name()}", flush=True)
        return len(todo)


def at(curve, pe):
    """The row of a curve at the load p/E' = pe (within 1e-5), or None."""
    return next((r for r in curve if abs(tables.number(r["load"]) / pe - 1) < 1e-5), None)


def progress(message):
    print(message, file=sys.stderr, flush=True)
