# SPDX-License-Identifier: GPL-3.0-or-later
"""Tidy tables: one CSV file a table, one row an observation, one column a variable (its unit in
its name where it has one: separation_m, h_per_k_per_m), the values kept as the text the tools
printed, so that a number read back is the number written. The data's manifest
(validation/data/MANIFEST.csv) gives each table's rows, size, SHA-256 and the command that
remakes it; `check` holds the files to it.
"""
import csv
import hashlib
import io
import os

MANIFEST = "MANIFEST.csv"


def number(text):
    """A cell as a float (nan for an empty or non-numeric one)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


class Table:
    def __init__(self, columns, rows=None, comments=None):
        self.columns = list(columns)
        self.rows = [dict(r) for r in rows or []]
        # Lines said before the header, each "# ..." (what the table is, its units)
        self.comments = list(comments or [])

    @staticmethod
    def read(path, columns=None):
        """The table in `path`; an empty one of `columns` when there is no such file."""
        if not os.path.exists(path):
            if columns is None:
                raise SystemExit(f"validation: there is no table {path}")
            return Table(columns)
        with open(path, newline="") as f:
            lines = f.read().splitlines(keepends=True)
        comments = []
        while lines and lines[0].startswith("#"):
            comments.append(lines.pop(0).rstrip("\n"))
        reader = csv.DictReader(lines)
        table = Table(reader.fieldnames or columns or [], list(reader), comments)
        if columns is not None and table.columns != list(columns):
            raise SystemExit(f"validation: {path} has the columns {table.columns}, not {list(columns)}")
        return table

    def text(self):
        out = io.StringIO()
        for line in self.comments:
            out.write(line + "\n")
        w = csv.DictWriter(out, fieldnames=self.columns, lineterminator="\n", extrasaction="raise")
        w.writeheader()
        for r in self.rows:
            w.writerow({c: r.get(c, "") for c in self.columns})
        return out.getvalue()

    def write(self, path):
        os.makedirs(os.path.dirname(path), exist_ok=True)
        temporary = path + ".partial"
        with open(temporary, "w", newline="") as f:
            f.write(self.text())
        os.replace(temporary, path)

    def sort(self, keys):
        """Rows ordered by `keys` (numbers as numbers, text as text, empty first)."""
        def value(v):
            x = number(v)
            return (0, "", 0.0) if v in ("", None) else ((1, "", x) if x == x else (2, v, 0.0))
        self.rows.sort(key=lambda r: tuple(value(r.get(k, "")) for k in keys))

    def where(self, **values):
        """The rows whose cells equal `values` (given as text or numbers)."""
        want = {k: (v if isinstance(v, str) else format_key(v)) for k, v in values.items()}
        return [r for r in self.rows if all(r.get(k, "") == v for k, v in want.items())]


def format_key(v):
    """A key's value as a table holds it: whole numbers without a point, None as empty."""
    if v is None:
        return ""
    if isinstance(v, float) and v.is_integer():
        return str(int(v))
    return str(v)


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 16), b""):
            h.update(chunk)
    return h.hexdigest()


def manifest(folder):
    """{file: row} of the folder's manifest (empty when there is none)."""
    path = os.path.join(folder, MANIFEST)
    if not os.path.exists(path):
        return {}
    with open(path, newline="") as f:
        return {r["file"]: r for r in csv.DictReader(f)}


def record(folder, name, command):
    """The manifest's row of the table `name` in `folder`, made anew from the file."""
    entries = manifest(folder)
    path = os.path.join(folder, name)
    with open(path, newline="") as f:
        rows = sum(1 for _ in f) - 1
    entries[name] = {"file": name, "rows": str(rows), "bytes": str(os.path.getsize(path)), "sha256": sha256(path),
                     "remade_by": command}
    Table(["file", "rows", "bytes", "sha256", "remade_by"], [entries[k] for k in sorted(entries)]).write(
        os.path.join(folder, MANIFEST))


def verify(folder, name):
    """Why the table `name` is not the one its manifest records, or None when it is."""
    entry = manifest(folder).get(name)
    path = os.path.join(folder, name)
    if entry is None:
        return f"{name} is not in {MANIFEST}"
    if not os.path.exists(path):
        return f"{name} is missing"
    if sha256(path) != entry["sha256"] or str(os.path.getsize(path)) != entry["bytes"]:
        return f"{name} is not the file {MANIFEST} records (size or SHA-256 differ): remake it with {entry['remade_by']}"
    return None
