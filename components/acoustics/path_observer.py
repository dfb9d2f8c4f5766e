"""Ground observers of a flight path seen from the pitched vehicle: body-frame positions."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_shape


class PathObserverComp(om.ExplicitComponent):
    """
    Body-frame positions of observers given in earth axes relative to the vehicle.

    The vehicle's reference point is the centroid of the rotor hubs (the point whose path the
    departure's legs trace, lpc_mdo.vehicle.footprint_path); ``offsets`` are the observers
    minus that point in earth axes (x along the track, y right, z down). With the pitch theta
    (nose up positive, no roll or yaw) the body axes are the earth axes turned by theta about
    y, so

        x_o = c + (cos(theta) dx - sin(theta) dz, dy, sin(theta) dx + cos(theta) dz),

    c = mean_k(hub_k) (docs theory/acoustics 'Noise footprint').

    Inputs
    ------
    pitch : float, (1,), rad
        Vehicle pitch.
    hub_position : float, (num_rotors, 3), m
        Hub positions in the body frame.

    Outputs
    -------
    observer_position : float, (num_observers, 3), m
        Observers in the body frame.

    Options
    -------
    offsets : array, (num_observers, 3)
        Observer minus reference point, earth axes (m).
    num_rotors : int
        Rotors whose hub centroid is the reference point.
    """

    def initialize(self):
        self.options.declare("offsets", types=np.ndarray, desc="observer - vehicle, earth axes, m")
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="number of hubs")

    def setup(self):
        offsets = np.asarray(self.options["offsets"], dtype=float)
        check_shape("offsets", offsets, (None, 3))
        no, nr = len(offsets), self.options["num_rotors"]
        self.add_input("pitch", np.zeros(1), units="rad", desc="vehicle pitch, nose up")
        self.add_input("hub_position", np.zeros((nr, 3)), units="m", desc="hubs, body frame")
        self.add_output("observer_position", np.zeros((no, 3)), units="m",
                        desc="observers, body frame")  # fmt: skip
        rows = np.arange(3 * no)
        self.declare_partials("observer_position", "pitch", rows=rows, cols=np.zeros(3 * no))
        self.declare_partials(
            "observer_position",
            "hub_position",
            rows=np.tile(rows, nr),
            cols=np.tile(np.arange(3 * nr).reshape(nr, 1, 3), (1, no, 1)).ravel(),
            val=np.full(3 * no * nr, 1.0 / nr),
        )

    def compute(self, inputs, outputs):
        d = self.options["offsets"]
        c, s = np.cos(inputs["pitch"][0]), np.sin(inputs["pitch"][0])
        turned = np.column_stack([c * d[:, 0] - s * d[:, 2], d[:, 1], s * d[:, 0] + c * d[:, 2]])
        outputs["observer_position"] = np.mean(inputs["hub_position"], axis=0) + turned

    def compute_partials(self, inputs, partials):
        d = self.options["offsets"]
        c, s = np.cos(inputs["pitch"][0]), np.sin(inputs["pitch"][0])
        rate = np.column_stack(
            [-s * d[:, 0] - c * d[:, 2], np.zeros(len(d)), c * d[:, 0] - s * d[:, 2]]
        )
        partials["observer_position", "pitch"] = rate.ravel()
