r"""Measuring amplification in the field: the public namespace of three small modules.

``from vbi_lib import monitoring as mon`` gives every tool of the study's chapter on in-situ
measurement (chapter 11):

* :mod:`~vbi_lib.monitoring.inertia`: why a displacement gauge reads more amplification than
  a strain gauge (equations 19-31): ``DAF_d = A_v + 48 r / pi^4``, ``DAF_s = A_v + 4 r / pi^2``
  for the first mode, :func:`displacement_daf`, :func:`strain_daf`,
  :func:`extra_amplification_ratio`;
* :mod:`~vbi_lib.monitoring.records`: the DAF of recorded events in service, estimated by a
  zero-phase low-pass filter (:func:`daf_from_record`, one :class:`RecordDAFs` result for
  one record or many);
* :mod:`~vbi_lib.monitoring.filtering`: the filter and the first-frequency estimate it uses
  (:func:`lowpass`, :func:`estimate_first_frequency`);
* :mod:`~vbi_lib.monitoring.synthetic`: gauge records made from simulated crossings, with
  noise and drift (:func:`record_from_crossing`);
* :mod:`~vbi_lib.monitoring.load_tests`: the DAF per gauge, speed and run of a load test with
  crawl runs or a parked truck (:func:`daf_from_load_test`), the definition (17).
"""

from __future__ import annotations

from .filtering import (
    DEFAULT_FILTER_ORDER,
    MIN_CUTOFF_PERIODS,
    estimate_first_frequency,
    lowpass,
)
from .inertia import (
    DISPLACEMENT_INERTIA_COEFFICIENT,
    STRAIN_INERTIA_COEFFICIENT,
    displacement_daf,
    extra_amplification_ratio,
    inertia_ratio,
    plot_extra_amplification,
    strain_daf,
)
from .load_tests import daf_from_load_test
from .records import MIN_SAMPLES_PER_CYCLE, RecordDAF, RecordDAFs, daf_from_record
from .synthetic import record_from_crossing

__all__ = [
    "DEFAULT_FILTER_ORDER",
    "DISPLACEMENT_INERTIA_COEFFICIENT",
    "MIN_CUTOFF_PERIODS",
    "MIN_SAMPLES_PER_CYCLE",
    "STRAIN_INERTIA_COEFFICIENT",
    "RecordDAF",
    "RecordDAFs",
    "daf_from_load_test",
    "daf_from_record",
    "displacement_daf",
    "estimate_first_frequency",
    "extra_amplification_ratio",
    "inertia_ratio",
    "lowpass",
    "plot_extra_amplification",
    "record_from_crossing",
    "strain_daf",
]
