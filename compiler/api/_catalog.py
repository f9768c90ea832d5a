"""`glint.catalog`: the snippet catalog as a read-only mapping from id ("D.ggx") to `Snippet`."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from glint.compiler.errors import InputError, UsageError

if TYPE_CHECKING:
    from glint.compiler.catalog import loader


class UnknownSnippet(InputError, KeyError):
    """An id that names no snippet: an InputError like every error of glint's, and a KeyError
    as a Mapping's lookup raises, so that `in` and `get` work."""

    def __str__(self) -> str:  # KeyError's own would quote the message
        return self.message


@dataclass(frozen=True, repr=False)
class Snippet:
    """One variant of a slot, as `glint catalog` lists it; `source` is its GLSL."""

    id: str  # "D.ggx": slot.variant
    slot: str
    summary: str
    source: str  # the GLSL body after the front matter
    file: str  # e.g. "snippets/D/ggx.glsl"
    provides: tuple[str, ...]  # the functions it defines
    requires: tuple[str, ...]  # the functions and constants it calls for
    params: dict[str, Any]  # `#define` knobs and their defaults
    sources: tuple[str, ...]  # where the model comes from
    formula: str = ""  # the model in LaTeX, from the front matter ("" when it has none)

    @property
    def variant(self) -> str:
        return self.id.split(".", 1)[1]

    def standalone(self, lang: str = "glsl") -> str:
        """What `glint catalog show ID --lang LANG` prints: the snippet with everything it needs
        (other slots at their balanced-tier variants) as one block of GLSL to paste, or that
        block converted to HLSL or MSL (`lang` "hlsl" or "msl") through SPIR-V."""
        from glint.compiler.catalog_tools.cross import show_in

        return show_in(self.id, lang)

    def __repr__(self) -> str:
        return f"<glint.Snippet {self.id}: {self.summary}>"

    def _repr_markdown_(self) -> str:
        return f"**{self.id}** ({self.file}): {self.summary}\n\n```glsl\n{self.source}```\n"


class Catalog(Mapping[str, Snippet]):
    """Every snippet by id, in the order of `glint catalog`."""

    def __init__(self, snippets: loader.Catalog) -> None:
        self._loaded = snippets
        self._snippets = {key: _snippet(value) for key, value in snippets.snippets.items()}

    def __getitem__(self, snippet_id: str) -> Snippet:
        if not isinstance(snippet_id, str):
            raise UnknownSnippet(
                f"a snippet id is a str such as 'D.ggx', not {type(snippet_id).__name__}"
            )
        if snippet_id in self._snippets:
            return self._snippets[snippet_id]
        try:
            self._loaded.get(snippet_id)  # raises, naming the closest ids
        except InputError as exc:
            raise UnknownSnippet(exc.message) from None
        raise UnknownSnippet(f"unknown snippet {snippet_id!r}; see `glint catalog`")

    def __iter__(self) -> Iterator[str]:
        return iter(self._snippets)

    def __len__(self) -> int:
        return len(self._snippets)

    def slot(self, name: str) -> list[Snippet]:
        """The variants of one slot, e.g. `slot("D")`; InputError for a slot that has none."""
        if not isinstance(name, str):
            raise UsageError(f"slot: expected a str such as 'D', not {type(name).__name__}")
        found = [s for s in self._snippets.values() if s.slot == name]
        if not found:
            slots = ", ".join(dict.fromkeys(s.slot for s in self._snippets.values()))
            raise InputError(f"unknown slot {name!r}; slots: {slots}")
        return found

    def __repr__(self) -> str:
        slots = len({s.slot for s in self._snippets.values()})
        return f"<glint.Catalog: {len(self)} snippets in {slots} slots>"


def catalog() -> Catalog:
    """The snippet catalog: `catalog()["D.ggx"].source`, `catalog().slot("shadow")`. An unknown
    id raises an InputError that is also a KeyError, with the message of `glint catalog show`
    (naming the closest ids)."""
    from glint.compiler.catalog.loader import load_catalog

    return Catalog(load_catalog())


def _snippet(snippet: loader.Snippet) -> Snippet:
    return Snippet(
        id=snippet.id,
        slot=snippet.slot,
        summary=snippet.summary,
        source=snippet.body,
        file=snippet.file,
        provides=snippet.provides,
        requires=snippet.requires,
        params={name: param.default for name, param in snippet.params.items()},
        sources=snippet.sources,
        formula=snippet.formula,
    )
