"""Lifting-surface mesh (VLM lattice nodes) from trapezoidal planform parameters."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_integer

SPACINGS = ("cosine", "uniform")


def span_stations(num_span_panels, spacing):
    """Span-wise node stations eta in [-1, 1] (left tip to right tip), symmetric about 0.

    ``cosine``: eta_j = -cos(pi j/N), nodes clustered at the tips (the "half-cosine" span-wise
    spacing of the public LPC code, docs theory/aerodynamics 'Reference-vehicle defaults');
    ``uniform``: eta_j = -1 + 2 j/N.
    """
    j = np.arange(num_span_panels + 1)
    if spacing == "cosine":
        eta = -np.cos(np.pi * j / num_span_panels)
    else:
        eta = -1.0 + 2.0 * j / num_span_panels
    eta = 0.5 * (eta - eta[::-1])  # exact symmetry
    return eta


class PlanformMeshComp(om.ExplicitComponent):
    """
    Mesh of a trapezoidal lifting surface mirrored about its root, from planform parameters.

    Body frame x forward, y right, z down. With eta_j in [-1, 1] the span-wise station
    (``spacing``), h_j = abs(eta_j) b/2 the distance from the root, s_i = i/nc the chord fraction
    and x0 the root leading edge:

    - leading edge: x_le = x0_x - h tan(sweep), y = x0_y + eta b/2, z_le = x0_z - h tan(dihedral)
      (sweep is the leading-edge sweep, positive aft; dihedral positive tip up; b the projected
      span);
    - chord: c_j = c_root (1 - abs(eta_j)) + c_tip abs(eta_j);
    - section incidence theta_j = incidence + twist[abs(j - N/2)] (positive nose up), a rotation
      about the leading edge:
      X[i, j] = (x_le - s_i c_j cos theta_j, y_j, z_le + s_i c_j sin theta_j).

    The planform and its symbols follow docs theory/aerodynamics 'Drag build-up' and the vehicle
    file (``lpc_mdo.vehicle.LiftingSurface``: leading-edge sweep, dihedral, root incidence, root
    leading edge). Partials are analytic and sparse.

    Inputs
    ------
    span : float, scalar, m
        Projected span b (both halves), > 0.
    root_chord, tip_chord : float, scalar, m
        > 0 and >= 0.
    sweep : float, scalar, rad
        Leading-edge sweep, abs(sweep) < 90 deg.
    dihedral : float, scalar, rad
        abs(dihedral) < 90 deg.
    incidence : float, scalar, rad
        Root incidence relative to the body x axis, positive nose up.
    twist : float, (N/2 + 1,), rad
        Extra section twist at the half-span nodes, root to tip (default 0).
    root_leading_edge : float, (3,), m
        Leading edge of the root chord, body frame.

    Outputs
    -------
    mesh : float, (num_chord_panels + 1, num_span_panels + 1, 3), m
        Nodes i chord-wise (0 = leading edge), j span-wise (0 = left tip).

    Options
    -------
    num_chord_panels : int
        Chord-wise panels nc (>= 1), uniform.
    num_span_panels : int
        Span-wise panels N over the whole span (even, >= 2), so a node lies on the root.
    spacing : str
        'cosine' (default) or 'uniform' span-wise spacing.
    """

    def initialize(self):
        self.options.declare(
            "num_chord_panels", default=1, types=int, lower=1, desc="chord-wise panels"
        )
        self.options.declare(
            "num_span_panels",
            types=int,
            lower=2,
            check_valid=_check_even,
            desc="span-wise panels, both halves (even)",
        )
        self.options.declare(
            "spacing", default="cosine", values=SPACINGS, desc="span-wise node spacing"
        )

    def setup(self):
        nc = self.options["num_chord_panels"]
        nsp = self.options["num_span_panels"]
        nx, ny = nc + 1, nsp + 1
        nh = nsp // 2 + 1
        eta = span_stations(nsp, self.options["spacing"])
        self._eta = eta
        self._abs_eta = np.abs(eta)
        self._half = np.abs(np.arange(ny) - nsp // 2)
        self._s = np.arange(nx) / nc

        self.add_input("span", 1.0, units="m", desc="projected span, both halves")
        self.add_input("root_chord", 1.0, units="m", desc="root chord")
        self.add_input("tip_chord", 1.0, units="m", desc="tip chord")
        self.add_input("sweep", 0.0, units="rad", desc="leading-edge sweep, positive aft")
        self.add_input("dihedral", 0.0, units="rad", desc="dihedral, positive tip up")
        self.add_input("incidence", 0.0, units="rad", desc="root incidence, positive nose up")
        self.add_input(
            "twist",
            np.zeros(nh),
            units="rad",
            desc="extra section twist at the half-span nodes, root to tip",
        )
        self.add_input(
            "root_leading_edge",
            np.zeros(3),
            units="m",
            desc="leading edge of the root chord, body frame",
        )
        self.add_output(
            "mesh",
            np.zeros((nx, ny, 3)),
            units="m",
            desc="lattice nodes, chord-wise x span-wise x (x, y, z)",
        )

        idx = np.arange(nx * ny * 3).reshape(nx, ny, 3)
        rx, ry, rz = idx[..., 0].ravel(), idx[..., 1].ravel(), idx[..., 2].ravel()
        rxz = np.concatenate([rx, rz])
        self.declare_partials(
            "mesh", "span", rows=np.concatenate([rx, ry, rz]), cols=np.zeros(3 * nx * ny, int)
        )
        self.declare_partials(
            "mesh",
            ["root_chord", "tip_chord", "incidence"],
            rows=rxz,
            cols=np.zeros(2 * nx * ny, int),
        )
        self.declare_partials("mesh", "sweep", rows=rx, cols=np.zeros(nx * ny, int))
        self.declare_partials("mesh", "dihedral", rows=rz, cols=np.zeros(nx * ny, int))
        half = np.tile(self._half, nx)
        self.declare_partials("mesh", "twist", rows=rxz, cols=np.concatenate([half, half]))
        self.declare_partials(
            "mesh",
            "root_leading_edge",
            rows=idx.ravel(),
            cols=np.tile(np.arange(3), nx * ny),
            val=1.0,
        )

    def _check_inputs(self, inputs):
        value = {
            name: float(np.real(inputs[name])[0])
            for name in ("span", "root_chord", "tip_chord", "sweep", "dihedral")
        }
        limit = np.pi / 2
        checks = (
            ("span", value["span"] > 0.0, "> 0 m"),
            ("root_chord", value["root_chord"] > 0.0, "> 0 m"),
            ("tip_chord", value["tip_chord"] >= 0.0, ">= 0 m"),
            ("sweep", -limit < value["sweep"] < limit, "in (-pi/2, pi/2) rad"),
            ("dihedral", -limit < value["dihedral"] < limit, "in (-pi/2, pi/2) rad"),
        )
        for name, ok, allowed in checks:
            if not ok:
                raise om.AnalysisError(
                    f"{self.msginfo}: {name} = {value[name]}; must be {allowed}."
                )

    def _sections(self, inputs):
        b = inputs["span"][0]
        c = inputs["root_chord"][0] * (1.0 - self._abs_eta) + inputs["tip_chord"][0] * self._abs_eta
        theta = inputs["incidence"][0] + inputs["twist"][self._half]
        return b, c, theta

    def compute(self, inputs, outputs):
        self._check_inputs(inputs)
        b, c, theta = self._sections(inputs)
        x0 = inputs["root_leading_edge"]
        h = 0.5 * b * self._abs_eta
        x_le = x0[0] - h * np.tan(inputs["sweep"][0])
        z_le = x0[2] - h * np.tan(inputs["dihedral"][0])
        sc = self._s[:, None] * c[None, :]
        mesh = outputs["mesh"]
        mesh[..., 0] = x_le[None, :] - sc * np.cos(theta)[None, :]
        mesh[..., 1] = (x0[1] + 0.5 * b * self._eta)[None, :]
        mesh[..., 2] = z_le[None, :] + sc * np.sin(theta)[None, :]

    def compute_partials(self, inputs, partials):
        nx = self._s.size
        _, c, theta = self._sections(inputs)
        ae, s = self._abs_eta, self._s[:, None]
        cos, sin = np.cos(theta)[None, :], np.sin(theta)[None, :]
        ones = np.ones((nx, 1))
        tan_sw, tan_di = np.tan(inputs["sweep"][0]), np.tan(inputs["dihedral"][0])
        partials["mesh", "span"] = np.concatenate(
            [
                (ones * (-0.5 * ae * tan_sw)).ravel(),
                (ones * 0.5 * self._eta).ravel(),
                (ones * (-0.5 * ae * tan_di)).ravel(),
            ]
        )
        for name, w in (("root_chord", 1.0 - ae), ("tip_chord", ae)):
            partials["mesh", name] = np.concatenate([(-s * w * cos).ravel(), (s * w * sin).ravel()])
        d_theta = np.concatenate([(s * c * sin).ravel(), (s * c * cos).ravel()])
        partials["mesh", "incidence"] = d_theta
        partials["mesh", "twist"] = d_theta
        h = 0.5 * inputs["span"][0] * ae
        partials["mesh", "sweep"] = (ones * (-h / np.cos(inputs["sweep"][0]) ** 2)).ravel()
        partials["mesh", "dihedral"] = (ones * (-h / np.cos(inputs["dihedral"][0]) ** 2)).ravel()


def _check_even(name, value):
    check_integer(
        name,
        value,
        allowed="even (a node on the root of the mirrored surface)",
        upper=None if value % 2 == 0 else value - 1,
        where="PlanformMeshComp",
    )


def planform_values(surface):
    """Input values of :class:`PlanformMeshComp` for a ``lpc_mdo.vehicle.LiftingSurface``.

    Returns a dict with span, root_chord, tip_chord, sweep, dihedral, incidence (SI, rad) and
    root_leading_edge, e.g. ``planform_values(reference_vehicle().wing)``.
    """
    return {
        "span": surface.span,
        "root_chord": surface.root_chord,
        "tip_chord": surface.tip_chord,
        "sweep": surface.sweep,
        "dihedral": surface.dihedral,
        "incidence": surface.incidence,
        "root_leading_edge": np.asarray(surface.root_leading_edge, dtype=float),
    }
