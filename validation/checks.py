# SPDX-License-Identifier: GPL-3.0-or-later
"""The check of a user's surface (the CLI's --check, Python's check()) as the studies keep it: its
CSV rows with the columns of the studies' tables.

The tables name the checked surface's exact answer as they always have (area_exact,
h_per_k_exact, ...: the check's own surfaces are what a study of the check measures); the check's
CSV names it for what it is to a user, the checked surface's (area_checked_surface, ...).
"""
import csv
import io

# The tables' column -> the check's CSV column.
CSV_NAMES = {
    "area_exact": "area_checked_surface",
    "h_per_k_exact": "h_per_k_checked_surface",
    "h_per_k_exact_min": "h_per_k_checked_surface_min",
    "h_per_k_exact_max": "h_per_k_checked_surface_max",
}


def rows(text, columns):
    """The rows of the check's CSV `text`, each a dict of the tables' `columns` ('' where absent)."""
    return [{c: row.get(CSV_NAMES.get(c, c), "") for c in columns} for row in csv.DictReader(io.StringIO(text))]
