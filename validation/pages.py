# SPDX-License-Identifier: GPL-3.0-or-later
"""What a study generates from its data, for its page and for the core: markdown tables and
summaries under docs/validation/generated/STUDY/ (the pages include them, so that a changed
number never rewrites a sentence), files of the core it owns (a table of constants), and
figures; and a block of a page that cannot include files (README.md, which GitHub shows as it
is), between two marker lines. `run` writes them; `check` compares every text with the committed
one (a figure, which depends on the plotting library, is made by `run` only).
"""
import os

from .context import ROOT


def fmt(v, digits=2):
    """A ratio as a table shows it; '-' where there is none."""
    if v is None or v != v or v in (float("inf"), float("-inf")):
        return "-"
    return f"{v:.{digits}f}"


def span(values, digits=2):
    values = [v for v in values if v is not None and v == v]
    return f"{min(values):.{digits}f}-{max(values):.{digits}f}" if values else "-"


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def generated(ctx, study, name):
    """A table another study generated (its summary.csv, the fit's exact.csv), as committed: a study
    after it in the order reads it there, and `check STUDY` keeps it what its data give. (In a quick
    run, the committed one too: a quick study's tables are of other sizes.)"""
    from .tables import Table
    folder = os.path.join(ROOT, "docs", "validation", "generated") if ctx.quick else ctx.generated
    return Table.read(os.path.join(folder, study, name))


class Outputs:
    def __init__(self, ctx, study):
        self.ctx = ctx
        self.study = study
        self.texts = {}  # path relative to the repository (or the quick scratch) -> text
        self.figures = []  # (path, draw(path))
        self.blocks = {}  # (page relative to the repository, name) -> text

    def _generated(self, name):
        return os.path.join(os.path.relpath(self.ctx.generated, ROOT) if not self.ctx.quick else "generated",
                            self.study, name)

    def table(self, name, header, rows):
        """A markdown table, generated/STUDY/NAME.md."""
        self.texts[self._generated(name + ".md")] = markdown_table(header, rows)

    def text(self, name, text):
        """A generated file of the study's folder (a summary CSV, a list)."""
        self.texts[self._generated(name)] = text

    def source(self, path, text):
        """A file of the repository the study owns (path relative to the repository: a table of
        constants the core builds with)."""
        self.texts[path] = text

    def figure(self, name, draw):
        """A PNG, generated/STUDY/NAME.png, drawn by draw(path) (run only)."""
        self.figures.append((self._generated(name + ".png"), draw))

    def where(self, path):
        return os.path.join(os.path.dirname(self.ctx.generated) if self.ctx.quick else ROOT, path)

    def block(self, page, name, text):
        """The text between the lines `<!-- generated: STUDY/NAME ... -->` and `<!-- end of
        STUDY/NAME -->` of `page` (relative to the repository): a page that cannot include a
        file. A quick run writes it as generated/STUDY/NAME.block.md instead."""
        if self.ctx.quick:
            self.text(name + ".block.md", text)
        else:
            self.blocks[(page, name)] = text

    def _block_span(self, page, name):
        """(the page's text, start, end) of the block's text; SystemExit without its markers."""
        with open(os.path.join(ROOT, page)) as f:
            whole = f.read()
        begin = f"<!-- generated: {self.study}/{name} "
        end = f"<!-- end of {self.study}/{name} -->"
        b, e = whole.find(begin), whole.find(end)
        if b < 0 or e < b:
            raise SystemExit(f"{self.study}: {page} has no lines '{begin}... -->' and '{end}' around the "
                             f"block {name}")
        return whole, whole.index("\n", b) + 1, e

    def write(self):
        for (page, name), text in self.blocks.items():
            whole, b, e = self._block_span(page, name)
            with open(os.path.join(ROOT, page), "w") as f:
                f.write(whole[:b] + text + whole[e:])
        for path, text in self.texts.items():
            full = self.where(path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(text)
        for path, draw in self.figures:
            full = self.where(path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            draw(full)

    def differences(self):
        """The generated texts that are not the committed files (paths)."""
        out = []
        for path, text in self.texts.items():
            full = self.where(path)
            if not os.path.exists(full) or open(full).read() != text:
                out.append(path)
        for (page, name), text in self.blocks.items():
            whole, b, e = self._block_span(page, name)
            if whole[b:e] != text:
                out.append(f"{page} (the block {self.study}/{name})")
        return out
