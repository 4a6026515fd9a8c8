"""Publications that entries of more than one topic cite, each written once: an entry cites one
with its own page and note, ``dataclasses.replace(IERS_2010, page=..., note=...)``."""

from __future__ import annotations

from .._catalogue import Source

__all__ = ["IERS_2010"]

#: The IERS Conventions (2010): the dynamical flattening H and the obliquity at J2000 of its
#: Table 1.1, the inputs of the free period (:mod:`.free_rotation`) and of the Earth as a rigid
#: top (:mod:`.rigid_earth`).
IERS_2010 = Source(
    who="G. Petit and B. Luzum (eds.), IERS Conventions Centre",
    first_hand=False,
    where="Bureau International des Poids et Mesures, Sèvres / US Naval Observatory",
    when="2010",
    publication=(
        "Petit, G. and Luzum, B. (eds.) (2010), IERS Conventions (2010), IERS Technical Note "
        "No. 36, Frankfurt am Main: Verlag des Bundesamts für Kartographie und Geodäsie"
    ),
    page="Table 1.1",
    url="https://www.iers.org/TN36/",
)
