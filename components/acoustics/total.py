"""Energetic (incoherent) summation of tonal and broadband levels to rotor and total levels."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import SPL_FLOOR


def energetic_sum(levels, axis=None):
    """10 log10(sum 10**(L/10)) over ``axis`` (dB); complex-step safe."""
    return 10.0 * np.log10(np.sum(10.0 ** (np.asarray(levels) / 10.0), axis=axis))


class TotalNoiseComp(om.ExplicitComponent):
    """
    Incoherent sum over harmonics, sources and rotors to per-rotor and total levels.

    docs theory/acoustics 'Total noise' and paper eq. 21: with E = 10**(L/10),

    - tonal_spl_r = 10 log10 sum_m (E(loading_rm) + E(thickness_rm))   (docs theory/acoustics
      'Total noise');
    - broadband_oaspl_r = 10 log10 sum_b E(broadband_rb)               (docs theory/acoustics
      'Broadband noise' OASPL);
    - rotor_spl_r = 10 log10(E(tonal_r) + E(broadband_r));
    - total_spl = 10 log10 sum_r E(rotor_spl_r)  (the hover constraint: total_spl_a <= 70 dBA).

    With ``num_observers`` = n_o > 1 the rows are rotor-observer pairs, observer-major (row
    j n + k is rotor k heard by observer j, n = num_rotors / n_o), and ``total_spl`` holds one
    level per observer (the sum over that observer's rows).

    The total is invariant to the order of the rotors and two identical sources add
    10 log10 2 = 3.0103 dB. The sums carry the -120 dB floor of ``common`` once, so they stay
    finite when every source is silent.

    Inputs (names carry the suffix '_a' when option ``weighting`` is 'A'):

    Inputs
    ------
    loading_spl<sfx> : float, (num_rotors, num_harmonics), dB (units=None)
        Loading-noise level per harmonic, dB re 20 uPa.
    thickness_spl<sfx> : float, (num_rotors, num_harmonics), dB (units=None)
        Thickness-noise level per harmonic, dB re 20 uPa.
    broadband_spl<sfx> : float, (num_rotors, num_bands), dB (units=None)
        Broadband one-third-octave band levels, dB re 20 uPa.

    Outputs
    -------
    tonal_spl<sfx> : float, (num_rotors,), dB (units=None)
        Tonal (loading + thickness) level of each rotor.
    broadband_oaspl<sfx> : float, (num_rotors,), dB (units=None)
        Broadband overall level of each rotor.
    rotor_spl<sfx> : float, (num_rotors,), dB (units=None)
        Total level of each rotor.
    total_spl<sfx> : float, (num_observers,), dB (units=None)
        Total level of all rotors at each observer.

    Options
    -------
    num_rotors, num_harmonics, num_bands : int
        Array sizes (num_rotors: rows, i.e. rotor-observer pairs with several observers).
    num_observers : int
        Observers (>= 1, divides num_rotors). Default 1.
    weighting : str
        'A' (A-weighted levels, names end in '_a', dBA) or 'none' (unweighted, dB).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_harmonics", default=3, types=int, lower=1, desc="Number of blade-passing harmonics"
        )
        self.options.declare(
            "num_bands", default=38, types=int, lower=1, desc="Number of one-third-octave bands"
        )
        self.options.declare(
            "num_observers", default=1, types=int, lower=1, desc="Number of observers"
        )
        self.options.declare(
            "weighting",
            default="A",
            values=("A", "none"),
            desc="'A': A-weighted levels (suffix _a); 'none': unweighted",
        )

    def setup(self):
        nr, nm, nb = (self.options[k] for k in ("num_rotors", "num_harmonics", "num_bands"))
        no = self.options["num_observers"]
        if nr % no:
            raise ValueError(
                f"{self.msginfo}: num_rotors = {nr} rows must be num_observers = {no} equal "
                "groups (rotor-observer pairs, observer-major)."
            )
        self._observer_of_row = np.repeat(np.arange(no), nr // no)
        weighted = self.options["weighting"] == "A"
        sfx = "_a" if weighted else ""
        unit = "dBA" if weighted else "dB"
        self._names = {
            k: f"{k}{sfx}"
            for k in (
                "loading_spl",
                "thickness_spl",
                "broadband_spl",
                "tonal_spl",
                "broadband_oaspl",
                "rotor_spl",
                "total_spl",
            )
        }
        n = self._names
        wtxt = "A-weighted " if weighted else ""
        self.add_input(
            n["loading_spl"],
            val=np.zeros((nr, nm)),
            units=None,
            desc=f"{wtxt}loading-noise level per harmonic, {unit} re 20 uPa",
        )
        self.add_input(
            n["thickness_spl"],
            val=np.zeros((nr, nm)),
            units=None,
            desc=f"{wtxt}thickness-noise level per harmonic, {unit} re 20 uPa",
        )
        self.add_input(
            n["broadband_spl"],
            val=np.zeros((nr, nb)),
            units=None,
            desc=f"{wtxt}broadband band levels, {unit} re 20 uPa",
        )
        self.add_output(
            n["tonal_spl"],
            val=np.zeros(nr),
            units=None,
            desc=f"{wtxt}tonal level of each rotor, {unit} re 20 uPa",
        )
        self.add_output(
            n["broadband_oaspl"],
            val=np.zeros(nr),
            units=None,
            desc=f"{wtxt}broadband overall level of each rotor, {unit} re 20 uPa",
        )
        self.add_output(
            n["rotor_spl"],
            val=np.zeros(nr),
            units=None,
            desc=f"{wtxt}total level of each rotor, {unit} re 20 uPa",
        )
        self.add_output(
            n["total_spl"],
            val=np.zeros(no),
            units=None,
            desc=f"{wtxt}total level of all rotors at each observer, {unit} re 20 uPa",
        )

        for src, width in (("loading_spl", nm), ("thickness_spl", nm), ("broadband_spl", nb)):
            rows = np.repeat(np.arange(nr), width)
            cols = np.arange(nr * width)
            targets = ["rotor_spl", "tonal_spl" if src != "broadband_spl" else "broadband_oaspl"]
            for out in targets:
                self.declare_partials(n[out], n[src], rows=rows, cols=cols)
            self.declare_partials(
                n["total_spl"], n[src], rows=np.repeat(self._observer_of_row, width), cols=cols
            )

    def _energies(self, inputs):
        n = self._names
        e_l = 10.0 ** (inputs[n["loading_spl"]] / 10.0)
        e_t = 10.0 ** (inputs[n["thickness_spl"]] / 10.0)
        e_b = 10.0 ** (inputs[n["broadband_spl"]] / 10.0)
        return e_l, e_t, e_b

    def compute(self, inputs, outputs):
        n = self._names
        e_l, e_t, e_b = self._energies(inputs)
        tonal = np.sum(e_l + e_t, axis=1)
        broad = np.sum(e_b, axis=1)
        # Energies are mean squares in units of p_ref**2, so the floor of ``common`` adds here.
        to_spl = self._to_spl
        outputs[n["tonal_spl"]] = to_spl(tonal)
        outputs[n["broadband_oaspl"]] = to_spl(broad)
        outputs[n["rotor_spl"]] = to_spl(tonal + broad)
        outputs[n["total_spl"]] = to_spl(self._per_observer(tonal + broad))

    def _per_observer(self, energy):
        """Sum of row energies per observer (num_observers,)."""
        no = self.options["num_observers"]
        return np.sum(energy.reshape(no, -1), axis=1)

    @staticmethod
    def _to_spl(energy):
        return 10.0 * np.log10(energy + SPL_FLOOR)

    def compute_partials(self, inputs, partials):
        n = self._names
        e_l, e_t, e_b = self._energies(inputs)
        tonal = np.sum(e_l + e_t, axis=1)
        broad = np.sum(e_b, axis=1)
        rotor = tonal + broad
        total = self._per_observer(rotor)[self._observer_of_row]
        # d(10 log10(E + floor))/dL_j = E_j/(E + floor) since dE_j/dL_j = E_j ln10/10.
        for src, e in (("loading_spl", e_l), ("thickness_spl", e_t), ("broadband_spl", e_b)):
            group = broad if src == "broadband_spl" else tonal
            out = "broadband_oaspl" if src == "broadband_spl" else "tonal_spl"
            partials[n[out], n[src]] = (e / (group + SPL_FLOOR)[:, None]).ravel()
            partials[n["rotor_spl"], n[src]] = (e / (rotor + SPL_FLOOR)[:, None]).ravel()
            partials[n["total_spl"], n[src]] = (e / (total + SPL_FLOOR)[:, None]).ravel()
