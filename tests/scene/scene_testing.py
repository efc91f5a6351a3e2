"""Helpers for the scene tests: where the real corpus lives, and fuzzing strategies."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from hypothesis import strategies as st
from support.corpus import CORPUS  # noqa: F401 (the scene tests take it from here)

REPO_ROOT = Path(__file__).resolve().parents[2]
SCENE_KINDS = ("sim", "wld", "maz", "robi", "esObj")


def manifest() -> list[tuple[str, str]]:
    """(relative path, kind) of every scene file of the corpus, as MANIFEST.tsv lists them."""
    rows = (CORPUS / "MANIFEST.tsv").read_text(encoding="utf-8").splitlines()[1:]
    return [(r.split("\t")[0], r.split("\t")[2]) for r in rows if r.split("\t")[2] in SCENE_KINDS]


def corpus_texts(kind: str) -> list[str]:
    """The decoded texts of the corpus files of one kind (distinct ones only)."""
    from eyesim.scene.lexer import read_text

    texts = {read_text(CORPUS / path) for path, k in manifest() if k == kind}
    return sorted(texts)


def mutated(texts: list[str]):
    """A strategy: one of `texts` with random characters and lines inserted, deleted or changed."""
    alphabet = st.sampled_from(
        list(" \t\n\r;#\"'()_|.,-+0123456789eE.SsUxXoOF") + ["push", "pop", "psd", "nan", "1e999"]
    )
    edit = st.tuples(st.integers(0, 10_000), st.integers(0, 3), alphabet)

    @st.composite
    def build(draw):
        text = draw(st.sampled_from(texts))
        for position, op, piece in draw(st.lists(edit, max_size=8)):
            i = position % (len(text) + 1)
            if op == 0:
                text = text[:i] + piece + text[i:]
            elif op == 1:
                text = text[:i] + text[i + len(piece) :]
            elif op == 2:
                text = text[:i] + piece + text[i + 1 :]
            else:
                lines = text.split("\n")
                j = position % len(lines)
                lines.insert(j, lines[(j * 7) % len(lines)])
                text = "\n".join(lines)
        return text

    return build()


def random_text():
    """A strategy: arbitrary text, biased towards the characters scene files use."""
    return st.one_of(
        st.text(max_size=300),
        st.text(alphabet=st.sampled_from(list(" \t\n;#\"'_|.-+0123456789abcdefSUDLRoxF()")), max_size=300),
    )


def without_locations(value):
    """A document compared without source names and locations (they differ across copies)."""
    if dataclasses.is_dataclass(value):
        return tuple(
            (f.name, without_locations(getattr(value, f.name)))
            for f in dataclasses.fields(value)
            if f.name not in ("location", "source", "row_lines")
        )
    if isinstance(value, (tuple, list)):
        return tuple(without_locations(v) for v in value)
    return value
