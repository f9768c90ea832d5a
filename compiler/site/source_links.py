"""Where a snippet's source can be read: the paper's DOI, or the page of notes, an article or a
book that the source names. Matched on how the catalog writes a source (author and year, or the
work's name); a source not listed here stays plain text (the project's own seed notes, course
notes without a stable address)."""

from __future__ import annotations

# (how a source starts, where it is): the first match wins.
LINKS: tuple[tuple[str, str], ...] = (
    ("Schlick 1994", "https://doi.org/10.1111/1467-8659.1330233"),
    ("Blinn 1977", "https://doi.org/10.1145/563858.563893"),
    ("Cook & Torrance 1982", "https://doi.org/10.1145/357290.357293"),
    ("Oren and Nayar 1994", "https://doi.org/10.1145/192161.192213"),
    ("Walter et al. 2007", "https://doi.org/10.2312/EGWR/EGSR07/195-206"),
    ("Heitz 2014", "https://jcgt.org/published/0003/02/03/"),
    ("Ramamoorthi and Hanrahan 2001", "https://doi.org/10.1145/383259.383317"),
    ("Reinhard et al. 2002", "https://doi.org/10.1145/566654.566575"),
    ("Henyey & Greenstein 1941", "https://doi.org/10.1086/144246"),
    ("Hart 1996", "https://doi.org/10.1007/s003710050084"),
    ("Fujii 2012", "https://mimosa-pudica.net/improved-oren-nayar.html"),
    (
        "Karis 2014, Physically Based Shading on Mobile",
        "https://www.unrealengine.com/en-US/blog/physically-based-shading-on-mobile",
    ),  # fmt: skip
    ("Hable 2014", "http://filmicworlds.com/blog/optimizing-ggx-shaders-with-dotlh/"),
    ("Filament PBR notes", "https://google.github.io/filament/Filament.html"),
    ("Filament, ", "https://github.com/google/filament"),
    ("Inigo Quilez, distance functions", "https://iquilezles.org/articles/distfunctions/"),
    ("Inigo Quilez, soft shadows", "https://iquilezles.org/articles/rmshadows/"),
    ("Pharr, Jakob and Humphreys, PBRT 3rd ed.", "https://pbr-book.org/3ed-2018/"),
    ("Valve Developer Wiki, Half Lambert", "https://developer.valvesoftware.com/wiki/Half_Lambert"),
)


def source_link(source: str) -> str | None:
    """The address of `source`, or None where none is known."""
    return next((url for start, url in LINKS if source.startswith(start)), None)
