"""The UsdValidation plugin of the ``lpe`` package: validators ``lpe:...`` (keyword
``lpe``) that check the LPE RenderVars of a stage as ``lpe-check lint`` does.

USD finds the plugin through ``plugInfo.json`` next to this file: put the package
folder on ``PXR_PLUGINPATH_NAME`` (``lpe.plugin_path()`` gives it), and
``UsdValidation.ValidationContext(keywords=["lpe"])`` runs only these validators.
Importing this module registers the validators (once); USD imports the ``lpe``
package when it first loads one of them, and the package imports this module when
``pxr.UsdValidation`` is already imported, or right after it is imported. Without the plugin on the path, importing
this module registers nothing and ``validate()`` raises ``RuntimeError``.

Every validator reads the same lint run of the stage (``lpe.lint(stage)``, the
composed stage; cached per stage until its contents change) and reports the findings
of its kinds:

=========================  ==========================  =============================
validator                  lint kinds                  runs on
=========================  ==========================  =============================
``lpe:Syntax``             ``parse_error``             each ``UsdRenderVar``
``lpe:NeverMatching``      ``empty``                   each ``UsdRenderVar``
``lpe:EquivalentAovs``     ``equivalent``              each ``UsdRenderVar``
``lpe:UnknownLightGroup``  ``unknown_light_group``     each ``UsdRenderVar``
``lpe:UnknownObjectGroup`` ``unknown_object_group``    each ``UsdRenderVar``
``lpe:UnfedLobe``          ``unfed_lobe``              each ``UsdRenderVar``
``lpe:AmbiguousDialect``   ``ambiguous_dialect``       each ``UsdRenderVar``
``lpe:NeverProduced``      ``never_produced``          each ``UsdRenderVar``
``lpe:DoubledLpeMark``     ``doubled_lpe_mark``        each ``UsdRenderVar``
``lpe:PartitionOverlap``   ``overlap``                 the stage
``lpe:PartitionGap``       ``gap``                     the stage
``lpe:PartitionOutside``   ``outside``                 the stage
``lpe:PartitionMember``    ``unknown_member``          the stage
``lpe:Readable``           (the stage cannot be read)  the stage
=========================  ==========================  =============================

The partition validators run once per stage: ``lpe:partition`` may be declared on
any prim (usually the ``UsdRenderSettings``); their sites are the declaring prim and
its ``lpe:partition...`` attribute. Each error's sites are the prim and the attribute
(``sourceName`` for an AOV), and its message carries the witness path.

The dialect and the rest of lint's options come from ``configure()`` or, when it was
not called, from the environment: ``LPE_DIALECT`` (``renderman`` or ``osl``),
``LPE_RENDERER`` (a shipped renderer profile: ``karma``, ``hdprman``, ...),
``LPE_INI``, ``LPE_REGISTER``, ``LPE_UNIVERSE``. ``lpe:NeverProduced`` and
``lpe:DoubledLpeMark`` report only under a renderer (its profile's rules), and a
renderer names the dialect, so ``lpe:AmbiguousDialect`` then reports nothing.
"""

from __future__ import annotations

import os
import threading

from pxr import Sdf, Tf, Usd, UsdValidation

import lpe

#: Validator name (without the ``lpe:`` plugin prefix) -> the lint kinds it reports.
AOV_VALIDATORS = {
    "Syntax": ("parse_error",),
    "NeverMatching": ("empty",),
    "EquivalentAovs": ("equivalent",),
    "UnknownLightGroup": ("unknown_light_group",),
    "UnknownObjectGroup": ("unknown_object_group",),
    "UnfedLobe": ("unfed_lobe",),
    "AmbiguousDialect": ("ambiguous_dialect",),
    "NeverProduced": ("never_produced",),
    "DoubledLpeMark": ("doubled_lpe_mark",),
}
STAGE_VALIDATORS = {
    "PartitionOverlap": ("overlap",),
    "PartitionGap": ("gap",),
    "PartitionOutside": ("outside",),
    "PartitionMember": ("unknown_member",),
    "Readable": (),
}
#: The keyword every validator carries.
KEYWORD = "lpe"

_options: dict | None = None
_cache: dict = {}
_lock = threading.RLock()
_registered = False
#: How many stages' lint runs the validators keep.
_CACHE_STAGES = 8


def plugin_path() -> str:
    """The folder to put on ``PXR_PLUGINPATH_NAME`` (it holds ``plugInfo.json``); the
    same as ``lpe.plugin_path()``, which does not import pxr."""
    return lpe.plugin_path()


def configure(dialect=None, ini=None, register=None, universe=None, partitions=(),
              renderer=None):
    """Sets the options every validator lints with (``lpe.lint``'s; ``renderer`` is a
    shipped profile's name); ``configure()`` with no argument goes back to the
    environment (``LPE_DIALECT``, ``LPE_RENDERER``, ...)."""
    global _options
    given = (dialect, ini, register, universe, tuple(partitions), renderer)
    _options = None if given == (None, None, None, None, (), None) else {
        "dialect": dialect,
        "ini": ini,
        "register": register,
        "universe": universe,
        "partitions": tuple(partitions),
        "renderer": renderer,
    }
    with _lock:
        _cache.clear()


def options() -> dict:
    """The options the validators lint with now."""
    if _options is not None:
        return dict(_options)
    env = os.environ.get
    return {
        "dialect": env("LPE_DIALECT") or None,
        "ini": env("LPE_INI") or None,
        "register": env("LPE_REGISTER") or None,
        "universe": env("LPE_UNIVERSE") or None,
        "partitions": (),
        "renderer": env("LPE_RENDERER") or None,
    }


def _report(stage):
    """``lpe.lint(stage)`` under the current options, cached until the stage changes;
    a lint that raised is returned as the exception."""
    opts = options()
    key = (stage, tuple(sorted((k, str(v)) for k, v in opts.items())))
    with _lock:
        hit = _cache.get(key)
        if hit is not None:
            return hit[0]
        try:
            report = lpe.lint(stage, **opts)
        except (ValueError, RuntimeError, OSError) as e:
            report = e

        def changed(notice, sender, key=key):
            with _lock:
                entry = _cache.pop(key, None)
            if entry is not None:
                entry[1].Revoke()

        # Tf.Notice holds the callback weakly: the cache entry keeps it alive. The
        # cache keeps the last few stages only (an entry holds its stage).
        listener = Tf.Notice.Register(Usd.Notice.StageContentsChanged, changed, stage)
        while len(_cache) >= _CACHE_STAGES:
            _cache.pop(next(iter(_cache)))[1].Revoke()
        _cache[key] = (report, listener, changed)
        return report


def message(f) -> str:
    """The error message of a finding: its kind, subject and message, then the
    witness, the other AOV, the remainder and the hint when there are."""
    text = f"{f.kind}: `{f.subject}`: {f.message}"
    for label, value in (
        ("witness", f.witness),
        ("other", f.other),
        ("remainder", f.remainder),
        ("help", f.help),
    ):
        if value:
            text += f"; {label}: {value}"
    return text


def _error(stage, f):
    loc = f.location
    prim = Sdf.Path(loc["prim"])
    sites = [
        UsdValidation.ValidationErrorSite(stage, prim),
        UsdValidation.ValidationErrorSite(stage, prim.AppendProperty(loc["attribute"])),
    ]
    return UsdValidation.ValidationError(
        f.kind, UsdValidation.ValidationErrorType.Error, sites, message(f)
    )


def _read_error(stage, report):
    if isinstance(report, Exception):
        why = str(report)
    else:
        why = "; ".join(f["error"] for f in report.files if f["error"])
    if not why:
        return []
    site = UsdValidation.ValidationErrorSite(stage, Sdf.Path.absoluteRootPath)
    return [
        UsdValidation.ValidationError(
            "unreadable", UsdValidation.ValidationErrorType.Error, [site],
            f"lpe lint could not read the stage: {why}",
        )
    ]


def _prim_task(kinds):
    def task(prim, time_range=None):
        stage = prim.GetStage()
        report = _report(stage)
        if isinstance(report, Exception):
            return []
        path = str(prim.GetPath())
        return [
            _error(stage, f)
            for f in report.findings
            if f.kind in kinds and f.location.get("prim") == path
        ]

    return task


def _stage_task(kinds):
    def task(stage, time_range=None):
        report = _report(stage)
        if not kinds:
            return _read_error(stage, report)
        if isinstance(report, Exception):
            return []
        return [_error(stage, f) for f in report.findings if f.kind in kinds]

    return task


def register() -> bool:
    """Registers the validators with ``UsdValidation.ValidationRegistry`` (once) and
    returns True; returns False when USD has not found the plugin's ``plugInfo.json``
    (``PXR_PLUGINPATH_NAME`` does not name ``plugin_path()``), which declares them."""
    global _registered
    if _registered:
        return True
    registry = UsdValidation.ValidationRegistry()
    if registry.GetValidatorMetadata(f"{KEYWORD}:Syntax") is None:
        return False
    for name, kinds in AOV_VALIDATORS.items():
        full = f"{KEYWORD}:{name}"
        if not registry.HasValidator(full):
            registry.RegisterPluginPrimValidator(full, _prim_task(kinds))
    for name, kinds in STAGE_VALIDATORS.items():
        full = f"{KEYWORD}:{name}"
        if not registry.HasValidator(full):
            registry.RegisterPluginStageValidator(full, _stage_task(kinds))
    _registered = True
    return True


def validate(stage):
    """Runs every ``lpe`` validator on ``stage`` (``ValidationContext(keywords=["lpe"])``)
    and returns the ``UsdValidation.ValidationError`` list."""
    if not register():
        raise RuntimeError(
            "USD has not found the lpe validators: set PXR_PLUGINPATH_NAME to "
            f"{plugin_path()} before pxr is first imported (docs/python.md)"
        )
    context = UsdValidation.ValidationContext(keywords=[KEYWORD])
    return context.Validate(stage)


register()
