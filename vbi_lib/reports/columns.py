"""The report's columns of results: an effect at a place, on one face for a support's shear."""

from __future__ import annotations

from dataclasses import dataclass

from .inputs import Place, ReportInputs

__all__ = ["Column", "columns", "entries"]


@dataclass(frozen=True)
class Column:
    """One result of a crossing: an effect at a place, on one face for a support's shear."""

    place: Place
    effect: str
    face: str = ""

    @property
    def label(self) -> str:
        """``"pier 1 (interior support), left face"``."""
        return self.place.name + (f", {self.face} face" if self.face else "")

    @property
    def key(self) -> tuple[float, str]:
        """The station and face a crossing's sections are computed at."""
        return self.place.x, self.face or "left"


def columns(inputs: ReportInputs) -> tuple[Column, ...]:
    """Every place and effect the report gives (the displacement over a support, zero
    statically, is left out; the shear of an interior support on both faces)."""
    out = []
    last = len(inputs.bridge.spans)
    for place in inputs.places:
        for effect in inputs.effects:
            if effect == "displacement" and place.support is not None:
                continue
            if effect == "shear" and place.interior_support:
                out += [Column(place, effect, "left"), Column(place, effect, "right")]
            elif effect == "shear" and place.support == 0:
                out.append(Column(place, effect, "right"))
            elif effect == "shear" and place.support == last:
                out.append(Column(place, effect, "left"))
            else:
                out.append(Column(place, effect))
    return tuple(out)


def entries(cols: tuple[Column, ...]) -> list[tuple[float, str]]:
    """The distinct stations and faces a crossing's sections are computed at, in order."""
    seen: list[tuple[float, str]] = []
    for col in cols:
        if col.key not in seen:
            seen.append(col.key)
    return seen
