"""Sphinx: every page that cites the unit's equations shows them.

The unit's equation numbers are cited across the site ("eq. 2.42", "eqs. 2.32–2.42", in the
topic pages, the API pages generated from the docstrings, the gallery). A transform finds the
numbers a page cites — with the scanner of :mod:`unit_equations`, the one that keeps the
equation index honest — and appends a section "The unit's equations on this page" giving each
formula from docs/equations.md, linked to its row of the index. So wherever a number is cited,
its equation is on the same page.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from sphinx import addnodes
from sphinx.transforms import SphinxTransform
from unit_equations import citations_in, index_rows

#: Pages that do not get the section: the index itself, the home page, the API overview.
SKIP = frozenset({"equations", "index", "api", "genindex", "search"})
#: Text inside these nodes is not prose (code, math, raw HTML, literals).
NOT_PROSE = (
    nodes.literal_block,
    nodes.literal,
    nodes.math,
    nodes.math_block,
    nodes.raw,
    nodes.comment,
    nodes.target,
    nodes.doctest_block,
)
SECTION_ID = "the-unit-s-equations-on-this-page"


def _prose_blocks(document: nodes.document) -> list[str]:
    """The text of each paragraph-like block, with code, math and literals blanked."""
    out = []
    for block in document.findall(
        lambda n: isinstance(n, (nodes.paragraph, nodes.title, nodes.term))
    ):
        parts = []
        for text in block.findall(nodes.Text):
            parent = text.parent
            inside = False
            while parent is not None and parent is not block:
                if isinstance(parent, NOT_PROSE):
                    inside = True
                    break
                parent = parent.parent
            parts.append(" " * len(text) if inside else str(text))
        out.append("".join(parts))
    return out


def cited_numbers(document: nodes.document, rel: str) -> list[int]:
    """The equation numbers N (of eq. 2.N) cited in ``document``, in ascending order."""
    found: set[int] = set()
    for block in _prose_blocks(document):
        found.update(c.number for c in citations_in(block, rel))
    return sorted(found)


class CitedEquations(SphinxTransform):
    """Appends "The unit's equations on this page" to a page that cites any."""

    default_priority = 880

    def apply(self, **kwargs: Any) -> None:
        docname = self.env.docname
        if docname in SKIP:
            return
        numbers = cited_numbers(self.document, f"docs/{docname}.md")
        if not numbers:
            return
        rows = {r.number: r for r in index_rows()}
        numbers = [n for n in numbers if n in rows and rows[n].formulas()]
        if not numbers:
            return
        section = nodes.section(ids=[SECTION_ID], names=[SECTION_ID])
        section += nodes.title(text="The unit's equations on this page")
        intro = nodes.paragraph()
        intro += nodes.Text(
            "Each equation of the unit cited above, as the unit has it (corrected where it "
            "misprints it); the "
        )
        ref = addnodes.pending_xref(
            "", refdomain="std", reftype="doc", reftarget="/equations", refexplicit=True
        )
        ref += nodes.inline(text="equation index")
        intro += ref
        intro += nodes.Text(" names the function that computes each and the test that checks it.")
        section += intro
        items = nodes.bullet_list(classes=["unit-equations"])
        for n in numbers:
            item = nodes.list_item()
            para = nodes.paragraph()
            para += nodes.strong(text=f"({'2.' + str(n)})")
            para += nodes.Text("  ")
            for k, tex in enumerate(rows[n].formulas()):
                if k:
                    para += nodes.Text(",  ")
                para += nodes.math(tex, tex)
            item += para
            items += item
        section += items
        # Inside the page's own top section, so it is a heading of the page, not a second page.
        top = next((c for c in self.document.children if isinstance(c, nodes.section)), None)
        (top if top is not None else self.document).append(section)


def setup(app: Any) -> dict[str, Any]:
    app.add_transform(CitedEquations)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
