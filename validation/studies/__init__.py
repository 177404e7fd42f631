# SPDX-License-Identifier: GPL-3.0-or-later
"""The studies, one module each, in the order one builds on another (python3 -m validation
list). A study module has a docstring whose first line says what it is, DATA (its tidy tables
in validation/data), solve(ctx) (its exact solves: the missing ones in run, a check that none
is missing in check) and outputs(ctx) (what it generates from its data: pages.Outputs).
docs/validation.md says how to add one."""
import importlib

ORDER = ["engineeringRange", "dektakLevels", "spectralShapes", "secondHoldOut", "blindSpectra", "largerPeriods", "fidelity", "checkPeriods", "roughness", "skewness", "paper", "anisotropy", "unloading", "unloadingMap", "mapSurrogates", "heavyLoads", "fittedElastoPlastic", "accuracyTable", "boundaryElementMap"]

STUDIES = [importlib.import_module(f"{__name__}.{name}") for name in ORDER]


def study(name):
    for m in STUDIES:
        if m.__name__.rsplit(".", 1)[1] == name:
            return m
    raise SystemExit(f"validation: no study {name} (python3 -m validation list)")
