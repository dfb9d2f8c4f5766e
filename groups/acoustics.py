"""Rotor aeroacoustics at an observer: the group assembly.

``RotorNoiseGroup`` assembles the acoustic components of ``lpc_mdo.components.acoustics`` for
``num_rotors`` rotors heard by one observer (paper Sec. III.E; docs
theory/acoustics). The plain functions for use outside an OpenMDAO model are
:func:`lpc_mdo.api.acoustics.rotor_noise` and
:func:`lpc_mdo.components.acoustics.a_weighting.a_weighting`.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.a_weighting import AWeightingComp
from lpc_mdo.components.acoustics.absorption import AtmosphericAbsorptionComp
from lpc_mdo.components.acoustics.bpm_broadband import BPMBroadbandComp
from lpc_mdo.components.acoustics.broadband import GillLeeBroadbandComp
from lpc_mdo.components.acoustics.common import (
    blade_counts,
    nominal_third_octave_bands,
    radial_quadrature,
)
from lpc_mdo.components.acoustics.loads import (
    HoverLoadDistributionComp,
    LoadFourierComp,
    default_load_harmonics,
    max_load_harmonics,
)
from lpc_mdo.components.acoustics.observer import ObserverGeometryComp, ObserverPositionComp
from lpc_mdo.components.acoustics.propagation import AbsorptionLossComp, SphericalPropagationComp
from lpc_mdo.components.acoustics.thickness import BarryMagliozziThicknessComp
from lpc_mdo.components.acoustics.tonal import LowsonLoadingNoiseComp, SearsGustLoadsComp
from lpc_mdo.components.acoustics.total import TotalNoiseComp
from lpc_mdo.core.checks import check_integer
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND
from lpc_mdo.vehicle.parts import BROADBAND_MODELS

__all__ = ["RotorNoiseGroup", "HOVER_NOISE_LIMIT_DBA"]

#: Paper hover noise constraint: total A-weighted SPL <= 70 dBA at the observer.
HOVER_NOISE_LIMIT_DBA = 70.0

#: Inputs with one row per rotor (first axis num_rotors); with several observers each
#: rotor-observer pair takes its rotor's row.
PER_ROTOR_INPUTS = (
    "radius", "rpm", "thrust", "torque", "thrust_per_span", "drag_per_span", "inflow_angle",
    "chord", "thickness_to_chord", "hub_position", "thrust_direction",
)  # fmt: skip


class RotorNoiseGroup(om.Group):
    """
    Tonal, broadband and total A-weighted noise of ``num_rotors`` rotors at one observer.

    Paper Sec. III.E (eqs. 19-22) with docs theory/acoustics:

    ``observer_position`` (ObserverPositionComp; only if observer_input = 'relative')
    -> ``geometry`` (ObserverGeometryComp: S, z, Y, Doppler r1, observer azimuth, speeds)
    -> ``blade_loads``, once per rotor whoever hears it: [``hover_loads``
    (HoverLoadDistributionComp; only if load_input = 'totals')] -> ``fourier``
    (LoadFourierComp, eqs. 19-20) -> [``sears`` (SearsGustLoadsComp)]
    -> ``loading`` (LowsonLoadingNoiseComp, eq. 21) · ``thickness`` (BarryMagliozziThicknessComp)
    -> ``tonal_absorption`` (AtmosphericAbsorptionComp at each harmonic) -> ``tonal_propagation``
    (AbsorptionLossComp: ISO 9613-1 absorption over the hub-observer path)
    · ``broadband`` (GillLeeBroadbandComp, eq. 22, or BPMBroadbandComp) -> [``band_absorption``,
    ``broadband_propagation``: spherical spreading and absorption from the reference distance]
    -> ``tonal_weighting``/``broadband_weighting`` (AWeightingComp, docs theory/acoustics
    'A-weighting') -> ``total_a`` and ``total`` (TotalNoiseComp, docs theory/acoustics 'Total
    noise').

    All variables are promoted. The hover constraint of the paper is ``total_spl_a`` <= 70 dBA
    (``HOVER_NOISE_LIMIT_DBA``) with the default observer (100 m from the rotor-hub centroid,
    45 deg below the rotor plane).

    Inputs
    ------
    radius, rpm, thrust : float, (num_rotors,), m, rpm, N
        Rotor radius, speed and thrust.
    torque : float, (num_rotors,), N*m
        Rotor torque (only with load_input = 'totals').
    thrust_per_span, drag_per_span : float, (num_rotors, num_radial, num_azimuth), N/m
        Sectional loads of one blade per unit span at the acoustic stations (load_input =
        'sectional'). From the BEM/Pitt-Peters blade-element outputs (all blades, per element,
        docs theory/rotors 'Loads and coefficients'): thrust_per_span = dT/(B dr), drag_per_span =
        dQ/(B r dr).
    inflow_angle : float, (num_rotors, num_radial, num_azimuth), rad
        Inflow angle at the stations (Sears gusts; load_input = 'sectional').
    chord : float, (num_rotors, num_radial), m
        Blade chord at the acoustic stations.
    thickness_to_chord : float, (num_rotors, num_radial), unitless
        Section t/c (default 0.12).
    hub_position, thrust_direction : float, (num_rotors, 3), m and unitless
        Hub positions and thrust axes in the body frame (x forward, y right, z down).
    observer_distance, observer_elevation, observer_azimuth : float, (num_observers,), m, rad, rad
        Observers about the hub centroid (observer_input = 'relative'); defaults 100 m, 45 deg
        below the rotor plane, 180 deg (aft).
    observer_position : float, (3,) or (num_observers, 3), m
        Observers in the body frame (an input when observer_input = 'position').
    flight_velocity : float, (3,), m/s
        Vehicle velocity in the body frame (zero in hover).
    density, speed_of_sound : float, (1,), kg/m**3 and m/s
        Atmosphere.

    Outputs (main ones; dB re 20 uPa, units=None):

    With ``num_observers`` n > 1 the per-rotor outputs below have n num_rotors rows,
    observer-major (row j num_rotors + k: rotor k heard by observer j; the components sit in
    the subgroup ``pairs``), and the totals one level per observer.

    Outputs
    -------
    total_spl_a : (num_observers,) dBA
        Total A-weighted level of all rotors at each observer (the hover constraint).
    total_spl : (num_observers,) dB
        Total unweighted level.
    rotor_spl_a, tonal_spl_a, broadband_oaspl_a : (num_rotors,) dBA
        Per-rotor total, tonal (loading + thickness) and broadband A-weighted levels.
    rotor_spl, tonal_spl, broadband_oaspl : (num_rotors,) dB
        The same, unweighted.
    loading_spl, thickness_spl, loading_spl_a, thickness_spl_a : (num_rotors, num_harmonics)
        Tonal levels per blade-passing harmonic, with the ISO 9613-1 absorption over the
        hub-observer path (``loading_spl_free``, ``thickness_spl_free``: without it);
        harmonic_frequency (Hz) gives m B rpm/60.
    broadband_spl, broadband_spl_a : (num_rotors, num_bands)
        Broadband band levels at ``band_frequencies`` (attribute, Hz).

    Options
    -------
    num_rotors, num_radial, num_azimuth, num_harmonics, num_bands : int
        Array sizes (defaults 1, 25, 1, 3, 38).
    num_observers : int
        Observers evaluated in one pass (default 1; docs theory/acoustics 'Several observers').
    num_blades : int or sequence of int
        Blades per rotor (default 2).
    num_load_harmonics : int or None
        Azimuthal load harmonics L of eq. 19 (None: min(10, (num_azimuth - 1)//2)).
    num_gust_harmonics : int
        Sears gust harmonics (default 10). gust_factor: q (default 0.06).
    loading_path : str
        'auto' (smooth Sears/unsteady switch on the in-plane speed), 'sears' or 'unsteady'.
    load_input : str
        'sectional' (default) or 'totals' (thrust and torque with an assumed hover load shape).
    observer_input : str
        'relative' (default) or 'position'.
    radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations (``common.radial_quadrature``).
    rotation_direction : tuple of int or None
        +1/-1 per rotor (azimuth convention of the unsteady path).
    lowest_band_frequency : float
        First one-third-octave band centre, Hz (default 12.5).
    broadband_model : str
        'gill_lee' (default, the paper's eq. 22) or 'bpm' (Brooks-Pope-Marcolini self-noise of
        the blade sections, which needs realistic sectional loads: an angle of attack above
        25 deg is an error).
    edgewise_broadband_correction : bool
        Gill-Lee edgewise adjustment (default True; zero in hover).
    """

    def initialize(self):
        self.options.declare(
            "num_observers",
            default=1,
            types=int,
            lower=1,
            desc="Number of observers; > 1 evaluates every rotor-observer pair in one pass",
        )
        self.options.declare(
            "broadband_reference_distance",
            default=100.0,
            types=(int, float),
            allow_none=True,
            desc="Distance (m) at which the Gill-Lee spectrum is the source spectrum; it is "
            "propagated to the observer by spherical spreading and ISO 9613-1 absorption. "
            "None: the observer distance enters the Gill-Lee f8 term directly (old form).",
        )
        opt = self.options
        opt.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        opt.declare(
            "num_blades",
            default=2,
            types=(int, tuple, list, np.ndarray),
            desc="Blades per rotor (int or one per rotor)",
        )
        opt.declare(
            "num_radial", default=25, types=int, lower=1, desc="Number of acoustic radial stations"
        )
        opt.declare(
            "num_azimuth",
            default=1,
            types=int,
            lower=1,
            desc="Number of azimuthal stations of the sectional loads",
        )
        opt.declare(
            "num_harmonics", default=3, types=int, lower=1, desc="Number of blade-passing harmonics"
        )
        opt.declare(
            "num_bands", default=38, types=int, lower=1, desc="Number of one-third-octave bands"
        )
        opt.declare(
            "lowest_band_frequency",
            default=12.5,
            types=(int, float),
            desc="Nominal centre of the first band, Hz",
        )
        opt.declare(
            "num_load_harmonics",
            default=None,
            types=int,
            allow_none=True,
            desc="Highest azimuthal load harmonic (None: all resolvable, <= 10)",
        )
        opt.declare(
            "num_gust_harmonics",
            default=10,
            types=int,
            lower=1,
            desc="Highest Sears gust load harmonic",
        )
        opt.declare(
            "gust_factor",
            default=0.06,
            types=(int, float),
            lower=0.0,
            desc="Sears gust amplification factor q",
        )
        opt.declare(
            "loading_path",
            default="auto",
            values=("auto", "sears", "unsteady"),
            desc="Loading-noise load model",
        )
        opt.declare(
            "load_input",
            default="sectional",
            values=("sectional", "totals"),
            desc="'sectional' loads or rotor 'totals' (thrust, torque)",
        )
        opt.declare(
            "observer_input",
            default="relative",
            values=("relative", "position"),
            desc="Observer given 'relative' to the hub centroid or as a 'position'",
        )
        opt.declare(
            "radial_stations",
            default=None,
            types=(np.ndarray, list, tuple),
            allow_none=True,
            desc="Radial stations r/R",
        )
        opt.declare(
            "radial_weights",
            default=None,
            types=(np.ndarray, list, tuple),
            allow_none=True,
            desc="Radial quadrature weights (fractions of R)",
        )
        opt.declare(
            "hub_radius_ratio", default=0.2, types=(int, float), desc="Hub radius / tip radius"
        )
        opt.declare(
            "rotation_direction",
            default=None,
            types=(tuple, list),
            allow_none=True,
            desc="+1/-1 per rotor",
        )
        opt.declare(
            "broadband_model",
            default="gill_lee",
            values=BROADBAND_MODELS,
            desc="Broadband model: 'gill_lee' (paper eq. 22) or 'bpm' (blade-section BPM "
            "self-noise, docs theory/acoustics 'BPM broadband model')",
        )
        opt.declare(
            "edgewise_broadband_correction",
            default=True,
            types=bool,
            desc="Gill-Lee edgewise adjustment",
        )

    def setup(self):
        opt = self.options
        nr, nrad, naz = opt["num_rotors"], opt["num_radial"], opt["num_azimuth"]
        no = opt["num_observers"]
        nm, nb = opt["num_harmonics"], opt["num_bands"]
        L = opt["num_load_harmonics"]
        if L is None:
            L = default_load_harmonics(naz)
        check_integer(
            "num_load_harmonics",
            L,
            lower=0,
            upper=max_load_harmonics(naz),
            allowed=f"in [0, (num_azimuth - 1)//2 = {max_load_harmonics(naz)}]",
            where=self.msginfo,
        )
        if opt["load_input"] == "totals" and naz != 1:
            raise ValueError(
                f"{self.msginfo}: load_input = 'totals' (assumed hover load shape) "
                f"needs num_azimuth = 1, got {naz}."
            )
        blades = blade_counts(opt["num_blades"], nr)
        rotation = opt["rotation_direction"]
        if rotation is not None and len(rotation) != nr:
            raise ValueError(
                f"{self.msginfo}: option 'rotation_direction' must hold num_rotors = {nr} "
                f"entries of +1 or -1, got {rotation!r}."
            )
        radial = {
            "num_radial": nrad,
            "radial_stations": opt["radial_stations"],
            "radial_weights": opt["radial_weights"],
            "hub_radius_ratio": opt["hub_radius_ratio"],
        }
        radial_quadrature(
            nrad, opt["radial_stations"], opt["radial_weights"], opt["hub_radius_ratio"]
        )  # validate once, early
        self.band_frequencies = nominal_third_octave_bands(nb, float(opt["lowest_band_frequency"]))
        path = opt["loading_path"]
        if opt["observer_input"] == "relative":
            self.add_subsystem(
                "observer_position",
                ObserverPositionComp(num_rotors=nr, num_observers=no),
                promotes=["*"] if no == 1 else ["hub_position", "observer_*"],
            )
        # The blade loads (the hover load shape, their Fourier harmonics, the Sears gusts) are
        # the rotors' own, whoever hears them: computed once per rotor, here.
        self.add_subsystem("blade_loads", om.Group(), promotes=["*"])
        if opt["load_input"] == "totals":
            self.blade_loads.add_subsystem(
                "hover_loads",
                HoverLoadDistributionComp(num_rotors=nr, num_blades=blades, **radial),
                promotes=["*"],
            )
        self.blade_loads.add_subsystem(
            "fourier",
            LoadFourierComp(num_rotors=nr, num_radial=nrad, num_azimuth=naz, num_load_harmonics=L),
            promotes=["*"],
        )
        if path != "unsteady":
            self.blade_loads.add_subsystem(
                "sears",
                SearsGustLoadsComp(
                    num_rotors=nr,
                    num_azimuth=naz,
                    num_gust_harmonics=opt["num_gust_harmonics"],
                    gust_factor=opt["gust_factor"],
                    **radial,
                ),
                promotes=["*"],
            )
        # Several observers: every rotor-observer pair is one "rotor" of the components below,
        # observer-major (row j nr + k is rotor k heard by observer j), in the subgroup 'pairs'
        # whose per-rotor inputs and blade loads take their rotor's values (configure). One
        # pass, vectorized.
        target = self if no == 1 else self.add_subsystem("pairs", om.Group())
        nr_pairs = nr * no
        blades = tuple(int(b) for b in blades) * no
        common = {"num_rotors": nr_pairs, "num_blades": blades}
        self._pair_setup = (target, nr, no)

        target.add_subsystem(
            "geometry",
            ObserverGeometryComp(
                num_rotors=nr_pairs,
                rotation_direction=None if rotation is None else tuple(rotation) * no,
                observer_per_rotor=no > 1,
            ),
            promotes=["*"],
        )
        target.add_subsystem(
            "loading",
            LowsonLoadingNoiseComp(
                **common,
                num_harmonics=nm,
                num_load_harmonics=L,
                num_gust_harmonics=opt["num_gust_harmonics"],
                loading_path=path,
                **radial,
            ),
            promotes=[("loading_spl", "loading_spl_free"), "*"],
        )
        target.add_subsystem(
            "thickness",
            BarryMagliozziThicknessComp(**common, num_harmonics=nm, **radial),
            promotes=[("thickness_spl", "thickness_spl_free"), "*"],
        )
        # ISO 9613-1 absorption of each harmonic over the hub-observer path (docs
        # theory/acoustics 'Propagation').
        target.add_subsystem(
            "tonal_absorption",
            AtmosphericAbsorptionComp(shape=(nr_pairs, nm)),
            promotes=[
                ("frequency", "harmonic_frequency"),
                ("absorption_coefficient", "harmonic_absorption_coefficient"),
                "*",
            ],
        )
        target.add_subsystem(
            "tonal_propagation",
            AbsorptionLossComp(
                num_rotors=nr_pairs, width=nm, names=["loading_spl", "thickness_spl"]
            ),
            promotes=[("absorption_coefficient", "harmonic_absorption_coefficient"), "*"],
        )
        band_options = {
            "num_bands": nb,
            "lowest_band_frequency": opt["lowest_band_frequency"],
            "reference_distance": opt["broadband_reference_distance"],
        }
        if opt["broadband_model"] == "bpm":
            broadband = BPMBroadbandComp(**common, num_azimuth=naz, **band_options, **radial)
        else:
            broadband = GillLeeBroadbandComp(
                **common,
                edgewise_correction=opt["edgewise_broadband_correction"],
                **band_options,
                **radial,
            )
        target.add_subsystem(
            "broadband",
            broadband,
            promotes=["*"]
            if opt["broadband_reference_distance"] is None
            else [("broadband_spl", "broadband_source_spl"), "*"],
        )
        if opt["broadband_reference_distance"] is not None:
            target.add_subsystem(
                "band_absorption",
                AtmosphericAbsorptionComp(shape=(nb,), frequencies=self.band_frequencies),
                promotes=[("absorption_coefficient", "band_absorption_coefficient"), "*"],
            )
            target.add_subsystem(
                "broadband_propagation",
                SphericalPropagationComp(
                    num_rotors=nr_pairs,
                    num_bands=nb,
                    reference_distance=opt["broadband_reference_distance"],
                    source_name="broadband_source_spl",
                    output_name="broadband_spl",
                ),
                promotes=[("absorption_coefficient", "band_absorption_coefficient"), "*"],
            )
        target.add_subsystem(
            "tonal_weighting",
            AWeightingComp(shape=(nr_pairs, nm), names=["loading_spl", "thickness_spl"]),
            promotes=[("frequency", "harmonic_frequency"), "*"],
        )
        target.add_subsystem(
            "broadband_weighting",
            AWeightingComp(
                shape=(nr_pairs, nb), names=["broadband_spl"], frequencies=self.band_frequencies
            ),
            promotes=["*"],
        )
        total_sizes = {
            "num_rotors": nr_pairs,
            "num_harmonics": nm,
            "num_bands": nb,
            "num_observers": no,
        }
        target.add_subsystem(
            "total_a", TotalNoiseComp(**total_sizes, weighting="A"), promotes=["*"]
        )
        target.add_subsystem(
            "total", TotalNoiseComp(**total_sizes, weighting="none"), promotes=["*"]
        )

        if no == 1:
            self._set_input_defaults()

    def _set_input_defaults(self):
        """
        Set one default value and unit of each input shared by several components.

        At the rotors' shapes; returns the names set.
        """
        opt = self.options
        nr, nrad, naz = opt["num_rotors"], opt["num_radial"], opt["num_azimuth"]
        self.set_input_defaults("radius", np.full(nr, 1.524), units="m")
        self.set_input_defaults("rpm", np.full(nr, 1200.0), units="rpm")
        self.set_input_defaults("chord", np.full((nr, nrad), 0.2), units="m")
        self.set_input_defaults("density", SEA_LEVEL_DENSITY, units="kg/m**3")
        self.set_input_defaults("speed_of_sound", SEA_LEVEL_SPEED_OF_SOUND, units="m/s")
        self.set_input_defaults("hub_position", np.zeros((nr, 3)), units="m")
        names = {"radius", "rpm", "chord", "density", "speed_of_sound", "hub_position"}
        bpm = opt["broadband_model"] == "bpm"
        if opt["load_input"] == "totals" or not bpm:  # the Gill-Lee model takes the thrust
            self.set_input_defaults("thrust", np.full(nr, 5000.0), units="N")
            names.add("thrust")
        if opt["load_input"] == "sectional" and (opt["loading_path"] != "unsteady" or bpm):
            self.set_input_defaults("inflow_angle", np.full((nr, nrad, naz), 0.1), units="rad")
            names.add("inflow_angle")
        if opt["load_input"] == "sectional" and bpm:
            self.set_input_defaults("thrust_per_span", np.full((nr, nrad, naz), 100.0), units="N/m")
            names.add("thrust_per_span")
        return names

    def configure(self):
        """Several observers: the pairs' per-rotor inputs take the rotors' values."""
        target, nr, no = self._pair_setup
        if no == 1:
            return
        meta = target.get_io_metadata(iotypes="input", metadata_keys=["val", "units"])
        outputs = {m["prom_name"] for m in target.get_io_metadata(iotypes="output").values()}
        # Inputs the pairs' own outputs feed stay inside.
        inputs = {m["prom_name"]: m for m in meta.values() if m["prom_name"] not in outputs}
        rotor_rows = np.tile(np.arange(nr), no)  # pair j nr + k <- rotor k
        observer_rows = np.repeat(np.arange(no), nr)  # pair j nr + k <- observer j
        loads = self.blade_loads.get_io_metadata(iotypes="output", metadata_keys=["shape"])
        load_shapes = {m["prom_name"]: m["shape"] for m in loads.values()}
        defaults = {}  # the components' own defaults, at the rotors' (observers') shapes
        for name, m in sorted(inputs.items()):
            if name in load_shapes:  # a blade load of the pair's rotor
                index = (rotor_rows,) + (slice(None),) * (len(load_shapes[name]) - 1)
                self.connect(name, f"pairs.{name}", src_indices=om.slicer[index])
                continue
            if name == "observer_position":
                if self.options["observer_input"] == "relative":
                    self.connect(
                        "observer_position",
                        "pairs.observer_position",
                        src_indices=om.slicer[observer_rows, :],
                    )
                    continue
                rows, src_shape = observer_rows, (no, 3)
                defaults[name] = (m["val"][::nr], m["units"])
            elif name in PER_ROTOR_INPUTS:
                rows, src_shape = rotor_rows, (nr,) + m["val"].shape[1:]
                defaults[name] = (m["val"][:nr], m["units"])
            else:
                self.promotes("pairs", inputs=[name])
                continue
            self.promotes(
                "pairs",
                inputs=[name],
                src_indices=om.slicer[(rows,) + (slice(None),) * (len(src_shape) - 1)],
                src_shape=src_shape,
            )
        self.promotes("pairs", outputs=["*"])
        set_here = self._set_input_defaults()
        for name, (value, units) in defaults.items():
            if name not in set_here:
                self.set_input_defaults(name, value, units=units)
