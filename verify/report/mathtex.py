"""LaTeX sources of the report's formulas, from the notation the checks print.

The checks and the proof checker print formulas in one compact plain-text notation
(``R̄_rᵀ``, ``tr(...)``, ``λmin(sym(R_rl))``, ``hat(ω_h^s)``, ``sk(R)^∨``, ``(1/2)``,
``>=``) that suits a terminal and JSON. The typeset formats need LaTeX: :func:`to_latex`
translates one formula of that notation into an ASCII LaTeX math source, and
:func:`prose_to_latex` marks the formulas inside a sentence (``$...$``) and escapes the
words around them. The result is the one source per formula from which the HTML report
makes MathML (:mod:`verify.report.mathml`), the Markdown report keeps ``$...$`` and the
appendix is typeset by LaTeX (:mod:`verify.report.latex`).

The notation is the one of the paper's Sections 2-4 (rotations ``R``, the quasi-average
``R̄``, the directions ``d_i``, the human model ``H(s)`` and its index ``ν(ω)``); a symbol
the table below does not know becomes upright text, never an error, so a new check's
wording degrades to text rather than breaking a report.
"""

from __future__ import annotations

import re
import unicodedata

__all__ = ["CLAIM_ID", "latex_text", "normalise", "prose_to_latex", "to_latex"]

_GREEK = {
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon",
    "θ": r"\theta", "κ": r"\kappa", "λ": r"\lambda", "μ": r"\mu", "ν": r"\nu", "ξ": r"\xi",
    "π": r"\pi", "ρ": r"\rho", "σ": r"\sigma", "τ": r"\tau", "φ": r"\varphi", "ϕ": r"\varphi",
    "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega", "Ω": r"\Omega", "Δ": r"\Delta",
    "Σ": r"\Sigma", "Φ": r"\Phi", "Λ": r"\Lambda", "Θ": r"\Theta", "Γ": r"\Gamma",
}
#: ASCII words of the plain notation that name a Greek letter or a decorated symbol
_WORDS = {
    "omega": r"\omega", "Omega": r"\Omega", "lambda": r"\lambda", "xi": r"\xi",
    "theta": r"\theta", "nu": r"\nu", "rho": r"\rho", "phi": r"\varphi", "beta": r"\beta",
    "pi": r"\pi", "dbar": r"\bar{d}", "Rbar": r"\bar{R}", "inf": r"\inf", "sum": r"\sum",
    "lambda_min": r"\lambda_{\min}", "λmin": r"\lambda_{\min}", "λ_min": r"\lambda_{\min}",
    "infinity": r"\infty", "e3": r"e_{3}", "I_3": r"I_{3}",
}
_OPERATORS = {"tr", "sk", "sym", "rank", "null", "grad", "det", "diag", "blockdiag", "Re",
              "Im", "vec", "range"}
_FUNCTIONS = {"cos": r"\cos", "sin": r"\sin", "tan": r"\tan", "exp": r"\exp",
              "log": r"\log", "min": r"\min", "max": r"\max"}
#: two-letter English words that stay words inside a formula ('V̇ at R_l = R̄'), not a
#: product of two symbols
_TEXT_WORDS = {"at", "on", "of", "in", "is", "if", "or", "as", "to", "by", "an", "be", "so",
               "no", "we", "it"}
_SYMBOLS = {
    "≥": r"\geq", "≤": r"\leq", "⪰": r"\succeq", "⪯": r"\preceq", "≻": r"\succ",
    "≺": r"\prec", "≠": r"\neq", "⟺": r"\iff", "⇔": r"\iff", "⇒": r"\Rightarrow",
    "→": r"\to", "∞": r"\infty", "∫": r"\int", "∂": r"\partial", "≈": r"\approx",
    "≡": r"\equiv", "∈": r"\in", "×": r"\times", "·": r"\cdot", "‖": r"\Vert",
    "∨": r"\vee", "∧": r"\wedge", "±": r"\pm", "∑": r"\sum", "−": "-", "…": r"\dots",
    "√": r"\sqrt", "∀": r"\forall", "∃": r"\exists", "⊂": r"\subset", "∩": r"\cap",
    "∪": r"\cup", "∅": r"\emptyset", "ℝ": r"\mathbb{R}", "ℂ": r"\mathbb{C}",
    "½": r"\tfrac{1}{2}", "|": r"\vert ", "{": r"\{", "}": r"\}", "%": r"\%", "#": r"\#",
    "&": r"\&", "$": r"\$", "~": r"\sim ", "\\": r"\backslash ",
}
_SUPERSCRIPTS = {"ᵀ": r"\top", "ᴴ": "H", "²": "2", "³": "3", "⁻": "-", "¹": "1", "⊥": r"\perp",
                 "∨": r"\vee", "⁺": "+"}
_ACCENTS = {"\u0304": r"\bar", "\u0305": r"\bar", "\u0303": r"\tilde", "\u0307": r"\dot",
            "\u0302": r"\hat", "\u0308": r"\ddot"}
_TWO = {">=": r"\geq", "<=": r"\leq", "!=": r"\neq", "->": r"\to", "=>": r"\Rightarrow",
        "<-": r"\leftarrow"}
_LETTER = re.compile(r"[A-Za-z\u0370-\u03ff]")
_TRAIL = ".,;:"
_FRACTION = re.compile(r"\((-?)(\d+)/(\d+)\)")


#: a claim id (``lemma1.boundary``, ``thm1.S_rl-dot.step4-sos``): a name, set as text
CLAIM_ID = re.compile(r"\b(?:sec\d|lemma\d|thm\d)\.[A-Za-z0-9_.\-]*[A-Za-z0-9]")
#: ASCII spellings of the plain notation and the symbol each stands for
_SPELLINGS = (
    (re.compile(r"\b([A-Za-z])-bar(?![A-Za-z])"), "\\1\u0304"),  # R-bar_r: R̄_r
    (re.compile(r"\b([A-Za-z])((?:_[A-Za-z0-9]+)?)-dot(?![A-Za-z])"),
     "\\1\u0307\\2"),  # S_h-dot: Ṡ_h
    (re.compile(r"\b([A-Z])~"), "\\1\u0303"),  # W~: W̃
    (re.compile(r"\b([dR])bar\b"), "\\1\u0304"),  # dbar: d̄
    (re.compile(r"\+/-"), "±"),
    (re.compile(r"\bkappa\b"), "κ"), (re.compile(r"\bchi2\b"), "χ²"),
    (re.compile(r"\balpha\b"), "α"), (re.compile(r"\bpi\b"), "π"),
    (re.compile(r"\bphi(?=\()"), "φ"),
    (re.compile(r"\bnu(?=[ (_]|$)"), "ν"),
    (re.compile(r"\beps\b"), "ε"),
    (re.compile(r"\bsum (?!of\b)(?=[A-Za-z](?:_\w+)?\b)"), "∑"),  # sum d_i: ∑d_i
    (re.compile(r"\bhat ([A-Za-z\u0370-\u03ff])(?![\w(])"), "hat(\\1)"),  # hat v: hat(v)
    (re.compile(r"\[((?:'[^'\]]*'(?:, )?)+)\]"),  # a Python list ['-1', '1']: (-1, 1)
     lambda m: "(" + m.group(1).replace("'", "") + ")"),
)


def normalise(text: str) -> str:
    """``text`` with the ASCII spellings of the notation (``R-bar_r``, ``kappa(W)``, ``W~``,
    ``sum d_i``, ``hat v``, a Python list of numbers) replaced by the symbols they stand
    for; claim ids are left exactly as they are."""
    out, pos = [], 0
    for m in [*CLAIM_ID.finditer(text), None]:
        end = m.start() if m else len(text)
        piece = text[pos:end]
        for pattern, repl in _SPELLINGS:
            piece = pattern.sub(repl, piece)
        out.append(piece)
        if m:
            out.append(m.group(0))
            pos = m.end()
    return "".join(out)


def _is_letter(ch: str) -> bool:
    return bool(_LETTER.fullmatch(ch))


_EN, _EM = "\x1c", "\x1d"  # an en and an em dash inside latex_text


def latex_text(text: str) -> str:
    """``text`` as LaTeX text mode (special characters escaped, ASCII only); a word with
    characters beyond ASCII (a stray ``ξ``, ``Ṡ_rl``) is set as a formula."""
    words = []
    # the dashes become markers that stay ASCII words, set as -- and --- below, so that
    # a written double hyphen (a flag such as --check) is kept apart from them
    text = text.replace("—", _EM).replace("–", _EN).replace("’", "'").replace("‘", "'")
    text = text.replace("\u00a0", " ").replace("≈", "~")
    for word in text.split(" "):
        core = word.rstrip(_TRAIL + ")")
        if word.isascii() or not core:
            words.append(_escape_ascii(word))
        else:
            lead = "(" if core.startswith("(") and core.count("(") > core.count(")") else ""
            core = core[len(lead):]
            words.append(f"{lead}${to_latex(core)}${_escape_ascii(word[len(lead) + len(core):])}")
    return " ".join(words)


def _escape_ascii(text: str) -> str:
    out = []
    for ch in text:
        if ch in "\\":
            out.append(r"\textbackslash{}")
        elif ch in "{}%#&$_":
            out.append("\\" + ch)
        elif ch == "^":
            out.append(r"\^{}")
        elif ch == "~":
            out.append(r"\textasciitilde{}")
        elif ch in "<>|":
            out.append({"<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}"}[ch])
        elif ch in ("—", _EM):
            out.append("---")
        elif ch in ("–", _EN):
            out.append("--")
        elif ch == "-" and out and out[-1].endswith("-"):  # no ligature from "--"
            out.append("{}-")
        elif ch in "’‘":
            out.append("'")
        elif ord(ch) < 128:
            out.append(ch)
        else:
            out.append("?")
    return "".join(out)


class _Scanner:
    """A left-to-right translation of one formula (see the module docstring)."""

    def __init__(self, text: str) -> None:
        text = text.replace("≠", "!=").replace("≢", "!=")  # NFD would split them
        text = re.sub(r"\b([A-Za-z])-bar\b", "\\1\u0304", text)
        text = re.sub(r"\b([A-Za-z])-dot\b", "\\1\u0307", text)
        self.s = unicodedata.normalize("NFD", text)
        self.i = 0
        self.angle = 0  # open ⟨ brackets made from '<'

    def peek(self, k: int = 0) -> str:
        j = self.i + k
        return self.s[j] if j < len(self.s) else ""

    def run(self, stop: str = "") -> list[str]:
        out: list[str] = []
        while self.i < len(self.s):
            ch = self.peek()
            if stop and ch == stop:
                break
            out.append(self.token(out))
        return out

    def group(self) -> str:
        """The content of a parenthesised argument after its '(' (consumes the ')')."""
        depth, start = 0, self.i
        while self.i < len(self.s):
            ch = self.s[self.i]
            if ch == "(":
                depth += 1
            elif ch == ")":
                if depth == 0:
                    inner = self.s[start:self.i]
                    self.i += 1
                    return to_latex(inner)
                depth -= 1
            self.i += 1
        return to_latex(self.s[start:])

    def word(self) -> str:
        j = self.i
        greek = None
        while j < len(self.s) and (_is_letter(self.s[j]) or self.s[j] in "0123456789"
                                   or unicodedata.combining(self.s[j])):
            if _is_letter(self.s[j]):
                is_greek = not self.s[j].isascii()
                if greek is not None and is_greek != greek and not (
                        self.s[self.i:j] == "λ" and self.s.startswith("min", j)):
                    break  # 'cosθ' is cos θ; 'λmin' stays one name
                greek = is_greek
            j += 1
        w = self.s[self.i:j]
        self.i = j
        return w

    def script(self) -> str:
        """A sub- or superscript body after '_' or '^'."""
        ch = self.peek()
        if ch == "{":
            depth, start = 0, self.i
            while self.i < len(self.s):
                c = self.s[self.i]
                depth += c == "{"
                depth -= c == "}"
                self.i += 1
                if depth == 0:
                    break
            return to_latex(self.s[start + 1:self.i - 1])
        if ch in _SUPERSCRIPTS:
            self.i += 1
            return _SUPERSCRIPTS[ch]
        if ch == "(":
            self.i += 1
            return "(" + self.group() + ")"
        if ch == "-" and self.peek(1).isdigit():
            self.i += 1
            return "-" + self.word()
        if ch in "+-*":
            self.i += 1
            return ch
        w = self.word()
        if w in ("T", "vee", "H"):
            return {"T": r"\top", "vee": r"\vee", "H": "H"}[w]
        if w:
            return "".join(_decorate(c) for c in _split_accents(w)) if not w.isdigit() else w
        return ""

    def suffixes(self, base: str) -> str:
        """Accents were handled by the caller; here sub/superscripts and primes."""
        sub, sup = "", []
        while self.i < len(self.s):
            ch = self.peek()
            if ch == "_" and not sub and (self.peek(1).isalnum() or self.peek(1) == "{"
                                          or _is_letter(self.peek(1))):
                self.i += 1
                sub = self.script()
            elif ch == "^":
                nxt = self.peek(1)
                if nxt in ("", " ", ")", ",", ";", "²") and not nxt.isalnum():
                    self.i += 1
                    sup.append(r"\wedge")
                    if nxt == "²":
                        self.i += 1
                        sup.append("2")
                else:
                    self.i += 1
                    sup.append(self.script())
            elif ch in _SUPERSCRIPTS and ch not in "∨":
                self.i += 1
                sup.append(_SUPERSCRIPTS[ch])
            elif ch == "'":
                self.i += 1
                sup.append(r"\prime")
            elif ch == "~":  # the plain notation's trailing tilde: omega~ is ω̃
                self.i += 1
                base = rf"\tilde{{{base}}}"
            else:
                break
        out = base
        if sub:
            out += f"_{{{sub}}}"
        if sup:
            out += "^{" + " ".join(sup) + "}"
        return out

    def token(self, out: list[str]) -> str:
        s, ch = self.s, self.peek()
        two = s[self.i:self.i + 2]
        if ch == " ":
            self.i += 1
            return " "
        m = _FRACTION.match(s, self.i)
        if m:
            self.i = m.end()
            return self.suffixes(f"{m.group(1)}\\tfrac{{{m.group(2)}}}{{{m.group(3)}}}")
        if s.startswith(("i.e.", "e.g."), self.i):
            self.i += 4
            return rf"\text{{{s[self.i - 4:self.i]}}}"
        if s.startswith("d/dt", self.i):
            self.i += 4
            return r"\tfrac{d}{dt}"
        if two in _TWO and not (two == "<-" and ">" in s[self.i:]):
            self.i += 2
            return f" {_TWO[two]} "
        if ch == "<":
            if self.peek(1) not in (" ", "", "=") and ">" in s[self.i:]:
                self.i += 1
                self.angle += 1
                return r"\langle "
            self.i += 1
            return " < "
        if ch == ">":
            self.i += 1
            if self.angle and self.i >= 2 and s[self.i - 2] != " ":
                self.angle -= 1
                return self.suffixes(r"\rangle")
            return " > "
        if ch == "(":
            self.i += 1
            return "("
        if ch == ")":
            self.i += 1
            return self.suffixes(")")
        if ch.isdigit():
            j = self.i
            while j < len(s) and (s[j].isdigit() or (s[j] == "." and j + 1 < len(s)
                                                    and s[j + 1].isdigit())):
                j += 1
            num = s[self.i:j]
            self.i = j
            if self.peek() == "x" and self.peek(1).isdigit():  # 3x3: a matrix size
                self.i += 1
                return f"{num} \\times "
            return self.suffixes(num)
        if _is_letter(ch):
            return self.identifier()
        if ch in _SYMBOLS:
            self.i += 1
            sym = _SYMBOLS[ch]
            if ch == "‖":
                return self.suffixes(r"\Vert ")
            if ch == "|":
                return self.suffixes(r"\vert ")
            return f" {sym} " if sym.startswith("\\") and sym[1:].isalpha() else sym
        if ch in _SUPERSCRIPTS:
            self.i += 1
            return f"^{{{_SUPERSCRIPTS[ch]}}}"
        if ch in "^_":
            self.i += 1
            return r"{}^{\wedge}" if ch == "^" else r"\_"
        self.i += 1
        if ord(ch) < 128:
            return ch
        if unicodedata.combining(ch):
            return ""
        name = unicodedata.name(ch, "symbol").lower()
        return rf"\text{{[{name}]}}"

    def identifier(self) -> str:
        w = self.word()
        parts = _split_accents(w)
        plain = "".join(c for c, _ in parts)
        # function-like operators with a parenthesised argument or a bare one
        if plain in ("hat", "vee") and w == plain:
            if self.peek() == "(":
                self.i += 1
                arg = self.group()
                if plain == "hat":
                    base = rf"\widehat{{{arg}}}" if len(arg) > 2 else rf"\hat{{{arg}}}"
                else:
                    base = rf"\left({arg}\right)^{{\vee}}"
                return self.suffixes(base)
            if self.peek() == " " and self.peek(1) and _is_letter(self.peek(1)):
                self.i += 1
                j = self.i
                arg = self.word()
                if arg:
                    return self.suffixes(rf"\hat{{{_decorated_word(arg)}}}")
                self.i = j
        if w == plain and plain in _OPERATORS:
            return self.suffixes(rf"\operatorname{{{plain}}}")
        if w == plain and plain in _FUNCTIONS:
            return self.suffixes(_FUNCTIONS[plain])
        if w in ("λmin", "lambda") and self.s.startswith("_min", self.i):
            self.i += 4
            return self.suffixes(r"\lambda_{\min}")
        if w in _WORDS:
            return self.suffixes(_WORDS[w])
        if w == "λmin":
            return self.suffixes(r"\lambda_{\min}")
        if w == "x" and self.i >= 2 and self.s[self.i - 2] == " " and self.peek() == " ":
            return r"\times"
        if len(plain) == 1 or all(not c.isascii() for c, _ in parts if c.isalpha()) \
                or re.fullmatch(r"[A-Za-z]\d+", plain):
            # one letter (with accents), a run of Greek letters, or e3-like
            if re.fullmatch(r"[A-Za-z]\d+", plain) and w == plain:
                return self.suffixes(f"{plain[0]}_{{{plain[1:]}}}")
            return self.suffixes("".join(_decorate(c) for c in parts))
        if len(plain) == 2 and w == plain and plain not in _TEXT_WORDS:  # AB, jw: products
            return self.suffixes(plain)
        return rf"\text{{{w}}}"


def _split_accents(w: str) -> list[tuple[str, list[str]]]:
    out: list[tuple[str, list[str]]] = []
    for ch in w:
        if unicodedata.combining(ch) and out:
            out[-1][1].append(ch)
        else:
            out.append((ch, []))
    return out


def _decorate(part: tuple[str, list[str]]) -> str:
    ch, accents = part
    out = _GREEK.get(ch, ch)
    for a in accents:
        cmd = _ACCENTS.get(a)
        if cmd:
            out = f"{cmd}{{{out}}}"
    return out + (" " if out.startswith("\\") and out[-1].isalpha() else "")


def _decorated_word(w: str) -> str:
    return "".join(_decorate(c) for c in _split_accents(w)).strip()


def _merge_text(tokens: list[str]) -> str:
    """Join the tokens; neighbouring words of text (with the spaces between) become one
    ``\\text{...}`` so that the words keep their spacing."""
    out: list[str] = []
    pending: list[str] = []  # words of one text run, with the spaces between them

    def flush() -> None:
        if pending:
            words = "".join(pending).strip()
            out.append(rf"\text{{{words}}}")
            if pending[-1] == " ":
                out.append(r"\ ")
            pending.clear()

    for t in tokens:
        if t.startswith(r"\text{") and t.endswith("}") and t.count("{") == 1:
            if not pending and out and out[-1] == " ":
                out[-1] = r"\ "
            pending.append(t[6:-1])
        elif t == " " and pending:
            pending.append(" ")
        elif pending and t in (".", ",", ";", ":") and not pending[-1] == " ":
            pending.append(t)
        else:
            flush()
            out.append(t)
    flush()
    text = "".join(out)
    text = re.sub(r" {2,}", " ", text).strip()
    return text


def to_latex(text: str) -> str:
    """The LaTeX math source (ASCII, no surrounding ``$``) of one formula in the plain
    notation; ``to_latex("tr(R̄_rᵀ) >= 1")`` is ``\\operatorname{tr}(\\bar{R}_{r}^{\\top})
    \\geq 1``."""
    tokens = _Scanner(normalise(text)).run()
    out = _merge_text(tokens) or "{}"
    return out.encode("ascii", "replace").decode("ascii")


# ---------------------------------------------------------------------------- prose

_STRONG = re.compile(
    r"[_^ᵀᴴ²≥≤⪰⪯≻≺≠⟺⇔→∞∫∂≈≡∈‖∨⊥]|[\u0370-\u03ff]|[\u0300-\u036f]|>=|<=|!=|->"
    r"|^(tr|sk|sym|hat|vee|rank|null|grad|det|cos|sin|exp|lambda_min|λmin|nu|Re|Im)\("
    r"|^[A-Za-z]\(|^\(?(dbar|Omega|omega|lambda|xi|theta)\b|\)\^|^[A-Za-z]'$|-bar\b|-dot\b"
    r"|^\(?e3\b|^\(?[abc]\d{1,2}\b|^<[^\s=]|[^\s<=-]>[.,;:]*$"
)
_WEAK = re.compile(r"^[-+=<>*/x·×]$|^\(?-?[A-Za-z0-9]\)?$|^\(?-?\d+(\.\d+)?\)?$|^[()]+$")


def _is_math_word(word: str) -> bool:
    core = word.rstrip(_TRAIL)
    if CLAIM_ID.search(core) or re.fullmatch(r"\(?[A-Za-z]+(_[A-Za-z0-9]+)+\(\)\)?", core):
        return False  # a claim id or a function name (by_sos()) is a name
    if not core or re.fullmatch(r"[A-Za-z]+(-[A-Za-z]+)+", core):
        return False  # hyphenated words ("rank-1" excepted below) are prose
    if re.fullmatch(r"\(?eqs?\.|\(\d+[a-z]?\)[,.;:)]*|\d+(\.\d+)?\s*%?", core):
        return False  # equation numbers and plain numbers read as text
    snake = re.fullmatch(r"\(?([A-Za-z]{2,})(_[A-Za-z0-9]+)+\)?", core)
    if snake and snake.group(1) not in _WORDS:
        return False  # an identifier such as passive_human is a name, not a subscript
    return bool(_STRONG.search(core))


def prose_to_latex(text: str) -> str:
    """A sentence in LaTeX text mode with its formulas in ``$...$``.

    A word is a formula when it carries the notation's marks (sub/superscripts, ᵀ,
    relations, Greek letters, accents, ``tr(``-like calls); single letters, numbers and
    operators between two formulas join them (``R + Rᵀ`` is one formula, ``a model`` is
    prose). Trailing punctuation stays in the text.
    """
    words = normalise(text).split(" ")
    kinds = [_is_math_word(w) for w in words]
    # weak words join the formulas on both sides of them
    n = len(words)
    joined = list(kinds)
    for k in range(n):
        if kinds[k] or not _WEAK.fullmatch(words[k].rstrip(_TRAIL) or "x!"):
            continue
        left = next((j for j in range(k - 1, -1, -1) if kinds[j]
                     or not _WEAK.fullmatch(words[j].rstrip(_TRAIL) or "x!")), None)
        right = next((j for j in range(k + 1, n) if kinds[j]
                      or not _WEAK.fullmatch(words[j].rstrip(_TRAIL) or "x!")), None)
        if left is not None and right is not None and kinds[left] and kinds[right] \
                and not words[left].endswith(tuple(_TRAIL)):
            joined[k] = True
        elif (left is not None and kinds[left] and not words[left].endswith(tuple(_TRAIL))
              and words[k].rstrip(_TRAIL) in ("0", "1", "2", "3") and k > 0
              and words[k - 1] in ("=", ">=", "<=", ">", "<", "≥", "≤", "≠")):
            joined[k] = True
    _extend(words, joined)
    _balance(words, joined)
    out: list[str] = []
    k = 0
    while k < n:
        if not joined[k]:
            out.append(latex_text(words[k]))
            k += 1
            continue
        j = k
        run = []
        while j < n and joined[j]:
            run.append(words[j])
            if words[j].endswith(tuple(_TRAIL)) and j + 1 < n and not _weak_op(words[j + 1]) \
                    and not _open_angle(" ".join(run)):
                j += 1
                break
            j += 1
        formula = " ".join(run)
        trail = ""
        while formula and formula[-1] in _TRAIL:
            trail = formula[-1] + trail
            formula = formula[:-1]
        if formula.count("(") < formula.count(")") and formula.endswith(")"):
            formula, trail = formula[:-1], ")" + trail  # a closing parenthesis of prose
        lead = ""
        if formula.count("(") > formula.count(")") and formula.startswith("("):
            lead, formula = "(", formula[1:]
        out.append(f"{lead}${to_latex(formula)}${latex_text(trail)}")
        k = j
    return " ".join(out)


_RELATIONS = ("=", ">=", "<=", ">", "<", "≥", "≤", "≠", "!=", "+", "-", "->", "→", "⪰", "≻")


def _extend(words: list[str], joined: list[bool]) -> None:
    """Grow formulas over a relation and one short operand on either side
    (``sym(R_rl) > 0``, ``V = S_r + ...``)."""
    n = len(words)

    def short(w: str) -> bool:
        return bool(re.fullmatch(r"-?(\d+(\.\d+)?|[A-Za-z])[,.;:]?", w))

    for k in range(n - 1):  # a capital before a formula is its factor: 'R hat(w)'
        if re.fullmatch(r"[A-Z]", words[k]) and joined[k + 1] and not joined[k] \
                and words[k + 1][0] not in "=<>≤≥+-":
            joined[k] = True
    for k in range(1, n - 1):  # and a letter between a formula and a relation: 'R_i w = 0'
        if re.fullmatch(r"[A-Za-z]", words[k]) and joined[k - 1] and not joined[k] \
                and not words[k - 1].endswith(tuple(_TRAIL)) and words[k + 1] in _RELATIONS:
            joined[k] = True
    for i, word in enumerate(words):  # an inner product <a, b> is one formula
        if len(word) > 1 and word[0] == "<" and word[1] not in " =":
            for j in range(i, min(i + 5, n)):
                if len(words[j]) > 1 and words[j].rstrip(_TRAIL).endswith(">"):
                    for k in range(i, j + 1):
                        joined[k] = True
                    break
    for k in range(1, n - 1):
        if words[k] in _RELATIONS and not joined[k]:
            if joined[k - 1] and not words[k - 1].endswith(tuple(_TRAIL)) \
                    and short(words[k + 1]):
                joined[k] = joined[k + 1] = True
            elif joined[k + 1] and short(words[k - 1]) \
                    and not words[k - 1].endswith(tuple(_TRAIL)):
                joined[k] = joined[k - 1] = True


def _depth(word: str) -> int:
    return word.count("(") - word.count(")")


def _balance(words: list[str], joined: list[bool], reach: int = 4) -> None:
    """Grow a formula whose parentheses do not balance over the few words that close
    them (``10/(s + 0.5)^2`` is one formula, not ``10/(s +`` and ``0.5)^2``)."""
    n = len(words)
    k = 0
    while k < n:
        if not joined[k]:
            k += 1
            continue
        j = k
        while j < n and joined[j]:
            j += 1
        depth = sum(_depth(w) for w in words[k:j])
        if depth > 0:  # an open parenthesis: close it within reach to the right
            total, end = depth, None
            for m in range(j, min(j + reach, n)):
                total += _depth(words[m])
                if total == 0:
                    end = m
                    break
            if end is not None:
                for m in range(j, end + 1):
                    joined[m] = True
        elif depth < 0:  # a closing one: open it within reach to the left
            total, start = depth, None
            for m in range(k - 1, max(k - 1 - reach, -1), -1):
                total += _depth(words[m])
                if total == 0:
                    start = m
                    break
            if start is not None:
                for m in range(start, k):
                    joined[m] = True
                k = start
                continue
        k = j


def _open_angle(text: str) -> bool:
    """Whether ``text`` opens an inner product ``<a, b>`` that it does not close."""
    opened = len(re.findall(r"<(?=[^\s=])", text))
    closed = len(re.findall(r"(?<=\S)>", text))
    return opened > closed


def _weak_op(word: str) -> bool:
    return word in ("=", "+", "-", ">=", "<=", "≥", "≤", "⪰", "≻")
