"""The checked inputs of a batch of crossings, as :func:`vbi_lib.simulate_many` hands them to
a model: the shared objects once, one array entry per crossing.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..bridges import Bridge
from ..profiles import Profile
from ..vehicles import Vehicle

__all__ = ["PEAK_SLOTS", "Batch"]

#: Spans whose midspan peaks a crossing's summary keeps (the others come from its histories).
PEAK_SLOTS = 2


@dataclass(frozen=True, eq=False)
class Batch:
    """The checked inputs of ``n`` crossings, one array entry per crossing.

    Objects shared by crossings are stored once: crossing ``i`` has the bridge
    ``bridges[bridge[i]]``, the vehicle ``vehicles[vehicle[i]]`` and the road
    ``profiles[profile[i]]``.  ``modes[i]`` is the model's checked ``modes`` option, 0 for a
    model that takes none.  Built by :func:`vbi_lib.simulate_many`.
    """

    bridges: tuple[Bridge, ...]
    vehicles: tuple[Any, ...]
    profiles: tuple[Profile, ...]
    bridge: np.ndarray
    vehicle: np.ndarray
    profile: np.ndarray
    speed: np.ndarray
    bridge_start: np.ndarray
    coupled: np.ndarray
    convective: np.ndarray
    modes: np.ndarray

    def __len__(self) -> int:
        return int(self.speed.size)

    def column(self, objects: str, attribute: str) -> np.ndarray:
        """An attribute of each crossing's bridge or vehicle, e.g. ``column("bridges", "span")``."""
        values = np.array([getattr(obj, attribute) for obj in getattr(self, objects)])
        return values[getattr(self, objects[:-1])]

    @staticmethod
    def groups(*keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distinct rows of the key columns: one crossing of each, and each crossing's row.

        Returns ``(first, inverse)``: ``first[k]`` is a crossing with the ``k``-th distinct
        combination of keys, and crossing ``i`` has combination ``inverse[i]``.
        """
        order = np.lexsort(keys[::-1])
        change = np.zeros(order.size, dtype=bool)
        change[0] = True
        for key in keys:
            ordered = key[order]
            change[1:] |= ordered[1:] != ordered[:-1]
        label = np.cumsum(change) - 1
        inverse = np.empty(order.size, np.int64)
        inverse[order] = label
        return order[change], inverse

    def n_spans(self) -> np.ndarray:
        """Each crossing's number of spans, ``(n,)``."""
        return np.array([x.n_spans for x in self.bridges], dtype=np.int64)[self.bridge]

    def lane_rows(self) -> np.ndarray:
        """Which crossings the lane kernels take, ``(n,)`` booleans: the study's sprung mass
        (:class:`~vbi_lib.Vehicle`) without a footprint on at most :data:`PEAK_SLOTS` spans
        (the summary's); a footprint takes the general path, whose grid averages the road."""
        # issue 20 hook (h20): the lane kernels' walker reads the raw road, no footprint
        sprung = np.array([isinstance(v, Vehicle) and v.footprint == 0.0 for v in self.vehicles],
                          dtype=bool)  # fmt: skip
        return sprung[self.vehicle] & (self.n_spans() <= PEAK_SLOTS)

    def take(self, rows: np.ndarray) -> Batch:
        """The crossings ``rows`` (indices or a mask) as a batch holding the objects they use."""

        def used(objects: tuple, codes: np.ndarray) -> tuple[tuple, np.ndarray]:
            kept, inverse = np.unique(codes[rows], return_inverse=True)
            return tuple(objects[k] for k in kept), inverse.astype(np.int64).ravel()

        bridges, bridge = used(self.bridges, self.bridge)
        vehicles, vehicle = used(self.vehicles, self.vehicle)
        profiles, profile = used(self.profiles, self.profile)
        return Batch(bridges, vehicles, profiles, bridge, vehicle, profile, self.speed[rows],
                     self.bridge_start[rows], self.coupled[rows], self.convective[rows],
                     self.modes[rows])  # fmt: skip

    def crossing(self, i: int) -> tuple[Bridge, Any, Profile, float, float, dict[str, Any]]:
        """Crossing ``i``'s bridge, vehicle, road, speed, bridge start and model options."""
        modes = int(self.modes[i]) if self.modes[i] else None
        options = {"coupled": bool(self.coupled[i]), "convective": bool(self.convective[i]),
                   "modes": modes}  # fmt: skip
        return (self.bridges[self.bridge[i]], self.vehicles[self.vehicle[i]],
                self.profiles[self.profile[i]], float(self.speed[i]), float(self.bridge_start[i]),
                options)  # fmt: skip
