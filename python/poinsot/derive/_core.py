"""The machinery of :mod:`poinsot.derive`: checked steps, the unit's vector notation, a fast
zero test, and the printed equations that :func:`poinsot.derive.errata` compares.

A step is written in the unit's notation (``Cross(omega, V)`` prints as ω⃗ × V⃗) and checked in a
*model*: the derivation's map from that notation to components (sympy matrices of functions of
time) in which every step must reduce to zero. What is shown and what is checked are the same
sympy object, so a derivation that builds is a proof of each equation it shows.
"""

from __future__ import annotations

import functools
import operator
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.physics.vector.printing import VectorPrettyPrinter, vlatex
from sympy.printing.pretty.stringpict import prettyForm

from ..errors import PoinsotError


def add(*terms: Any) -> Any:
    """A sum printed in the order written (unevaluated)."""
    return sp.Add(*terms, evaluate=False)


def mul(*factors: Any) -> Any:
    """A product printed in the order written (unevaluated)."""
    return sp.Mul(*factors, evaluate=False)


def power(base: Any, exp: Any) -> Any:
    """``base**exp`` printed as written (unevaluated)."""
    return sp.Pow(base, exp, evaluate=False)


def eq(lhs: Any, rhs: Any) -> Any:
    """The equation ``lhs = rhs`` as written (unevaluated)."""
    return sp.Eq(lhs, rhs, evaluate=False)


def dot_value(x: sp.Matrix, y: sp.Matrix) -> Any:
    """The value of ``Dot(x, y)`` on components: a (3, 3) matrix times a column, a column
    times a matrix (as a column), or the scalar product of two columns."""
    if x.shape == (3, 3):
        return x * y
    if y.shape == (3, 3):
        return (x.T * y).T
    return (x.T * y)[0, 0]


def in_order(e: sp.Add | sp.Mul, values: Sequence[Any]) -> Any:
    """The sum or product ``e`` of the ``values`` of its terms (matrices or expressions), taken
    left to right: a matrix product keeps its order."""
    if isinstance(e, sp.Add):
        return functools.reduce(operator.add, values)
    return functools.reduce(operator.mul, values, sp.Integer(1))


__all__ = [
    "Vec",
    "Unit",
    "Cross",
    "Dot",
    "DtFix",
    "DtRot",
    "VectorModel",
    "Step",
    "Derivation",
    "Printed",
    "Erratum",
    "is_zero",
    "cross_matrix",
]

# ---- the unit's vector notation -----------------------------------------------------------------


class Vec(sp.Symbol):
    """A vector of the unit, printed with an arrow: ``Vec("omega")`` is ω⃗, ``Vec("r'")`` is r⃗′.

    It is a scalar to sympy (sums and scalar multiples print as written); a :class:`VectorModel`
    gives it components when a step is checked."""

    def _latex(self, printer: Any) -> str:
        base, prime = (self.name[:-1], "'") if self.name.endswith("'") else (self.name, "")
        sub = ""
        if "_" in base:
            base, sub = base.split("_", 1)
            sub = "_{" + sub + "}"
        return r"\vec{" + printer._print(sp.Symbol(base)) + "}" + prime + sub

    def _pretty(self, printer: Any) -> Any:
        base, prime = (self.name[:-1], "'") if self.name.endswith("'") else (self.name, "")
        base, _, sub = base.partition("_")
        glyph = printer._print(sp.Symbol(base)).render(wrap_line=False)
        return prettyForm(glyph + "\u20d7" + prime + (f"_{sub}" if sub else ""))


class Unit(sp.Symbol):
    """A unit vector of the unit, printed with a hat: ``Unit("i")`` is î, ``Unit("k'")`` is k̂′,
    ``Unit("e_x")`` is ê with the subscript x."""

    def _latex(self, printer: Any) -> str:
        base, prime = (self.name[:-1], "'") if self.name.endswith("'") else (self.name, "")
        base, _, sub = base.partition("_")
        body = {"i": r"\imath", "j": r"\jmath"}.get(base, printer._print(sp.Symbol(base)))
        return r"\hat{" + body + "}" + prime + (f"_{{{sub}}}" if sub else "")

    def _pretty(self, printer: Any) -> Any:
        base, prime = (self.name[:-1], "'") if self.name.endswith("'") else (self.name, "")
        base, _, sub = base.partition("_")
        return prettyForm(base + "\u0302" + prime + (f"_{sub}" if sub else ""))


def _pwrap(printer: Any, e: Any, cross_right: bool = False) -> Any:
    f = printer._print(e)
    if isinstance(e, sp.Add) or (cross_right and isinstance(e, Cross)):
        f = prettyForm(*f.parens())
    return f


def _pretty_binary(printer: Any, e: Any, op: str) -> Any:
    a, b = e.args
    left = _pwrap(printer, a)
    return prettyForm(*left.right(f" {op} ", _pwrap(printer, b, cross_right=op == "×")))


def _wrap(printer: Any, e: Any, cross_right: bool = False, in_dot: bool = False) -> str:
    s = printer._print(e)
    if (
        isinstance(e, sp.Add)
        or (cross_right and isinstance(e, Cross))
        or (in_dot and isinstance(e, (Cross, Dot)))
    ):
        return r"\left(" + s + r"\right)"
    return s


def _power(text: str, exp: Any, printer: Any) -> str:
    """``text`` raised to ``exp`` (sympy's printer passes ``exp`` for a power of a function)."""
    if exp is None:
        return text
    return r"\left(" + text + r"\right)^{" + str(printer._print(exp)) + "}"


class _Notation(sp.Function):
    """A function of the unit's notation, printed by its ``_body_latex`` (raised to a power
    when sympy's printer asks)."""

    def _latex(self, printer: Any, exp: Any = None) -> str:
        return _power(self._body_latex(printer), exp, printer)

    def _body_latex(self, printer: Any) -> str:
        """The LaTeX without a power; here sympy's for a function, ``name(args)`` (each notation
        of the unit writes its own)."""
        return str(printer._print_Function(self))


class Cross(_Notation):
    """The cross product a × b, unevaluated (its components come from the model)."""

    nargs = 2

    def _body_latex(self, printer: Any) -> str:
        """The LaTeX without a power (a notation of a topic overrides this)."""
        a, b = self.args
        return _wrap(printer, a) + r" \times " + _wrap(printer, b, cross_right=True)

    def _pretty(self, printer: Any) -> Any:
        return _pretty_binary(printer, self, "×")


class Dot(_Notation):
    """The scalar product a · b, unevaluated."""

    nargs = 2

    def _body_latex(self, printer: Any) -> str:
        """The LaTeX without a power (a notation of a topic overrides this)."""
        a, b = self.args
        return _wrap(printer, a, in_dot=True) + r" \cdot " + _wrap(printer, b, in_dot=True)

    def _pretty(self, printer: Any) -> Any:
        return _pretty_binary(printer, self, "·")


def _dt_latex(printer: Any, e: Any, frame: str) -> str:
    order, inner = 1, e.args[0]
    while isinstance(inner, type(e)):
        order, inner = order + 1, inner.args[0]
    d = "d" if order == 1 else f"d^{{{order}}}"
    dt = "dt" if order == 1 else f"dt^{{{order}}}"
    if isinstance(inner, (sp.Symbol, sp.Function)) and not isinstance(inner, (Cross, Dot)):
        frac = r"\frac{" + d + " " + printer._print(inner) + "}{" + dt + "}"
    else:
        frac = r"\frac{" + d + "}{" + dt + r"}\left(" + printer._print(inner) + r"\right)"
    return r"\left(" + frac + r"\right)_{\mathrm{" + frame + "}}"


def _dt_pretty(printer: Any, e: Any, frame: str) -> Any:
    order, inner = 1, e.args[0]
    while isinstance(inner, type(e)):
        order, inner = order + 1, inner.args[0]
    power = "" if order == 1 else "²³⁴⁵⁶⁷⁸⁹"[order - 2]
    body = printer._print(inner)
    if isinstance(inner, (Vec, Unit, sp.Symbol)):
        text = f"(d{power}{body.render(wrap_line=False)}/dt{power})_{frame}"
        return prettyForm(text)
    head = prettyForm(f"(d{power}/dt{power})_{frame}")
    return prettyForm(*head.right(prettyForm(*body.parens())))


class _FrameRate(_Notation):
    """A rate of change of X seen in the frame ``_frame`` ("fix" or "rot")."""

    nargs = 1
    _frame = ""

    def _body_latex(self, printer: Any) -> str:
        """The LaTeX without a power (a notation of a topic overrides this)."""
        return _dt_latex(printer, self, self._frame)

    def _pretty(self, printer: Any) -> Any:
        return _dt_pretty(printer, self, self._frame)


class DtFix(_FrameRate):
    """(dX/dt)_fix: the rate of change of X seen in the fixed (primed, inertial) frame."""

    _frame = "fix"


class DtRot(_FrameRate):
    """(dX/dt)_rot: the rate of change of X seen in the rotating (unprimed) frame."""

    _frame = "rot"


def cross_matrix(a: Any) -> sp.Matrix:
    """The matrix [a]× with [a]× b = a × b (a a 3-vector of sympy expressions)."""
    return sp.Matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])


@dataclass
class VectorModel:
    """Components for the unit's notation: ``vectors`` maps each :class:`Vec`/:class:`Unit` to a
    3×1 sympy matrix; ``dt_fix`` and ``dt_rot`` map a component matrix to the components of its
    rate in the fixed and the rotating frame; ``scalars`` substitutes scalar symbols."""

    vectors: Mapping[Any, sp.Matrix]
    dt_fix: Callable[[sp.Matrix], sp.Matrix] | None = None
    dt_rot: Callable[[sp.Matrix], sp.Matrix] | None = None
    scalars: Mapping[Any, Any] = field(default_factory=dict)

    def __call__(self, e: Any) -> Any:
        """The components of ``e`` (a matrix for a vector expression, else a scalar)."""
        return self._ev(sp.sympify(e))

    def _ev(self, e: Any) -> Any:
        if e in self.vectors:
            return self.vectors[e]
        if e in self.scalars:
            return self.scalars[e]
        if isinstance(e, (Vec, Unit)):
            raise PoinsotError(f"the model has no components for the vector {e}")
        if isinstance(e, Cross):
            a, b = (self._ev(x) for x in e.args)
            return sp.Matrix(a).cross(sp.Matrix(b))
        if isinstance(e, Dot):
            a, b = (sp.Matrix(self._ev(x)) for x in e.args)
            if a.shape == (3, 3):  # a tensor: I·ω is the vector I ω
                return a * b
            if b.shape == (3, 3):  # ω·I is the (row) vector ωᵀ I, returned as a column
                return (a.T * b).T
            return (a.T * b)[0, 0]
        if isinstance(e, DtFix):
            if self.dt_fix is None:
                raise PoinsotError("the model has no fixed-frame rate")
            return self.dt_fix(self._ev(e.args[0]))
        if isinstance(e, DtRot):
            if self.dt_rot is None:
                raise PoinsotError("the model has no rotating-frame rate")
            return self.dt_rot(self._ev(e.args[0]))
        if isinstance(e, (sp.Add, sp.Mul)):
            return in_order(e, [self._ev(x) for x in e.args])
        if isinstance(e, sp.Pow):
            return self._ev(e.base) ** e.exp
        if e.args and not isinstance(e, sp.Derivative) and isinstance(e, sp.Function):
            return e.func(*(self._ev(x) for x in e.args))
        return e


# ---- the zero test ------------------------------------------------------------------------------


def _trig_polynomial_zero(e: Any) -> bool:
    """Whether ``e`` (expanded, free of matrices) is zero as a polynomial in the sines and cosines
    of its angles modulo sin² + cos² = 1, with every other function treated as a symbol.

    Exact and fast for the rotation matrices of Euler angles, where ``simplify`` takes seconds."""
    e = sp.expand_trig(e)
    atoms = sorted(e.atoms(sp.sin, sp.cos), key=sp.default_sort_key)
    args = sorted({a.args[0] for a in atoms}, key=sp.default_sort_key)
    rep: dict[Any, Any] = {}
    mods = []
    for k, a in enumerate(args):
        s, c = sp.Dummy(f"s{k}"), sp.Dummy(f"c{k}")
        rep[sp.sin(a)], rep[sp.cos(a)] = s, c
        mods.append((s, c))
    # every remaining function of time (and its derivatives) becomes a plain symbol
    others = sorted(e.atoms(sp.Derivative), key=lambda x: -sp.count_ops(x))
    for k, x in enumerate(others):
        rep[x] = sp.Dummy(f"d{k}")
    p = sp.expand(e.xreplace(rep) if not others else e.subs(rep))
    funcs = [f for f in p.atoms(sp.Function) if not isinstance(f, (sp.sin, sp.cos))]
    p = p.xreplace({f: sp.Dummy(f"f{k}") for k, f in enumerate(funcs)})
    num = sp.numer(sp.together(p))
    num = sp.expand(num)
    for s, c in mods:
        if num.has(s):
            num = sp.expand(sp.rem(num, s**2 + c**2 - 1, s))
    return bool(num == 0)


def _clearly_nonzero(x: Any) -> bool:
    """Whether ``x`` (free of unknown functions) is nonzero at two points of its symbols'
    domain, evaluated to 30 digits: a value far from zero there proves it is not identically
    zero, so a false equation is refused without ``simplify`` (which may take seconds)."""
    from sympy.core.function import AppliedUndef

    if x.atoms(AppliedUndef, sp.Derivative) or not x.free_symbols:
        return False
    if any(sym.is_integer for sym in x.free_symbols):  # sin(nπ) = 0 holds only at integers
        return False
    rng = __import__("random").Random(20261124)
    for _ in range(2):
        point = {}
        for sym in x.free_symbols:
            v = sp.Rational(rng.randint(300, 1700), 1000)
            point[sym] = -v if sym.is_negative or sym.is_nonpositive else v
        try:
            value = complex(x.xreplace(point).evalf(30))
            scale = max(
                (abs(complex(a.xreplace(point).evalf(30))) for a in sp.Add.make_args(x)),
                default=0.0,
            )
        except (TypeError, ValueError, ZeroDivisionError):
            return False
        if not (abs(value) > 1e-12 * scale and abs(value) == abs(value)):  # NaN: undecided
            return False
    return True


def is_zero(e: Any) -> bool:
    """Whether the scalar or matrix ``e`` is identically zero: expanded first, then as a
    trigonometric polynomial (:func:`_trig_polynomial_zero`), then by ``simplify``."""
    if isinstance(e, sp.MatrixBase):
        return all(is_zero(x) for x in e)
    e = sp.sympify(e)
    if e == 0:
        return True
    x = sp.expand(e)
    if x == 0:
        return True
    if not x.has(sp.Function, sp.Derivative) and all(
        p.exp.is_Integer for p in x.atoms(sp.Pow)
    ):  # a rational function of symbols: exact and quick
        return bool(sp.cancel(sp.together(x)) == 0)
    if _clearly_nonzero(x):
        return False
    if x.has(sp.sin, sp.cos) or x.has(sp.Derivative):
        try:
            if _trig_polynomial_zero(x):
                return True
        except (sp.PolynomialError, sp.polys.polyerrors.PolificationFailed):
            pass
    return bool(sp.simplify(x) == 0)


# ---- steps and derivations ----------------------------------------------------------------------


def _latex(e: Any) -> str:
    """LaTeX in the unit's style: functions of time without "(t)", rates with dots
    (sympy.physics.vector's printer), terms in the order written."""
    return str(vlatex(e, order="none"))


@dataclass(frozen=True)
class Step:
    """One step of a derivation: what is done (``text``), the equation it gives
    (``equation``, a sympy ``Eq`` in the unit's notation, or a chain of them) and the unit's
    equation ``number`` it reaches, if any."""

    text: str
    equation: Any
    number: str | None = None

    def latex(self) -> str:
        """The step's equation as LaTeX, tagged with the unit's number."""
        tag = f" \\tag{{{self.number}}}" if self.number else ""
        return _chain_latex(self.equation) + tag

    def pretty(self) -> str:
        """The step's equation as Unicode text (multi-line where there are fractions)."""
        tag = f"   ({self.number})" if self.number else ""
        return _chain_text(self.equation) + tag


def _printer() -> Any:
    return VectorPrettyPrinter({"use_unicode": True, "order": "none", "wrap_line": False})


def _chain_text(eq: Any, prefix: str = "") -> str:
    """An equation (or a chain a = b = c) as Unicode text the way a terminal shows it (sympy's
    pretty printer: fractions on lines, rates with dots), after ``prefix`` on its baseline."""
    printer = _printer()
    eqs = _eqs(eq)
    if not isinstance(eqs[0], sp.Equality):
        out = printer._print(eqs[0])
    else:
        out = printer._print(eqs[0].lhs)
        for e in eqs:
            out = prettyForm(*out.right(" = ", printer._print(e.rhs)))
    if prefix:
        out = prettyForm(*prettyForm(prefix).right(out))
    return str(out.render(wrap_line=False))


def _chain_latex(eq: Any) -> str:
    if isinstance(eq, (list, tuple)):
        out = _latex(eq[0].lhs)
        for e in eq:
            out += " = " + _latex(e.rhs)
        return out
    if isinstance(eq, sp.Equality):
        return _latex(eq.lhs) + " = " + _latex(eq.rhs)
    return _latex(eq)


def _eqs(eq: Any) -> list[Any]:
    return list(eq) if isinstance(eq, (list, tuple)) else [eq]


@dataclass
class Derivation:
    """A derivation of the unit: ``steps`` from its starting point to ``result`` (the derived
    equations keyed by the unit's equation numbers, e.g. ``"2.14"``).

    ``model`` maps the notation to components (identity for scalar derivations); ``context``
    substitutes the derivation's standing assumptions (e.g. ``I₂ = I₁``) before a check."""

    name: str
    title: str
    summary: str = ""
    model: Callable[[Any], Any] = field(default=lambda e: e, repr=False)
    context: dict[Any, Any] = field(default_factory=dict)
    steps: list[Step] = field(default_factory=list)
    result: dict[str, Any] = field(default_factory=dict)
    #: lambdify-ready forms of results: number → (expression, symbols in order)
    functions: dict[str, tuple[Any, tuple[Any, ...]]] = field(default_factory=dict)

    def residual(self, eq: Any) -> Any:
        """``lhs − rhs`` of ``eq`` in components under the context (zero when ``eq`` holds)."""
        if not isinstance(eq, sp.Equality):
            raise PoinsotError(
                f"derivation {self.name}: {eq!r} is not an equation (write Eq(lhs, rhs, "
                "evaluate=False): sympy reduced an Eq whose sides it could compare to True/False)"
            )
        lhs, rhs = self.model(eq.lhs), self.model(eq.rhs)
        # a vector equated to 0 (or 0 to a vector): the zero vector of that shape
        if isinstance(lhs, sp.MatrixBase) and not isinstance(rhs, sp.MatrixBase) and rhs == 0:
            rhs = sp.zeros(*lhs.shape)
        if isinstance(rhs, sp.MatrixBase) and not isinstance(lhs, sp.MatrixBase) and lhs == 0:
            lhs = sp.zeros(*rhs.shape)
        diff = lhs - rhs
        if self.context:
            diff = diff.subs(self.context)
        return diff

    def holds(self, eq: Any) -> bool:
        """Whether ``eq`` (an ``Eq`` in the notation, or a chain of them) holds in the model."""
        return all(is_zero(self.residual(e)) for e in _eqs(eq))

    def step(self, text: str, eq: Any, number: str | None = None) -> Any:
        """Records ``eq`` (an ``Eq``, or a list ``[Eq(a, b), Eq(b, c), ...]`` shown as
        ``a = b = c``) after checking that it holds; returns the last right-hand side. A step that
        does not hold raises :class:`PoinsotError` naming it: a derivation cannot record a false
        equation."""
        for e in _eqs(eq):
            if not is_zero(self.residual(e)):
                raise PoinsotError(
                    f"derivation {self.name}: the step {text!r} does not hold: "
                    f"{sp.sstr(e)} leaves {sp.sstr(self.residual(e))}"
                )
        return self._record(text, eq, number)

    def given(self, text: str, eq: Any, number: str | None = None) -> Any:
        """Records a definition or starting point of the unit (an axiom of this derivation: it
        is not checked, and a reader should see it as the place the derivation starts)."""
        return self._record("Given: " + text if not text.startswith("Given") else text, eq, number)

    def _record(self, text: str, eq: Any, number: str | None) -> Any:
        self.steps.append(Step(text, eq, number))
        if number is not None:
            self.result[number] = eq
        return _eqs(eq)[-1].rhs

    def function(self, number: str, expr: Any, symbols: Sequence[Any]) -> None:
        """Registers the numeric form of result ``number`` (for :meth:`lambdify`)."""
        self.functions[number] = (expr, tuple(symbols))

    def lambdify(self, number: str) -> Callable[..., Any]:
        """The result ``number`` as a numpy function of its symbols (in registration order)."""
        expr, syms = self.functions[number]
        return sp.lambdify(syms, expr, "numpy")  # type: ignore[no-any-return]

    def latex(self) -> str:
        """The derivation as a LaTeX document fragment: each step's sentence and equation."""
        parts = [f"\\section*{{{self.title}}}"]
        if self.summary:
            parts.append(self.summary)
        for s in self.steps:
            parts.append(s.text)
            parts.append("\\begin{equation}" + s.latex() + "\\end{equation}")
        return "\n\n".join(parts) + "\n"

    def text(self) -> str:
        """The derivation as plain Unicode text for a terminal: each step's sentence and its
        equation pretty-printed."""
        import textwrap

        parts = [self.title, "=" * len(self.title), ""]
        if self.summary:
            parts += [textwrap.fill(self.summary, 96), ""]
        for k, s in enumerate(self.steps, 1):
            parts.append(textwrap.fill(f"{k}. {s.text}", 96, subsequent_indent="   "))
            parts.append("")
            parts += ["      " + line for line in s.pretty().splitlines()]
            parts.append("")
        return "\n".join(parts)

    def markdown(self, heading: str = "##") -> str:
        """The derivation as Markdown with ``$$`` display math (MyST, Jupyter, GitHub)."""
        parts = [f"{heading} {self.title}", ""]
        if self.summary:
            parts += [self.summary, ""]
        for k, s in enumerate(self.steps, 1):
            parts += [f"{k}. {s.text}", "", f"   $$ {s.latex()} $$", ""]
        return "\n".join(parts)


# ---- the unit as printed ------------------------------------------------------------------------


@dataclass(frozen=True)
class Printed:
    """An equation of the unit as printed: its ``number``, the printed text transcribed
    (``as_printed``, LaTeX as in the unit) and the same equation in the derivation's notation
    (``equation``, an ``Eq`` or a chain). ``derivation`` names the derivation whose model judges
    it; ``note`` says what was read into the scan (e.g. a subscript f read as (d/dt)_fix)."""

    number: str
    derivation: str
    as_printed: str
    equation: Any
    note: str = ""


@dataclass(frozen=True)
class Erratum:
    """A printed equation that does not follow from the derivation: the printed form, the
    derived form (``derived``, the derivation's result of that number) and which link of a
    printed chain fails (``failing``)."""

    number: str
    derivation: str
    as_printed: str
    printed: Any
    derived: Any
    failing: tuple[Any, ...]
    note: str = ""

    def printed_latex(self) -> str:
        """The printed equation, in the derivation's notation, as LaTeX."""
        return _chain_latex(self.printed)

    def derived_latex(self) -> str:
        """The derived equation as LaTeX."""
        return _chain_latex(self.derived)


def judge(printed: Iterable[Printed], derivations: Mapping[str, Derivation]) -> list[Erratum]:
    """The printed equations that do not hold in their derivation's model."""
    out = []
    for p in printed:
        d = derivations[p.derivation]
        failing = tuple(e for e in _eqs(p.equation) if not is_zero(d.residual(e)))
        if failing:
            if p.number not in d.result:
                raise PoinsotError(
                    f"printed equation {p.number} does not follow, and derivation {d.name} "
                    "derives no equation of that number to show instead"
                )
            out.append(
                Erratum(
                    p.number, d.name, p.as_printed, p.equation, d.result[p.number], failing, p.note
                )
            )
    return out


def render_errata(errata: Sequence[Erratum], style: str = "text") -> str:
    """The errata as ``"text"`` (Unicode, for a terminal), ``"markdown"`` or ``"latex"``: each
    with the unit's number, the equation as printed, and the derived form."""
    if style not in ("text", "markdown", "latex"):
        raise PoinsotError(f"style: {style!r} is not one of text, markdown, latex")
    out: list[str] = []
    for e in errata:
        if style == "text":
            out += [f"({e.number})  [{e.derivation}]"]
            out += [
                _chain_text(e.printed, "   printed:  "),
                _chain_text(e.derived, "   derived:  "),
            ]
            if e.note:
                out.append("   note:     " + e.note)
            out.append("")
        elif style == "markdown":
            out += [f"**({e.number})** — derivation `{e.derivation}`", ""]
            out += [f"- printed: $\\displaystyle {e.printed_latex()}$"]
            out += [f"- derived: $\\displaystyle {e.derived_latex()}$"]
            if e.note:
                out.append(f"- note: {e.note}")
            out.append("")
        else:
            out += [f"\\paragraph{{({e.number})}} derivation \\texttt{{{e.derivation}}}"]
            out += [
                f"printed: \\[ {e.printed_latex()} \\]",
                f"derived: \\[ {e.derived_latex()} \\]",
            ]
            if e.note:
                out.append(e.note)
            out.append("")
    return "\n".join(out)
