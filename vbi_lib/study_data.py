"""The study's data: each row of its model-assessment set turned into model inputs."""

from __future__ import annotations

from .bridges import Bridge, reference_beam
from .profiles import Profile
from .vehicles import Vehicle

__all__ = ["assessment_inputs"]


def assessment_inputs(
    table: object,
    profiles: dict[str, Profile],
    beam: str = "study",
    damping_ratio: float = 0.01,
) -> tuple[list[Bridge], list[Vehicle], list[Profile]]:
    """Bridges, trucks and roads of a model-assessment table like the study's Chapter 13.

    Every parameter comes from the row: the span, number of spans, midspan stiffness of the
    path and first frequency give the beam; mass, stiffness and damping coefficient give the
    truck.  Columns (US customary, as in the study): ``span_ft``, ``n_spans``,
    ``k_mid_lbf_per_in``, ``bridge_f1_hz``, ``vehicle_mass_slinch``,
    ``vehicle_k_lbf_per_in``, ``vehicle_c_lbf_s_per_in``, ``profile`` (a key of
    ``profiles``).

    Parameters
    ----------
    table
        A ``pandas.DataFrame`` (or anything with ``itertuples``) with the columns above.
    profiles
        Roads by name, stations and elevations in metres.
    beam
        ``"study"``: :meth:`Bridge.from_midspan_stiffness`, the one-coordinate model's rule
        (82)-(84); ``"exact"``: :func:`reference_beam`, the beam whose exact midspan
        stiffness is ``K_mid`` (the consistent choice for the many-mode model).
    damping_ratio
        Bridge damping ratio (the study: 1 %).

    Examples
    --------
    >>> import pandas as pd
    >>> row = dict(span_ft=40, n_spans=2, k_mid_lbf_per_in=721006, bridge_f1_hz=9.98,
    ...            vehicle_mass_slinch=200, vehicle_k_lbf_per_in=879290.0,
    ...            vehicle_c_lbf_s_per_in=2652.23, profile="flat")
    >>> road = Profile.flat(200.0, 0.0254)
    >>> b, v, p = assessment_inputs(pd.DataFrame([row]), {"flat": road}, beam="exact")
    >>> round(b[0].first_frequency_hz, 2), round(v[0].frequency_hz, 2)
    (9.98, 10.55)
    """
    from . import units as u

    if beam not in ("study", "exact"):
        raise ValueError(f"beam={beam!r} must be 'study' or 'exact'")
    make = Bridge.from_midspan_stiffness if beam == "study" else reference_beam
    bridges, vehicles, roads = [], [], []
    for i, row in enumerate(table.itertuples()):
        if row.profile not in profiles:
            raise ValueError(f"row {i}: profile {row.profile!r} is not among the roads given")
        bridges.append(
            make(
                row.span_ft * u.ft,
                int(row.n_spans),
                row.k_mid_lbf_per_in * u.lbf / u.inch,
                row.bridge_f1_hz,
                damping_ratio,
            )
        )
        vehicles.append(
            Vehicle(
                row.vehicle_mass_slinch * u.slinch,
                row.vehicle_k_lbf_per_in * u.lbf / u.inch,
                row.vehicle_c_lbf_s_per_in * u.lbf * u.s / u.inch,
            )
        )
        roads.append(profiles[row.profile])
    return bridges, vehicles, roads
