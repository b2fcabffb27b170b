"""The Python API against values worked by hand from docs/language.md: canonical text,
syntax errors with their positions, matching (text and tuple paths, both dialects),
equivalence and partition witnesses, lint findings of a fixture, and the exceptions
bad arguments raise."""

import pathlib

import pytest

import lpe

ROOT = pathlib.Path(__file__).resolve().parents[2]
USD = ROOT / "tests" / "testdata" / "usd"


# --- parse ---------------------------------------------------------------------------


def test_macros_expand_to_the_table_of_docs_language_md():
    # docs/language.md §macros: indirectDiffuse is C<RD>.+[<L.>O]; a light-group
    # suffix puts the label on the light.
    assert lpe.parse("indirectDiffuse").text == "C<RD>.+[<L.>O]"
    assert str(lpe.parse("lpe:indirectDiffuse_key")) == "C<RD>.+[<L.'key'>O]"
    e = lpe.parse("directDiffuse")
    assert (e.text, e.source, e.dialect) == ("C<RD>[<L.>O]", "directDiffuse", "renderman")


def test_a_syntax_error_has_message_position_hint_and_a_caret():
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse("C<RD")
    e = info.value
    assert isinstance(e, ValueError)
    # The `<` at character 1 is never closed.
    assert e.position == 1
    assert "<" in e.message
    assert str(e).splitlines() == [f"{e.message} (at character 1)", "  C<RD", "   ^"]


def test_a_label_in_the_event_position_gets_a_hint():
    # `<L'rim'>`: the label belongs in the third position, `<L.'rim'>`.
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse("C.*<L'rim'>")
    assert info.value.hint is not None and "<L.'rim'>" in info.value.hint
    assert "hint:" in str(info.value)


def test_an_ini_file_adds_macros_and_a_bad_line_names_its_line(tmp_path):
    # docs/language.md: `/prman/lpe/macro/NAME EXPR` defines a macro.
    ini = tmp_path / "rendermn.ini"
    ini.write_text("/prman/lpe/macro/keyOnly C.*<L.'key'>\n")
    assert lpe.parse("keyOnly", ini=ini).text == "C.*<L.'key'>"
    assert lpe.AovSet({"k": "keyOnly"}, ini=str(ini)).match("C RD L'key'") == ["k"]
    bad = tmp_path / "bad.ini"
    bad.write_text("/prman/lpe/macro/\n")
    with pytest.raises(ValueError, match="bad.ini"):
        lpe.parse("C L", ini=bad)


def test_osl_dialect_and_its_registration():
    assert lpe.parse("C<RD>L", dialect="osl").dialect == "osl"
    # OSL errors point at the character.
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse("C<RD", dialect="osl")
    assert info.value.position == 4
    # §18.2: `R` matches `R,D,floor` (the eater skips `floor`), and `R,D,U` too, but
    # not once `U` is registered (a registered label is basic: not eaten).
    plain = lpe.AovSet({"r": "CRL"}, dialect="osl")
    assert plain.match("C,_ R,D,floor L,_") == ["r"]
    assert plain.match("C,_ R,D,U L,_") == ["r"]
    registered = lpe.AovSet({"r": "CRL"}, dialect="osl", register="events=U")
    assert registered.match("C,_ R,D,floor L,_") == ["r"]
    assert registered.match("C,_ R,D,U L,_") == []
    with pytest.raises(ValueError, match="register"):
        lpe.parse("C L", dialect="osl", register="nonsense")


# --- AovSet --------------------------------------------------------------------------


def aovs():
    return lpe.AovSet({"direct": "C<RD>L", "indirect": "C<RD>.+L", "any": "C.*L"})


def test_match_returns_the_aovs_in_set_order():
    s = aovs()
    assert s.names == ["direct", "indirect", "any"]
    assert len(s) == 3
    assert s.match("C RD L") == ["direct", "any"]
    assert s.match("C RD RS L") == ["indirect", "any"]
    assert s.match("C RS L") == ["any"]
    assert s.match("C RD O") == []


def test_paths_as_tuples():
    s = aovs()
    path = [("C", None, None), ("R", "D2", "floor"), ("T", "S8", None), ("L", None, "key")]
    assert s.match(path) == ["indirect", "any"]
    assert s.match([("C", None, None), ("L", None, None)]) == ["any"]


def test_match_many_equals_match_per_path():
    s = aovs()
    paths = ["C RD L", "C RS L", [("C", None, None), ("R", "D", None), ("T", "S", None), ("L", None, None)], "C O"]
    got = s.match_many(paths)
    assert got == [("direct", "any"), ("any",), ("indirect", "any"), ()]
    assert [list(t) for t in got] == [s.match(p) for p in paths]
    assert s.match_many([]) == []
    assert s.match_many(p for p in ["C L"]) == [("any",)]
    # Long lists are matched on every core, in order.
    many = ["C RD L", "C RS L", "C O"] * 5000
    assert s.match_many(many) == [("direct", "any"), ("any",), ()] * 5000


def test_explain_names_the_landing_aovs_and_the_closest_miss():
    s = aovs()
    e = s.explain("C RD RS L")
    assert e.landed == ["indirect", "any"]
    assert str(e).endswith("lands in: indirect, any\n")
    miss = lpe.AovSet({"spec": "C<RS>L", "diffuse2": "C<RD><RD>L"}).explain("C RD RS L")
    assert miss.landed == []
    assert "closest AOV: diffuse2 (dead at vertex 3)" in miss.text


def test_osl_aov_set():
    s = lpe.AovSet([("diffuse", "C<RD>L"), ("glossy", "C<RG>L")], dialect="osl")
    assert s.dialect == "osl"
    assert s.match("C,~ R,D L,~") == ["diffuse"]
    assert s.match([("C", None, None), ("R", "G", None), ("L", None, "key")]) == ["glossy"]


def test_osl_tuple_labels_with_spaces_and_commas_are_quoted():
    # §18.1: a label holding a space or comma is quoted in the text form; a tuple
    # carries it unquoted, so the tuple's label must reach the matcher whole.
    s = lpe.AovSet({"key": "C<R.'a b'>L", "comma": "C<R.'x,y'>L", "any": "C.*L"}, dialect="osl")
    assert s.match([("C", None, None), ("R", "D", "a b"), ("L", None, None)]) == ["key", "any"]
    assert s.match([("C", None, None), ("R", "D", "x,y"), ("L", None, None)]) == ["comma", "any"]
    assert s.match([("C", None, None), ("R", "D", "a"), ("L", None, None)]) == ["any"]


def test_reprs_name_the_type_and_its_counts():
    assert repr(lpe.parse("C<RD>L")) == '<lpe.Lpe "C<RD>L" (renderman)>'
    # OSL prints an item outside `<…>` as its vertex pattern (§18.3): C is <C.>.
    assert repr(lpe.parse("C<RD>L", dialect="osl")) == '<lpe.Lpe "<C.><RD><L.>" (osl)>'
    assert repr(aovs()) == "<lpe.AovSet 3 AOVs (renderman)>"
    assert repr(lpe.AovSet({"a": "CL"}, dialect="osl")) == "<lpe.AovSet 1 AOVs (osl)>"
    assert repr(aovs().explain("C RD L")) == '<lpe.Explanation landed=["direct", "any"]>'
    assert repr(aovs().explain("C O")) == "<lpe.Explanation landed=[]>"


def test_parsed_expressions_compare_and_hash_by_canonical_text_and_dialect():
    direct = lpe.parse("C<RD>L")
    # The same canonical text from another source is equal, and hashes alike.
    assert direct == lpe.parse("C<RD>L")
    macro = lpe.parse("indirectDiffuse")
    assert macro == lpe.parse("C<RD>.+[<L.>O]") and macro.source != "C<RD>.+[<L.>O]"
    assert hash(direct) == hash(lpe.parse("C<RD>L"))
    assert len({direct, lpe.parse("C<RD>L")}) == 1
    # Another text, another dialect, or no Lpe at all: unequal.
    assert direct != lpe.parse("C<RS>L")
    assert direct != lpe.parse("C<RD>L", dialect="osl")
    assert direct != "C<RD>L"
    assert not (direct == lpe.parse("C<RD>L", dialect="osl"))
    # Distinct expressions spread over distinct hashes (a constant hash would not).
    texts = ["C<RD>L", "C<RS>L", "C.*L", "CL", "C<TD>L"]
    assert len({hash(lpe.parse(t)) for t in texts}) == len(texts)
    assert len({lpe.parse(t) for t in texts + texts}) == len(texts)


# --- equiv, partition ----------------------------------------------------------------


def test_equiv():
    # `|` binds only its neighbours: CD|(SD)L is C(D|(SD))L (README).
    assert lpe.equiv("CD|(SD)L", "C(D|(SD))L") is None
    # C.*L also matches the path with no bounce.
    assert lpe.equiv("C.+L", "C.*L") == "C L"
    assert lpe.equiv("C<RD>L", "C<RS>L", dialect="osl") is not None


def test_equiv_returns_the_shorter_witness_and_the_first_expressions_on_a_tie():
    # C<RD>L and CL: `C RD L` only the first matches, `C L` only the second: the
    # shorter one is returned whichever side it is on.
    assert lpe.equiv("C<RD>L", "CL") == "C L"
    assert lpe.equiv("CL", "C<RD>L") == "C L"
    # A tie (three vertices each side): the first expression's path.
    a, b = "C<RD>L", "C<RS>L"
    w = lpe.equiv(a, b)
    assert lpe.AovSet({"a": a, "b": b}).match(w) == ["a"]
    w = lpe.equiv(b, a)
    assert lpe.AovSet({"a": a, "b": b}).match(w) == ["b"]


def test_partition_gap_with_its_remainder():
    p = lpe.partition({"any_light": "C.*L", "d2": "C<RD2>L"})
    # Both match C RD2 L; nothing matches a path ending on an emissive object.
    assert p.overlaps == [("any_light", "d2", "C RD2 L")]
    assert p.gaps == ["C O"]
    assert p.outside == []
    assert not p.clean and not p
    # The remainder closes the gap: it is the universe minus the members.
    assert p.remainder is not None
    closed = lpe.partition({"any_light": "C.*L", "rest": p.remainder})
    assert closed.clean and closed.overlaps == [] and closed.gaps == []


def test_partition_outside_a_given_universe():
    p = lpe.partition([("a", "C<RD>L"), ("b", "C<RS3>L")], universe="C<RD>L")
    assert p.outside == [("b", "C RS3 L")]
    assert p.gaps == [] and p.overlaps == []
    assert p.universe == "C<RD>L"


def test_partition_of_bare_expressions_names_them_by_their_text():
    p = lpe.partition(["C.*[<L.>O]"])
    assert p.clean and p.remainder is None


def test_a_partition_is_true_when_clean_and_prints_its_report():
    clean = lpe.partition(["C.*[<L.>O]"])
    assert bool(clean) is True
    assert repr(clean) == "<lpe.Partition clean=true overlaps=0 gaps=0 outside=0>"
    gap = lpe.partition({"any_light": "C.*L", "d2": "C<RD2>L"})
    assert bool(gap) is False
    assert repr(gap) == "<lpe.Partition clean=false overlaps=1 gaps=1 outside=0>"
    # str() is the report `lpe-check partition` prints, which names the gap's witness.
    assert str(gap) == gap.text and "C O" in str(gap)
    assert str(clean) == clean.text and clean.text != ""


# --- lint ----------------------------------------------------------------------------


def test_lint_a_fixture_file():
    # tests/testdata/usd/hdprman.usda: rimLight has a label in the event position,
    # lightBehindCamera can reach no emitter, diffuseAgain repeats directDiffuse,
    # wetness names lobe U9 that no rendermn.ini maps; the stage does not declare its
    # dialect, and the user lobes of albedo and wetness have no OSL view.
    report = lpe.lint(str(USD / "hdprman.usda"))
    got = sorted((f.kind, f.subject) for f in report.findings)
    assert got == [
        ("ambiguous_dialect", "albedo"),
        ("ambiguous_dialect", "wetness"),
        ("empty", "lightBehindCamera"),
        ("equivalent", "diffuseAgain"),
        ("parse_error", "rimLight"),
        ("unfed_lobe", "wetness"),
    ]
    f = next(f for f in report.findings if f.kind == "equivalent")
    assert f.other == "directDiffuse"
    assert f.location == {"line": None, "column": None, "prim": "/Render/vars/diffuseAgain", "attribute": "sourceName"}
    assert set(f.to_dict()) == set(lpe.FINDING_FIELDS)
    assert not report.clean


def test_lint_a_clean_fixture_and_a_declared_partition():
    assert lpe.lint(USD / "clean_basic.usda").clean
    report = lpe.lint([USD / "clean_basic.usda"], partitions=[["directDiffuse", "indirectDiffuse"]])
    gap = [f for f in report.findings if f.kind == "gap"]
    assert len(gap) == 1 and gap[0].subject == "--partition #1"


def test_lint_an_unreadable_file_is_in_the_report():
    report = lpe.lint("/nonexistent/stage.usda")
    assert report.files[0]["error"] and not report.clean


# --- renderer profiles ---------------------------------------------------------------
# The expected values come from docs/profiles.md and the profiles' pages: Arnold and
# Karma read OSL's dialect plus the albedo event `A`; Arnold's `diffuse_direct` is
# `C<RD>L`; Karma reads the prefix `unoccluded;` and no other; hdPrman reads RenderMan's
# dialect and prepends `lpe:` to a sourceName itself. OSL prints an item outside `<...>`
# as its vertex pattern (docs/language.md §18.3), so `C<RD>A` is `<C.><RD><A.>`.


def test_a_renderer_registers_its_letters_on_its_base_dialect():
    e = lpe.parse("C<RD>A", renderer="arnold")
    assert (e.text, e.source, e.dialect) == ("<C.><RD><A.>", "C<RD>A", "osl")
    # Plain OSL does not know `A`: the error is at the `A`, character 5.
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse("C<RD>A", dialect="osl")
    assert info.value.position == 5 and "A" in info.value.message
    # Naming the renderer's own base dialect as well is no contradiction.
    assert lpe.parse("C<RD>A", renderer="arnold", dialect="osl").text == "<C.><RD><A.>"
    # equiv and partition read the letters too: one member that is the universe.
    assert lpe.equiv("C<RD>A", "C<RD>A", renderer="karma") is None
    assert lpe.partition({"albedo": "C<RD>A"}, universe="C<RD>A", renderer="karma").clean
    # hdPrman reads RenderMan's dialect: its macros, printed in RenderMan's syntax.
    e = lpe.parse("directDiffuse", renderer="hdprman")
    assert (e.text, e.dialect) == ("C<RD>[<L.>O]", "renderman")


def test_a_renderers_builtin_name_reads_as_its_expression():
    named = lpe.parse("diffuse_direct", renderer="arnold")
    assert named.text == lpe.parse("C<RD>L", renderer="arnold").text == "<C.><RD><L.>"
    assert named.source == "diffuse_direct"
    assert named == lpe.parse("C<RD>L", renderer="arnold")
    assert lpe.equiv("diffuse_direct", "C<RD>L", renderer="arnold") is None
    # Without the renderer the name is no expression.
    with pytest.raises(lpe.LpeSyntaxError):
        lpe.parse("diffuse_direct", dialect="osl")


def test_a_prefix_the_renderer_does_not_read_is_an_error_naming_those_it_reads():
    assert lpe.parse("unoccluded;C<RD>L", renderer="karma").text == "unoccluded;<C.><RD><L.>"
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse("shadw;C<RD>L", renderer="karma")
    assert info.value.position == 0
    assert "`unoccluded;`" in info.value.message


def test_an_unknown_renderer_lists_the_known_ones_with_the_nearest():
    with pytest.raises(ValueError) as info:
        lpe.parse("C<RD>L", renderer="karm")
    message = str(info.value)
    assert not isinstance(info.value, lpe.LpeSyntaxError)
    assert "unknown renderer `karm`" in message
    assert "(did you mean `karma`?)" in message
    assert "renderman, osl, karma, arnold, hdprman, vray, moonray" in message
    # A name two edits or more from every shipped one gets no suggestion.
    with pytest.raises(ValueError) as info:
        lpe.AovSet({"a": "CL"}, renderer="cycles")
    assert "did you mean" not in str(info.value)
    for call in (
        lambda: lpe.equiv("CL", "CL", renderer="karm"),
        lambda: lpe.partition(["CL"], renderer="karm"),
        lambda: lpe.lint(USD / "solaris_karma.usda", renderer="karm"),
    ):
        with pytest.raises(ValueError, match="did you mean `karma`"):
            call()


def test_a_dialect_other_than_the_renderers_base_is_an_error():
    with pytest.raises(ValueError, match='dialect="renderman" contradicts renderer "arnold"'):
        lpe.parse("C<RD>L", renderer="arnold", dialect="renderman")
    with pytest.raises(ValueError, match='dialect="osl" contradicts renderer "hdprman"'):
        lpe.AovSet({"d": "C<RD>L"}, renderer="hdprman", dialect="osl")
    with pytest.raises(ValueError, match="contradicts"):
        lpe.equiv("CL", "CL", renderer="karma", dialect="renderman")
    with pytest.raises(ValueError, match="contradicts"):
        lpe.partition(["CL"], renderer="karma", dialect="renderman")
    with pytest.raises(ValueError, match="contradicts"):
        lpe.lint(USD / "solaris_karma.usda", renderer="karma", dialect="renderman")
    with pytest.raises(ValueError, match="give one of them"):
        lpe.parse("CL", renderer="karma", profile=ROOT / "profile" / "data" / "karma.toml")


def test_a_renderers_aov_set_reads_its_letters():
    s = lpe.AovSet({"albedo": "C<RD>A", "direct": "C<RD>L"}, renderer="karma")
    assert s.dialect == "osl"
    assert repr(s) == "<lpe.AovSet 2 AOVs (osl)>"
    assert s.match("C,~ R,D A,~") == ["albedo"]
    assert s.match([("C", None, None), ("R", "D", None), ("A", None, None)]) == ["albedo"]
    assert s.match("C,~ R,D L,~") == ["direct"]
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.AovSet({"albedo": "C<RD>A"}, dialect="osl")
    assert info.value.aov == "albedo"


def test_a_profile_file_describes_an_in_house_renderer(tmp_path):
    # An OSL-based renderer adding the event `U` and the prefix `direct;`.
    toml = tmp_path / "ourray.toml"
    toml.write_text(
        'name = "ourray"\n'
        'title = "Our ray tracer"\n'
        'base = "osl"\n'
        "[[sources]]\n"
        'id = "manual"\n'
        'title = "Our manual"\n'
        'where = "https://example.com/ourray/lpe"\n'
        "[[events]]\n"
        'letter = "U"\n'
        'meaning = "a user event"\n'
        'source = "manual"\n'
        "[[prefixes]]\n"
        'name = "direct"\n'
        'meaning = "direct light only"\n'
        'source = "manual"\n'
    )
    e = lpe.parse("C<RD>U", profile=toml)
    assert (e.text, e.dialect) == ("<C.><RD><U.>", "osl")
    assert lpe.parse("direct;C<RD>L", profile=str(toml)).text == "direct;<C.><RD><L.>"
    assert lpe.AovSet({"u": "C.*U"}, profile=toml).match("C,~ R,D U,~") == ["u"]
    # A file that does not load names itself.
    with pytest.raises(ValueError, match="nowhere.toml"):
        lpe.parse("CL", profile=tmp_path / "nowhere.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\ntitle = "Bad"\nbase = "osl"\ncolour = "red"\n')
    with pytest.raises(ValueError, match="bad.toml"):
        lpe.parse("CL", profile=bad)


def test_lint_under_karma_flags_the_specular_aov_it_never_renders():
    # solaris_karma.usda: specular_key is C<RS>.*<L.'key'>, and Karma labels every
    # specular scatter G, so no path it matches is ever produced; diffuse_fill names
    # the light group 'fil' where the lights carry 'key' and 'fill'. Naming the
    # renderer names the dialect: no ambiguous_dialect.
    report = lpe.lint(USD / "solaris_karma.usda", renderer="karma")
    assert sorted((f.kind, f.subject) for f in report.findings) == [
        ("never_produced", "specular_key"),
        ("unknown_light_group", "diffuse_fill"),
    ]
    f = next(f for f in report.findings if f.kind == "never_produced")
    assert f.location["prim"] == "/Render/Products/Vars/specular_key"
    assert "`<.[Ss]>`" in f.message
    # The shipped file given as profile= is the same renderer.
    by_file = lpe.lint(USD / "solaris_karma.usda", profile=ROOT / "profile" / "data" / "karma.toml")
    assert [f.to_dict() for f in by_file.findings] == [f.to_dict() for f in report.findings]
    # Without the renderer the same AOV is only ambiguous between the dialects.
    plain = lpe.lint(USD / "solaris_karma.usda")
    assert sorted((f.kind, f.subject) for f in plain.findings) == [
        ("ambiguous_dialect", "specular_key"),
        ("unknown_light_group", "diffuse_fill"),
    ]


def test_lint_under_hdprman_flags_every_lpe_mark_it_would_double():
    # hdprman.usda writes all seven of its LPE sourceNames with `lpe:`; the eighth
    # RenderVar (P) is not an LPE.
    report = lpe.lint(str(USD / "hdprman.usda"), renderer="hdprman")
    doubled = [f for f in report.findings if f.kind == "doubled_lpe_mark"]
    assert sorted(f.subject for f in doubled) == [
        "albedo", "diffuseAgain", "directDiffuse", "indirectDiffuse",
        "lightBehindCamera", "rimLight", "wetness",
    ]
    d = next(f for f in doubled if f.subject == "directDiffuse")
    assert (d.source, d.span) == ("lpe:C<RD>[<L.>O]", [0, 4])
    assert d.help == "write the sourceName without its mark: `C<RD>[<L.>O]`"
    assert "`lpe:lpe:C<RD>[<L.>O]`" in d.message
    assert not any(f.kind == "ambiguous_dialect" for f in report.findings)
    # Under no renderer the mark is RenderMan's own, not doubled.
    assert not any(f.kind == "doubled_lpe_mark" for f in lpe.lint(USD / "hdprman.usda"))


# --- bad arguments -------------------------------------------------------------------


def test_bad_arguments_raise_type_and_value_errors():
    with pytest.raises(TypeError):
        lpe.parse(42)
    with pytest.raises(ValueError, match="unknown dialect `prman`"):
        lpe.parse("C L", dialect="prman")
    with pytest.raises(ValueError, match="register"):
        lpe.parse("C L", register="events=U")
    with pytest.raises(ValueError, match="ini"):
        lpe.parse("C L", dialect="osl", ini="rendermn.ini")
    with pytest.raises(ValueError, match="/nonexistent/rendermn.ini"):
        lpe.parse("C L", ini="/nonexistent/rendermn.ini")
    with pytest.raises(TypeError):
        lpe.AovSet("C L")
    with pytest.raises(TypeError):
        lpe.AovSet({"a": 1})
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.AovSet({"good": "C L", "bad": "C<RD"})
    assert info.value.aov == "bad" and info.value.position == 1
    s = aovs()
    with pytest.raises(ValueError, match="path `C XD L`"):
        s.match("C XD L")
    with pytest.raises(TypeError):
        s.match(42)
    with pytest.raises(TypeError):
        s.match([("C",)])
    with pytest.raises(ValueError, match=r"paths\[1\]"):
        s.match_many(["C L", "C Q L"])
    with pytest.raises(TypeError):
        s.match_many(7)
    with pytest.raises(lpe.LpeSyntaxError):
        lpe.equiv("C L", "C<")
    with pytest.raises(TypeError):
        lpe.partition("C L")
    with pytest.raises(ValueError):
        lpe.partition([])
    with pytest.raises(TypeError):
        lpe.lint(42)
    with pytest.raises(TypeError):
        lpe.lint(["a.usda", 3])
    with pytest.raises(ValueError, match="universe"):
        lpe.lint(USD / "clean_basic.usda", universe="C<")


def test_no_input_panics():
    # Arbitrary text is an answer or an exception, never a Rust panic.
    samples = ["", "(", ")", "<<<", "C{999999}L", "C" + "(" * 300 + "L", "\x00", "é<R'",
               "C.*L - ^C.*L", "C[^]L", "<.'" + "x" * 1000]
    for dialect in lpe.DIALECTS:
        for s in samples:
            try:
                lpe.parse(s, dialect=dialect)
            except ValueError:
                pass
            try:
                lpe.AovSet({"a": "C.*L"}, dialect=dialect).match(s)
            except ValueError:
                pass


# Text that is not ASCII: positions count characters, as Python indexes a str, never
# bytes. Each position is counted by hand; `é` and `Ä` are two bytes in UTF-8, so a byte
# offset would be one more. Planted fault, checked by hand: returning the byte offset
# (`python/src/error.rs`) fails all three.
@pytest.mark.parametrize(
    "expr, kwargs, char",
    [
        # RenderMan blames the unclosed `<`: byte 8, character 7.
        ("C'café'<RD", {}, 7),
        # OSL blames the end of the text: 11 bytes, 10 characters.
        ("C'café'<RD", {"dialect": "osl"}, 10),
        # Under Karma, `Ä` is no letter: byte 9, character 8.
        ("C'é'<RD>Ä", {"renderer": "karma"}, 8),
    ],
)
def test_positions_in_text_that_is_not_ascii_count_characters(expr, kwargs, char):
    with pytest.raises(lpe.LpeSyntaxError) as info:
        lpe.parse(expr, **kwargs)
    assert info.value.position == char


def test_labels_that_are_not_ascii_match_exactly_in_both_dialects():
    rm = lpe.AovSet({"k": "C<RD'café'>L"})
    assert rm.match("C RD'café' L") == ["k"]
    assert rm.match("C RD'cafe' L") == []
    osl = lpe.AovSet({"k": "C<RD'café'>L"}, dialect="osl")
    assert osl.match("C,~ R,D,café L,~") == ["k"]
    assert osl.match("C,~ R,D,cafe L,~") == []
