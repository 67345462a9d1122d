r"""How much of a DAF survives when the tyre can leave the road: one truck, three contacts.

The study's truck is a sprung mass whose spring and damper stand on the road (study
equations 46-47): the contact force

.. math:: F_c = m_v g + k_v (r - u_v) + c_v (\dot r - \dot u_v)

may become negative, as if the tyre pulled the road down.  A crossing in which it does is
outside the model's validity.  :func:`compare_contact` runs the same crossings with three
idealisations of the same truck (:func:`contact_variants`):

* ``"bilateral"``: the study's sprung mass as it is (:class:`~vbi_lib.Vehicle`);
* ``"lift-off"``: the same mass, spring and damper, but the contact pushes and never pulls,
  :math:`F_c = \max(0, \dots)`: the truck flies when the force would turn tensile and lands
  when it turns compressive again (:class:`~vbi_lib.vehicles.VehicleSystem` with
  ``unilateral=[True]``);
* ``"quarter car"``: the sprung mass and its suspension on an axle of mass
  ``unsprung_fraction`` times the sprung mass and a tyre ``tyre_stiffness_ratio`` times as
  stiff as the suspension, which can leave the road and sees it through its footprint
  (:meth:`vbi_lib.QuarterCar.from_vehicle`).

A truck that flies lands in a chain of impacts whose timing is sensitive to everything,
including the time step: each crossing is therefore also run at a fraction of its own
default step (``step_factors``), and :class:`ContactComparison` shows how far each DAF
moved.  Where it moves, the DAF of that crossing is a sample of what such crossings do, not
a prediction of one.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from . import _validation as check
from .models import simulate_many
from .models.base import broadcast
from .validity import ContactFlags, ContactLossWarning, mark_lost_contact
from .vehicles import DEFAULT_FOOTPRINT, QuarterCar, Vehicle, VehicleSystem

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["IDEALISATIONS", "ContactComparison", "compare_contact", "contact_variants"]

#: The three idealisations of the contact, in the order of every result's last axis.
IDEALISATIONS = ("bilateral", "lift-off", "quarter car")


def contact_variants(
    vehicle: Vehicle,
    unsprung_fraction: float = 0.1,
    tyre_stiffness_ratio: float = 10.0,
    footprint: float = DEFAULT_FOOTPRINT,
) -> dict[str, Vehicle | VehicleSystem | QuarterCar]:
    """The study's sprung mass three ways, by the names of :data:`IDEALISATIONS`.

    Parameters
    ----------
    vehicle
        The study's sprung mass.
    unsprung_fraction
        Unsprung (axle) mass of the quarter car over the sprung mass, > 0.
    tyre_stiffness_ratio
        Tyre stiffness of the quarter car over the suspension stiffness, > 0.
    footprint
        Tyre contact length of the quarter car [m] (the lift-off truck, like the study's,
        has none).

    Returns
    -------
    dict
        ``"bilateral"``: ``vehicle`` itself; ``"lift-off"``: its
        :class:`~vbi_lib.vehicles.VehicleSystem` with a unilateral contact;
        ``"quarter car"``: a :class:`~vbi_lib.QuarterCar`, heavier by its axle.

    Raises
    ------
    TypeError
        ``vehicle`` is not a :class:`~vbi_lib.Vehicle`.
    ValueError
        A ratio that is not a finite number > 0, a negative footprint.

    Examples
    --------
    >>> truck = Vehicle.from_frequency(35_000.0, 4.0, 0.1)
    >>> cars = contact_variants(truck)
    >>> cars["lift-off"].unilateral.tolist(), round(cars["quarter car"].weight / truck.weight, 2)
    ([True], 1.1)
    """
    if not isinstance(vehicle, Vehicle):
        raise TypeError(
            f"vehicle must be the study's sprung mass, a vbi.Vehicle; got {type(vehicle).__name__}"
        )
    fraction = check.positive("unsprung_fraction", unsprung_fraction)
    ratio = check.positive("tyre_stiffness_ratio", tyre_stiffness_ratio)
    footprint = check.non_negative("footprint", footprint)
    lift_off = dataclasses.replace(vehicle.system, unilateral=[True], name="sprung mass, lift-off")
    quarter = QuarterCar.from_vehicle(
        vehicle, fraction * vehicle.mass, ratio * vehicle.stiffness, footprint=footprint
    )
    return {"bilateral": vehicle, "lift-off": lift_off, "quarter car": quarter}


@dataclass(frozen=True, eq=False, kw_only=True)
class ContactComparison(ContactFlags):
    """The same crossings with three contacts and at several time steps.

    Arrays are ``(n_steps, n, 3)``: step factor, crossing, idealisation (the order of
    :data:`IDEALISATIONS`).

    Attributes
    ----------
    idealisations
        Names of the idealisations.
    step_factors
        Each crossing ran at these fractions of its own default step (the first is the
        reference of :meth:`step_sensitivity`).
    daf
        The crossing's DAF, the largest over its spans [-].
    min_contact_force_ratio
        Smallest contact force on the bridge over the static load [-]: below 0 a bilateral
        contact pulled the road down (outside validity); 0 when a tyre flew.
    flight_fraction
        Fraction of the time on the bridge with the truck off the road (modelled).
    dt
        Largest time step of each run [s].
    """

    idealisations: tuple[str, ...]
    step_factors: tuple[float, ...]
    daf: np.ndarray
    min_contact_force_ratio: np.ndarray
    flight_fraction: np.ndarray
    dt: np.ndarray

    def __len__(self) -> int:
        return int(self.daf.shape[1])

    def summary(self) -> pd.DataFrame:
        """One row per idealisation and step: DAF statistics and how many lost contact.

        Columns: ``crossings``, ``worst DAF``, ``mean DAF``, ``median DAF``, ``lost
        contact`` (a count) and its share ``lost contact [%]``, ``outside validity``
        (tensile contact, a count) and ``worst DAF, contact kept`` (over the crossings that
        never lost contact; NaN if none).
        """
        rows = []
        for s, factor in enumerate(self.step_factors):
            for k, name in enumerate(self.idealisations):
                daf = self.daf[s, :, k]
                lost = self.lost_contact[s, :, k]
                kept = daf[~lost]
                rows.append(
                    {
                        "idealisation": name,
                        "step factor": factor,
                        "crossings": daf.size,
                        "worst DAF": daf.max(),
                        "mean DAF": daf.mean(),
                        "median DAF": float(np.median(daf)),
                        "lost contact": int(lost.sum()),
                        "lost contact [%]": 100.0 * lost.mean(),
                        "outside validity": int(self.outside_validity[s, :, k].sum()),
                        "worst DAF, contact kept": kept.max() if kept.size else np.nan,
                    }
                )
        return pd.DataFrame(rows).set_index(["idealisation", "step factor"])

    def step_sensitivity(self) -> pd.DataFrame:
        """How far each crossing's DAF moved from the first step factor to the others.

        One row per idealisation and other step: the median and largest change of the DAF
        [%], how many crossings changed by more than 1 %, and how many of those lost
        contact.

        Raises
        ------
        ValueError
            The comparison ran at one step only.
        """
        if len(self.step_factors) < 2:
            raise ValueError(
                f"step_factors={self.step_factors} holds one step; run compare_contact with "
                "step_factors=(1.0, 0.5) to compare"
            )
        rows = []
        for s, factor in enumerate(self.step_factors[1:], start=1):
            for k, name in enumerate(self.idealisations):
                change = 100.0 * np.abs(self.daf[s, :, k] / self.daf[0, :, k] - 1.0)
                moved = change > 1.0
                rows.append(
                    {
                        "idealisation": name,
                        "step factor": factor,
                        "median change [%]": float(np.median(change)),
                        "largest change [%]": change.max(),
                        "changed by > 1 %": int(moved.sum()),
                        "of which lost contact": int((moved & self.lost_contact[0, :, k]).sum()),
                    }
                )
        return pd.DataFrame(rows).set_index(["idealisation", "step factor"])

    def crossings(self, step: int = 0) -> pd.DataFrame:
        """One row per crossing at one step: its DAF with each contact, side by side.

        Parameters
        ----------
        step
            Index into :attr:`step_factors` (0: each crossing's default step).

        Returns
        -------
        pandas.DataFrame
            Index ``crossing`` (the order of the inputs); columns ``DAF, <idealisation>``
            for each idealisation, ``min F_c / P, bilateral`` (the smallest contact force of
            the study's contact over the static load: below 0 it pulled the road down) and
            ``in the air [%], <idealisation>`` for the two that can fly.

        Raises
        ------
        IndexError
            ``step`` is not an index of :attr:`step_factors`.
        """
        if not -len(self.step_factors) <= step < len(self.step_factors):
            raise IndexError(
                f"step={step!r} must index step_factors={self.step_factors}; use 0 for the "
                "default step"
            )
        columns = {
            f"DAF, {name}": self.daf[step, :, k] for k, name in enumerate(self.idealisations)
        }
        columns["min F_c / P, bilateral"] = self.min_contact_force_ratio[step, :, 0]
        for k, name in enumerate(self.idealisations[1:], start=1):
            columns[f"in the air [%], {name}"] = 100.0 * self.flight_fraction[step, :, k]
        return pd.DataFrame(columns, index=pd.RangeIndex(len(self), name="crossing"))

    def to_dataframe(self) -> pd.DataFrame:
        """One row per crossing, idealisation and step factor, with the contact checks."""
        n_steps, n, k = self.daf.shape
        step, crossing, ideal = np.meshgrid(np.arange(n_steps), np.arange(n), np.arange(k),
                                            indexing="ij")  # fmt: skip
        return pd.DataFrame(
            {
                "crossing": crossing.ravel(),
                "idealisation": np.array(self.idealisations, dtype=object)[ideal.ravel()],
                "step factor": np.array(self.step_factors)[step.ravel()],
                "dt [s]": self.dt.ravel(),
                "daf": self.daf.ravel(),
                "min contact force ratio": self.min_contact_force_ratio.ravel(),
                "flight fraction": self.flight_fraction.ravel(),
                "outside validity": self.outside_validity.ravel(),
                "lost contact": self.lost_contact.ravel(),
            }
        )

    def plot(self, ax: Axes | None = None, kind: str = "daf") -> Axes:
        """Scatter of DAFs, crossing by crossing.

        ``kind="daf"``: each other idealisation against the first (the bilateral contact),
        at the first step; crossings in which the bilateral contact went tensile are
        filled, the others hollow.  ``kind="step"``: each idealisation at the second step
        against the first, the bilateral crossings that went tensile crossed
        (:func:`vbi_lib.validity.mark_lost_contact`).  Returns the axes.
        """
        import matplotlib.pyplot as plt

        if kind not in ("daf", "step"):
            raise ValueError(f"kind={kind!r} is not known; use 'daf' or 'step'")
        if kind == "step" and len(self.step_factors) < 2:
            raise ValueError("kind='step' needs a comparison run at two step factors")
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.6))
        if kind == "daf":
            x = self.daf[0, :, 0]
            tensile = self.outside_validity[0, :, 0]
            for k in range(1, len(self.idealisations)):
                for rows, fill, what in ((tensile, None, "went tensile"),
                                         (~tensile, "none", "kept")):  # fmt: skip
                    label = f"{self.idealisations[k]} (bilateral contact {what})"
                    ax.plot(x[rows], self.daf[0, rows, k], "o", ms=4, color=f"C{k}", mfc=fill,
                            label=label)  # fmt: skip
            ax.set_xlabel(f"DAF, {self.idealisations[0]} contact [-]")
            ax.set_ylabel("DAF, contact that can lift off [-]")
        else:
            x = self.daf[0]
            for k, name in enumerate(self.idealisations):
                ax.plot(x[:, k], self.daf[1, :, k], "o", ms=4, mfc="none", color=f"C{k}",
                        label=name)  # fmt: skip
            tensile = self.outside_validity[0, :, 0]  # the bilateral contact pulled the road
            mark_lost_contact(ax, x[:, 0], self.daf[1, :, 0], tensile, color="C0",
                              label="bilateral contact tensile (outside validity)")  # fmt: skip
            ax.set_xlabel(f"DAF at {self.step_factors[0]:g} x the default step [-]")
            ax.set_ylabel(f"DAF at {self.step_factors[1]:g} x the default step [-]")
        top = np.nanmax(self.daf) * 1.03
        ax.plot([1.0, top], [1.0, top], color="0.4", lw=0.8)
        ax.legend(loc="upper left", fontsize="small")
        return ax

    def __repr__(self) -> str:
        worst = ", ".join(
            f"{name} {self.daf[0, :, k].max():.2f}" for k, name in enumerate(self.idealisations)
        )
        lost = ", ".join(str(int(c)) for c in self.lost_contact[0].sum(axis=0))
        return f"ContactComparison({len(self)} crossings: worst DAF {worst}; lost contact {lost})"


def _run(columns: dict[str, list], vehicles: list, rows: np.ndarray, dt: float | None,
         model: str, modes: int | None) -> object:  # fmt: skip
    """``simulate_many`` on some rows; the comparison reports contact loss itself."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        return simulate_many(
            [columns["bridges"][i] for i in rows],
            [vehicles[i] for i in rows],
            [columns["profiles"][i] for i in rows],
            [columns["speeds"][i] for i in rows],
            [columns["bridge_starts"][i] for i in rows],
            model=model,
            modes=modes,
            dt=dt,
        )


def compare_contact(
    bridges: object,
    vehicles: Vehicle | Sequence[Vehicle],
    profiles: object,
    speeds: float | Sequence[float],
    bridge_starts: float | Sequence[float],
    *,
    model: str = "one-coordinate",
    modes: int | None = None,
    unsprung_fraction: float = 0.1,
    tyre_stiffness_ratio: float = 10.0,
    footprint: float = DEFAULT_FOOTPRINT,
    step_factors: Sequence[float] = (1.0, 0.5),
) -> ContactComparison:
    """Run crossings of the study's sprung mass with a bilateral contact, lifting off, on a tyre.

    Arguments broadcast as in :func:`vbi_lib.simulate_many` (lists of one length, or single
    values).  Each crossing runs three times (:func:`contact_variants`) at its own default
    time step, then again at ``factor`` times that step for every further factor; runs are
    batched with :func:`vbi_lib.simulate_many` (compiled, in parallel).

    Parameters
    ----------
    bridges, vehicles, profiles, speeds, bridge_starts
        As :func:`vbi_lib.simulate_many`; the vehicles are the study's sprung masses
        (:class:`~vbi_lib.Vehicle`).
    model, modes
        The crossing model (``"one-coordinate"``, the study's, or ``"modal"`` with
        ``modes``).
    unsprung_fraction, tyre_stiffness_ratio, footprint
        The quarter car's axle and tyre (:func:`contact_variants`).
    step_factors
        Fractions of each crossing's default step, each in (0, 1], the first the reference
        (default: the step and half of it).

    Returns
    -------
    ContactComparison

    Raises
    ------
    TypeError, ValueError
        A vehicle that is not a :class:`~vbi_lib.Vehicle`, bad ratios or step factors, or
        inputs :func:`vbi_lib.simulate_many` refuses (named in the message).

    Warns
    -----
    ContactLossWarning
        Once, when the bilateral contact became tensile in some crossings (their count).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> bridge = vbi.Bridge(20.0, 1, 4e9, 6000.0)
    >>> truck = vbi.Vehicle.from_frequency(2e4, 4.0, 0.1)
    >>> flat = vbi.Profile.flat(80.0, 0.02)
    >>> result = compare_contact(bridge, truck, flat, [15.0, 25.0], 50.0)
    >>> result.daf.shape, bool(result.lost_contact.any())
    ((2, 2, 3), False)
    """
    factors = tuple(check.positive("step factor", f) for f in step_factors)
    if not factors or any(f > 1.0 for f in factors):
        raise ValueError(
            f"step_factors={tuple(step_factors)!r} must be one or more fractions of the "
            "default step, each in (0, 1], e.g. (1.0, 0.5)"
        )
    args = {
        "bridges": bridges,
        "vehicles": vehicles,
        "profiles": profiles,
        "speeds": speeds,
        "bridge_starts": bridge_starts,
    }
    n, columns = broadcast(args, "compare_contact")
    variants = []
    for i, vehicle in enumerate(columns["vehicles"]):
        try:
            variants.append(contact_variants(vehicle, unsprung_fraction, tyre_stiffness_ratio,
                                             footprint))  # fmt: skip
        except TypeError as error:
            raise TypeError(f"vehicles[{i}]: {error}") from None
    shape = (len(factors), n, len(IDEALISATIONS))
    out = {name: np.full(shape, np.nan) for name in ("daf", "min", "flight", "dt")}
    every = np.arange(n)
    for k, name in enumerate(IDEALISATIONS):
        chosen = [v[name] for v in variants]
        default = _run(columns, chosen, every, None, model, modes)
        groups = [(step, np.flatnonzero(default.dt == step)) for step in np.unique(default.dt)]
        for s, factor in enumerate(factors):
            parts = [(default, every)] if factor == 1.0 else [
                (_run(columns, chosen, rows, factor * step, model, modes), rows)
                for step, rows in groups
            ]  # fmt: skip
            for result, rows in parts:
                out["daf"][s, rows, k] = np.nanmax(result.daf, axis=1)
                out["min"][s, rows, k] = result.min_contact_force_ratio
                out["flight"][s, rows, k] = result.flight_fraction
                out["dt"][s, rows, k] = result.dt
    comparison = ContactComparison(
        idealisations=IDEALISATIONS,
        step_factors=factors,
        daf=out["daf"],
        min_contact_force_ratio=out["min"],
        flight_fraction=out["flight"],
        dt=out["dt"],
    )
    tensile = int(comparison.outside_validity[0, :, 0].sum())
    if tensile:
        warnings.warn(
            f"{tensile} of {n} crossings lost contact with the bilateral contact (tensile "
            "contact force): their bilateral DAFs are outside the model's validity; the "
            "lift-off and quarter-car runs model the flight instead",
            ContactLossWarning,
            stacklevel=2,
        )
    for array in vars(comparison).values():
        if isinstance(array, np.ndarray):
            array.setflags(write=False)
    return comparison
