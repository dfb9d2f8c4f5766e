"""Propagation of a band spectrum from its reference distance: spherical spreading + absorption."""

import numpy as np
import openmdao.api as om

_LN10 = np.log(10.0)


class SphericalPropagationComp(om.ExplicitComponent):
    """
    Band levels at the observer from band levels defined at a reference distance r_ref.

    L(f, S) = L_ref(f) - 20 log10(S/r_ref) - alpha(f) S (docs theory/acoustics 'Propagation'):
    spherical spreading of a compact source (p ~ 1/S, e.g. Pierce, "Acoustics", 1989, sec. 4.1)
    and the ISO 9613-1:1993 atmospheric absorption over the whole hub-observer path S (alpha in
    dB/m from AtmosphericAbsorptionComp, taken at the band centre as ISO 9613-1 clause 8.2.1
    allows).

    Inputs
    ------
    source_spl : float, (num_rotors, num_bands), dB (units=None)
        Band levels at r_ref (absorption not included).
    distance : float, (num_rotors,), m
        Hub-observer distance S (> 0).
    absorption_coefficient : float, (num_bands,), dB/m (units=None)
        Atmospheric attenuation coefficient per band.

    Outputs
    -------
    spl : float, (num_rotors, num_bands), dB (units=None)
        Band levels at the observer.

    Options
    -------
    num_rotors, num_bands : int
    reference_distance : float
        r_ref, m (> 0).
    source_name, output_name : str
        Variable names of the source and observer spectra.
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1)
        self.options.declare("num_bands", default=38, types=int, lower=1)
        self.options.declare("reference_distance", default=100.0, types=(int, float), lower=1e-6)
        self.options.declare("source_name", default="source_spl", types=str)
        self.options.declare("output_name", default="spl", types=str)

    def setup(self):
        nr, nb = self.options["num_rotors"], self.options["num_bands"]
        src, out = self.options["source_name"], self.options["output_name"]
        self.add_input(src, val=np.zeros((nr, nb)), units=None, desc="Band levels at r_ref, dB")
        self.add_input("distance", val=np.full(nr, 100.0), units="m", desc="Hub-observer distance")
        self.add_input(
            "absorption_coefficient", val=np.zeros(nb), units=None, desc="Absorption, dB/m"
        )
        self.add_output(out, val=np.zeros((nr, nb)), units=None, desc="Band levels at observer, dB")
        rows = np.arange(nr * nb)
        self.declare_partials(out, src, rows=rows, cols=rows, val=1.0)
        self.declare_partials(out, "distance", rows=rows, cols=rows // nb)
        self.declare_partials(out, "absorption_coefficient", rows=rows, cols=rows % nb)

    def compute(self, inputs, outputs):
        S = inputs["distance"][:, None]
        r_ref = float(self.options["reference_distance"])
        outputs[self.options["output_name"]] = (
            inputs[self.options["source_name"]]
            - 20.0 * np.log10(S / r_ref)
            - inputs["absorption_coefficient"][None, :] * S
        )

    def compute_partials(self, inputs, partials):
        out = self.options["output_name"]
        nb = self.options["num_bands"]
        S = inputs["distance"][:, None]
        alpha = inputs["absorption_coefficient"][None, :]
        partials[out, "distance"] = (-20.0 / (S * _LN10) - alpha).ravel()
        partials[out, "absorption_coefficient"] = np.repeat(-inputs["distance"], nb)


class AbsorptionLossComp(om.ExplicitComponent):
    """
    Atmospheric absorption along the hub-observer path of levels already at the observer.

    L(r, m) = L_free(r, m) - alpha(r, m) S_r for every rotor r and entry m (docs
    theory/acoustics 'Propagation'): the tonal models (Lowson loading, Barry-Magliozzi
    thickness) give free-field levels at the observer (spherical spreading is in their 1/S
    kernels); ISO 9613-1:1993 adds the absorption alpha (dB/m, from AtmosphericAbsorptionComp at
    each harmonic's frequency) over the hub-observer distance S.

    Inputs
    ------
    <name>_free : float, (num_rotors, width), dB (units=None)
        Free-field (lossless) levels at the observer, for each name of option ``names``.
    distance : float, (num_rotors,), m
        Hub-observer distance S.
    absorption_coefficient : float, (num_rotors, width), dB/m (units=None)
        Attenuation coefficient of each entry.

    Outputs
    -------
    <name> : float, (num_rotors, width), dB (units=None)
        Levels at the observer with absorption.

    Options
    -------
    num_rotors, width : int
        Array sizes.
    names : list of str
        The level arrays (e.g. ['loading_spl', 'thickness_spl']).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1)
        self.options.declare("width", default=3, types=int, lower=1)
        self.options.declare("names", types=list, desc="level arrays")

    def setup(self):
        nr, w = self.options["num_rotors"], self.options["width"]
        self.add_input("distance", val=np.full(nr, 100.0), units="m", desc="Hub-observer distance")
        self.add_input(
            "absorption_coefficient", val=np.zeros((nr, w)), units=None, desc="Absorption, dB/m"
        )
        rows = np.arange(nr * w)
        for name in self.options["names"]:
            self.add_input(
                f"{name}_free", val=np.zeros((nr, w)), units=None, desc="Free-field level, dB"
            )
            self.add_output(name, val=np.zeros((nr, w)), units=None, desc="Level with absorption")
            self.declare_partials(name, f"{name}_free", rows=rows, cols=rows, val=1.0)
            self.declare_partials(name, "distance", rows=rows, cols=rows // w)
            self.declare_partials(name, "absorption_coefficient", rows=rows, cols=rows)

    def compute(self, inputs, outputs):
        loss = inputs["absorption_coefficient"] * inputs["distance"][:, None]
        for name in self.options["names"]:
            outputs[name] = inputs[f"{name}_free"] - loss

    def compute_partials(self, inputs, partials):
        w = self.options["width"]
        alpha = inputs["absorption_coefficient"]
        for name in self.options["names"]:
            partials[name, "distance"] = -alpha.ravel()
            partials[name, "absorption_coefficient"] = -np.repeat(inputs["distance"], w)
