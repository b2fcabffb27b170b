#!/usr/bin/env python3
"""A deliberately simple RenderMan LPE matcher speaking the external-matcher protocol.

It shares no code with lpe: its own recursive-descent parser, and a matcher that walks
the syntax tree over the path's vertex list, collecting every position each subtree can
end at (backtracking over all choices). Slow and obvious on purpose, so that
`lpe-check diff --external 'python3 examples/python/naive_matcher.py'` compares two
independent readings of docs/language.md.

Not implemented (answered `unsupported`, which the harness counts and skips): macros
(`directDiffuse`, ...) and the OSL dialect. Limits (repeat counts <= 256) are not
enforced.

--plant-bug makes `{n,m}` (both bounds written, n < m) require more than n repetitions:
the off-by-one of a loop written `range(n + 1, m + 1)`. CI proves the harness finds it.

Protocol: docs/protocol.md (JSON Lines on stdin/stdout, one reply per request).
"""

import json
import sys

PREFIXES = {"unoccluded", "shadows", "holdouts", "nothruput", "noclamp", "overwrite",
            "noinfinitecheck"}
MAX_LOBE = {"D": 4, "S": 8, "U": 12}
TYPES = "CRTLO"
TRANSPORT = ("D", "S")
PLANT_BUG = "--plant-bug" in sys.argv[1:]


class LpeError(Exception):
    def __init__(self, message, position):
        super().__init__(message)
        self.message = message
        self.position = position


class Unsupported(Exception):
    pass


# --- vertices ---------------------------------------------------------------------
# A vertex is a tuple (type, kind, lobe, label): kind/lobe None on C, L, O; label None
# when the vertex has none.

def parse_path(text):
    vertices, i, n = [], 0, len(text)
    while i < n:
        if text[i].isspace():
            i += 1
            continue
        ty = text[i].upper()
        if ty not in TYPES:
            raise LpeError("not a vertex type", i)
        i += 1
        kind = lobe = label = None
        if ty in "RT":
            if i >= n or text[i].upper() not in MAX_LOBE:
                raise LpeError("R/T without an event", i)
            kind = text[i].upper()
            i += 1
            start = i
            while i < n and text[i].isdigit():
                i += 1
            lobe = int(text[start:i]) if i > start else 1
        if i < n and text[i] == "'":
            end = text.find("'", i + 1)
            if end < 0:
                raise LpeError("unterminated label", i)
            label = text[i + 1:end]
            i = end + 1
        vertices.append((ty, kind, lobe, label))
    return vertices


# --- expressions ------------------------------------------------------------------
# Predicates on one vertex, built from the atoms. `transport(v)`: what `.` matches.

def transport(v):
    return v[0] in "RT" and v[1] in TRANSPORT


class Parser:
    def __init__(self, src):
        self.src = src
        self.i = 0

    def peek(self):
        while self.i < len(self.src) and self.src[self.i].isspace():
            self.i += 1
        return self.src[self.i] if self.i < len(self.src) else ""

    def take(self, ch):
        if self.peek() != ch:
            raise LpeError("expected `%s`" % ch, self.i)
        self.i += 1

    def label(self):
        self.take("'")
        end = self.src.find("'", self.i)
        if end < 0:
            raise LpeError("unclosed label", self.i - 1)
        text = self.src[self.i:end]
        self.i = end + 1
        return text

    def number(self):
        self.peek()
        start = self.i
        while self.i < len(self.src) and self.src[self.i].isdigit():
            self.i += 1
        if start == self.i:
            raise LpeError("expected a number", start)
        return int(self.src[start:self.i])

    def event(self):
        """An event letter with an optional lobe: (kind, lobe or None)."""
        at = self.i
        kind = self.src[self.i].upper()
        self.i += 1
        start = self.i
        while self.i < len(self.src) and self.src[self.i].isdigit():
            self.i += 1
        if self.i == start:
            return kind, None
        lobe = int(self.src[start:self.i])
        if not 1 <= lobe <= MAX_LOBE[kind]:
            raise LpeError("lobe out of range", at)
        return kind, lobe

    # sequence := alt alt*
    def sequence(self, closing):
        parts = []
        while self.peek() not in ("", closing):
            parts.append(self.alt())
        if not parts:
            raise LpeError("nothing to match", self.i)
        return ("seq", parts)

    # alt := rep ('|' rep)*
    def alt(self):
        options = [self.rep()]
        while self.peek() == "|":
            self.i += 1
            if self.peek() in ("", ")", "|"):
                raise LpeError("`|` needs two sides", self.i)
            options.append(self.rep())
        return options[0] if len(options) == 1 else ("alt", options)

    def rep(self):
        unit = self.unit()
        c = self.peek()
        if c == "*":
            self.i += 1
            return ("rep", unit, 0, None, False)
        if c == "+":
            self.i += 1
            return ("rep", unit, 1, None, False)
        if c == "?":
            self.i += 1
            return ("rep", unit, 0, 1, False)
        if c == "{":
            at = self.i
            self.i += 1
            lo = self.number()
            hi, both = lo, False
            if self.peek() == ",":
                self.i += 1
                hi = None if self.peek() == "}" else self.number()
                both = hi is not None
            self.take("}")
            if hi is not None and hi < lo:
                raise LpeError("{n,m} with n > m", at)
            return ("rep", unit, lo, hi, both and lo < hi)
        return unit

    def unit(self):
        c = self.peek()
        at = self.i
        if c == "(":
            self.i += 1
            inner = self.sequence(")")
            self.take(")")
            return inner
        if c == "[":
            return ("atom", self.top_class())
        if c == "<":
            return ("atom", self.triple())
        if c in ("*", "+", "?", "{"):
            raise LpeError("quantifier with nothing before it", at)
        if c == "":
            raise LpeError("unexpected end", at)
        return ("atom", self.item())

    def item(self):
        """A letter, `.`, a label or a triple: one vertex predicate."""
        c = self.peek()
        at = self.i
        if c == "<":
            return self.triple()
        if c == ".":
            self.i += 1
            return transport
        if c == "'":
            name = self.label()
            return lambda v: transport(v) and v[3] == name
        up = c.upper()
        if up in TYPES:
            self.i += 1
            if up in "RT":
                return lambda v: v[0] == up and v[1] in TRANSPORT
            return lambda v: v[0] == up
        if up in MAX_LOBE:
            kind, lobe = self.event()
            return lambda v: (v[0] in "RT" and v[1] == kind
                              and (lobe is None or v[2] == lobe))
        raise LpeError("unexpected `%s`" % c, at)

    def top_class(self):
        self.take("[")
        negated = self.peek() == "^"
        if negated:
            self.i += 1
        items = []
        while self.peek() not in ("]", ""):
            items.append(self.item())
        if not items and not negated:
            raise LpeError("empty class", self.i)
        self.take("]")
        if negated:
            return lambda v: transport(v) and not any(p(v) for p in items)
        return lambda v: any(p(v) for p in items)

    def position(self, allowed, read):
        """One triple position: `.`, an item, or a class of items. Returns (kind,
        members): kind is "any", "in" or "not"."""
        c = self.peek()
        if c == ".":
            self.i += 1
            return ("any", [])
        if c == "[":
            self.i += 1
            negated = self.peek() == "^"
            if negated:
                self.i += 1
            members = []
            while self.peek() not in ("]", ""):
                members.append(read())
            self.take("]")
            return ("not" if negated else "in", members)
        return ("in", [read()])

    def triple(self):
        self.take("<")

        def type_letter():
            c = self.peek()
            if c.upper() not in TYPES:
                raise LpeError("not a type letter", self.i)
            self.i += 1
            return c.upper()

        def event_item():
            if self.peek().upper() not in MAX_LOBE:
                raise LpeError("not an event", self.i)
            return self.event()

        def label_item():
            if self.peek() != "'":
                raise LpeError("not a label", self.i)
            return self.label()

        ty = self.position(TYPES, type_letter)
        ev = ("any", [])
        lb = ("any", [])
        if self.peek() not in (">", ""):
            ev = self.position(None, event_item)
        if self.peek() not in (">", ""):
            lb = self.position(None, label_item)
        self.take(">")

        def type_ok(v):
            kind, members = ty
            if kind == "any":
                return v[0] in "RT"
            hit = v[0] in members
            return hit if kind == "in" else (v[0] in "RT" and not hit)

        def event_hit(v, e):
            return v[1] == e[0] and (e[1] is None or v[2] == e[1])

        def event_ok(v):
            kind, members = ev
            dot = v[1] in TRANSPORT if v[0] in "RT" else v[1] is None
            if kind == "any":
                return dot
            hit = v[1] is not None and any(event_hit(v, e) for e in members)
            return hit if kind == "in" else (dot and not hit)

        def label_ok(v):
            kind, members = lb
            if kind == "any":
                return True
            hit = v[3] is not None and v[3] in members
            return hit if kind == "in" else not hit

        return lambda v: type_ok(v) and event_ok(v) and label_ok(v)


def parse_lpe(src):
    """The syntax tree of one expression (prefixes dropped: they never change a match)."""
    body, offset = src, 0
    stripped = body.lstrip()
    if stripped[:4].lower() == "lpe:":
        offset = len(body) - len(stripped) + 4
        body = body[offset:]
    while ";" in body:
        name, rest = body.split(";", 1)
        if name.strip().lower() not in PREFIXES:
            raise LpeError("unknown prefix `%s`" % name.strip(), offset)
        offset += len(name) + 1
        body = rest
    if body.strip().replace("_", "").isalnum() and len(body.strip()) > 1 and any(
            ch.islower() for ch in body if ch not in "cdlorstu"):
        raise Unsupported("macros are not implemented")
    p = Parser(src)
    p.i = offset
    tree = p.sequence(")")
    if p.peek() != "":
        raise LpeError("unexpected `%s`" % p.peek(), p.i)
    return tree


# --- matching ---------------------------------------------------------------------

def nullable(node):
    tag = node[0]
    if tag == "atom":
        return False
    if tag == "seq":
        return all(nullable(n) for n in node[1])
    if tag == "alt":
        return any(nullable(n) for n in node[1])
    return node[2] == 0 or (node[3] != 0 and nullable(node[1]))


def ends(node, path, i):
    """Every index j such that `node` matches path[i:j]."""
    tag = node[0]
    if tag == "atom":
        return {i + 1} if i < len(path) and node[1](path[i]) else set()
    if tag == "seq":
        at = {i}
        for part in node[1]:
            at = {j for k in at for j in ends(part, path, k)}
        return at
    if tag == "alt":
        return {j for option in node[1] for j in ends(option, path, i)}
    _, body, lo, hi, counted = node
    if nullable(body):
        lo = 0  # empty iterations pad the count (docs/language.md §5.3)
    if PLANT_BUG and counted:
        lo += 1
    out = {i} if lo == 0 else set()
    frontier, seen, k = {i}, {i}, 0
    while frontier and (hi is None or k < hi):
        k += 1
        # Every iteration consumes at least one vertex.
        step = {j for p in frontier for j in ends(body, path, p) if j > p}
        if k >= lo:
            out |= step
        frontier = step if hi is not None or k < lo else step - seen
        seen |= step
    return out


def matches(tree, path):
    return len(path) in ends(tree, path, 0)


# --- protocol ---------------------------------------------------------------------

def main():
    aovs = []
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        rid, op = req.get("id"), req.get("op")
        reply = {"id": rid, "ok": True}
        if op == "hello":
            if req.get("dialect") != "renderman":
                reply = {"id": rid, "ok": False, "unsupported": "only the renderman dialect"}
            else:
                reply.update(protocol=1, name="naive-python" + (" (planted bug)" if PLANT_BUG else ""))
        elif op == "compile":
            aovs = []
            for k, aov in enumerate(req["aovs"]):
                try:
                    aovs.append((aov["name"], parse_lpe(aov["expr"])))
                except LpeError as e:
                    reply = {"id": rid, "ok": False,
                             "error": {"message": e.message, "aov": k, "position": e.position}}
                    aovs = []  # no set: later matches answer "no AOV"
                    break
                except Unsupported as e:
                    reply = {"id": rid, "ok": False, "unsupported": str(e)}
                    aovs = []
                    break
        elif op == "match":
            try:
                paths = [parse_path(p) for p in req["paths"]]
            except LpeError as e:
                reply = {"id": rid, "ok": False, "unsupported": "path: " + e.message}
            else:
                reply["matches"] = [[name for name, tree in aovs if matches(tree, path)]
                                    for path in paths]
        elif op == "quit":
            print(json.dumps(reply), flush=True)
            return
        else:
            reply = {"id": rid, "ok": False, "unsupported": "op %r" % op}
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
