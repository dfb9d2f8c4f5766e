"""Span-wise sectional lift coefficients of the VLM strips."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, dot, outer, skew
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of
from lpc_mdo.components.aero.vlm_loads import Q_FLOOR
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY


class VLMSectionalLiftComp(om.ExplicitComponent):
    """
    Sectional lift coefficient of every strip, the input of the airfoil alpha* inversion.

    Paper eq. 16 and docs theory/aerodynamics 'Airfoil coupling':

        c_l = sum_{k in strip} F_k . e_k / (q A_strip),   e_k = (e_D x l_k)/norm(e_D x l_k),

    with F_k the inviscid panel force, l_k the bound vector, e_D the relative-wind direction,
    q = rho V^2/2 (+1e-10 Pa so that V = 0 gives 0) and A_strip the strip area. e_k is the
    section's own lift direction (normal to the wind and to the local span), so dihedral does
    not reduce c_l.

    Inputs
    ------
    panel_forces : float, (nn, np, 3), N
    bound_vectors : float, (np, 3), m
    freestream_direction : float, (nn, 3)
    strip_areas : float, (nst,), m**2
    speed : float, (nn,), m/s
    density : float, (nn,), kg/m**3

    Outputs
    -------
    {name}_sectional_cl : float, (nn, ns)
        Sectional lift coefficient of each strip of each surface (left tip to right tip).

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
        npn, nst = lat.num_panels, lat.num_strips
        self.add_input(
            "panel_forces", np.zeros((nn, npn, 3)), units="N", desc="inviscid panel forces"
        )
        self.add_input("bound_vectors", np.zeros((npn, 3)), units="m", desc="bound segment vectors")
        self.add_input(
            "freestream_direction",
            np.zeros((nn, 3)),
            units=None,
            desc="unit vector along the relative wind",
        )
        self.add_input("strip_areas", np.zeros(nst), units="m**2", desc="strip areas")
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )

        for isurf, s in enumerate(lat.surfaces):
            ns, nc = s.num_span_panels, s.num_chord_panels
            name = f"{s.name}_sectional_cl"
            self.add_output(
                name,
                np.zeros((nn, ns)),
                units=None,
                desc=f"sectional lift coefficient of the strips of '{s.name}'",
            )
            # panel k = offset + i*ns + j in strip j; entries ordered (n, j, i, c)
            n_, j_, i_, c_ = (
                a.ravel()
                for a in np.meshgrid(
                    np.arange(nn), np.arange(ns), np.arange(nc), np.arange(3), indexing="ij"
                )
            )
            k_ = lat.panel_offset[isurf] + i_ * ns + j_
            rows = n_ * ns + j_
            self.declare_partials(name, "panel_forces", rows=rows, cols=(n_ * npn + k_) * 3 + c_)
            self.declare_partials(name, "bound_vectors", rows=rows, cols=3 * k_ + c_)
            n2, j2, c2 = (
                a.ravel()
                for a in np.meshgrid(np.arange(nn), np.arange(ns), np.arange(3), indexing="ij")
            )
            self.declare_partials(name, "freestream_direction", rows=n2 * ns + j2, cols=3 * n2 + c2)
            ar = np.arange(nn * ns)
            self.declare_partials(name, ["speed", "density"], rows=ar, cols=ar // ns)
            self.declare_partials(
                name, "strip_areas", rows=ar, cols=lat.strip_offset[isurf] + ar % ns
            )

    def _parts(self, inputs, isurf):
        lat = self._lattice
        s = lat.surfaces[isurf]
        nn = self.options["num_nodes"]
        nc, ns = s.num_chord_panels, s.num_span_panels
        sl = lat.surface_panels(isurf)
        force = inputs["panel_forces"][:, sl].reshape(nn, nc, ns, 3)
        bound = inputs["bound_vectors"][sl].reshape(nc, ns, 3)
        e_d = inputs["freestream_direction"]
        g = cross(e_d[:, None, None, :], bound[None])  # (nn, nc, ns, 3)
        g_len = np.sqrt(dot(g, g))
        e = g / g_len[..., None]
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2 + Q_FLOOR
        area = inputs["strip_areas"][lat.surface_strips(isurf)]
        lift = np.sum(dot(force, e), axis=1)  # (nn, ns)
        return force, bound, e_d, g_len, e, q, area, lift

    def compute(self, inputs, outputs):
        for isurf, s in enumerate(self._lattice.surfaces):
            _, _, _, _, _, q, area, lift = self._parts(inputs, isurf)
            outputs[f"{s.name}_sectional_cl"] = lift / (q[:, None] * area[None])

    def compute_partials(self, inputs, partials):
        rho, speed = inputs["density"], inputs["speed"]
        eye = np.eye(3)
        for isurf, s in enumerate(self._lattice.surfaces):
            name = f"{s.name}_sectional_cl"
            force, bound, e_d, g_len, e, q, area, lift = self._parts(inputs, isurf)
            qa = q[:, None] * area[None]  # (nn, ns)
            cl = lift / qa
            inv = 1.0 / qa[:, None, :, None]  # broadcast over (nn, nc, ns, 3)
            partials[name, "panel_forces"] = (e * inv).transpose(0, 2, 1, 3).ravel()
            # d(F.e)/dg = F^T (I - e e^T)/|g|
            de_dg = (eye - outer(e, e)) / g_len[..., None, None]
            f_dg = np.einsum("...i,...ij->...j", force, de_dg)  # (nn, nc, ns, 3)
            # g = e_D x l: dg/dl = skew(e_D), dg/de_D = -skew(l)
            d_l = np.einsum("nicj,njk->nick", f_dg, skew(e_d)) * inv
            partials[name, "bound_vectors"] = d_l.transpose(0, 2, 1, 3).ravel()
            d_ed = -np.einsum("nicj,icjk->nck", f_dg, skew(bound)) / qa[..., None]
            partials[name, "freestream_direction"] = d_ed.ravel()
            partials[name, "speed"] = (-cl * (rho * speed)[:, None] / q[:, None]).ravel()
            partials[name, "density"] = (-cl * (0.5 * speed**2)[:, None] / q[:, None]).ravel()
            partials[name, "strip_areas"] = (-cl / area[None]).ravel()
