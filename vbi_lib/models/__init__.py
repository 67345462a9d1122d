"""Crossing models behind one driver, as ``scipy.integrate.solve_ivp`` keeps its methods.

:func:`simulate` and :func:`simulate_many` look the model up by name in :data:`MODELS` and run
the shared frame (:mod:`~vbi_lib.models.base`): input checks, node grid, peak refinement,
contact checks and result assembly.  Each model module holds only what differs, its kernel
and its default time step, and no model module imports another:

* :mod:`~vbi_lib.models.one_coordinate`: ``"one-coordinate"``, the study's two-degree-of-
  freedom model (33)-(99), RK4;
* :mod:`~vbi_lib.models.modal`: ``"modal"``, N exact beam modes of any layout of spans,
  Newmark average acceleration.

Each model integrates any vehicle of :mod:`vbi_lib.vehicles` with its general kernel
(:mod:`~vbi_lib.models.coordinate_kernel`, :mod:`~vbi_lib.models.modal_kernel`; shared axle
bookkeeping and event location in :mod:`~vbi_lib.models.axles`); the study's sprung mass
keeps each model's compiled sprung-mass kernel.

Results are :class:`~vbi_lib.models.results.Crossing` (a subclass per model) and
:class:`~vbi_lib.models.results.BatchResult`; responses at sections, computed after the run
(:mod:`~vbi_lib.models.sections`), are :class:`~vbi_lib.models.sections.SectionResponse`.
"""

from .base import CrossingModel
from .driver import MODELS, simulate, simulate_many
from .modal import Modal, ModalCrossing
from .one_coordinate import OneCoordinate, OneCoordinateCrossing, state_matrices
from .results import BatchResult, Crossing
from .sections import SectionResponse

__all__ = [
    "MODELS",
    "BatchResult",
    "Crossing",
    "CrossingModel",
    "Modal",
    "ModalCrossing",
    "OneCoordinate",
    "OneCoordinateCrossing",
    "SectionResponse",
    "simulate",
    "simulate_many",
    "state_matrices",
]
