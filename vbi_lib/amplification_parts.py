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

:func:`amplification_parts_over` does it for many crossings (roads and speeds) at once, and
:func:`mode_contributions` shows where the inertia part comes from: how much a unit of
vibration of each exact mode adds to each section's DAF, for the deflection and the moment
(the study's equations 29-31 on a simple span, any bridge here).
"""

from __future__ import annotations

import itertools
import warnings
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from .beam_statics import EFFECTS, continuous_statics, static_envelope
from .bridges import Bridge
from .models import Crossing, SectionResponse, simulate
from .modes import beam_modes
from .profiles import Profile
from .validity import ContactLossWarning
from .vehicles import as_system

__all__ = ["amplification_parts", "amplification_parts_over", "mode_contributions"]


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


def amplification_parts_over(
    bridge: Bridge,
    vehicle: object,
    roads: Mapping[object, Profile],
    speeds: float | Sequence[float],
    bridge_start: float,
    sections: float | Sequence[float],
    **options: object,
) -> pd.DataFrame:
    """:func:`amplification_parts` of every crossing of a vehicle over several roads and speeds.

    Parameters
    ----------
    bridge, vehicle, bridge_start, options
        As :func:`vbi_lib.simulate` (e.g. ``model="modal", modes=10``).
    roads
        ``{name: road}``; every road crosses every speed.
    speeds
        Speeds [m/s].
    sections
        Stations from the bridge start [m], as for :meth:`vbi_lib.Crossing.sections`.

    Returns
    -------
    pandas.DataFrame
        The rows of :func:`amplification_parts` for every crossing, with ``road`` (the
        name), ``speed`` [m/s], ``min F_c / P`` (the crossing's smallest contact force over
        the static load) and ``lost contact``.
    """
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    parts = []
    with warnings.catch_warnings():  # contact loss is a column of the result
        warnings.simplefilter("ignore", ContactLossWarning)
        for (name, road), speed in itertools.product(roads.items(), speeds):
            run = simulate(bridge, vehicle, road, speed, bridge_start, **options)
            split = amplification_parts(run, run.sections(sections))
            parts.append(
                split.assign(
                    road=name,
                    speed=speed,
                    **{
                        "min F_c / P": run.min_contact_force_ratio,
                        "lost contact": run.lost_contact,
                    },
                )  # fmt: skip
            )
    return pd.concat(parts, ignore_index=True)


def mode_contributions(
    bridge: Bridge, vehicle: object, sections: Sequence[float], modes: int = 4
) -> pd.DataFrame:
    r"""What a unit of vibration of each mode adds to each section's DAF, by effect.

    Mode :math:`k` of the bridge (:func:`vbi_lib.beam_modes`) vibrates with a largest
    deflection along the bridge equal to the largest static deflection the vehicle's axles
    cause at the sections (:func:`vbi_lib.beam_statics.static_envelope`).  Its deflection
    :math:`\phi_k` and its bending moment :math:`EI\phi_k''` at each section, over the
    governing static extreme of the same effect there, are what that vibration adds to the
    section's DAF: on a simple span in its first mode, the study's :math:`48/\pi^4` and
    :math:`4/\pi^2` per unit of inertia (its equations 26-27), whose ratio is
    :math:`12/\pi^2`.

    Parameters
    ----------
    bridge
        Any bridge.
    vehicle
        Any vehicle (its static axle loads and offsets).
    sections
        Stations from the bridge start [m].
    modes
        How many modes, from the first.

    Returns
    -------
    pandas.DataFrame
        Index ``section`` [m]; columns ``(mode k, "deflection")`` and ``(mode k,
        "moment")``, magnitudes.  The deflection is NaN where its static extreme is zero
        (over a support).

    Examples
    --------
    A simple span and one axle: the first mode adds 12/pi^2 times more to the midspan
    deflection than to the midspan moment.

    >>> import vbi_lib as vbi
    >>> added = mode_contributions(vbi.Bridge(20.0, 1, 4e9, 6000.0),
    ...                            vbi.Vehicle(2e4, 1e7, 0.0), [10.0], modes=1)
    >>> row = added.loc[10.0, "mode 1"]
    >>> round(float(row["deflection"] / row["moment"]), 4), round(12 / np.pi**2, 4)
    (1.2159, 1.2159)
    """
    stations = np.atleast_1d(np.asarray(sections, dtype=float))
    system = as_system(vehicle)
    static = static_envelope(bridge.spans, bridge.EI, stations, system.static_loads,
                             system.offsets)  # fmt: skip
    larger = static.maximum >= -static.minimum
    governing = np.where(larger, static.maximum, static.minimum)  # (effect, section)
    shapes = beam_modes(bridge, int(modes))
    along = shapes.shape(np.linspace(0.0, bridge.length, 1201))
    scale = np.abs(governing[0]).max() / np.abs(along).max(axis=0)  # per mode
    deflection = governing[0].copy()
    deflection[np.abs(deflection) <= 1e-9 * np.abs(deflection).max()] = np.nan
    columns = {}
    for k in range(int(modes)):
        name = f"mode {k + 1}"
        columns[(name, "deflection")] = np.abs(shapes.shape(stations)[:, k] / deflection) * scale[k]
        moment = bridge.EI * shapes.curvature(stations)[:, k] / governing[1]
        columns[(name, "moment")] = np.abs(moment) * scale[k]
    return pd.DataFrame(columns, index=pd.Index(stations, name="section"))
