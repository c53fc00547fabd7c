"""A small grammar for the text of a quantity (``"45 mm"``, ``"1.2 t/m^3"``, ``"5 N*m*s/rad"``).

The text is tokenised and parsed here, with limits on its length, its number of tokens, the nesting of its
parentheses and the size of every exponent, so that any string is accepted or refused in well under a
millisecond; pint is asked only to look up each unit name. Nothing is evaluated as an expression: ``"9**9**9 mm"``
is refused as a number followed by an operator, not computed.

Grammar (whitespace between factors means multiplication, as in ``"N m"``)::

    quantity  := [sign] [number] [("*" | "/") units] | [sign] number units
    units     := factor (("*" | "·" | "/" | " ") factor)*
    factor    := (NAME | "(" units ")") [("^" | "**") exponent | SUPERSCRIPT]
    exponent  := [sign] digits ["." digits] | "(" [sign] digits ["." digits] ")"

The limits are :data:`MAX_TOKENS`, :data:`MAX_DEPTH` and :data:`MAX_EXPONENT`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

#: The longest text parsed.
MAX_TEXT = 100
#: The most tokens a quantity may have (``"5 N*m*s/rad"`` has 8).
MAX_TOKENS = 40
#: The deepest nesting of parentheses in a unit.
MAX_DEPTH = 3
#: The largest exponent (in magnitude) of a unit factor (``m^3``).
MAX_EXPONENT = 12

_NUMBER = re.compile(r"(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_NAME = re.compile(r"[^\W\d⁰¹²³⁴⁵⁶⁷⁸⁹][^\W⁰¹²³⁴⁵⁶⁷⁸⁹]*")
_SUPERSCRIPTS = {"⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8",
                 "⁹": "9", "⁻": "-"}
_DIGITS = "0123456789"
_SYMBOLS = {"°": "degree", "%": "percent", "Ω": "ohm", "Å": "angstrom"}


class QuantitySyntaxError(ValueError):
    """The text is not a quantity; the message says why, in words a user understands."""


@dataclass(frozen=True)
class Token:
    kind: str  # "number", "name", "op", "(", ")", "sup", "space"
    text: str


def tokenize(text: str) -> list[Token]:
    """The tokens of ``text``; raises :class:`QuantitySyntaxError` at the first character that belongs to no
    token, or when there are more than :data:`MAX_TOKENS`."""
    out: list[Token] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in " \t":
            j = i
            while j < n and text[j] in " \t":
                j += 1
            out.append(Token("space", " "))
            i = j
        elif ch in _DIGITS or (ch == "." and i + 1 < n and text[i + 1] in _DIGITS):
            m = _NUMBER.match(text, i)
            assert m is not None
            out.append(Token("number", m.group()))
            i = m.end()
        elif ch in _SUPERSCRIPTS:
            j = i
            while j < n and text[j] in _SUPERSCRIPTS:
                j += 1
            out.append(Token("sup", "".join(_SUPERSCRIPTS[c] for c in text[i:j])))
            i = j
        elif ch in _SYMBOLS:
            out.append(Token("name", _SYMBOLS[ch]))
            i += 1
        elif ch == "*" and text.startswith("**", i):
            out.append(Token("op", "^"))
            i += 2
        elif ch in "*·⋅/^+-":
            out.append(Token("op", "*" if ch in "·⋅" else ch))
            i += 1
        elif ch in "()":
            out.append(Token(ch, ch))
            i += 1
        elif ch == ",":
            raise QuantitySyntaxError("a comma is not part of a quantity; write decimals with a point and no "
                                      "thousands separator (\"1500.5 N\")")
        else:
            m = _NAME.match(text, i)
            if m is None:
                raise QuantitySyntaxError(f"the character {ch!r} is not part of a quantity")
            word = m.group()
            # inf and nan are read as numbers so that the caller refuses them as not finite
            out.append(Token("number" if word.lower() in ("inf", "infinity", "nan") else "name", word))
            i = m.end()
        if len(out) > MAX_TOKENS:
            raise QuantitySyntaxError(f"it has more than {MAX_TOKENS} parts; a quantity such as \"45 mm\" or "
                                      f"\"1.2 t/m^3\" needs a few")
    # Spaces only matter between two factors; elsewhere they are dropped.
    kept: list[Token] = []
    for k, tok in enumerate(out):
        if tok.kind == "space":
            before = kept[-1] if kept else None
            after = out[k + 1] if k + 1 < len(out) else None
            if (before is not None and after is not None and before.kind in ("name", ")", "sup", "number")
                    and after.kind in ("name", "(")):
                kept.append(tok)
            continue
        kept.append(tok)
    return kept


#: A unit expression: the product of (unit name, exponent) pairs.
Units = tuple[tuple[str, float], ...]


class _Parser:
    def __init__(self, tokens: list[Token]) -> None:
        self.tokens = tokens
        self.pos = 0

    def peek(self) -> Token | None:
        return self.tokens[self.pos] if self.pos < len(self.tokens) else None

    def take(self) -> Token:
        tok = self.tokens[self.pos]
        self.pos += 1
        return tok

    def quantity(self) -> tuple[float, Units]:
        sign = 1.0
        tok = self.peek()
        if tok is not None and tok.kind == "op" and tok.text in "+-":
            self.take()
            sign = -1.0 if tok.text == "-" else 1.0
            tok = self.peek()
        magnitude = 1.0
        units: Units = ()
        if tok is not None and tok.kind == "number":
            magnitude = float(self.take().text)
            tok = self.peek()
            if tok is None:
                return sign * magnitude, ()
            if tok.kind == "op" and tok.text == "^":
                raise QuantitySyntaxError("a number may not be raised to a power; write its value "
                                          "(\"1e6 N\", not \"10**6 N\")")
            if tok.kind == "op" and tok.text in "*/":
                self.take()
                units = self.units(0)
                if tok.text == "/":
                    units = tuple((name, -e) for name, e in units)
            elif tok.kind == "space":
                self.take()
                units = self.units(0)
            else:
                units = self.units(0)
        elif tok is None:
            raise QuantitySyntaxError("it is empty")
        else:
            units = self.units(0)
        if self.peek() is not None:
            raise QuantitySyntaxError(f"'{self.peek().text}' cannot follow there")  # type: ignore[union-attr]
        return sign * magnitude, units

    def units(self, depth: int) -> Units:
        out = list(self.factor(depth))
        while True:
            tok = self.peek()
            if tok is None or tok.kind == ")":
                return tuple(out)
            if tok.kind == "op" and tok.text in "*/":
                self.take()
                factor = self.factor(depth)
                if tok.text == "/":
                    factor = tuple((name, -e) for name, e in factor)
                out.extend(factor)
            elif tok.kind == "space":
                self.take()
                out.extend(self.factor(depth))
            else:
                raise QuantitySyntaxError(f"'{tok.text}' cannot follow a unit")

    def factor(self, depth: int) -> Units:
        tok = self.peek()
        if tok is None:
            raise QuantitySyntaxError("a unit is missing at the end")
        if tok.kind == "name":
            self.take()
            base: Units = ((tok.text, 1.0),)
        elif tok.kind == "(":
            if depth >= MAX_DEPTH:
                raise QuantitySyntaxError(f"its parentheses are nested more than {MAX_DEPTH} deep")
            self.take()
            base = self.units(depth + 1)
            closing = self.peek()
            if closing is None or closing.kind != ")":
                raise QuantitySyntaxError("a parenthesis is not closed")
            self.take()
        elif tok.kind == "number" and tok.text == "1" and self._next_is_division():
            self.take()  # "1/s"
            return ()
        else:
            raise QuantitySyntaxError(f"'{tok.text}' is not a unit")
        power = self.exponent()
        return tuple((name, e * power) for name, e in base)

    def _next_is_division(self) -> bool:
        nxt = self.tokens[self.pos + 1] if self.pos + 1 < len(self.tokens) else None
        return nxt is not None and nxt.kind == "op" and nxt.text == "/"

    def exponent(self) -> float:
        tok = self.peek()
        if tok is not None and tok.kind == "sup":
            self.take()
            return _bounded_exponent(tok.text)
        if tok is None or tok.kind != "op" or tok.text != "^":
            return 1.0
        self.take()
        parenthesised = self.peek() is not None and self.peek().kind == "("  # type: ignore[union-attr]
        if parenthesised:
            self.take()
        text = ""
        nxt = self.peek()
        if nxt is not None and nxt.kind == "op" and nxt.text in "+-":
            text = self.take().text
        nxt = self.peek()
        if nxt is None or nxt.kind != "number":
            raise QuantitySyntaxError("an exponent must be a small number (\"m^3\")")
        value = _bounded_exponent(text + self.take().text)
        if parenthesised:
            closing = self.peek()
            if closing is None or closing.kind != ")":
                raise QuantitySyntaxError("a parenthesis is not closed")
            self.take()
        return value


def _bounded_exponent(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise QuantitySyntaxError(f"the exponent '{text}' is not a number") from None
    if not abs(value) <= MAX_EXPONENT:
        raise QuantitySyntaxError(f"the exponent {text} is larger than {MAX_EXPONENT} in magnitude")
    return value


def parse(text: str) -> tuple[float, Units]:
    """The number and the unit factors of ``text``: ``"-1.2 t/m^3"`` -> ``(-1.2, (("t", 1), ("m", -3)))``.

    A number alone has no units; a unit alone has the number 1 (``"rpm"``). Raises
    :class:`QuantitySyntaxError` for anything else.

    Examples
    --------
    >>> parse("-1.2 t/m^3")
    (-1.2, (('t', 1.0), ('m', -3.0)))
    >>> parse("5 N*m*s/rad")
    (5.0, (('N', 1.0), ('m', 1.0), ('s', 1.0), ('rad', -1.0)))
    >>> parse("9**9**9 mm")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    machdyn.quantity_text.QuantitySyntaxError: a number may not be raised to a power; write its value ...
    """
    if len(text) > MAX_TEXT:
        raise QuantitySyntaxError(f"its text has {len(text)} characters, more than {MAX_TEXT}")
    return _Parser(tokenize(text.strip())).quantity()
