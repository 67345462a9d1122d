r"""Measuring amplification in the field: the public namespace of a few small modules.

``from vbi_lib import monitoring as mon`` gives every tool of the study's chapter on in-situ
measurement (chapter 11):

* :mod:`~vbi_lib.monitoring.inertia`: why a displacement gauge reads more amplification than
  a strain gauge (equations 19-31): ``DAF_d = A_v + 48 eta / pi^4``,
  ``DAF_s = A_v + 4 eta / pi^2``
  for the first mode, :func:`displacement_daf`, :func:`strain_daf`,
  :func:`extra_amplification_ratio`;
* :mod:`~vbi_lib.monitoring.records`: the DAF of recorded events in service
  (:func:`daf_from_record`), the peak over a quasi-static estimate made by a zero-phase
  low-pass filter (smooth records), a fitted influence line (kinked strain records) or a
  crawl run; one :class:`RecordDAFs` result (:mod:`~vbi_lib.monitoring.record_results`)
  for one record or many;
* :mod:`~vbi_lib.monitoring.influence`: the influence line of a gauge's response to a
  vehicle's axles (:func:`influence_line`, :class:`Axles`) and its least-squares fit to a
  record;
* :mod:`~vbi_lib.monitoring.filtering`: the filter, the first-frequency estimate and the
  noise level (:func:`lowpass`, :func:`estimate_first_frequency`, :func:`noise_std`);
* :mod:`~vbi_lib.monitoring.synthetic`: gauge records made from simulated crossings, with
  noise and drift (:func:`record_from_crossing`);
* :mod:`~vbi_lib.monitoring.load_tests`: the DAF per gauge, speed and run of a load test with
  crawl runs or a parked truck (:func:`daf_from_load_test`), the definition (17);
* :mod:`~vbi_lib.monitoring.trials`: the methods tried on simulated crossings whose true DAF
  is known (:func:`crawl_static`, :func:`gauge_trial`, :func:`filter_trial`,
  :func:`strain_trial`, :func:`load_test_trial`).
"""

from __future__ import annotations

from .filtering import (
    DEFAULT_FILTER_ORDER,
    MIN_CUTOFF_PERIODS,
    estimate_first_frequency,
    lowpass,
    noise_std,
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
from .influence import RESPONSES, SPEED_BOUNDS, Axles, influence_line
from .load_tests import daf_from_load_test
from .record_results import RecordDAF, RecordDAFs
from .records import (
    MAX_CRAWL_RESIDUAL,
    MAX_EVENT_PASSAGES,
    MAX_FIT_RESIDUAL,
    MAX_FIT_RESIDUAL_SPEED_SEARCHED,
    MAX_PLAUSIBLE_DAF,
    MIN_EVENT_SNR,
    MIN_FREQUENCY_RATIO,
    MIN_SAMPLES_PER_CYCLE,
    NOISE_PEAK_TOLERANCE,
    daf_from_record,
)
from .synthetic import record_from_crossing
from .trials import (
    CRAWL_SPEED,
    crawl_static,
    filter_trial,
    gauge_trial,
    load_test_trial,
    strain_trial,
)

__all__ = [
    "CRAWL_SPEED",
    "DEFAULT_FILTER_ORDER",
    "DISPLACEMENT_INERTIA_COEFFICIENT",
    "MAX_CRAWL_RESIDUAL",
    "MAX_EVENT_PASSAGES",
    "MAX_FIT_RESIDUAL",
    "MAX_FIT_RESIDUAL_SPEED_SEARCHED",
    "MAX_PLAUSIBLE_DAF",
    "MIN_CUTOFF_PERIODS",
    "MIN_EVENT_SNR",
    "MIN_FREQUENCY_RATIO",
    "MIN_SAMPLES_PER_CYCLE",
    "NOISE_PEAK_TOLERANCE",
    "RESPONSES",
    "SPEED_BOUNDS",
    "STRAIN_INERTIA_COEFFICIENT",
    "Axles",
    "RecordDAF",
    "RecordDAFs",
    "crawl_static",
    "daf_from_load_test",
    "daf_from_record",
    "displacement_daf",
    "estimate_first_frequency",
    "extra_amplification_ratio",
    "filter_trial",
    "gauge_trial",
    "inertia_ratio",
    "influence_line",
    "load_test_trial",
    "lowpass",
    "noise_std",
    "plot_extra_amplification",
    "record_from_crossing",
    "strain_daf",
    "strain_trial",
]
