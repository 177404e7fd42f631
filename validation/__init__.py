# SPDX-License-Identifier: GPL-3.0-or-later
"""The studies behind the project's conductance laws, as one package (docs/validation.md).

    python3 -m validation list
    python3 -m validation run STUDY [--quick] [--jobs N] [--cli PATH]
    python3 -m validation check [STUDY ...]

Each study is a module of validation.studies; what several share is here: the build's tools
(context), the materials and regimes (materials), the surfaces (spectra), the exact solves and
their tidy tables (solves, tables), the laws on a surface (laws), the pages' tables (pages).
"""
