"""Crossing models behind one driver, as ``scipy.integrate.solve_ivp`` keeps its methods.

:func:`simulate` and :func:`simulate_many` look the model up by name in :data:`MODELS` and run
the shared frame (:mod:`~vbi_lib.models.base`): input checks, node grid, peak refinement,
contact checks and result assembly.  Each model module holds only what differs, its kernel
and its default time step, and no model module imports another:

* :mod:`~vbi_lib.models.one_coordinate`: ``"one-coordinate"``, the study's two-degree-of-
  freedom model (33)-(99), RK4;
* :mod:`~vbi_lib.models.modal`: ``"modal"``, N exact beam modes, Newmark average
  acceleration.

Batches of crossings run on *lane kernels* (:mod:`~vbi_lib.models.lanes`,
:mod:`~vbi_lib.models.lanes_one_coordinate`, :mod:`~vbi_lib.models.lanes_modal`): a block
of crossings advances one step at a time on the CPU's SIMD lanes, each crossing over the
grid :func:`vbi_lib.simulate` would build (:mod:`~vbi_lib.models.grid`).

Results are :class:`~vbi_lib.models.results.Crossing` (a subclass per model) and
:class:`~vbi_lib.models.results.BatchResult`.
"""

from .base import CrossingModel
from .driver import MODELS, simulate, simulate_many
from .modal import Modal, ModalCrossing
from .one_coordinate import OneCoordinate, OneCoordinateCrossing, state_matrices
from .results import BatchResult, Crossing

__all__ = [
    "MODELS",
    "BatchResult",
    "Crossing",
    "CrossingModel",
    "Modal",
    "ModalCrossing",
    "OneCoordinate",
    "OneCoordinateCrossing",
    "simulate",
    "simulate_many",
    "state_matrices",
]
