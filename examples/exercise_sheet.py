"""A problem sheet for a class
===========================

:mod:`poinsot.exercises` makes problem sheets with a different variant of each problem for every
student, each answer computed through poinsot and checked by a second, independent route before it
is issued, and a worked solution whose steps come from :mod:`poinsot.derive`. Here: four problems
of seed 2026 (one from each of four topics of the unit) as a markdown sheet and, where a TeX
engine is installed, as a PDF; the first page of the problem sheet is shown below. The command
line does the same: ``poinsot exercises earth "free tops" --n 30 --seed 2026 --format pdf``.

Run: python examples/exercise_sheet.py [out-folder]   (writes problems.md and solutions.md, and
problems.pdf and solutions.pdf where pdflatex or latexmk is installed, and sheet.png into out/, or
the folder given as the first argument)
"""

# %%
# The set
# -------
#
# One variant from each of four templates, drawn with seed 2026: the same seed gives the same set
# on every machine. Each variant holds its statement, its answer with a grading tolerance, and the
# worked steps.

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import matplotlib.pyplot as plt
from poinsot import exercises

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

chosen = ["turntable-bug", "dropped-ball", "composite-inertia", "top-slow-precession"]
sheet = exercises.generate(chosen, n=len(chosen), seed=2026)
for v in sheet:
    print(
        f"{v.template.name:22s} seed {v.seed:>11d}  answer {v.answer:.4g} ± {v.tolerance:.2g} {v.unit.replace('**2', '²').replace('*', '·')}"
    )

# %%
# The files
# ---------
#
# Markdown always; LaTeX built to PDF where a TeX engine is installed (on Debian or Ubuntu:
# ``apt install texlive-latex-base latexmk``; without one the example says so and writes markdown only).
# The problem sheet and the solution sheet are separate files.

written = exercises.write(sheet, "markdown", out)
if shutil.which("pdflatex") or shutil.which("latexmk"):  # what exercises looks for
    written += exercises.write(sheet, "pdf", out)
else:
    print("no TeX engine (pdflatex or latexmk) is installed: markdown only, no PDF")
for path in written:
    print(f"wrote {Path(path).name}")

# %%
# The first page of the problem sheet
# -----------------------------------
#
# Rendered from the PDF by poppler's ``pdftoppm`` where both exist; otherwise the markdown sheet's
# text is set on an A4 page by matplotlib (plain text, no TeX needed).

png = out / "sheet.png"
pdf = out / "problems.pdf"
if pdf.exists() and shutil.which("pdftoppm"):
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(
            [
                "pdftoppm",
                "-png",
                "-r",
                "110",
                "-f",
                "1",
                "-l",
                "1",
                "-singlefile",
                str(pdf),
                str(Path(tmp) / "page"),
            ],
            check=True,
        )
        page = plt.imread(Path(tmp) / "page.png")
    fig, ax = plt.subplots(figsize=(8.27, 11.69))
    ax.imshow(page)
    ax.set_axis_off()
    fig.subplots_adjust(0, 0, 1, 1)
    source = "the PDF (pdflatex, pdftoppm)"
else:
    text = (out / "problems.md").read_text(encoding="utf-8")
    lines = [w for line in text.splitlines() for w in (textwrap.wrap(line, 92) or [""])]
    fig = plt.figure(figsize=(8.27, 11.69))
    fig.text(
        0.07,
        0.96,
        "\n".join(lines[:70]),
        va="top",
        ha="left",
        family="monospace",
        fontsize=8,
        parse_math=False,
    )
    source = "the markdown sheet (matplotlib)"
fig.savefig(png, dpi=80)
print(f"wrote {png.name}: the first page of the problem sheet, from {source}")
