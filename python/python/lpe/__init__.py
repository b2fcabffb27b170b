"""lpe: light path expressions (RenderMan's and OSL's dialects), from Python.

Thin over the Rust library of the same name:

- ``parse(expr, dialect=None, ini=None, register=None, renderer=None, profile=None)``:
  the expression's canonical text (an ``Lpe``); a syntax error raises
  ``LpeSyntaxError`` with ``message``, ``position``, ``hint`` and the caret rendering
  as ``str()``. ``dialect`` is ``"renderman"`` (``None``: the default) or ``"osl"``;
  ``renderer="karma"`` (a shipped profile) or ``profile="ourray.toml"`` reads
  expressions as that renderer does (docs/profiles.md), in its base dialect.
- ``AovSet({"name": expr, ...}, dialect=...)``: ``match(path)`` (the AOV names a path
  lands in), ``match_many(paths)`` (the batch form), ``explain(path)``, ``names``.
  A path is text (``"C RD2'floor' L'key'"``, OSL: ``"C,_ R,D L,_"``) or a list of
  ``(type, event, label)`` tuples.
- ``equiv(a, b)``: ``None``, or the shortest path one matches and the other does not.
- ``partition(members, universe=None)``: overlaps, gaps and paths outside the
  universe with shortest witnesses, and the remainder expression.
- ``lint(files_or_stage, partitions=..., dialect=..., renderer=...)``: ``lpe-check
  lint --format json``'s findings, for files or a ``pxr.Usd.Stage`` (read as
  composed).

The UsdValidation plugin (validators ``lpe:...``, keyword ``lpe``) is in
``lpe.usd_validation``; docs/python.md says how USD finds it.
"""

from __future__ import annotations

import importlib as _importlib
import importlib.abc as _importlib_abc
import importlib.util as _importlib_util
import json as _json
import os as _os
import sys as _sys
import warnings as _warnings

from ._lpe import (
    DIALECTS,
    AovSet,
    Explanation,
    Lpe,
    LpeSyntaxError,
    Partition,
    Undecided,
    equiv,
    parse,
    partition,
)
from ._lpe import USD_ORDERED_VARS as _USD_ORDERED_VARS
from ._lpe import StageReading as _StageReading
from ._lpe import lint_json as _lint_json
from ._lpe import lint_stage_json as _lint_stage_json

__all__ = [
    "DIALECTS",
    "AovSet",
    "Explanation",
    "Finding",
    "LintReport",
    "Lpe",
    "LpeSyntaxError",
    "Partition",
    "Undecided",
    "equiv",
    "lint",
    "parse",
    "partition",
    "plugin_path",
]

#: The keys of one finding in ``lpe-check lint --format json`` (docs/lint.md).
FINDING_FIELDS = (
    "kind",
    "file",
    "subject",
    "location",
    "message",
    "source",
    "span",
    "help",
    "other",
    "witness",
    "remainder",
)


class Finding:
    """One lint finding, with the fields of ``lpe-check lint --format json``:
    ``kind`` (``parse_error``, ``empty``, ``equivalent``, ``unknown_light_group``,
    ``unknown_object_group``, ``unfed_lobe``, ``unknown_member``, ``overlap``,
    ``gap``, ``outside``, ``ambiguous_dialect``, and under a renderer
    ``never_produced`` and ``doubled_lpe_mark``), ``file``, ``subject`` (the AOV or partition),
    ``location`` (a dict: ``line``, ``column``, ``prim``, ``attribute``), ``message``,
    ``source`` and ``span`` (the caret), ``help``, ``other``, ``witness``,
    ``remainder``. ``to_dict()`` gives the JSON object back."""

    __slots__ = FINDING_FIELDS

    def __init__(self, fields: dict):
        for k in FINDING_FIELDS:
            setattr(self, k, fields.get(k))

    def to_dict(self) -> dict:
        return {k: getattr(self, k) for k in FINDING_FIELDS}

    def __eq__(self, other):
        return isinstance(other, Finding) and self.to_dict() == other.to_dict()

    def __repr__(self):
        where = self.location.get("prim") or self.location.get("line")
        return f"<lpe.Finding {self.kind} {self.subject!r} at {where}>"


class LintReport:
    """What ``lint`` found: ``findings`` (``Finding`` objects), ``aovs``,
    ``partitions`` and ``files`` (dicts as in the JSON report) and ``json`` (the
    whole ``lpe-lint/1`` document). True when there is no finding and every file
    could be read."""

    def __init__(self, document: dict):
        self.json = document
        self.findings = [Finding(f) for f in document["findings"]]
        self.aovs = document["aovs"]
        self.partitions = document["partitions"]
        self.files = document["files"]

    @property
    def clean(self) -> bool:
        return not self.findings and not any(f["error"] for f in self.files)

    def __bool__(self):
        return self.clean

    def __len__(self):
        return len(self.findings)

    def __iter__(self):
        return iter(self.findings)

    def __repr__(self):
        return f"<lpe.LintReport {len(self.findings)} findings, {len(self.aovs)} AOVs>"


def plugin_path() -> str:
    """The folder holding the UsdValidation plugin's ``plugInfo.json``: put it on
    ``PXR_PLUGINPATH_NAME`` before pxr is first imported (docs/python.md)."""
    return _os.path.dirname(_os.path.abspath(__file__))


def _is_stage(obj) -> bool:
    return hasattr(obj, "ExportToString") and hasattr(obj, "GetRootLayer")


def stage_name(stage) -> str:
    """The name a stage's findings carry in ``file``: its root layer's real path (the
    file ``lpe-check lint`` would be given), or its identifier for an anonymous one."""
    layer = stage.GetRootLayer()
    return layer.realPath or layer.identifier


def _stage_facts(stage):
    """What lint reads of a composed stage, as a completed ``_lpe.StageReading``
    (``facts()`` shows it). Every prim of ``stage.Traverse()`` gives its type name and
    authored property names, and the Rust reader's conventions say which prims lint
    reads; of those, only the attributes lint reads are fetched (their values), and only
    the prims that declare something (RenderVars, RenderProducts, RenderSettings, prims
    with ``lpe:`` attributes) give their paths and ``orderedVars``. Each query runs over
    all prims through ``map``: pxr is called from C, with no Python code per prim."""
    from pxr import Usd

    prims = list(stage.Traverse())
    reading = _StageReading(
        map(Usd.Prim.GetTypeName, prims), map(Usd.Prim.GetAuthoredPropertyNames, prims)
    )
    at, names = reading.wanted()
    # An attribute that is not one (a relationship of a name lint reads) gets no value.
    values = map(Usd.Attribute.Get, map(Usd.Prim.GetAttribute, map(prims.__getitem__, at), names))
    reading.complete(
        values,
        lambda i: prims[i].GetPath().pathString,
        lambda i: _ordered_vars(prims[i]),
    )
    return reading


def _ordered_vars(product):
    """The prim names of a RenderProduct's ``orderedVars`` targets, in order."""
    rel = product.GetRelationship(_USD_ORDERED_VARS)
    return [t.name for t in rel.GetTargets()] if rel else []


def lint(
    files_or_stage,
    partitions=(),
    universe=None,
    dialect=None,
    ini=None,
    register=None,
    renderer=None,
    profile=None,
) -> LintReport:
    """Lints LPE AOVs as ``lpe-check lint --format json`` does.

    ``files_or_stage`` is a path (``str`` or ``os.PathLike``: ``.usda``/``.usdc``/
    ``.usdz``, ``.rib``, ``.ini``), a list of paths, or a ``pxr.Usd.Stage``. A stage is
    read as composed (session layer, variant selections, references and payloads
    loaded) through pxr's own traversal: only the prims and attributes lint reads are
    queried (RenderVars, RenderProducts, RenderSettings, the group attributes,
    ``lpe:`` attributes), no geometry is fetched or serialized, and the Rust reader's
    own code makes the declarations of them; its findings name the root layer's file. ``partitions`` are lists of AOV names, each ``"a,b,c"`` or a list of names,
    that must partition ``universe``. ``dialect`` (``"renderman"`` or ``"osl"``) reads
    every AOV in that dialect; left ``None``, AOVs are read as RenderMan's and a stage
    that declares no dialect is also checked for AOVs whose RenderMan and OSL readings
    differ (``ambiguous_dialect``). ``renderer`` (a shipped profile: ``"karma"``,
    ``"hdprman"``, ...) or ``profile`` (a profile TOML file) reads every AOV as that
    renderer does and checks its rules too (``never_produced``, ``doubled_lpe_mark``);
    it names the dialect, so ``ambiguous_dialect`` is not checked, and a ``dialect``
    other than its base is a ``ValueError``. Returns a ``LintReport``; a bad argument
    raises ``TypeError`` or ``ValueError`` (an unreadable file is in ``report.files``,
    as in the JSON report).
    """
    parts = []
    for p in partitions if not isinstance(partitions, str) else [partitions]:
        if isinstance(p, str):
            parts.append(p)
        elif all(isinstance(m, str) for m in p):
            parts.append(",".join(p))
        else:
            raise TypeError("a partition is 'a,b,c' or a list of AOV names")
    if _is_stage(files_or_stage):
        out = _lint_stage_json(
            _stage_facts(files_or_stage), stage_name(files_or_stage), parts, universe,
            dialect, ini, register, renderer, profile,
        )
    else:
        if isinstance(files_or_stage, (str, _os.PathLike)):
            files = [files_or_stage]
        else:
            try:
                files = list(files_or_stage)
            except TypeError:
                raise TypeError(
                    "lint takes a path, a list of paths or a pxr.Usd.Stage, not "
                    f"{type(files_or_stage).__name__}"
                ) from None
        for f in files:
            if not isinstance(f, (str, _os.PathLike)):
                raise TypeError(f"a file is a str or os.PathLike, not {type(f).__name__}")
        if not files:
            raise ValueError("lint needs at least one file")
        out = _lint_json(
            [_os.fspath(f) for f in files], parts, universe, dialect, ini, register,
            None, renderer, profile,
        )
    return LintReport(_json.loads(out))


# The UsdValidation plugin (plugInfo.json names this package) registers its validators
# when `lpe.usd_validation` is imported. USD imports this package when it first loads
# one of them; if pxr's validation module is imported already, register now. Otherwise
# register right after it is imported (USD does not import an imported package again).


class _RegisterAfter(_importlib_abc.Loader):
    """Runs pxr.UsdValidation's own loader, then registers the validators."""

    def __init__(self, loader):
        self._loader = loader

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        try:
            _importlib.import_module("lpe.usd_validation")
        except Exception as e:  # never break the user's import of pxr
            _warnings.warn(f"lpe: the UsdValidation plugin did not register: {e}")


class _WhenPxrValidationImports(_importlib_abc.MetaPathFinder):
    """Finds nothing itself: wraps the loader of pxr.UsdValidation, once."""

    def find_spec(self, name, path=None, target=None):
        if name != "pxr.UsdValidation":
            return None
        _sys.meta_path.remove(self)
        spec = _importlib_util.find_spec(name)
        if spec is not None and spec.loader is not None:
            spec.loader = _RegisterAfter(spec.loader)
        return spec


if "pxr.UsdValidation" in _sys.modules:
    from . import usd_validation as _usd_validation  # noqa: F401
else:
    _sys.meta_path.insert(0, _WhenPxrValidationImports())
