"""How :mod:`poinsot.exercises` writes numbers, units and symbols: the units registry and the
units people use (:data:`UNITS`: plain text and LaTeX), numbers to the figures carried, and
Unicode statement text as LaTeX."""

from __future__ import annotations

import re
from typing import Any

import pint
import sympy as sp

__all__ = [
    "CARRIED_DIGITS",
    "UNITS",
    "latex_text",
    "number_latex",
    "number_symbol",
    "si_factor",
    "si_unit",
    "shown",
    "sig",
    "ureg",
]

#: Significant figures a student is expected to carry through the working.
CARRIED_DIGITS = 4

ureg: pint.UnitRegistry = pint.UnitRegistry()

#: How each unit is printed: pint's spelling → (plain text, LaTeX math).
UNITS: dict[str, tuple[str, str]] = {
    "m": ("m", r"\mathrm{m}"),
    "cm": ("cm", r"\mathrm{cm}"),
    "mm": ("mm", r"\mathrm{mm}"),
    "um": ("µm", r"\mu\mathrm{m}"),
    "km": ("km", r"\mathrm{km}"),
    "g": ("g", r"\mathrm{g}"),
    "kg": ("kg", r"\mathrm{kg}"),
    "tonne": ("t", r"\mathrm{t}"),
    "deg": ("°", r"^\circ"),
    "arcmin": ("′", r"'"),
    "rad": ("rad", r"\mathrm{rad}"),
    "rpm": ("rpm", r"\mathrm{rpm}"),
    "rad/s": ("rad/s", r"\mathrm{rad/s}"),
    "deg/s": ("°/s", r"^\circ/\mathrm{s}"),
    "km/h": ("km/h", r"\mathrm{km/h}"),
    "m/s": ("m/s", r"\mathrm{m/s}"),
    "cm/s": ("cm/s", r"\mathrm{cm/s}"),
    "m/s**2": ("m/s²", r"\mathrm{m/s^2}"),
    "rad/s**2": ("rad/s²", r"\mathrm{rad/s^2}"),
    "s": ("s", r"\mathrm{s}"),
    "min": ("min", r"\mathrm{min}"),
    "h": ("h", r"\mathrm{h}"),
    "N": ("N", r"\mathrm{N}"),
    "kN": ("kN", r"\mathrm{kN}"),
    "N*m": ("N·m", r"\mathrm{N\,m}"),
    "mN*m": ("mN·m", r"\mathrm{mN\,m}"),
    "J": ("J", r"\mathrm{J}"),
    "mW": ("mW", r"\mathrm{mW}"),
    "mJ": ("mJ", r"\mathrm{mJ}"),
    "kg*m**2": ("kg·m²", r"\mathrm{kg\,m^2}"),
    "kg*cm**2": ("kg·cm²", r"\mathrm{kg\,cm^2}"),
    "g*cm**2": ("g·cm²", r"\mathrm{g\,cm^2}"),
    "kg*m**2/s": ("kg·m²/s", r"\mathrm{kg\,m^2/s}"),
    "": ("", ""),
}


def si_factor(unit: str) -> float:
    """The SI value of one ``unit`` (``"cm"`` → 0.01, ``"rpm"`` → 2π/60, ``"deg"`` → π/180)."""
    if unit == "":
        return 1.0
    return float(ureg.Quantity(1.0, unit).to_base_units().magnitude)


def shown(value: float, unit: str, latex: bool = False) -> str:
    """``value`` (in ``unit``) with its unit, as printed in a statement."""
    plain, tex = UNITS[unit]
    number = _number(value)
    if latex:
        return f"${number}\\,{tex}$" if tex and not tex.startswith("^") else f"${number}{tex}$"
    return f"{number}{plain}" if plain in ("°", "′") else f"{number} {plain}".rstrip()


def _number(value: float) -> str:
    """A number printed exactly as drawn (a grid value): no trailing zeros, no exponent."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def sig(value: float, digits: int = CARRIED_DIGITS) -> str:
    """``value`` to ``digits`` significant figures (for answers and worked steps)."""
    return f"{value:.{digits}g}"


class _Number(sp.Symbol):
    """A number shown in a worked step: a sympy atom whose name is its LaTeX."""

    def _latex(self, printer: Any) -> str:
        return self.name


def number_latex(value: float, grouped: bool = False) -> str:
    """``value`` to :data:`CARRIED_DIGITS` figures in LaTeX (``7.292 \\cdot 10^{-5}``); with
    ``grouped``, in parentheses where it has a power of ten or a sign (a factor or a base)."""
    text = sig(value)
    mantissa, _, exponent = text.partition("e")
    if exponent:
        text = f"{mantissa} \\cdot 10^{{{int(exponent)}}}"
    if grouped and (exponent or value < 0):
        text = f"\\left({text}\\right)"
    return text


def number_symbol(value: float) -> Any:
    """``value`` as a sympy atom that prints as :func:`number_latex` (grouped: a square of it
    is ``(7.292 \\cdot 10^{-5})^{2}``, not a double superscript)."""
    return _Number(number_latex(value, grouped=True))


def si_unit(unit: str) -> str:
    """The SI unit (a key of :data:`UNITS`) of values given in ``unit``."""
    base = str(ureg.Quantity(1.0, unit).to_base_units().units) if unit else ""
    return {
        "meter": "m",
        "kilogram": "kg",
        "radian": "rad",
        "radian / second": "rad/s",
        "meter / second": "m/s",
        "second": "s",
        "kilogram * meter ** 2": "kg*m**2",
        "dimensionless": "",
    }.get(base, "")


# ---- LaTeX text ------------------------------------------------------------------------------------

_GREEK = dict(
    zip(
        "αβγδεθλμνπρστφχψωΩΦΨΘΛΔΣ",
        [
            r"\alpha",
            r"\beta",
            r"\gamma",
            r"\delta",
            r"\varepsilon",
            r"\theta",
            r"\lambda",
            r"\mu",
            r"\nu",
            r"\pi",
            r"\rho",
            r"\sigma",
            r"\tau",
            r"\phi",
            r"\chi",
            r"\psi",
            r"\omega",
            r"\Omega",
            r"\Phi",
            r"\Psi",
            r"\Theta",
            r"\Lambda",
            r"\Delta",
            r"\Sigma",
        ],
    )
)
_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
_SUP = dict(zip("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))
_POWER = re.compile("([" + "".join(_SUP) + "]+)")
_LETTER = "[A-Za-z" + "".join(_GREEK) + "]"
_DOTTED = re.compile(f"({_LETTER})\u0307([₀-₉]*)")
_SYMBOL = re.compile(f"({_LETTER})([₀-₉]+)|([" + "".join(_GREEK) + "])")
#: Other Unicode of the statements and steps, as LaTeX (pdflatex's utf8 input knows none of it).
_OTHER = {
    "°": r"$^\circ$",
    "′": "'",
    "−": "$-$",
    "×": r"$\times$",
    "≈": r"$\approx$",
    "½": r"$\frac12$",
    "⅓": r"$\frac13$",
    "¾": r"$\frac34$",
    "↔": r"$\leftrightarrow$",
    "→": r"$\to$",
    "µ": r"$\mu$",
    "√": r"$\surd$",
    "≤": r"$\le$",
    "≥": r"$\ge$",
    "§": r"\S{}",
}


def _sub(digits: str) -> str:
    return f"_{{{''.join(_SUB[c] for c in digits)}}}" if digits else ""


def latex_text(text: str) -> str:
    """Unicode statement text as LaTeX text: specials escaped, Greek letters, dotted and
    subscripted symbols (I₁, θ₀, ω̇₁) set in math, powers (10⁻⁵), ° and the other signs of
    :data:`_OTHER` as LaTeX."""
    for a, b in (("\\", r"\textbackslash{}"), ("%", r"\%"), ("&", r"\&"), ("#", r"\#")):
        text = text.replace(a, b)
    text = text.replace("_", r"\_").replace("²", r"$^2$").replace("·", r"$\cdot$")

    def dotted(m: re.Match[str]) -> str:
        return r"$\dot{" + _GREEK.get(m.group(1), m.group(1)) + "}" + _sub(m.group(2)) + "$"

    def symbol(m: re.Match[str]) -> str:
        if m.group(3):
            return f"${_GREEK[m.group(3)]}$"
        return f"${_GREEK.get(m.group(1), m.group(1))}{_sub(m.group(2))}$"

    text = _DOTTED.sub(dotted, text)
    text = _SYMBOL.sub(symbol, text)
    text = _POWER.sub(lambda m: "$^{" + "".join(_SUP[c] for c in m.group(1)) + "}$", text)
    for a, b in _OTHER.items():
        text = text.replace(a, b)
    return text
