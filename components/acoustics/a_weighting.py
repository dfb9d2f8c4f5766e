"""A-weighting of sound pressure levels (IEC 61672-1 analytic A-weighting curve)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import DB_PER_NEPER
from lpc_mdo.core.checks import check_range

# Pole frequencies of the IEC 61672-1 (Annex E) A-weighting, Hz.
_F1, _F2, _F3, _F4 = 20.598997, 107.65265, 737.86223, 12194.217


def _log_response(frequency):
    """
    Return the natural logarithm of the A-weighting response R_A(f), up to a constant.

    R_A = f4**2 f**4/((f**2+f1**2) sqrt((f**2+f2**2)(f**2+f3**2)) (f**2+f4**2)).
    """
    f2 = frequency * frequency
    return (
        4.0 * np.log(frequency)
        - np.log(f2 + _F1**2)
        - 0.5 * np.log(f2 + _F2**2)
        - 0.5 * np.log(f2 + _F3**2)
        - np.log(f2 + _F4**2)
    )


_LOG_RESPONSE_1000 = _log_response(1000.0)


def a_weighting(frequency):
    """
    A-weighting A(f) in dB at frequency ``frequency`` (Hz, > 0), array-like.

    A(f) = 20 log10(R_A(f)/R_A(1000 Hz)) with the analytic IEC 61672-1 response
    R_A(f) = f4**2 f**4/[(f**2 + f1**2) sqrt((f**2 + f2**2)(f**2 + f3**2)) (f**2 + f4**2)],
    f1..f4 = 20.599, 107.65, 737.86, 12194.2 Hz (docs theory/acoustics 'A-weighting'; the
    normalisation is exact, so A(1000) = 0; IEC writes it as + 2.00 dB). Complex-step safe.
    Examples: A(100) = -19.15, A(1000) = 0.0, A(10000) = -2.49 dB.
    """
    frequency = np.asarray(frequency)
    check_range("frequency", frequency, lower=0.0, lower_open=True, units="Hz", where="a_weighting")
    return 2.0 * DB_PER_NEPER * (_log_response(frequency) - _LOG_RESPONSE_1000)


def a_weighting_derivative(frequency):
    """dA/df in dB/Hz of :func:`a_weighting` (analytic)."""
    f = np.asarray(frequency)
    f2 = f * f
    dlog = (
        4.0 / f
        - 2.0 * f / (f2 + _F1**2)
        - f / (f2 + _F2**2)
        - f / (f2 + _F3**2)
        - 2.0 * f / (f2 + _F4**2)
    )
    return 2.0 * DB_PER_NEPER * dlog


class AWeightingComp(om.ExplicitComponent):
    """
    A-weighted levels SPL_A = SPL + A(f) for one or more level arrays of a common shape.

    Implements docs theory/acoustics 'A-weighting' (project default): each tonal harmonic is
    weighted at its own frequency m B rpm/60 and broadband noise per one-third-octave band at the
    band centre (docs theory/acoustics 'Broadband noise'). The A(f) curve is
    :func:`a_weighting`.

    Inputs
    ------
    <name> : float, ``shape``, dB (units=None)
        Unweighted level, dB re 20 uPa, for each name in option ``names``.
    frequency : float, ``shape``, Hz
        Frequency of each level (only when option ``frequencies`` is None, e.g. tonal harmonics
        whose frequency follows the rpm).

    Outputs
    -------
    <name>_a : float, ``shape``, dBA (units=None)
        A-weighted level, dB re 20 uPa, for each name in ``names``.

    Options
    -------
    shape : tuple of int
        Shape of every level array, e.g. (num_rotors, num_harmonics).
    names : list of str
        Names of the level inputs. Default ['spl'].
    frequencies : array or None
        Fixed frequencies in Hz broadcastable to ``shape`` (e.g. band centres of shape
        (num_bands,)). None (default): frequency is an input.
    """

    def initialize(self):
        self.options.declare("shape", types=tuple, desc="Shape of every level array")
        self.options.declare(
            "names",
            default=["spl"],
            types=list,
            desc="Names of the level inputs; outputs are <name>_a",
        )
        self.options.declare(
            "frequencies",
            default=None,
            types=np.ndarray,
            allow_none=True,
            desc="Fixed frequencies (Hz), broadcastable to shape; None: input",
        )

    def setup(self):
        shape = self.options["shape"]
        size = int(np.prod(shape))
        fixed = self.options["frequencies"]
        if fixed is None:
            self.add_input(
                "frequency", val=np.full(shape, 1000.0), units="Hz", desc="Frequency of each level"
            )
        else:
            try:
                fixed = np.broadcast_to(np.asarray(fixed, dtype=float), shape)
            except ValueError:
                raise ValueError(
                    f"{self.msginfo}: option 'frequencies' of shape "
                    f"{np.shape(self.options['frequencies'])} does not broadcast to "
                    f"shape {shape}."
                ) from None
            self._weights = a_weighting(fixed)
        for name in self.options["names"]:
            self.add_input(
                name, val=np.zeros(shape), units=None, desc="Unweighted level, dB re 20 uPa"
            )
            self.add_output(
                f"{name}_a", val=np.zeros(shape), units=None, desc="A-weighted level, dBA re 20 uPa"
            )
            self.declare_partials(f"{name}_a", name, diagonal=True, val=np.ones(size))
            if fixed is None:
                self.declare_partials(f"{name}_a", "frequency", diagonal=True)

    def compute(self, inputs, outputs):
        if self.options["frequencies"] is None:
            freq = inputs["frequency"]
            check_range(
                "frequency",
                freq,
                lower=0.0,
                lower_open=True,
                units="Hz",
                error=om.AnalysisError,
                where=self.msginfo,
            )
            weights = a_weighting(freq)
        else:
            weights = self._weights
        for name in self.options["names"]:
            outputs[f"{name}_a"] = inputs[name] + weights

    def compute_partials(self, inputs, partials):
        if self.options["frequencies"] is None:
            dweight = a_weighting_derivative(inputs["frequency"]).ravel()
            for name in self.options["names"]:
                partials[f"{name}_a", "frequency"] = dweight
