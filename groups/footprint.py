"""The departure's noise footprint: rotor noise at ground observers from each leg, SEL and L_Amax.

Each condition of the departure (lpc_mdo.vehicle.footprint_path: the vertiport hover, then the
transition points) hears its own legs with :func:`add_footprint_noise`: its rotors, in their
trimmed state, at every observer from each leg's quadrature points. :class:`FootprintGroup`, at the
vehicle level, adds up the exposure of every observer over the path and the smooth maxima the
constraint kind ``noise_footprint`` bounds (docs theory/acoustics 'Noise footprint').
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.exposure import NoiseExposureComp
from lpc_mdo.components.acoustics.path_observer import PathObserverComp
from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.rotor_stack import RotorStackComp
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.vehicle.condition_kinds import num_lift_pairs
from lpc_mdo.vehicle.footprint_path import (
    departure_points,
    footprint_geometry,
    footprint_observers,
)

__all__ = [
    "FootprintGroup",
    "add_footprint_noise",
    "footprint_chord_inputs",
    "footprint_sources",
    "footprint_stations",
    "FOOTPRINT_BANDS",
    "FOOTPRINT_GUST_HARMONICS",
]

#: One-third-octave bands of the footprint's broadband noise: 24 bands, 50 Hz to 10 kHz, where
#: the A-weighting is above -30 dB (IEC 61672-1:2013, Table 3). The hover constraint's 38 bands
#: from 12.5 Hz add nothing the A-weighted level shows (docs theory/acoustics 'Noise footprint'
#: measures it).
FOOTPRINT_BANDS = (24, 50.0)
#: Sears gust load harmonics of the footprint's loading noise (the hover constraint's 10;
#: measured in docs theory/acoustics 'Noise footprint').
FOOTPRINT_GUST_HARMONICS = 4
#: Every third station of the rotor model, tip element included: the acoustic stations of the
#: footprint (9 of 25; the loads come from the rotor's thrust and torque).
FOOTPRINT_STATION_STEP = 3
#: Smooth maximum over the observers, per dB: at most ln(n)/rho above the largest (0.23 dB for
#: ten observers).
FOOTPRINT_KS_RHO = 10.0


def footprint_stations(num_radial):
    """Return the rotor model's radial stations (indices) the footprint's noise uses."""
    return np.arange(num_radial - 1, -1, -FOOTPRINT_STATION_STEP)[::-1]


def footprint_sources(vehicle, flying):
    """
    Return the rotor sets of a departure condition's footprint noise, grouped for evaluation.

    One list per noise evaluation, each of (set name, rotors): the lift rotors and, if
    ``flying`` (a transition point), the pusher, in one evaluation when their hubs have the same
    radius ratio (the acoustic stations are fractions of the radius), else in two.
    """
    lift = ("lift", list(vehicle.lift_rotors))
    if not flying:
        return [[lift]]
    pusher = ("pusher", [vehicle.pusher])
    if vehicle.pusher.hub_radius_ratio == vehicle.lift_rotors[0].hub_radius_ratio:
        return [[lift, pusher]]
    return [[lift], [pusher]]


def _suffix(k, evaluations):
    """Return the name suffix of noise evaluation ``k``: none if it is the only one, else _1..."""
    return "" if len(evaluations) == 1 else f"_{k + 1}"


def footprint_chord_inputs(vehicle, flying, num_radial):
    """
    Return the blade chords of a departure condition's footprint noise.

    (source, target, src_indices) of the vehicle's ``blade_chord`` (one row per rotor group,
    ``num_radial`` stations) at the acoustic stations (:func:`footprint_stations`), for each
    rotor set of each noise evaluation (:func:`footprint_sources`): the stack's input
    ``footprint_rotors{suffix}.{set}_chord`` of :func:`add_footprint_noise`, as one flat fancy
    index shaped like the target, for the vehicle-level model to connect.
    """
    stations = footprint_stations(num_radial)[None, :]
    rows = {
        "lift": np.array([r.pair for r in vehicle.lift_rotors])[:, None],
        "pusher": np.array([[num_lift_pairs(vehicle.lift_rotors)]]),
    }
    evaluations = footprint_sources(vehicle, flying)
    return tuple(
        (
            "blade_chord",
            f"footprint_rotors{_suffix(k, evaluations)}.{name}_chord",
            (rows[name] * num_radial + stations,),
        )
        for k, sets in enumerate(evaluations)
        for name, _ in sets
    )


def add_footprint_noise(group, vehicle, condition, flying):
    """
    Add the noise of ``condition``'s legs at the footprint's observers to a condition group.

    Output ``footprint_spl_a`` (num_points,): the total
    A-weighted level of the lift rotors (and, if ``flying``, the pusher; a transition point)
    at each observer from each quadrature point of the condition's legs. Loads from each
    rotor's thrust and torque (hover load shape,
    :class:`~lpc_mdo.components.acoustics.loads.HoverLoadDistributionComp`), at the stations
    :func:`footprint_stations`. The rotors' state reaches the noise model through
    ``footprint_rotors`` (:class:`~lpc_mdo.components.rotor_stack.RotorStackComp`), whose
    chord inputs ``{set}_chord`` the vehicle-level model connects
    (:func:`footprint_chord_inputs`).
    """
    points = departure_points(*footprint_geometry(vehicle))[condition]
    width = len(points.observer)
    nrad = group.options["num_radial"]
    stations = footprint_stations(nrad)
    group.add_subsystem(
        "footprint_observers",
        PathObserverComp(offsets=points.offset, num_rotors=len(vehicle.lift_rotors)),
        promotes_inputs=["pitch", ("hub_position", "lift_hub_position")],
    )
    speeds = {"lift": "lift_rotor_rpm", "pusher": "pusher_rpm"}
    evaluations = footprint_sources(vehicle, flying)
    for k, sets in enumerate(evaluations):
        suffix = _suffix(k, evaluations)
        members = [r for _, rotors in sets for r in rotors]
        # The rotors' state through a stack that is also a copy: OpenMDAO 3.x cannot chain the
        # noise group's per-pair indices onto a (1, 3) or row-selecting view of the model's
        # outputs.
        group.add_subsystem(
            f"footprint_rotors{suffix}",
            RotorStackComp(
                sets=[(name, len(rotors)) for name, rotors in sets],
                quantities=[
                    ("radius", (), "m"),
                    ("rpm", (), "rpm"),
                    ("thrust", (), "N"),
                    ("torque", (), "N*m"),
                    ("hub_position", (3,), "m"),
                    ("chord", (len(stations),), "m"),
                ],
            ),
            promotes_inputs=[
                (f"{name}_{q}", speeds[name] if q == "rpm" else f"{name}_{q}")
                for name, _ in sets
                for q in ("radius", "rpm", "thrust", "torque", "hub_position")
            ],
        )
        noise = f"footprint_noise{suffix}"
        hub = members[0].hub_radius_ratio
        bem_stations = hub + (1.0 - hub) * (np.arange(nrad) + 0.5) / nrad
        group.add_subsystem(
            noise,
            RotorNoiseGroup(
                num_rotors=len(members),
                num_observers=width,
                num_radial=len(stations),
                radial_stations=bem_stations[stations],
                hub_radius_ratio=hub,
                num_blades=[r.num_blades for r in members],
                num_bands=FOOTPRINT_BANDS[0],
                lowest_band_frequency=FOOTPRINT_BANDS[1],
                num_gust_harmonics=FOOTPRINT_GUST_HARMONICS,
                load_input="totals",
                observer_input="position",
                rotation_direction=tuple(float(r.spin_direction) for r in members),
            ),
            promotes_inputs=[
                ("thrust_direction", f"{noise}_thrust_direction"),
                ("thickness_to_chord", f"{noise}_thickness_to_chord"),
                "density",
                "speed_of_sound",
            ],
        )
        for q in ("radius", "rpm", "thrust", "torque", "hub_position", "chord"):
            group.connect(f"footprint_rotors{suffix}.{q}", f"{noise}.{q}")
        group.connect("footprint_observers.observer_position", f"{noise}.observer_position")
        group.set_input_defaults(
            f"{noise}_thrust_direction", np.array([r.thrust_axis for r in members])
        )
        group.set_input_defaults(
            f"{noise}_thickness_to_chord",
            np.repeat([[r.thickness_to_chord] for r in members], len(stations), axis=1),
        )
        if flying:  # the flight velocity in the body frame (the kinematics'); zero in hover
            group.connect(
                "velocity", f"{noise}.flight_velocity", src_indices=[0, 1, 2], flat_src_indices=True
            )
    if len(evaluations) == 1:
        group.promotes("footprint_noise", outputs=[("total_spl_a", "footprint_spl_a")])
        return
    group.add_subsystem(
        "footprint_total",
        om.ExecComp(
            "footprint_spl_a = 10.0 * log10(10.0 ** (a / 10.0) + 10.0 ** (b / 10.0))",
            shape=(width,),
            has_diag_partials=True,
        ),
        promotes_outputs=["footprint_spl_a"],
    )
    group.connect("footprint_noise_1.total_spl_a", "footprint_total.a")
    group.connect("footprint_noise_2.total_spl_a", "footprint_total.b")


class FootprintGroup(om.Group):
    """
    Sound exposure and maximum level of every footprint observer over the departure.

    Inputs ``{condition}`` (num_points,): the levels of each departure condition's
    quadrature points at their observers (connected from ``{condition}.footprint_spl_a``);
    ``exposure.duration`` holds their equivalent times (lpc_mdo.vehicle.footprint_path).
    Outputs (dBA, units=None): ``footprint_sel`` and ``footprint_lamax`` per observer
    (NoiseExposureComp) and their smooth maxima over the observers ``footprint_sel_max``,
    ``footprint_lamax_max`` (KS, :data:`FOOTPRINT_KS_RHO`), which the constraint kind
    ``noise_footprint`` bounds.

    Options
    -------
    vehicle : Vehicle
        A vehicle with a ``noise_footprint``.
    """

    def initialize(self):
        self.options.declare("vehicle", desc="lpc_mdo.vehicle.Vehicle with a noise_footprint")

    def setup(self):
        vehicle = self.options["vehicle"]
        points = departure_points(*footprint_geometry(vehicle))
        no = len(footprint_observers(vehicle.noise_footprint))
        self.add_subsystem(
            "exposure",
            NoiseExposureComp(
                num_observers=no,
                sources=[(name, p.observer) for name, p in points.items()],
            ),
            promotes_outputs=[("sel", "footprint_sel"), ("lmax", "footprint_lamax")],
        )
        times = np.concatenate([p.equivalent_time for p in points.values()])
        self.set_input_defaults("exposure.duration", times, units="s")
        for level in ("sel", "lamax"):
            self.add_subsystem(
                f"{level}_max",
                KSComp(width=no, rho=FOOTPRINT_KS_RHO),
                promotes_outputs=[("KS", f"footprint_{level}_max")],
            )
            self.connect(
                f"footprint_{level}",
                f"{level}_max.g",
                src_indices=(np.arange(no)[None, :],),
                flat_src_indices=True,
            )
