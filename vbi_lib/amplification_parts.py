r"""A section's DAF split into the truck's dynamic load and the bridge's inertia.

The study explains why a displacement and a strain are amplified differently by splitting
the response at the instant of its peak in two (its Chapter 11, equations 25 to 31): the
static response to the truck's force at that instant, :math:`A_v` times the static one if
the force is :math:`A_v` times the weight, and the response to the inertia of the
vibrating bridge,

.. math:: \mathrm{DAF} = A_v + c\,\beta, \qquad \beta = m_b A_\max / P ,

with :math:`c = 48/\pi^4` for the midspan deflection and :math:`4/\pi^2` for its moment on
a simple span in its first mode.  :func:`amplification_parts` measures the same two parts
at every section and effect of a crossing, on any bridge and with any vehicle:

* ``forces``: the axle forces of the instant of the dynamic extreme, applied statically at
  their positions (exact influence lines, :func:`vbi_lib.beam_statics.continuous_statics`),
  over the static extreme; it falls below the axles' force amplification when the axles are
  not where they would give the static extreme;
* ``inertia``: the rest, ``daf - forces``, the response to the bridge's own inertia and
  damping forces (the dynamic part of the mode-acceleration method,
  :mod:`vbi_lib.models.sections`).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .beam_statics import EFFECTS, continuous_statics
from .models import Crossing, SectionResponse

__all__ = ["amplification_parts"]


def amplification_parts(crossing: Crossing, response: SectionResponse) -> pd.DataFrame:
    """Split the DAF of each section and effect into axle forces and bridge inertia.

    Parameters
    ----------
    crossing
        A crossing with its histories (:func:`vbi_lib.simulate`).
    response
        ``crossing.sections(x)`` for the sections wanted.

    Returns
    -------
    pandas.DataFrame
        One row per effect and section: ``effect``, ``section`` [m from the bridge start],
        ``sense`` (``"max"`` or ``"min"``, the governing one), ``daf``, ``forces`` and
        ``inertia`` (module docstring; ``daf = forces + inertia``), the ``time`` [s] of the
        dynamic extreme and the axles' ``force ratio`` then (the force of the axles on the
        bridge over their static loads).  NaN where the static extreme is zero (the
        deflection over a support).

    Raises
    ------
    TypeError
        ``crossing`` or ``response`` of the wrong type.
    ValueError
        ``response`` does not belong to ``crossing`` (other nodes or another bridge).

    Examples
    --------
    A truck crawling over a flat road: the forces explain the whole DAF of 1.

    >>> import vbi_lib as vbi
    >>> bridge = vbi.Bridge(20.0, 1, 4e9, 6000.0)
    >>> truck = vbi.Vehicle.from_frequency(2e4, 4.0, 0.1)
    >>> run = vbi.simulate(bridge, truck, vbi.Profile.flat(60.0, 0.05), 0.5, 20.0)
    >>> parts = amplification_parts(run, run.sections([10.0]))
    >>> parts[["effect", "daf", "forces"]].round(3).to_records(index=False).tolist()
    [('displacement', 1.0, 1.0), ('moment', 1.0, 1.0), ('shear', 1.0, 1.0)]
    """
    if not isinstance(crossing, Crossing):
        raise TypeError(f"crossing must be a vbi Crossing, got {type(crossing).__name__}")
    if not isinstance(response, SectionResponse):
        raise TypeError(
            f"response must be a SectionResponse (crossing.sections(x)), got "
            f"{type(response).__name__}"
        )
    if response.bridge != crossing.bridge or response.time.shape != crossing.time.shape:
        raise ValueError(
            "response does not belong to crossing: compute it with crossing.sections(x)"
        )
    bridge, system = crossing.bridge, crossing.system
    positions = crossing.axle_position - crossing.bridge_start
    on_bridge = crossing.axle_on_bridge
    rows = []
    for e, effect in enumerate(EFFECTS):
        for j, section in enumerate(response.sections):
            sense = "max" if response.governing[e, j] > 0 else "min"
            static = (response.static.maximum if sense == "max" else response.static.minimum)[e, j]
            k = int(response.extreme_index(effect, sense)[j])
            on = on_bridge[k]
            daf = response.daf[e, j]
            part = np.nan
            if np.isfinite(daf):  # else the static extreme is zero: no DAF to split
                part = 0.0
                if on.any():
                    face = response.faces[j] or "left"  # the shear's face at a support
                    lines = continuous_statics(
                        section, positions[k, on], bridge.spans, bridge.EI, side=face
                    )
                    influence = (-lines.deflection, lines.moment, lines.shear)[e]
                    forces = crossing.axle_contact_force[k, on] @ np.atleast_1d(influence)
                    part = float(forces) / static
            ratio = np.nan
            if on.any():
                ratio = crossing.axle_contact_force[k, on].sum() / system.static_loads[on].sum()
            rows.append(
                {
                    "effect": effect,
                    "section": float(section),
                    "sense": sense,
                    "daf": daf,
                    "forces": part,
                    "inertia": daf - part,
                    "time": float(crossing.time[k]),
                    "force ratio": float(ratio),
                }
            )
    return pd.DataFrame(rows)
