"""Rotor blade geometry: radial and azimuthal stations, chord and twist from B-splines.

docs theory/rotors 'Blade parameterization' (BladeAD ``BsplineParameterization``) and docs
theory/rotors 'Stations and disk frame' (stations). The names of the outputs (``hub_radius``,
``station_radius``, ``station_width``,
``azimuth``, ``chord``, ``twist``) are the interface of the rotor models (BEM, Pitt–Peters) and of
the rotor acoustics; keep them stable.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.bspline import BsplineComp
from lpc_mdo.core.checks import check_choice, check_integer, check_range

#: Radial-quadrature choices of :class:`BladeStationsComp` (docs theory/rotors 'Stations and disk
#: frame', 'Loads and coefficients', 'Public-code compatibility').
QUADRATURES = ("midpoint", "bladead")
#: Where the B-spline values are placed (docs theory/rotors 'Blade parameterization').
SPLINE_STATIONS = ("as_coded", "element_centres")
#: Outputs of :class:`BladeGeometryGroup` that the rotor models read (all but the azimuth).
BLADE_OUTPUTS = ("hub_radius", "station_radius", "station_width", "chord", "twist")


def per_rotor(
    value, num_rotors, name, kind=float, lower=None, upper=None, upper_open=False, owner=""
):
    """
    Broadcast a scalar or per-rotor option to an array (num_rotors,) and check its range.

    Parameters
    ----------
    value : scalar or sequence
        One value for all rotors or one per rotor.
    num_rotors : int
        Number of rotors.
    name : str
        Option name, for the error message.
    kind : type
        float or int.
    lower, upper : float or None
        Inclusive lower bound; upper bound (exclusive when ``upper_open``).
    upper_open : bool
        Whether the upper bound is excluded.
    owner : str
        Prefix of the error message (e.g. the component's msginfo).

    Returns
    -------
    ndarray, (num_rotors,)

    Raises
    ------
    ValueError
        Naming the option, the value and the allowed range or shape.
    """
    where = f"{owner}: " if owner else ""
    arr = np.asarray(value)
    if arr.ndim == 0:
        arr = np.full(num_rotors, arr)
    if arr.shape != (num_rotors,):
        raise ValueError(
            f"{where}option '{name}' = {np.asarray(value).tolist()} must be a "
            f"scalar or have num_rotors = {num_rotors} entries."
        )
    check_range(name, arr, lower=lower, upper=upper, upper_open=upper_open, where=owner)
    if kind is int:
        for i, entry in enumerate(arr.tolist()):
            check_integer(f"{name}[{i}]", entry, where=owner)
        return arr.astype(int)
    return arr.astype(float)


def azimuth_angles(num_azimuth):
    """
    Return the azimuthal stations psi_k = 2 pi k / N_psi, k = 0..N_psi-1, rad.

    See docs theory/rotors 'Stations and disk frame'.
    """
    return 2.0 * np.pi * np.arange(num_azimuth) / num_azimuth


def station_fractions(num_radial, quadrature="midpoint"):
    """
    Element centres and quadrature weights as fractions of the blade length R - r_h.

    r_i = r_h + (R - r_h) eta_i and int f dr ~ (R - r_h) sum_i q_i f(r_i), with
    eta_i = (i + 1/2)/N (docs theory/rotors 'Stations and disk frame') and

    - 'midpoint' (default): q_i = 1/N, the midpoint rule;
    - 'bladead' (compatibility switch, docs theory/rotors 'Public-code compatibility'): q_i = 1/(N -
      1) with halved end weights, the public code's width and end-corrected sum, needed to reproduce
      the docs theory/rotors 'Validation' numbers.

    Returns
    -------
    eta, q : ndarray, (num_radial,)
    """
    check_choice("quadrature", quadrature, QUADRATURES)
    eta = (np.arange(num_radial) + 0.5) / num_radial
    if quadrature == "midpoint":
        q = np.full(num_radial, 1.0 / num_radial)
    else:
        check_integer("num_radial", num_radial, lower=2, allowed=">= 2 (quadrature 'bladead')")
        q = np.full(num_radial, 1.0 / (num_radial - 1))
        q[[0, -1]] *= 0.5
    return eta, q


class BladeStationsComp(om.ExplicitComponent):
    """
    Radial stations, quadrature widths and hub radius of each rotor from its tip radius.

    docs theory/rotors 'Stations and disk frame': r_h = h R (h the hub-radius ratio, 0.2 in the LPC
    study), element centres r_i = r_h + (R - r_h)(i + 1/2)/N_r, widths dr_i = (R - r_h)/N_r
    (midpoint rule) or, with quadrature='bladead', the public code's (R - r_h)/(N_r - 1) with
    halved end widths (docs theory/rotors 'Public-code compatibility'). Azimuthal stations psi_k = 2
    pi k/N_psi. All outputs are linear in R, so the partials are constants set in setup.

    Inputs
    ------
    radius : float, (num_rotors,), m
        Tip radius R (design variable).

    Outputs
    -------
    hub_radius : float, (num_rotors,), m
        Hub radius r_h = h R.
    station_radius : float, (num_rotors, num_radial), m
        Radius r_i of the element centres.
    station_width : float, (num_rotors, num_radial), m
        Quadrature width dr_i (sum_i dr_i f_i integrates f over the blade).
    azimuth : float, (num_azimuth,), rad
        Azimuthal stations psi_k (constant; for edgewise models).

    Options
    -------
    num_rotors : int
        Number of rotors (>= 1). Default 1.
    num_radial : int
        Radial stations N_r (>= 1). Default 25.
    num_azimuth : int
        Azimuthal stations N_psi (>= 1). Default 25 (edgewise models; BEM ignores them).
    hub_radius_ratio : float or sequence of float
        h = r_h/R in [0, 1), one for all rotors or one per rotor. Default 0.2.
    quadrature : str
        'midpoint' (default) or 'bladead' (docs theory/rotors 'Public-code compatibility').
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_radial",
            default=25,
            types=int,
            lower=1,
            desc="Number of radial stations (element centres)",
        )
        self.options.declare(
            "num_azimuth",
            default=25,
            types=int,
            lower=1,
            desc="Number of azimuthal stations (edgewise models)",
        )
        self.options.declare(
            "hub_radius_ratio",
            default=0.2,
            types=(int, float, list, tuple, np.ndarray),
            desc="Hub radius over tip radius, in [0, 1); scalar or per rotor",
        )
        self.options.declare(
            "quadrature",
            default="midpoint",
            values=QUADRATURES,
            desc="Radial quadrature: 'midpoint' or 'bladead' "
            "(docs theory/rotors 'Public-code compatibility')",
        )

    def setup(self):
        nr, nrad = self.options["num_rotors"], self.options["num_radial"]
        naz = self.options["num_azimuth"]
        h = per_rotor(
            self.options["hub_radius_ratio"],
            nr,
            "hub_radius_ratio",
            lower=0.0,
            upper=1.0,
            upper_open=True,
            owner=self.msginfo,
        )
        eta, q = station_fractions(nrad, self.options["quadrature"])
        # Output per unit tip radius: r_i / R and dr_i / R.
        self._hub = h
        self._station = h[:, None] + (1.0 - h)[:, None] * eta
        self._width = (1.0 - h)[:, None] * q

        self.add_input("radius", val=np.ones(nr), units="m", desc="Rotor tip radius")
        self.add_output("hub_radius", val=h.copy(), units="m", desc="Hub radius")
        self.add_output(
            "station_radius",
            val=self._station.copy(),
            units="m",
            desc="Radius of the blade-element centres",
        )
        self.add_output(
            "station_width",
            val=self._width.copy(),
            units="m",
            desc="Radial quadrature width of each blade element",
        )
        self.add_output(
            "azimuth",
            val=azimuth_angles(naz),
            units="rad",
            desc="Azimuthal stations 2 pi k / num_azimuth",
        )

        ar = np.arange(nr)
        self.declare_partials("hub_radius", "radius", diagonal=True, val=h)
        rows = np.arange(nr * nrad)
        cols = np.repeat(ar, nrad)
        self.declare_partials(
            "station_radius", "radius", rows=rows, cols=cols, val=self._station.ravel()
        )
        self.declare_partials(
            "station_width", "radius", rows=rows, cols=cols, val=self._width.ravel()
        )

    def compute(self, inputs, outputs):
        radius = inputs["radius"]
        if np.any(radius.real <= 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: radius = {radius.real.tolist()} m; allowed range (0, inf)."
            )
        outputs["hub_radius"] = self._hub * radius
        outputs["station_radius"] = self._station * radius[:, None]
        outputs["station_width"] = self._width * radius[:, None]


class BladeGeometryGroup(om.Group):
    """
    Blade geometry of several rotors: stations, and chord and twist at the stations.

    The stations come from BladeStationsComp, the chord and twist at the
    stations from cubic B-splines (BsplineComp), docs theory/rotors 'Blade parameterization'.

    Chord and twist are order-4 clamped B-splines of ``num_cp`` control points each (4: a single
    cubic Bezier segment). By default (spline_stations='as_coded', docs theory/rotors 'Blade
    parameterization') the spline is evaluated at t = linspace(0, 1, N_r) and value i goes to
    element i, so cp_0 is the hub-element value and
    cp_last the tip-element value; this deliberate approximation of the public code is the
    default. 'element_centres' evaluates the spline at the element centres' normalized position
    t_i = (r_i - r_h)/(R - r_h) = (i + 1/2)/N_r instead. All partials are analytic constants.

    The inputs are promoted.

    Inputs
    ------
    radius : float, (num_rotors,), m
        Tip radius R.
    chord_cp : float, (num_rotors, num_cp), m
        Chord control points, root to tip.
    twist_cp : float, (num_rotors, num_cp), rad
        Twist (blade pitch relative to the rotor plane) control points, root to tip.

    The outputs are promoted.

    Outputs
    -------
    hub_radius, station_radius, station_width, azimuth
        See BladeStationsComp.
    chord : float, (num_rotors, num_radial), m
        Chord at the stations.
    twist : float, (num_rotors, num_radial), rad
        Twist at the stations.

    Options
    -------
    num_rotors, num_radial, num_azimuth, hub_radius_ratio, quadrature
        See BladeStationsComp.
    num_cp : int
        Control points per curve (>= 4). Default 4.
    spline_stations : str
        'as_coded' (default) or 'element_centres'.
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_radial", default=25, types=int, lower=1, desc="Number of radial stations"
        )
        self.options.declare(
            "num_azimuth",
            default=25,
            types=int,
            lower=1,
            desc="Number of azimuthal stations (edgewise models)",
        )
        self.options.declare(
            "hub_radius_ratio",
            default=0.2,
            types=(int, float, list, tuple, np.ndarray),
            desc="Hub radius over tip radius, in [0, 1); scalar or per rotor",
        )
        self.options.declare(
            "quadrature",
            default="midpoint",
            values=QUADRATURES,
            desc="Radial quadrature: 'midpoint' or 'bladead' "
            "(docs theory/rotors 'Public-code compatibility')",
        )
        self.options.declare(
            "num_cp", default=4, types=int, lower=4, desc="Chord and twist control points per rotor"
        )
        self.options.declare(
            "spline_stations",
            default="as_coded",
            values=SPLINE_STATIONS,
            desc="Spline parameter of station i: 'as_coded' i/(N-1) or "
            "'element_centres' (i + 1/2)/N",
        )

    def setup(self):
        opts = self.options
        nr, nrad, ncp = opts["num_rotors"], opts["num_radial"], opts["num_cp"]
        self.add_subsystem(
            "stations",
            BladeStationsComp(
                num_rotors=nr,
                num_radial=nrad,
                num_azimuth=opts["num_azimuth"],
                hub_radius_ratio=opts["hub_radius_ratio"],
                quadrature=opts["quadrature"],
            ),
            promotes=["*"],
        )
        if opts["spline_stations"] == "as_coded":
            t = np.linspace(0.0, 1.0, nrad) if nrad > 1 else np.zeros(1)
        else:
            t = (np.arange(nrad) + 0.5) / nrad
        for name, units in (("chord", "m"), ("twist", "rad")):
            self.add_subsystem(
                f"{name}_spline",
                BsplineComp(
                    num_cp=ncp,
                    num_points=nrad,
                    order=4,
                    vec_size=nr,
                    x_interp=t,
                    in_name=f"{name}_cp",
                    out_name=name,
                    units=units,
                ),
                promotes=["*"],
            )
        self.set_input_defaults("chord_cp", np.tile(np.linspace(0.3, 0.1, ncp), (nr, 1)), units="m")
        self.set_input_defaults(
            "twist_cp", np.tile(np.radians(np.linspace(30.0, 10.0, ncp)), (nr, 1)), units="rad"
        )
