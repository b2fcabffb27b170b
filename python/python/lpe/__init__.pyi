"""Type stubs of the lpe package (the native module lpe._lpe and __init__.py)."""

import os
from collections.abc import Iterable, Mapping, Sequence
from typing import Any, Literal, Optional, Union

Dialect = Literal["renderman", "osl"]
#: A shipped renderer profile's name (docs/profiles.md): "renderman", "osl", "karma",
#: "arnold", "hdprman", "vray", "moonray". A str, not a Literal: the name often comes
#: from a setting, and an unknown one is a ValueError naming the known ones.
Renderer = str
StrPath = Union[str, os.PathLike[str]]
Vertex = tuple[str, Optional[str], Optional[str]]
PathLike = Union[str, Sequence[Vertex]]
Named = Union[Mapping[str, str], Iterable[tuple[str, str]]]

DIALECTS: list[str]
FINDING_FIELDS: tuple[str, ...]

class LpeSyntaxError(ValueError):
    """An expression that does not parse; str() is the caret rendering."""

    message: str
    position: int
    span: tuple[int, int]
    hint: Optional[str]
    source: str
    aov: Optional[str]

class Lpe:
    """A parsed expression."""

    @property
    def text(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def dialect(self) -> str: ...

class Explanation:
    """What AovSet.explain found."""

    @property
    def landed(self) -> list[str]: ...
    @property
    def text(self) -> str: ...

class AovSet:
    """Named AOVs compiled into one automaton."""

    def __init__(
        self,
        aovs: Named,
        dialect: Optional[Dialect] = None,
        ini: Optional[StrPath] = None,
        register: Optional[str] = None,
        renderer: Optional[Renderer] = None,
        profile: Optional[StrPath] = None,
    ) -> None: ...
    @property
    def names(self) -> list[str]: ...
    @property
    def dialect(self) -> str: ...
    def __len__(self) -> int: ...
    def match(self, path: PathLike) -> list[str]: ...
    def match_many(self, paths: Iterable[PathLike]) -> list[tuple[str, ...]]: ...
    def explain(self, path: PathLike) -> Explanation: ...
    def _repr_html_(self) -> str: ...

class Partition:
    """A partition check with shortest witnesses."""

    @property
    def universe(self) -> str: ...
    @property
    def overlaps(self) -> list[tuple[str, str, str]]: ...
    @property
    def gaps(self) -> list[str]: ...
    @property
    def outside(self) -> list[tuple[str, str]]: ...
    @property
    def remainder(self) -> Optional[str]: ...
    @property
    def clean(self) -> bool: ...
    @property
    def text(self) -> str: ...
    def __bool__(self) -> bool: ...
    def _repr_html_(self) -> str: ...

class Undecided:
    """An analysis that ran out of its budget before deciding (truthy)."""

    @property
    def reason(self) -> str: ...
    def __bool__(self) -> bool: ...

def parse(
    expr: str,
    dialect: Optional[Dialect] = None,
    ini: Optional[StrPath] = None,
    register: Optional[str] = None,
    renderer: Optional[Renderer] = None,
    profile: Optional[StrPath] = None,
) -> Lpe: ...
def equiv(
    a: str,
    b: str,
    dialect: Optional[Dialect] = None,
    ini: Optional[StrPath] = None,
    register: Optional[str] = None,
    max_steps: Optional[int] = None,
    max_seconds: Optional[float] = None,
    renderer: Optional[Renderer] = None,
    profile: Optional[StrPath] = None,
) -> Union[None, str, Undecided]: ...
def partition(
    members: Union[Mapping[str, str], Iterable[Union[str, tuple[str, str]]]],
    universe: Optional[str] = None,
    dialect: Optional[Dialect] = None,
    ini: Optional[StrPath] = None,
    register: Optional[str] = None,
    max_steps: Optional[int] = None,
    max_seconds: Optional[float] = None,
    renderer: Optional[Renderer] = None,
    profile: Optional[StrPath] = None,
) -> Union[Partition, Undecided]: ...

class Finding:
    """One lint finding, with the fields of lpe-check lint --format json."""

    kind: str
    file: str
    subject: str
    location: dict[str, Any]
    message: str
    source: Optional[str]
    span: Optional[list[int]]
    help: Optional[str]
    other: Optional[str]
    witness: Optional[str]
    remainder: Optional[str]
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    def to_dict(self) -> dict[str, Any]: ...

class LintReport:
    """What lint found."""

    json: dict[str, Any]
    findings: list[Finding]
    aovs: list[dict[str, Any]]
    partitions: list[dict[str, Any]]
    files: list[dict[str, Any]]
    @property
    def clean(self) -> bool: ...
    def __bool__(self) -> bool: ...
    def __len__(self) -> int: ...

def stage_name(stage: Any) -> str: ...
def plugin_path() -> str: ...
def lint(
    files_or_stage: Union[StrPath, Iterable[StrPath], Any],
    partitions: Iterable[Union[str, Sequence[str]]] = (),
    universe: Optional[str] = None,
    dialect: Optional[Dialect] = None,
    ini: Optional[StrPath] = None,
    register: Optional[str] = None,
    renderer: Optional[Renderer] = None,
    profile: Optional[StrPath] = None,
) -> LintReport: ...
