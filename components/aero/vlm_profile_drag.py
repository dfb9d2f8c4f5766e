"""Sectional profile drag of the VLM strips from the airfoil drag coefficient (strip theory)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY


class VLMProfileDragComp(om.ExplicitComponent):
    """
    Viscous panel forces from the sectional profile-drag coefficient of each strip.

    Strip theory: every panel carries F_v = (1/2) rho V^2 c_d(strip) A_panel e_D, along the
    relative wind e_D, applied at its force point, so a strip's drag is q c_d A_strip. c_d is the
    airfoil's profile drag at the strip's Reynolds and Mach number (an input, from the airfoil
    polar). docs theory/aerodynamics 'Forces and induced drag' (the VLM itself has no viscous drag;
    the public code computed this and dropped it, quirk Q3, which is not copied). A model that books
    the wing and tail friction in the parasite-drag build-up (docs theory/aerodynamics 'Drag
    build-up') sets c_d = 0 here (the default) to avoid counting it twice.

    Inputs
    ------
    {name}_sectional_cd : float, (nn, ns), dimensionless
        Profile-drag coefficient of each strip of each surface.
    panel_areas : float, (np,), m**2
    speed : float, (nn,), m/s
    density : float, (nn,), kg/m**3
    freestream_direction : float, (nn, 3)

    Outputs
    -------
    viscous_panel_forces : float, (nn, np, 3), N

    Options
    -------
    surfaces : tuple of VLMSurface
    num_nodes : int
    """

    def initialize(self):
        declare_lattice_options(self)

    def setup(self):
        nn = self.options["num_nodes"]
        lat = self._lattice = lattice_of(self.options["surfaces"])
        npn = lat.num_panels
        self.add_input("panel_areas", np.zeros(npn), units="m**2", desc="panel areas")
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )
        self.add_input(
            "freestream_direction",
            np.zeros((nn, 3)),
            units=None,
            desc="unit vector along the relative wind",
        )
        self.add_output(
            "viscous_panel_forces",
            np.zeros((nn, npn, 3)),
            units="N",
            desc="strip-theory profile-drag force on each panel, body axes",
        )

        n_r, k_r, c_r = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(3), indexing="ij")
        )
        row = (n_r * npn + k_r) * 3 + c_r
        self.declare_partials("viscous_panel_forces", "panel_areas", rows=row, cols=k_r)
        self.declare_partials("viscous_panel_forces", ["speed", "density"], rows=row, cols=n_r)
        self.declare_partials(
            "viscous_panel_forces", "freestream_direction", rows=row, cols=3 * n_r + c_r
        )
        for isurf, s in enumerate(lat.surfaces):
            ns = s.num_span_panels
            name = f"{s.name}_sectional_cd"
            self.add_input(
                name,
                np.zeros((nn, ns)),
                units=None,
                desc=f"profile-drag coefficient of the strips of '{s.name}'",
            )
            mine = lat.panel_surface[k_r] == isurf
            strip_local = lat.panel_strip[k_r[mine]] - lat.strip_offset[isurf]
            self.declare_partials(
                "viscous_panel_forces", name, rows=row[mine], cols=n_r[mine] * ns + strip_local
            )

    def _panel_cd(self, inputs):
        lat = self._lattice
        nn = self.options["num_nodes"]
        pieces = [
            np.tile(inputs[f"{s.name}_sectional_cd"], (1, s.num_chord_panels)).reshape(
                nn, s.num_panels
            )
            for s in lat.surfaces
        ]
        return np.concatenate(pieces, axis=1)

    def compute(self, inputs, outputs):
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        cd = self._panel_cd(inputs)
        mag = q[:, None] * cd * inputs["panel_areas"][None]
        outputs["viscous_panel_forces"] = mag[..., None] * inputs["freestream_direction"][:, None]

    def compute_partials(self, inputs, partials):
        lat = self._lattice
        rho, speed = inputs["density"], inputs["speed"]
        q = 0.5 * rho * speed**2
        cd = self._panel_cd(inputs)
        area = inputs["panel_areas"][None]
        e_d = inputs["freestream_direction"][:, None]
        partials["viscous_panel_forces", "panel_areas"] = (
            (q[:, None] * cd)[..., None] * e_d
        ).ravel()
        base = (cd * area)[..., None] * e_d
        partials["viscous_panel_forces", "speed"] = ((rho * speed)[:, None, None] * base).ravel()
        partials["viscous_panel_forces", "density"] = (
            (0.5 * speed**2)[:, None, None] * base
        ).ravel()
        partials["viscous_panel_forces", "freestream_direction"] = np.broadcast_to(
            (q[:, None] * cd * area)[..., None], base.shape
        ).ravel()
        for isurf, s in enumerate(lat.surfaces):
            sl = lat.surface_panels(isurf)
            partials["viscous_panel_forces", f"{s.name}_sectional_cd"] = (
                (q[:, None] * area[:, sl])[..., None] * e_d
            ).ravel()
