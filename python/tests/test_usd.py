"""The package with Pixar's USD (usd-core): `lpe.lint` on a composed `Usd.Stage`
(session layer, variants), and the UsdValidation plugin: found by the registry through
PXR_PLUGINPATH_NAME (conftest.py), flags a bad RenderVar in a stage built here, and on
every fixture of tests/testdata/usd reports exactly what `lpe-check lint --format json`
reports (LPE_CHECK names the binary; default target/release/lpe-check), with no option,
a dialect or a renderer's profile; and the plugin's options (`configure()`, the
environment) followed on the same stage."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

if os.environ.get("LPE_CHECK"):
    import pxr  # noqa: F401  (CI sets LPE_CHECK: nothing here may be skipped)
else:
    pxr = pytest.importorskip("pxr")
from pxr import Sdf, Usd, UsdValidation  # noqa: E402

import lpe  # noqa: E402
import lpe.usd_validation as uv  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = sorted((ROOT / "tests" / "testdata" / "usd").glob("*.usda"))
LPE_CHECK = os.environ.get("LPE_CHECK", str(ROOT / "target" / "release" / "lpe-check"))

NAMES = [
    "lpe:Syntax",
    "lpe:NeverMatching",
    "lpe:EquivalentAovs",
    "lpe:UnknownLightGroup",
    "lpe:UnknownObjectGroup",
    "lpe:UnfedLobe",
    "lpe:AmbiguousDialect",
    "lpe:NeverProduced",
    "lpe:DoubledLpeMark",
    "lpe:PartitionOverlap",
    "lpe:PartitionGap",
    "lpe:PartitionOutside",
    "lpe:PartitionMember",
    "lpe:Readable",
]


@pytest.fixture(autouse=True)
def default_options():
    uv.configure()
    yield
    uv.configure()


def dialect_of(fixture):
    # The OSL fixtures say so in their doc ("lint with --dialect osl"); the others are
    # linted with no dialect named, so that undeclared stages are read both ways.
    return "osl" if "osl" in fixture.name else None


def render_var(stage, path, source):
    prim = stage.DefinePrim(path, "RenderVar")
    prim.CreateAttribute("sourceType", Sdf.ValueTypeNames.Token).Set("lpe")
    prim.CreateAttribute("sourceName", Sdf.ValueTypeNames.String).Set(source)
    return prim


def test_the_registry_finds_every_validator_by_keyword():
    registry = UsdValidation.ValidationRegistry()
    found = sorted(m.name for m in registry.GetValidatorMetadataForKeyword("lpe"))
    assert found == sorted(NAMES)
    for name in NAMES:
        assert registry.GetOrLoadValidatorByName(name) is not None
    syntax = registry.GetValidatorMetadata("lpe:Syntax")
    assert list(syntax.GetSchemaTypes()) == ["UsdRenderVar"]


def run_python(code, plugin):
    env = dict(os.environ)
    env.pop("PXR_PLUGINPATH_NAME", None)
    if plugin:
        env["PXR_PLUGINPATH_NAME"] = lpe.plugin_path()
    return subprocess.run([sys.executable, "-c", code],
                          capture_output=True, text=True, env=env, check=False)


def test_without_the_plugin_path_validate_says_what_to_set():
    run = run_python(
        "import lpe.usd_validation as v\n"
        "from pxr import Usd\n"
        "try:\n    v.validate(Usd.Stage.CreateInMemory())\n"
        "except RuntimeError as e:\n    print(e)\n",
        plugin=False,
    )
    assert run.returncode == 0, run.stderr
    assert "PXR_PLUGINPATH_NAME" in run.stdout and lpe.plugin_path() in run.stdout


def test_usd_loads_the_plugin_whichever_is_imported_first():
    check = (
        "from pxr import UsdValidation\n"
        "r = UsdValidation.ValidationRegistry()\n"
        "print(r.GetOrLoadValidatorByName('lpe:Syntax') is not None)\n"
    )
    # pxr first: USD imports the package when it loads the validator.
    run = run_python(check, plugin=True)
    assert run.stdout.split() == ["True"], run.stderr
    # lpe first: the package registers right after pxr.UsdValidation is imported.
    run = run_python("import lpe\n" + check, plugin=True)
    assert run.stdout.split() == ["True"], run.stderr
    run = run_python("import lpe\nimport lpe.usd_validation\n" + check, plugin=True)
    assert run.stdout.split() == ["True"], run.stderr
    # Without the plugin path, importing pxr after lpe still works (nothing registered).
    run = run_python("import lpe\n" + check, plugin=False)
    assert run.returncode == 0 and run.stdout.split() == ["False"], run.stderr


def test_a_bad_render_var_in_a_built_stage_is_flagged_at_its_attribute():
    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/Render", "Scope")
    render_var(stage, "/Render/good", "C<RD>[<L.>O]")
    render_var(stage, "/Render/bad", "C<RD")
    errors = UsdValidation.ValidationContext(keywords=["lpe"]).Validate(stage)
    assert len(errors) == 1
    e = errors[0]
    assert e.GetValidator().GetMetadata().name == "lpe:Syntax"
    assert e.GetType() == UsdValidation.ValidationErrorType.Error
    sites = [str(s.GetPrim().GetPath()) if s.GetPrim() else str(s.GetProperty().GetPath())
             for s in e.GetSites()]
    assert sites == ["/Render/bad", "/Render/bad.sourceName"]
    assert e.GetMessage().startswith("parse_error: `bad`: unclosed `<`")


def test_witnesses_are_in_the_messages():
    stage = Usd.Stage.CreateInMemory()
    render_var(stage, "/Render/a", "C<RD>L")
    render_var(stage, "/Render/b", "C<RD>L")
    settings = stage.DefinePrim("/Render/settings", "RenderSettings")
    settings.CreateAttribute("lpe:partition", Sdf.ValueTypeNames.String).Set("a,b")
    errors = uv.validate(stage)
    by_name = {e.GetValidator().GetMetadata().name: e.GetMessage() for e in errors}
    assert set(by_name) == {"lpe:EquivalentAovs", "lpe:PartitionOverlap", "lpe:PartitionGap"}
    assert "witness: C RD1 L" in by_name["lpe:PartitionOverlap"]
    # The shortest universe path neither matches: no bounce at all.
    assert "witness: C L" in by_name["lpe:PartitionGap"]


def test_lint_reads_the_composed_stage_session_layer_and_variants():
    fixture = ROOT / "tests" / "testdata" / "usd" / "clean_basic.usda"
    stage = Usd.Stage.Open(str(fixture))
    assert lpe.lint(stage).clean
    # An opinion in the session layer is what the user sees; the file is unchanged.
    var = next(p for p in stage.Traverse() if p.GetTypeName() == "RenderVar")
    with Usd.EditContext(stage, stage.GetSessionLayer()):
        var.GetAttribute("sourceName").Set("C<RD")
    report = lpe.lint(stage)
    assert [(f.kind, f.subject) for f in report.findings][:1] == [("parse_error", var.GetName())]
    assert report.findings[0].file == str(fixture)
    assert lpe.lint(fixture).clean
    # The validators see the change, and see it go away.
    assert any(e.GetValidator().GetMetadata().name == "lpe:Syntax" for e in uv.validate(stage))
    stage.GetSessionLayer().Clear()
    assert not uv.validate(stage)

    # A variant selection decides which RenderVar exists.
    stage = Usd.Stage.CreateInMemory()
    prim = stage.DefinePrim("/Render")
    vset = prim.GetVariantSets().AddVariantSet("look")
    for name, source in [("ok", "C<RD>[<L.>O]"), ("broken", "C<RD")]:
        vset.AddVariant(name)
        vset.SetVariantSelection(name)
        with vset.GetVariantEditContext():
            render_var(stage, "/Render/var", source)
    vset.SetVariantSelection("ok")
    assert lpe.lint(stage).clean
    vset.SetVariantSelection("broken")
    assert [f.kind for f in lpe.lint(stage).findings] == ["parse_error"]


def lpe_check_json(fixture, dialect=None, renderer=None):
    if not os.path.exists(LPE_CHECK):
        if os.environ.get("LPE_CHECK"):
            pytest.fail(f"LPE_CHECK={LPE_CHECK} does not exist")
        pytest.skip(f"no lpe-check at {LPE_CHECK} (set LPE_CHECK)")
    named = ["--dialect", dialect] if dialect else []
    named += ["--renderer", renderer] if renderer else []
    run = subprocess.run(
        [LPE_CHECK, "lint", "--format", "json", *named, str(fixture)],
        capture_output=True, text=True, check=False,
    )
    assert run.returncode in (0, 1), run.stderr
    return json.loads(run.stdout)


def assert_equal_to_lpe_check(fixture, dialect=None, renderer=None):
    want = lpe_check_json(fixture, dialect, renderer)
    stage = Usd.Stage.Open(str(fixture))

    # lpe.lint on the stage: the same findings, field for field.
    got = lpe.lint(stage, dialect=dialect, renderer=renderer)
    assert [f.to_dict() for f in got.findings] == want["findings"]
    assert [(a["name"], a["source"], a["location"]) for a in got.aovs] == [
        (a["name"], a["source"], a["location"]) for a in want["aovs"]
    ]

    # The validators with keyword `lpe`: one error per finding, at its prim and
    # attribute, its message the finding's with the witness.
    uv.configure(dialect=dialect, renderer=renderer)
    errors = UsdValidation.ValidationContext(keywords=["lpe"]).Validate(stage)
    kinds = {n: k for n, k in {**uv.AOV_VALIDATORS, **uv.STAGE_VALIDATORS}.items()}
    seen = []
    for e in errors:
        name = e.GetValidator().GetMetadata().name
        assert name.startswith("lpe:")
        assert e.GetName() in kinds[name.removeprefix("lpe:")]
        prim, attr = e.GetSites()
        seen.append((e.GetName(), str(prim.GetPrim().GetPath()),
                     prim.GetPrim().GetPath().AppendProperty(attr.GetProperty().GetName()).name,
                     e.GetMessage()))
    expected = []
    for f in want["findings"]:
        loc = f["location"]
        msg = uv.message(lpe.Finding(f))
        if f["witness"]:
            assert f"witness: {f['witness']}" in msg
        expected.append((f["kind"], loc["prim"], loc["attribute"], msg))
    assert sorted(seen) == sorted(expected)
    return want


@pytest.mark.parametrize("fixture", FIXTURES, ids=[f.name for f in FIXTURES])
def test_validation_and_lint_equal_lpe_check_lint_json(fixture):
    assert_equal_to_lpe_check(fixture, dialect=dialect_of(fixture))


# The fixtures written for one renderer, linted under its profile.
RENDERER_FIXTURES = [("solaris_karma.usda", "karma"), ("hdprman.usda", "hdprman")]


@pytest.mark.parametrize("name,renderer", RENDERER_FIXTURES, ids=[r for _, r in RENDERER_FIXTURES])
def test_under_a_renderer_validation_and_lint_equal_lpe_check_lint_json(name, renderer):
    fixture = ROOT / "tests" / "testdata" / "usd" / name
    want = assert_equal_to_lpe_check(fixture, renderer=renderer)
    # The renderer's own checks are among the findings compared (worked by hand in
    # test_api.py), and no ambiguous_dialect: the renderer names the dialect.
    kinds = [f["kind"] for f in want["findings"]]
    new = {"karma": "never_produced", "hdprman": "doubled_lpe_mark"}[renderer]
    assert kinds.count(new) == {"karma": 1, "hdprman": 7}[renderer]
    assert "ambiguous_dialect" not in kinds
    # lpe.lint of the file, as lpe-check is given it: the whole JSON document.
    assert lpe.lint(str(fixture), renderer=renderer).json == want


def errors_by_validator(stage):
    return sorted((e.GetValidator().GetMetadata().name, str(e.GetSites()[0].GetPrim().GetPath()))
                  for e in uv.validate(stage))


def test_the_validators_follow_the_renderer_option_on_the_same_stage(monkeypatch):
    # solaris_karma.usda: diffuse_fill names the unknown group 'fil' whatever the
    # options; specular_key (C<RS>.*<L.'key'>) is never produced by Karma, and without
    # a renderer it is only ambiguous between RenderMan's and OSL's readings (the stage
    # declares no dialect).
    monkeypatch.delenv("LPE_RENDERER", raising=False)
    monkeypatch.delenv("LPE_DIALECT", raising=False)
    stage = Usd.Stage.Open(str(ROOT / "tests" / "testdata" / "usd" / "solaris_karma.usda"))
    vars_ = "/Render/Products/Vars"
    under_karma = [
        ("lpe:NeverProduced", f"{vars_}/specular_key"),
        ("lpe:UnknownLightGroup", f"{vars_}/diffuse_fill"),
    ]
    plain = [
        ("lpe:AmbiguousDialect", f"{vars_}/specular_key"),
        ("lpe:UnknownLightGroup", f"{vars_}/diffuse_fill"),
    ]
    uv.configure(renderer="karma")
    assert uv.options()["renderer"] == "karma"
    assert errors_by_validator(stage) == under_karma
    # configure() goes back to the environment, which names no renderer.
    uv.configure()
    assert uv.options()["renderer"] is None
    assert errors_by_validator(stage) == plain
    # The environment names one: the same stage is linted again under it.
    monkeypatch.setenv("LPE_RENDERER", "karma")
    assert errors_by_validator(stage) == under_karma
    monkeypatch.setenv("LPE_RENDERER", "hdprman")
    # hdPrman reads RenderMan's dialect; Karma's bare sourceNames carry no `lpe:` mark
    # to double, and its `S` is RenderMan's, which hdPrman does produce.
    assert errors_by_validator(stage) == [("lpe:UnknownLightGroup", f"{vars_}/diffuse_fill")]
    # An unknown renderer in the environment is reported by lpe:Readable, not raised
    # out of USD's validation.
    monkeypatch.setenv("LPE_RENDERER", "karm")
    errors = uv.validate(stage)
    assert [e.GetValidator().GetMetadata().name for e in errors] == ["lpe:Readable"]
    assert "did you mean `karma`" in errors[0].GetMessage()


def test_the_doubled_mark_validator_under_hdprman():
    stage = Usd.Stage.Open(str(ROOT / "tests" / "testdata" / "usd" / "hdprman.usda"))
    uv.configure(renderer="hdprman")
    doubled = [e for e in uv.validate(stage)
               if e.GetValidator().GetMetadata().name == "lpe:DoubledLpeMark"]
    assert sorted(str(e.GetSites()[0].GetPrim().GetPath()).rsplit("/", 1)[1] for e in doubled) == [
        "albedo", "diffuseAgain", "directDiffuse", "indirectDiffuse",
        "lightBehindCamera", "rimLight", "wetness",
    ]
    e = next(e for e in doubled if e.GetSites()[0].GetPrim().GetName() == "directDiffuse")
    assert e.GetName() == "doubled_lpe_mark"
    assert e.GetMessage().startswith("doubled_lpe_mark: `directDiffuse`: ")
    assert e.GetMessage().endswith("; help: write the sourceName without its mark: `C<RD>[<L.>O]`")


def test_lint_of_a_stage_collects_only_what_lint_reads():
    # A mesh with points and a group, a typeless Xform with an lpe: attribute, a plain
    # Xform, a RenderProduct and a RenderVar: the facts handed to the Rust reader, by hand.
    stage = Usd.Stage.CreateInMemory()
    mesh = stage.DefinePrim("/World/floor", "Mesh")
    mesh.CreateAttribute("points", Sdf.ValueTypeNames.Point3fArray).Set([(0, 0, 0)] * 4)
    mesh.CreateAttribute("primvars:karma:object:lpetag", Sdf.ValueTypeNames.String).Set("floor")
    tagged = stage.DefinePrim("/World/tagged")
    tagged.CreateAttribute("lpe:partition:groups", Sdf.ValueTypeNames.String).Set("a")
    tagged.CreateAttribute("lpe:note", Sdf.ValueTypeNames.Int).Set(3)
    product = stage.DefinePrim("/Render/product", "RenderProduct")
    product.CreateRelationship("orderedVars").SetTargets(["/Render/a"])
    render_var(stage, "/Render/a", "C<RD>L")
    inactive = render_var(stage, "/Render/off", "C<RD")
    inactive.SetActive(False)
    prims, types = lpe._stage_facts(stage).facts()
    assert prims == [
        ("/World/tagged", "", ["lpe:note", "lpe:partition:groups"],
         [("lpe:note", None), ("lpe:partition:groups", "a")], []),
        ("/Render/product", "RenderProduct", ["orderedVars"], [], ["a"]),
        ("/Render/a", "RenderVar", ["sourceName", "sourceType"],
         [("sourceName", "C<RD>L"), ("sourceType", "lpe")], []),
        # Of the mesh only its group is read: no path, type or property names.
        ("", "", [], [("primvars:karma:object:lpetag", "floor")], []),
    ]
    assert types == ["", "Mesh", "RenderProduct", "RenderVar"]


def test_a_stage_changed_after_validation_is_read_again():
    stage = Usd.Stage.CreateInMemory()
    render_var(stage, "/Render/a", "C<RD><L.'key'>")
    light = stage.DefinePrim("/World/light", "RectLight")
    group = light.CreateAttribute("inputs:karma:light:lpetag", Sdf.ValueTypeNames.String)
    group.Set("fill")
    assert errors_by_validator(stage) == [("lpe:UnknownLightGroup", "/Render/a")]
    # The group is renamed in the root layer: the next validation reads it.
    group.Set("key")
    assert errors_by_validator(stage) == []
    group.Set("rim")
    assert errors_by_validator(stage) == [("lpe:UnknownLightGroup", "/Render/a")]


# --- what lpe.lint(stage) reads: each kind of fact on a stage built here -----------------
# The findings are worked by hand from the stage: the groups each message lists are the
# values of the group attributes written here.


def attribute(prim, name, value, type_name=Sdf.ValueTypeNames.String):
    prim.CreateAttribute(name, type_name).Set(value)
    return prim


def kinds_and_messages(report):
    return [(f.kind, f.subject, f.location["prim"], f.location["attribute"], f.message)
            for f in report.findings]


def test_every_group_attribute_of_lights_and_objects_is_read():
    # Each light group attribute on a light of its own type, the object group attributes
    # on meshes (two meshes carry the same attribute with different groups, one of them
    # twice); one RenderVar per group and one naming a group nobody carries.
    # Planted faults, seen failing: the values-only reading skipping
    # `primvars:arnold:aov` (`fill` unknown, missing from the list); keeping one text per
    # attribute (`door` or `wall` lost).
    stage = Usd.Stage.CreateInMemory()
    attribute(stage.DefinePrim("/World/key", "RectLight"), "inputs:karma:light:lpetag", "key")
    attribute(stage.DefinePrim("/World/fill", "SphereLight"), "primvars:arnold:aov", "fill")
    attribute(stage.DefinePrim("/World/rim", "DiskLight"), "ri:light:lightGroup", "rim")
    attribute(stage.DefinePrim("/World/top", "DistantLight"), "inputs:ri:light:lightGroup", "top")
    attribute(stage.DefinePrim("/World/floor", "Mesh"), "primvars:karma:object:lpetag", "floor")
    wall = "primvars:ri:attributes:identifier:lpegroup"
    attribute(stage.DefinePrim("/World/wall", "Mesh"), wall, "wall")
    attribute(stage.DefinePrim("/World/door", "Mesh"), wall, "door")
    attribute(stage.DefinePrim("/World/door2", "Mesh"), wall, "door")
    for g in ["key", "fill", "rim", "top", "sky"]:
        render_var(stage, f"/Render/light_{g}", f"C<RD>.*<L.'{g}'>")
    for g in ["floor", "wall", "door", "roof"]:
        render_var(stage, f"/Render/object_{g}", f"C<RD'{g}'>.*L")
    assert kinds_and_messages(lpe.lint(stage, dialect="renderman")) == [
        ("unknown_light_group", "light_sky", "/Render/light_sky", "sourceName",
         "no light in this stage carries group 'sky' (they carry 'fill', 'key', 'rim', 'top')"),
        ("unknown_object_group", "object_roof", "/Render/object_roof", "sourceName",
         "no object in this stage carries group 'roof' (they carry 'door', 'floor', 'wall')"),
    ]


@pytest.mark.parametrize("light", ["CylinderLight", "PxrRectLight"])
def test_a_light_type_without_groups_makes_light_groups_checkable(light):
    # Any type named ...Light counts, a schema pxr does not know too (hdPrman's lights
    # without its plugin). Without one, a light group cannot be checked. Planted fault,
    # seen failing: type names recorded only of the prims lint reads (no finding).
    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/World/lamp", light)
    render_var(stage, "/Render/k", "C<RD>.*<L.'key'>")
    assert kinds_and_messages(lpe.lint(stage, dialect="renderman")) == [
        ("unknown_light_group", "k", "/Render/k", "sourceName",
         "no light in this stage carries group 'key' (none carries a group)"),
    ]
    stage.RemovePrim("/World/lamp")
    stage.DefinePrim("/World/lamp", "Xform")
    assert lpe.lint(stage, dialect="renderman").clean


def test_a_geometry_type_without_groups_makes_object_groups_checkable():
    # Planted fault, seen failing: type names recorded only of the prims lint reads.
    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/World/box", "Cube")
    render_var(stage, "/Render/o", "C<RD'floor'>.*L")
    assert kinds_and_messages(lpe.lint(stage, dialect="renderman")) == [
        ("unknown_object_group", "o", "/Render/o", "sourceName",
         "no object in this stage carries group 'floor' (none carries a group)"),
    ]


def test_lpe_attributes_on_a_typeless_prim_declare_at_its_path():
    # A partition and the dialect declared on a plain prim, not the RenderSettings: the
    # partition's findings stand at that prim and attribute. `a` and `b` are the same
    # expression: equivalent, overlapping on every path they match (shortest: C RD1 L)
    # and leaving a gap (shortest universe path neither matches: C L). Planted fault,
    # seen failing: the prims' paths given as their names (`notes`).
    stage = Usd.Stage.CreateInMemory()
    render_var(stage, "/Render/a", "C<RD>L")
    render_var(stage, "/Render/b", "C<RD>L")
    notes = attribute(stage.DefinePrim("/World/notes"), "lpe:partition:pair", "a,b")
    attribute(notes, "lpe:dialect", "renderman")
    report = lpe.lint(stage)
    got = [(f.kind, f.subject, f.location["prim"], f.location["attribute"], f.witness)
           for f in report.findings]
    assert got == [
        ("equivalent", "b", "/Render/b", "sourceName", None),
        ("overlap", "pair", "/World/notes", "lpe:partition:pair", "C RD1 L"),
        ("gap", "pair", "/World/notes", "lpe:partition:pair", "C L"),
    ]
    # A dialect no one reads: the stage cannot be read, and the error names the prim
    # and the attribute under the stage's own name.
    attribute(notes, "lpe:dialect", "karma")
    report = lpe.lint(stage)
    assert [f["error"] for f in report.files] == [
        f"{stage.GetRootLayer().identifier}: </World/notes>.lpe:dialect: unknown dialect "
        "`karma` (expected `renderman` or `osl`); did you mean `osl`?"
    ]


KARMA_NEVER = (
    "renders black in Karma (Houdini Solaris): every path it matches passes a vertex it "
    "never produces: `<.[Ss]>`"
)


def test_the_renderer_is_named_by_an_lpe_attribute_or_the_settings_namespaces():
    # Karma labels no vertex S: `C<RS>.*L` renders black there, whether `lpe:renderer`
    # names Karma on a plain prim or the RenderSettings hold `karma:` settings.
    # Planted fault, seen failing: RenderSettings given no property names (no finding
    # in the second stage).
    for declare in ("attribute", "settings"):
        stage = Usd.Stage.CreateInMemory()
        render_var(stage, "/Render/spec", "C<RS>.*L")
        if declare == "attribute":
            attribute(stage.DefinePrim("/World/notes"), "lpe:renderer", "karma")
        else:
            settings = stage.DefinePrim("/Render/settings", "RenderSettings")
            attribute(settings, "karma:global:samples", 3, Sdf.ValueTypeNames.Int)
        [f] = lpe.lint(stage).findings
        assert (f.kind, f.subject, f.location["prim"]) == ("never_produced", "spec", "/Render/spec")
        assert f.message.startswith(KARMA_NEVER), declare


def test_a_dialect_or_renderer_given_to_lint_outranks_the_one_the_stage_names():
    # The stage names Karma, which labels no vertex S; the caller's choice wins, as on
    # `lpe-check lint --dialect/--renderer`: RenderMan and hdPrman produce S vertices,
    # so `C<RS>.*L` is no `never_produced` there. Planted fault, seen failing (by
    # python/mutants.py): the stage's renderer taken when only one of dialect and
    # renderer is unset (`&&` as `||`).
    stage = Usd.Stage.CreateInMemory()
    render_var(stage, "/Render/spec", "C<RS>.*L")
    attribute(stage.DefinePrim("/World/notes"), "lpe:renderer", "karma")
    assert [f.kind for f in lpe.lint(stage).findings] == ["never_produced"]
    for given in ({"dialect": "renderman"}, {"renderer": "hdprman"}):
        assert [f.kind for f in lpe.lint(stage, **given).findings] == [], given


def test_a_relationship_with_a_group_attributes_name_carries_no_group():
    # Only an attribute's value is a group: the light carries none, and reading it
    # raises nothing.
    stage = Usd.Stage.CreateInMemory()
    light = stage.DefinePrim("/World/key", "RectLight")
    light.CreateRelationship("inputs:karma:light:lpetag").SetTargets(["/World"])
    render_var(stage, "/Render/k", "C<RD>.*<L.'key'>")
    assert [f.message for f in lpe.lint(stage, dialect="renderman").findings] == [
        "no light in this stage carries group 'key' (none carries a group)"
    ]


def test_a_value_that_cannot_be_fetched_is_an_error_naming_the_prim_and_attribute():
    # The native reading on its own, given by hand what pxr would give: a RectLight with
    # a group attribute and a RenderVar (read whole); the light's value raises. Planted
    # fault, seen failing: the error message without the prim's path.
    from lpe._lpe import StageReading

    reading = StageReading(["RectLight", "RenderVar"],
                           [["inputs:karma:light:lpetag", "points"], ["sourceName"]])
    at, names = reading.wanted()
    assert (at, names) == ([1, 0], ["sourceName", "inputs:karma:light:lpetag"])

    def values():
        yield "C<RD>L"
        raise RuntimeError("the layer could not be read")

    paths = ["/World/key", "/Render/a"]
    with pytest.raises(ValueError) as e:
        reading.complete(values(), paths.__getitem__, lambda i: [])
    assert str(e.value) == (
        "</World/key>.inputs:karma:light:lpetag: RuntimeError: the layer could not be read"
    )
    assert isinstance(e.value.__cause__, RuntimeError)
    with pytest.raises(ValueError, match="not complete"):
        lpe._lpe.lint_stage_json(reading, "stage")
    # Too few or too many values, or lists of different lengths, are errors too.
    with pytest.raises(ValueError, match=r"fewer values \(1\)"):
        reading.complete(iter(["C<RD>L"]), paths.__getitem__, lambda i: [])
    with pytest.raises(ValueError, match="more values than the 2 attributes"):
        reading.complete(iter(["C<RD>L", "key", "extra"]), paths.__getitem__, lambda i: [])
    with pytest.raises(ValueError, match="ended at prim 1"):
        StageReading(["RectLight"], [[], []])
    reading.complete(iter(["C<RD>L", "key"]), paths.__getitem__, lambda i: [])
    assert reading.facts() == (
        [("/Render/a", "RenderVar", ["sourceName"], [("sourceName", "C<RD>L")], []),
         ("", "", [], [("inputs:karma:light:lpetag", "key")], [])],
        ["RectLight", "RenderVar"],
    )


# --- the package's Python code ----------------------------------------------------------
# Each test below kills mutants of python/python/lpe/*.py that the rest of the suite let
# through (cosmic-ray, docs/mutants.toml); the expected values are written out by hand.


def test_findings_of_an_anonymous_stage_name_its_identifier():
    # An in-memory stage has no file: its findings name the root layer's identifier.
    # Planted fault, seen failing: `realPath and identifier` (the empty real path).
    stage = Usd.Stage.CreateInMemory()
    render_var(stage, "/Render/bad", "C<RD")
    ident = stage.GetRootLayer().identifier
    assert ident.startswith("anon:")
    files = {f.file for f in lpe.lint(stage).findings if f.kind == "parse_error"}
    assert files == {ident}


def test_an_asset_valued_attribute_reads_as_its_authored_path():
    # Planted fault, seen failing: `_as_text` returning None for an asset path.
    stage = Usd.Stage.CreateInMemory()
    prim = stage.DefinePrim("/World/tagged")
    prim.CreateAttribute("lpe:ini", Sdf.ValueTypeNames.Asset).Set(Sdf.AssetPath("looks/rendermn.ini"))
    prims, types = lpe._stage_facts(stage).facts()
    assert prims == [("/World/tagged", "", ["lpe:ini"], [("lpe:ini", "looks/rendermn.ini")], [])]
    assert types == [""]  # /World and /World/tagged: each type name once


def test_options_come_from_the_environment_until_configured(monkeypatch):
    # Planted faults, seen failing: each `env(...) or None` as `and` (a set variable read
    # as unset).
    monkeypatch.setenv("LPE_DIALECT", "osl")
    monkeypatch.setenv("LPE_INI", "/studio/rendermn.ini")
    monkeypatch.setenv("LPE_REGISTER", "events=U")
    monkeypatch.setenv("LPE_UNIVERSE", "C.*L")
    monkeypatch.setenv("LPE_RENDERER", "")  # set but empty: unset
    assert uv.options() == {
        "dialect": "osl",
        "ini": "/studio/rendermn.ini",
        "register": "events=U",
        "universe": "C.*L",
        "partitions": (),
        "renderer": None,
    }
    uv.configure(dialect="renderman")
    assert uv.options() == {
        "dialect": "renderman",
        "ini": None,
        "register": None,
        "universe": None,
        "partitions": (),
        "renderer": None,
    }


def test_the_validators_follow_the_dialect_in_the_environment_on_the_same_stage(monkeypatch):
    # solaris_karma.usda declares no dialect: specular_key (C<RS>.*<L.'key'>) reads
    # differently as RenderMan's and as OSL's, until LPE_DIALECT names one; diffuse_fill
    # names the unknown group 'fil' either way.
    monkeypatch.delenv("LPE_RENDERER", raising=False)
    monkeypatch.delenv("LPE_DIALECT", raising=False)
    stage = Usd.Stage.Open(str(ROOT / "tests" / "testdata" / "usd" / "solaris_karma.usda"))
    vars_ = "/Render/Products/Vars"
    assert errors_by_validator(stage) == [
        ("lpe:AmbiguousDialect", f"{vars_}/specular_key"),
        ("lpe:UnknownLightGroup", f"{vars_}/diffuse_fill"),
    ]
    monkeypatch.setenv("LPE_DIALECT", "osl")
    assert errors_by_validator(stage) == [("lpe:UnknownLightGroup", f"{vars_}/diffuse_fill")]


def test_the_validators_keep_the_lint_runs_of_the_last_eight_stages():
    # The cache holds a stage alive: it keeps eight, the newest, so that validating many
    # stages does not keep them all. Planted faults, seen failing: nine or seven kept;
    # `>` for `>=` (nine kept); the listener of an evicted entry read from the wrong
    # slot (`[2]`, `[0]`: no Revoke).
    stages = []
    for _ in range(10):
        stage = Usd.Stage.CreateInMemory()
        render_var(stage, "/Render/a", "C<RD>L")
        assert uv.validate(stage) == []
        stages.append(stage)
    assert [key[0] for key in uv._cache] == stages[2:]


def test_register_says_true_when_it_registers(monkeypatch):
    # The module registered when imported; registering again (as after a reload) finds
    # every validator there and says so. Planted fault, seen failing: `return False` at
    # the end of register().
    monkeypatch.setattr(uv, "_registered", False)
    assert uv.register() is True
    registry = UsdValidation.ValidationRegistry()
    found = sorted(m.name for m in registry.GetValidatorMetadataForKeyword("lpe"))
    assert found == sorted(NAMES)


def test_a_plugin_that_fails_to_register_warns_and_pxr_still_imports():
    # Planted fault, seen failing: the loader letting the error out of `import pxr...`.
    run = run_python(
        "import sys, warnings\n"
        "import lpe\n"
        "sys.modules['lpe.usd_validation'] = None  # its import now fails\n"
        "with warnings.catch_warnings(record=True) as caught:\n"
        "    warnings.simplefilter('always')\n"
        "    from pxr import UsdValidation\n"
        "print(UsdValidation.__name__)\n"
        "for w in caught:\n"
        "    print(w.message)\n",
        plugin=True,
    )
    assert run.returncode == 0, run.stderr
    name, warning = run.stdout.splitlines()[:2]
    assert name == "pxr.UsdValidation"
    assert warning.startswith("lpe: the UsdValidation plugin did not register: ")


def test_importing_lpe_and_other_modules_leaves_pxr_unimported():
    # The import hook waits for pxr.UsdValidation alone. Planted faults, seen failing:
    # its name test inverted or made an ordering (`colorsys` sorts before `pxr...`,
    # `wave` after), which wraps the first module imported after lpe and imports pxr
    # with it.
    run = run_python(
        "import sys\nimport lpe\nimport colorsys\nimport wave\n"
        "print('pxr' in sys.modules, 'lpe.usd_validation' in sys.modules)\n",
        plugin=True,
    )
    assert run.stdout.split() == ["False", "False"], run.stderr


def test_a_usd_without_validation_fails_to_import_it_as_it_would_without_lpe(tmp_path):
    # A USD build older than UsdValidation: a `pxr` package without the module.
    # Planted fault, seen failing: `spec is not None or ...` (AttributeError on None).
    (tmp_path / "pxr").mkdir()
    (tmp_path / "pxr" / "__init__.py").write_text("")
    run = run_python(
        f"import sys\nsys.path.insert(0, {str(tmp_path)!r})\nimport lpe\n"
        "try:\n    import pxr.UsdValidation\n"
        "except ModuleNotFoundError as e:\n    print(e.name)\n",
        plugin=False,
    )
    assert run.stdout.split() == ["pxr.UsdValidation"], run.stderr


def test_lpe_sees_pxr_validation_before_an_import_hook_installed_earlier():
    # An import hook installed before lpe that finds every module itself (as profilers
    # and type checkers install): lpe's hook goes in front, so it still wraps
    # pxr.UsdValidation. Planted faults, seen failing: lpe's hook inserted at 1 or last.
    run = run_python(
        "import sys, importlib.machinery\n"
        "class Hook:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        return importlib.machinery.PathFinder.find_spec(name, path)\n"
        "sys.meta_path.insert(0, Hook())\n"
        "import lpe\n"
        "from pxr import UsdValidation\n"
        "r = UsdValidation.ValidationRegistry()\n"
        "print(r.GetOrLoadValidatorByName('lpe:Syntax') is not None)\n",
        plugin=True,
    )
    assert run.stdout.split() == ["True"], run.stderr
