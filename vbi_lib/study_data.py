r"""The study's data: its printed tables, and the reader of its 239-scenario assessment set.

**Tables, as printed** (US customary units, the study's own rounding; a column's unit is in
its name, ``lbf_in2`` for lb in^2, ``slinch`` for lbf s^2/in).  Each function returns a new
:class:`pandas.DataFrame`:

* :func:`table_2_13_1`: the validation beam and sprung mass (:func:`validation_models`
  builds them);
* :func:`table_2_13_2`, :func:`table_2_13_3`, :func:`table_2_13_4`: what the study reported
  from its finite-element (FE) beam runs of the validation (time step, FE against the
  state-space model, one mode against five); :func:`table_2_13_12`: the decisions of its
  3D FE moving-mass runs;
* :func:`table_2_13_8`: the twelve state-space beams of the model assessment, whose EI and
  mass per span follow from the path's midspan stiffness and the first frequency by
  equations (82)-(84) (:meth:`vbi_lib.Bridge.from_midspan_stiffness`);
* :func:`table_2_13_9` and :func:`table_2_13_10`: the assessment's sprung-mass trucks, with
  ``k = m omega^2`` and ``c = 2 zeta m omega`` (85);
* :func:`table_2_15_3` and :func:`table_2_15_4`: the bridges and trucks of the parametric
  study.

**The model-assessment set** (chapter 13): :func:`read_assessment_set` reads a folder laid
out like the study's data set (``scenarios-239.csv`` and ``profiles/*.csv``, see its
README), and :func:`assessment_inputs` turns each scenario row into the model's inputs:
a :class:`vbi_lib.Bridge`, a :class:`vbi_lib.Vehicle` and a :class:`vbi_lib.Profile`.
In every scenario the truck starts at station 0 and drives at 720 in/s onto a bridge that
starts at 3840 in (:data:`ASSESSMENT_SPEED`, :data:`ASSESSMENT_BRIDGE_START`).

Without the data set, :func:`vbi_lib.assessment_design.published_assessment_design` builds
the same design from the printed tables (Tables 2.13.8 to 2.13.11) on roads it generates; it
has no FE results.

The data set itself has no licence: it is read from where it lies, never copied.
"""

from __future__ import annotations

import io
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from . import units as u
from ._files import read_text
from .bridges import Bridge, reference_beam
from .decks.study import StudyDeck, assessment_site
from .profile_files import read_profile
from .profiles import Profile
from .vehicles import Vehicle

__all__ = [
    "ASSESSMENT_BRIDGE_START",
    "ASSESSMENT_SPEED",
    "AssessmentSet",
    "assessment_inputs",
    "read_assessment_set",
    "table_2_13_1",
    "table_2_13_2",
    "table_2_13_3",
    "table_2_13_4",
    "table_2_13_8",
    "table_2_13_9",
    "table_2_13_10",
    "table_2_13_12",
    "table_2_15_3",
    "table_2_15_4",
    "validation_models",
]

#: Speed of every assessment crossing, 720 in/s [m/s].
ASSESSMENT_SPEED = 720 * u.inch
#: Station where every assessment bridge starts: 320 ft of approach, 3840 in [m].
ASSESSMENT_BRIDGE_START = 3840 * u.inch

#: Columns :func:`assessment_inputs` reads from each scenario row.
SCENARIO_COLUMNS = (
    "span_ft",
    "n_spans",
    "k_mid_lbf_per_in",
    "bridge_f1_hz",
    "vehicle_mass_slinch",
    "vehicle_k_lbf_per_in",
    "vehicle_c_lbf_s_per_in",
    "profile",
)


# ---------------------------------------------------------------------------- printed tables
def table_2_13_1() -> pd.DataFrame:
    """Table 2.13.1: the beam and sprung mass of the validation simulations (one row).

    Columns ``span_ft``, ``mass_per_length_kip_per_ft`` (the text's "distributed mass",
    a weight per length: divide by g), ``EI_lbf_in2``, ``vehicle_mass_slinch``,
    ``vehicle_k_lbf_per_in``, ``vehicle_damping_ratio``.

    Examples
    --------
    >>> table_2_13_1().iloc[0].to_dict()  # doctest: +NORMALIZE_WHITESPACE
    {'span_ft': 100.0, 'mass_per_length_kip_per_ft': 4.6, 'EI_lbf_in2': 7500000000000.0,
     'vehicle_mass_slinch': 100.0, 'vehicle_k_lbf_per_in': 63165.5, 'vehicle_damping_ratio': 0.1}
    """
    return pd.DataFrame(
        {
            "span_ft": [100.0],
            "mass_per_length_kip_per_ft": [4.6],
            "EI_lbf_in2": [7.5e12],
            "vehicle_mass_slinch": [100.0],
            "vehicle_k_lbf_per_in": [63.1655e3],
            "vehicle_damping_ratio": [0.10],
        }
    )


def validation_models(n_spans: int = 1) -> tuple[Bridge, Vehicle]:
    """The beam and sprung mass of Table 2.13.1, in SI: one span or two equal spans.

    The study gave both validation beams the same parameters.  The truck's damping ratio is
    the table's 10 % of critical.

    Parameters
    ----------
    n_spans
        1 or 2.

    Raises
    ------
    ValueError
        ``n_spans`` other than 1 or 2.

    Examples
    --------
    >>> bridge, truck = validation_models()
    >>> round(bridge.first_frequency_hz, 2), round(truck.frequency_hz, 2)
    (3.0, 4.0)
    """
    if n_spans not in (1, 2):
        raise ValueError(f"n_spans={n_spans!r} must be 1 or 2 (the study's two validation beams)")
    row = table_2_13_1().iloc[0]
    bridge = Bridge(
        row.span_ft * u.ft,
        n_spans,
        row.EI_lbf_in2 * u.lbf * u.inch**2,
        row.mass_per_length_kip_per_ft * u.kip / u.ft / u.g,
    )
    mass = row.vehicle_mass_slinch * u.slinch
    stiffness = row.vehicle_k_lbf_per_in * u.lbf / u.inch
    damping = 2.0 * row.vehicle_damping_ratio * (mass * stiffness) ** 0.5
    return bridge, Vehicle(mass, stiffness, damping)


def table_2_13_2() -> pd.DataFrame:
    """Table 2.13.2 as reported: the study's FE beam at 0.0015 s against 0.003 s (one row).

    Midspan displacement of the single-span validation beam: the largest and the mean
    absolute difference of the two runs, in inches and in per cent of the largest downward
    displacement at 0.0015 s.  Columns ``max_diff_in``, ``max_diff_percent``, ``mae_in``,
    ``mae_percent``.

    >>> table_2_13_2().iloc[0].tolist()
    [0.001056, 0.22, 0.000308, 0.07]
    """
    columns = ["max_diff_in", "max_diff_percent", "mae_in", "mae_percent"]
    index = pd.Index(["FE dt=0.0015 s vs dt=0.003 s"], name="comparison")
    return pd.DataFrame([[0.001056, 0.22, 0.000308, 0.07]], columns=columns, index=index)


def table_2_13_3() -> pd.DataFrame:
    """Table 2.13.3 as reported: the study's state-space model against its one-mode FE beam.

    Index ``n_spans`` (1, 2); columns ``state_space_max_in`` and ``fe_max_in`` (largest
    downward midspan displacement, negative), ``diff_percent``, ``mae_in``, ``mae_percent``
    (per cent of the FE peak).

    >>> table_2_13_3().loc[2, "diff_percent"]
    np.float64(8.24)
    """
    columns = ["state_space_max_in", "fe_max_in", "diff_percent", "mae_in", "mae_percent"]
    rows = [[-0.54011, -0.47087, 14.70, 0.023058, 4.90], [-0.26863, -0.24819, 8.24, 0.024253, 9.77]]
    return pd.DataFrame(rows, columns=columns, index=pd.Index([1, 2], name="n_spans"))


def table_2_13_4() -> pd.DataFrame:
    """Table 2.13.4 as reported: the study's two-span FE beam with one mode against five.

    One row: ``one_mode_max_in``, ``five_modes_max_in`` (largest downward midspan
    displacement), ``diff_percent``, ``mae_in``, ``mae_percent`` (per cent of the five-mode
    peak).

    >>> table_2_13_4().iloc[0].tolist()
    [-0.2482, -0.3048, 18.58, 0.0673, 22.09]
    """
    columns = ["one_mode_max_in", "five_modes_max_in", "diff_percent", "mae_in", "mae_percent"]
    return pd.DataFrame([[-0.2482, -0.3048, 18.58, 0.0673, 22.09]], columns=columns)


def table_2_13_8() -> pd.DataFrame:
    """Table 2.13.8: the twelve state-space beams of the model assessment.

    One row per bridge and path (index ``row``, 1 to 12, as printed): ``span_ft``,
    ``n_spans``, ``f1_hz`` (first natural frequency), ``path``, ``k_mid_lbf_per_in`` (midspan
    stiffness of the path, Tables 2.13.5-2.13.7), ``EI_lbf_in2`` and ``mass_per_span_slinch``
    (from (82)-(84), rounded as printed).  Bridge damping: 1 %.

    Examples
    --------
    >>> row = table_2_13_8().loc[3]
    >>> int(row.span_ft), int(row.n_spans), float(row.k_mid_lbf_per_in), f"{row.EI_lbf_in2:.4g}"
    (40, 2, 721006.0, '8.186e+11')
    """
    rows = [
        # span ft, spans, f1 Hz, path, K_mid lb/in, EI lb in^2, mass per span slinch
        (40, 1, 9.95, 1, 587723, 1.354e12, 305.16),
        (40, 1, 9.95, 2, 524293, 1.208e12, 272.22),
        (40, 2, 9.98, 1, 721006, 8.186e11, 183.37),
        (40, 2, 9.98, 2, 661235, 7.507e11, 168.16),
        (100, 1, 3.99, 1, 497527, 1.791e13, 1606.46),
        (100, 1, 3.99, 2, 639676, 2.303e13, 2065.44),
        (100, 1, 3.99, 3, 667262, 2.402e13, 2154.51),
        (100, 2, 3.99, 1, 668815, 1.186e13, 1064.14),
        (100, 2, 3.99, 2, 822043, 1.458e13, 1307.94),
        (100, 2, 3.99, 3, 837570, 1.486e13, 1332.65),
        (140, 1, 2.08, 1, 222278, 2.196e13, 2641.00),
        (140, 2, 2.08, 1, 246992, 1.202e13, 1446.09),
    ]
    columns = [
        "span_ft",
        "n_spans",
        "f1_hz",
        "path",
        "k_mid_lbf_per_in",
        "EI_lbf_in2",
        "mass_per_span_slinch",
    ]
    table = pd.DataFrame(rows, columns=columns, index=pd.RangeIndex(1, 13, name="row"))
    return table.astype({"span_ft": float, "k_mid_lbf_per_in": float})


def table_2_13_9() -> pd.DataFrame:
    """Table 2.13.9: the sprung-mass truck of each assessment bridge length.

    Index ``span_ft`` (40, 100, 140); columns ``mass_slinch``, ``k_lbf_per_in``,
    ``c_lbf_s_per_in``, ``damping_ratio`` and ``damped_frequency_hz`` (the table gives the
    damped frequency: ``omega = 2 pi f_d / sqrt(1 - zeta^2)`` in (85)).

    Examples
    --------
    >>> table_2_13_9().loc[100.0, ["k_lbf_per_in", "c_lbf_s_per_in"]].tolist()
    [161500.0, 1136.67]
    """
    return pd.DataFrame(
        {
            "mass_slinch": [200.0, 200.0, 200.0],
            "k_lbf_per_in": [8.7929e5, 1.6150e5, 4.9846e4],
            "c_lbf_s_per_in": [2652.23, 1136.67, 631.48],
            "damping_ratio": [0.10, 0.10, 0.10],
            "damped_frequency_hz": [10.5, 4.5, 2.5],
        },
        index=pd.Index([40.0, 100.0, 140.0], name="span_ft"),
    )


def table_2_13_10() -> pd.DataFrame:
    """Table 2.13.10: the 2.8 Hz sprung-mass truck used on every assessment bridge (one row).

    Columns ``mass_slinch``, ``k_lbf_per_in``, ``c_lbf_s_per_in``, ``damping_ratio``,
    ``frequency_hz`` (undamped).

    Examples
    --------
    >>> table_2_13_10().iloc[0].tolist()
    [200.0, 61902.2, 1407.43, 0.2, 2.8]
    """
    return pd.DataFrame(
        {
            "mass_slinch": [200.0],
            "k_lbf_per_in": [61902.2],
            "c_lbf_s_per_in": [1407.43],
            "damping_ratio": [0.20],
            "frequency_hz": [2.8],
        }
    )


def table_2_13_12() -> pd.DataFrame:
    """Table 2.13.12: the decisions of the study's 3D FE moving-mass runs (LUSAS IMDPlus).

    Index ``decision``; columns ``selection`` (as printed, text) and ``step`` (of the
    study's six-step procedure).

    >>> table_2_13_12().loc["time integration scheme", "selection"]
    'Hilber-Hughes-Taylor (HHT)'
    """
    rows = {
        "modes solved for and included": ("15", "1, 4"),
        "load increment along the path": ("6 in", "2"),
        "time integration scheme": ("Hilber-Hughes-Taylor (HHT)", "4"),
        "profile interpolation": ("linear", "4"),
        "structural damping": ("1 %", "4"),
        "vehicle speed": ("720 in/s", "4"),
        "time step": ("0.0015 s", "4"),
    }
    return pd.DataFrame(
        list(rows.values()),
        columns=["selection", "step"],
        index=pd.Index(list(rows), name="decision"),
    )


def table_2_15_3() -> pd.DataFrame:
    """Table 2.15.3: the four bridges of the parametric study (100 ft, 2000 slinch in all).

    Index ``bridge`` (1 to 4); columns ``span_ft``, ``total_mass_slinch``, ``EI_lbf_in2``,
    ``damping_ratio``, ``f1_hz``.

    Examples
    --------
    >>> [f"{ei:.3e}" for ei in table_2_15_3()["EI_lbf_in2"]]
    ['5.603e+12', '1.261e+13', '2.241e+13', '3.502e+13']
    """
    return pd.DataFrame(
        {
            "span_ft": [100.0] * 4,
            "total_mass_slinch": [2000.0] * 4,
            "EI_lbf_in2": [5.603e12, 1.261e13, 2.241e13, 3.502e13],
            "damping_ratio": [0.01] * 4,
            "f1_hz": [2.0, 3.0, 4.0, 5.0],
        },
        index=pd.RangeIndex(1, 5, name="bridge"),
    )


def table_2_15_4() -> pd.DataFrame:
    """Table 2.15.4: the four trucks of the parametric study (200 slinch, 10 % damping).

    Index ``truck`` (1 to 4); columns ``mass_slinch``, ``k_lbf_per_in``, ``damping_ratio``,
    ``frequency_hz``.

    Examples
    --------
    >>> table_2_15_4()["k_lbf_per_in"].tolist()
    [31582.7, 71061.2, 126330.9, 197392.1]
    """
    return pd.DataFrame(
        {
            "mass_slinch": [200.0] * 4,
            "k_lbf_per_in": [31582.7, 71061.2, 126330.9, 197392.1],
            "damping_ratio": [0.10] * 4,
            "frequency_hz": [2.0, 3.0, 4.0, 5.0],
        },
        index=pd.RangeIndex(1, 5, name="truck"),
    )


# ---------------------------------------------------------------------------- assessment set
@dataclass(frozen=True, eq=False)
class AssessmentSet:
    """The study's model-assessment scenarios and the roads they name.

    Unpacks as ``table, profiles = read_assessment_set(folder)``.

    Attributes
    ----------
    table
        One row per scenario (the columns of ``scenarios-239.csv``: bridge, truck, profile
        file name, and the finite-element and study DAFs ``fe_daf``,
        ``study_statespace_daf``).
    profiles
        The roads by file name, stations and elevations in metres, first elevation zero.
    folder
        The folder read (None for
        :func:`vbi_lib.assessment_design.published_assessment_design`).
    """

    table: pd.DataFrame = field(repr=False)
    profiles: dict[str, Profile] = field(repr=False)
    folder: Path | None

    def __iter__(self) -> Iterator[object]:
        return iter((self.table, self.profiles))

    def __len__(self) -> int:
        return len(self.table)

    def __repr__(self) -> str:
        source = "generated" if self.folder is None else f"from {str(self.folder)!r}"
        return f"AssessmentSet({len(self.table)} scenarios, {len(self.profiles)} profiles {source})"


def read_assessment_set(folder: str | Path) -> AssessmentSet:
    """Read the study's model-assessment set from a folder laid out like its data set.

    ``folder/scenarios-239.csv`` holds one row per scenario; ``folder/profiles/<name>``
    holds each road the table names: two columns, no header, station and elevation in
    inches.  Each road becomes a :class:`vbi_lib.Profile` in metres with its first elevation
    subtracted (the set's README: the truck starts at station 0).

    Parameters
    ----------
    folder
        The data set's folder (``../shared/data/seed-study`` beside the repository).

    Returns
    -------
    AssessmentSet
        ``table`` (a DataFrame) and ``profiles`` (``{file name: Profile}``); it unpacks as
        ``table, profiles``.

    Raises
    ------
    FileNotFoundError
        The folder, the table or a profile the table names does not exist (the message
        names the path).
    ValueError
        The table lacks a column :func:`assessment_inputs` needs, or is no regular text file
        (a folder, a pipe, ...: :class:`vbi_lib._files.FileReadError`); a profile file is
        malformed (:class:`vbi_lib.ProfileFileError`, naming the file and line).

    Examples
    --------
    >>> read_assessment_set("/nowhere")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    FileNotFoundError: no assessment data set at '/nowhere': ...
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(
            f"no assessment data set at {str(folder)!r}: give the folder holding "
            "scenarios-239.csv and profiles/ (the study's data, ../shared/data/seed-study)"
        )
    path = folder / "scenarios-239.csv"
    if not path.exists() and not path.is_symlink():
        raise FileNotFoundError(f"{str(path)!r} does not exist: the scenario table is missing")
    text = read_text(path, "folder / 'scenarios-239.csv'")  # a regular file, capped, UTF-8/16
    try:
        table = pd.read_csv(io.StringIO(text))
    except (pd.errors.ParserError, pd.errors.EmptyDataError) as error:
        raise ValueError(f"{str(path)!r} is not a readable CSV table: {error}") from None
    missing = [c for c in SCENARIO_COLUMNS if c not in table.columns]
    if missing:
        raise ValueError(
            f"{str(path)!r} lacks the column(s) {missing}; a scenario table needs "
            f"{list(SCENARIO_COLUMNS)}"
        )
    profiles = {}
    for name in table["profile"].unique():
        file = folder / "profiles" / str(name)
        if not file.is_file():
            raise FileNotFoundError(
                f"{str(file)!r} does not exist: the scenario table names profile {name!r}"
            )
        road = read_profile(file, unit="in", name=str(name))
        profiles[str(name)] = Profile(road.x, road.elevation - road.elevation[0], name=road.name)
    return AssessmentSet(table, profiles, folder)


def assessment_inputs(
    table: object,
    profiles: dict[str, Profile],
    beam: str = "study",
    damping_ratio: float = 0.01,
    *,
    skew_hand: str | None = None,
) -> tuple[list[Bridge] | list[StudyDeck], list[Vehicle], list[Profile]]:
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
        (82)-(84); ``"exact"``: :func:`vbi_lib.bridges.reference_beam`, the beam whose exact
        midspan stiffness is ``K_mid`` (the consistent choice for the many-mode model);
        ``"deck"``: a :class:`vbi_lib.decks.study.StudyDeck` per row, the deck across its
        width with the row's path and girder (:func:`vbi_lib.decks.study.assessment_site`;
        the 140 ft rows keep the exact beam, and their notes say why).
    damping_ratio
        Bridge damping ratio (the study: 1 %).
    skew_hand
        ``beam="deck"`` only: ``None`` (the 40 ft decks square; the seed leaves the hand of
        their 16 degree skew open), ``"left"`` or ``"right"``.

    Returns
    -------
    bridges, vehicles, roads
        One of each per row, in the table's order.

    Raises
    ------
    ValueError
        ``beam`` not ``"study"``, ``"exact"`` or ``"deck"``, a row naming a profile not given,
        or a row whose numbers the :class:`Bridge`, the deck or :class:`Vehicle` refuses (the
        message names the row).

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
    if beam not in ("study", "exact", "deck"):
        raise ValueError(f"beam={beam!r} must be 'study', 'exact' or 'deck'")
    if skew_hand is not None and beam != "deck":
        raise ValueError(f"skew_hand={skew_hand!r} applies to beam='deck' only")
    make = {"study": Bridge.from_midspan_stiffness, "exact": reference_beam}.get(beam)
    if beam == "deck" and "path" not in getattr(table, "columns", ()):
        raise ValueError("beam='deck' needs the table's 'path' column (the study's path)")
    bridges, vehicles, roads = [], [], []
    for i, row in enumerate(table.itertuples()):
        if row.profile not in profiles:
            raise ValueError(f"row {i}: profile {row.profile!r} is not among the roads given")
        try:
            if beam == "deck":
                bridges.append(assessment_site(row, skew_hand, damping_ratio))
            else:
                span, k_mid = row.span_ft * u.ft, row.k_mid_lbf_per_in * u.lbf / u.inch
                bridges.append(make(span, int(row.n_spans), k_mid, row.bridge_f1_hz, damping_ratio))
            vehicles.append(
                Vehicle(
                    row.vehicle_mass_slinch * u.slinch,
                    row.vehicle_k_lbf_per_in * u.lbf / u.inch,
                    row.vehicle_c_lbf_s_per_in * u.lbf * u.s / u.inch,
                )
            )
        except ValueError as error:
            raise ValueError(f"row {i}: {error}") from None
        roads.append(profiles[row.profile])
    return bridges, vehicles, roads
