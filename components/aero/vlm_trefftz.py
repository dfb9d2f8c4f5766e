"""Trefftz-plane induced drag of the vortex lattice (a far-field check of the near-field drag)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, dot
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY

#: Squared core radius (m**2) of the 2-D Trefftz-plane vortices (finite if two legs coincide).
TREFFTZ_CORE_SQ = 1.0e-12


class VLMTrefftzDragComp(om.ExplicitComponent):
    """
    Induced drag from the trailing vortices in the Trefftz plane, normal to the wake direction u.

    Far downstream each wake leg is an infinite 2-D vortex: +Gamma_t from the trailing-edge ring
    corner b_t = p3 and -Gamma_t from a_t = p4 of every strip t (all surfaces). The Kutta–
    Joukowski drag of the projected bound segments e_k = b_k - a_k in the far-field wash
    (twice the wash at the lifting line, hence the factor 1/2) is

        D = (rho/2) sum_k Gamma_k w_k . (e_k x u),
        w_k = sum_m gamma_m (u x d_km) / (2 pi (norm(d_km)^2 - (u.d_km)^2 + eps^2)),

    d_km = (a_k + b_k)/2 - Q_m. It uses the same sign convention as the near-field drag of
    :class:`VLMLoadsComp`, so the two agree on a converged planar lattice
    (docs theory/aerodynamics 'Forces and induced drag' has near field only; the Trefftz plane is
    the textbook check, Katz & Plotkin §12.2).

    Inputs
    ------
    ring_vertices : float, (np, 4, 3), m
    circulation : float, (nn, np), m**2/s
    freestream_direction : float, (nn, 3)
    density : float, (nn,), kg/m**3

    Outputs
    -------
    trefftz_induced_drag : float, (nn,), N

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
        self.add_input(
            "ring_vertices",
            np.zeros((npn, 4, 3)),
            units="m",
            desc="corners p1..p4 of the vortex rings",
        )
        self.add_input("circulation", np.zeros((nn, npn)), units="m**2/s", desc="ring circulations")
        self.add_input(
            "freestream_direction",
            np.zeros((nn, 3)),
            units=None,
            desc="unit vector along the relative wind (wake direction)",
        )
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )
        self.add_output(
            "trefftz_induced_drag",
            np.zeros(nn),
            units="N",
            desc="induced drag from the Trefftz plane",
        )
        te = lat.te_panels
        nte = te.size
        self.declare_partials(
            "trefftz_induced_drag",
            "circulation",
            rows=np.repeat(np.arange(nn), nte),
            cols=(npn * np.arange(nn)[:, None] + te[None]).ravel(),
        )
        cols_v = (
            12 * te[:, None, None]
            + 3 * np.array([2, 3])[None, :, None]
            + np.arange(3)[None, None, :]
        ).ravel()  # (t, p3/p4, xyz)
        self.declare_partials(
            "trefftz_induced_drag",
            "ring_vertices",
            rows=np.repeat(np.arange(nn), cols_v.size),
            cols=np.tile(cols_v, nn),
        )
        self.declare_partials(
            "trefftz_induced_drag",
            "freestream_direction",
            rows=np.repeat(np.arange(nn), 3),
            cols=np.arange(3 * nn),
        )
        self.declare_partials(
            "trefftz_induced_drag", "density", rows=np.arange(nn), cols=np.arange(nn)
        )

    def _terms(self, inputs, derivatives=False):
        te = self._lattice.te_panels
        verts = inputs["ring_vertices"]
        b, a = verts[te, 2], verts[te, 3]  # (nte, 3)
        mid = 0.5 * (a + b)
        e = b - a
        legs = np.concatenate([b, a])  # (2 nte, 3): +Gamma at b, -Gamma at a
        u = inputs["freestream_direction"][:, None, None, :]  # (nn, 1, 1, 3)
        d = (mid[:, None, :] - legs[None, :, :])[None]  # (1, nte, 2nte, 3)
        c1 = cross(u, d)
        c2 = cross(e[None, :, None, :], u)
        num = dot(c1, c2)
        ud = dot(u, d)
        den = dot(d, d) - ud**2 + TREFFTZ_CORE_SQ
        f = num / den  # (nn, nte, 2nte)
        out = {"f": f}
        if derivatives:
            # d num/dd = c2 x u; d num/de = u x c1; d num/du = d x c2 + c1 x e
            dnum_dd = cross(c2, u)
            dnum_de = cross(u, c1)
            dnum_du = cross(d, c2) + cross(c1, e[None, :, None, :])
            dden_dd = 2.0 * d - 2.0 * ud[..., None] * u
            dden_du = -2.0 * ud[..., None] * d
            inv = (1.0 / den)[..., None]
            fq = (f / den)[..., None]
            out["df_dd"] = dnum_dd * inv - fq * dden_dd
            out["df_de"] = dnum_de * inv
            out["df_du"] = dnum_du * inv - fq * dden_du
        return out

    def compute(self, inputs, outputs):
        te = self._lattice.te_panels
        gamma = inputs["circulation"][:, te]  # (nn, nte)
        strengths = np.concatenate([gamma, -gamma], axis=1)  # (nn, 2nte)
        f = self._terms(inputs)["f"]
        scale = inputs["density"] / (4.0 * np.pi)
        outputs["trefftz_induced_drag"] = scale * np.einsum("nk,nm,nkm->n", gamma, strengths, f)

    def compute_partials(self, inputs, partials):
        te = self._lattice.te_panels
        nte = te.size
        gamma = inputs["circulation"][:, te]
        strengths = np.concatenate([gamma, -gamma], axis=1)
        t = self._terms(inputs, True)
        f = t["f"]
        rho = inputs["density"]
        scale = rho / (4.0 * np.pi)
        drag_sum = np.einsum("nk,nm,nkm->n", gamma, strengths, f)
        partials["trefftz_induced_drag", "density"] = drag_sum / (4.0 * np.pi)
        # Gamma_t enters as Gamma_k (k = t) and through strengths m = t (+) and m = nte + t (-).
        d_gamma = np.einsum("nm,nkm->nk", strengths, f) + np.einsum(
            "nk,nkt->nt", gamma, f[:, :, :nte] - f[:, :, nte:]
        )
        partials["trefftz_induced_drag", "circulation"] = (scale[:, None] * d_gamma).ravel()
        w = (scale[:, None, None] * gamma[:, :, None] * strengths[:, None, :])[..., None]
        d_mid = np.sum(w * t["df_dd"], axis=2)  # (nn, nte, 3)
        d_legs = -np.sum(w * t["df_dd"], axis=1)  # (nn, 2nte, 3)
        d_e = np.sum(w * t["df_de"], axis=2)
        d_b = 0.5 * d_mid + d_e + d_legs[:, :nte]
        d_a = 0.5 * d_mid - d_e + d_legs[:, nte:]
        partials["trefftz_induced_drag", "ring_vertices"] = np.stack([d_b, d_a], axis=2).ravel()
        partials["trefftz_induced_drag", "freestream_direction"] = np.sum(
            w * t["df_du"], axis=(1, 2)
        ).ravel()
