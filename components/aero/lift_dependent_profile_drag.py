"""Lift-dependent profile drag of the VLM strips from the airfoil polar."""

import numpy as np
import openmdao.api as om

from .airfoil import get_polar

#: Angles scanned for the minimum profile drag of a section (the polar's drag bucket), rad:
#: -6..+10 deg in 0.5 deg steps, then +-0.5 deg about the best of them in 0.02 deg steps. The
#: minimum of a smooth cd(alpha) is found to within cd'' (0.02 deg)^2/8: measured within 3e-7 of
#: a 0.005 deg scan of -10..15 deg on the packaged tables (Re 3e5-1e7, M 0-0.3).
MINIMUM_DRAG_SCAN = np.radians(np.arange(-6.0, 10.0 + 1e-9, 0.5))
_REFINE = np.radians(np.arange(-0.5, 0.5 + 1e-9, 0.02))


class StripFlowComp(om.ExplicitComponent):
    """
    Chord Reynolds number and Mach number of each span-wise strip of a lifting surface.

    The strip chord is the mean of the chord lengths at its two span-wise mesh stations,
    c_j = norm(x_TE - x_LE) (leading and trailing edge nodes of the mesh); Re_ij = (rho V/mu)_i c_j,
    M_ij = M_i.

    Inputs
    ------
    mesh : (nx, ny, 3), m
    reynolds_per_length : (nn,), 1/m
    mach : (nn,)

    Outputs
    -------
    strip_reynolds : (nn * ns,), row-major over (condition, strip)
    strip_mach : (nn * ns,)

    Options
    -------
    num_nodes : int
    num_chord_panels, num_span_panels : int
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("num_chord_panels", types=int, lower=1)
        self.options.declare("num_span_panels", types=int, lower=1)

    def setup(self):
        nn, ns = self.options["num_nodes"], self.options["num_span_panels"]
        nx = self.options["num_chord_panels"] + 1
        self.add_input("mesh", np.zeros((nx, ns + 1, 3)), units="m", desc="surface mesh")
        self.add_input("reynolds_per_length", np.zeros(nn), units="1/m", desc="rho V/mu")
        self.add_input("mach", np.zeros(nn), desc="Mach number")
        self.add_output("strip_reynolds", np.ones(nn * ns), desc="chord Reynolds number")
        self.add_output("strip_mach", np.zeros(nn * ns), desc="Mach number")
        i, j = (a.ravel() for a in np.meshgrid(np.arange(nn), np.arange(ns), indexing="ij"))
        row = i * ns + j
        self.declare_partials("strip_reynolds", "reynolds_per_length", rows=row, cols=i)
        self.declare_partials("strip_mach", "mach", rows=row, cols=i, val=1.0)
        # Each strip's chord depends on the leading and trailing edge nodes of its two stations.
        rows, cols = [], []
        for side in (0, nx - 1):
            for k in (0, 1):
                for c in range(3):
                    rows.append(row)
                    cols.append((side * (ns + 1) + j + k) * 3 + c)
        self.declare_partials(
            "strip_reynolds", "mesh", rows=np.concatenate(rows), cols=np.concatenate(cols)
        )

    def _chords(self, mesh):
        edge = mesh[-1] - mesh[0]  # (ny, 3), leading to trailing edge
        length = np.sqrt(np.sum(edge**2, axis=-1))
        return edge, length, 0.5 * (length[:-1] + length[1:])

    def compute(self, inputs, outputs):
        nn = self.options["num_nodes"]
        _, _, chord = self._chords(inputs["mesh"])
        outputs["strip_reynolds"] = (inputs["reynolds_per_length"][:, None] * chord).ravel()
        outputs["strip_mach"] = np.repeat(inputs["mach"], chord.size).reshape(nn * chord.size)

    def compute_partials(self, inputs, partials):
        nn, ns = self.options["num_nodes"], self.options["num_span_panels"]
        edge, length, chord = self._chords(inputs["mesh"])
        re_l = inputs["reynolds_per_length"]
        partials["strip_reynolds", "reynolds_per_length"] = np.tile(chord, nn)
        unit = edge / length[:, None]  # d|e|/d(TE) = e/|e|, d|e|/d(LE) = -e/|e|
        blocks = []
        for sign in (-1.0, 1.0):  # leading edge, trailing edge (the order of setup)
            for k in (0, 1):
                d = 0.5 * sign * unit[k : k + ns]  # (ns, 3)
                blocks.append((re_l[:, None, None] * d[None]).reshape(nn * ns, 3).T)
        partials["strip_reynolds", "mesh"] = np.concatenate([block.ravel() for block in blocks])


class LiftDependentProfileDragComp(om.ExplicitComponent):
    """
    Lift-dependent part of each strip's profile-drag coefficient, from the airfoil polar.

    Delta c_d = c_d(alpha*, Re, M) - c_d,min(Re, M): the polar's drag at the section angle
    alpha* that gives the strip's VLM lift coefficient (:class:`AlphaStarComp`, paper eq. 16a)
    less the polar's minimum drag at the strip's Reynolds and Mach number (the bottom of the
    drag bucket, scanned over :data:`MINIMUM_DRAG_SCAN` and refined; the angle is kept while Re
    and M do not change). The minimum belongs to the
    parasite-drag build-up (skin friction and form factor of the wing, docs theory/aerodynamics
    'Drag build-up'); the increment is what lift adds to the section's profile drag, the term
    a build-up of C_D0 plus the lattice's induced drag leaves out (Raymer, *Aircraft Design*,
    6th ed., sec. 12.6: the drag-due-to-lift includes the profile drag's variation with lift;
    Torenbeek, *Synthesis of Subsonic Airplane Design*, app. F). It is >= 0 up to the scan's
    resolution (within 3e-7 of the minimum).

    Derivatives: d c_d/d alpha* at alpha*, and the envelope theorem for the minimum,
    d c_d,min/dRe = dc_d/dRe at the scanned minimizing angle (likewise M).

    Inputs
    ------
    alpha_star : (n,), rad
    reynolds : (n,)
    mach : (n,)

    Outputs
    -------
    sectional_cd : (nn, ns), the increment per strip (n = nn ns, row-major)

    Options
    -------
    num_nodes, num_span_panels : int
    airfoil : anything :func:`~lpc_mdo.components.aero.airfoil.get_polar` takes
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("num_span_panels", types=int, lower=1)
        self.options.declare("airfoil", default="ls413", desc="airfoil (see get_polar)")

    def setup(self):
        nn, ns = self.options["num_nodes"], self.options["num_span_panels"]
        n = nn * ns
        self._polar = get_polar(self.options["airfoil"])
        self._minimum_angle = None
        self.add_input("alpha_star", np.zeros(n), units="rad", desc="section angle of attack")
        self.add_input("reynolds", np.full(n, 1e6), desc="chord Reynolds number")
        self.add_input("mach", np.zeros(n), desc="Mach number")
        self.add_output(
            "sectional_cd", np.zeros((nn, ns)), desc="lift-dependent profile-drag coefficient"
        )
        self.declare_partials("sectional_cd", ["alpha_star", "reynolds", "mach"], diagonal=True)

    def _minimum(self, reynolds, mach):
        """
        Polar values at the angle of minimum drag of each section (scan).

        The angle depends on (Re, M) only, which stay fixed while a trim or a line search moves
        the rotor speeds, pitch and elevator: the scan is kept for the last (Re, M) seen.
        """
        re, m = np.real(reynolds), np.real(mach)
        last = self._minimum_angle
        if last is None or not (np.array_equal(re, last[0]) and np.array_equal(m, last[1])):
            cd = self._polar.evaluate(MINIMUM_DRAG_SCAN[None, :], re[:, None], m[:, None]).cd
            grid = MINIMUM_DRAG_SCAN[np.argmin(cd, axis=1)][:, None] + _REFINE[None, :]
            cd = self._polar.evaluate(grid, re[:, None], m[:, None]).cd
            angle = grid[np.arange(grid.shape[0]), np.argmin(cd, axis=1)]
            self._minimum_angle = last = (re.copy(), m.copy(), angle)
        return self._polar.evaluate(last[2], reynolds, mach)

    def compute(self, inputs, outputs):
        re, m = inputs["reynolds"], inputs["mach"]
        at = self._polar.evaluate(inputs["alpha_star"], re, m)
        outputs["sectional_cd"] = (at.cd - self._minimum(re, m).cd).reshape(
            outputs["sectional_cd"].shape
        )

    def compute_partials(self, inputs, partials):
        re, m = inputs["reynolds"], inputs["mach"]
        at = self._polar.evaluate(inputs["alpha_star"], re, m)
        low = self._minimum(re, m)
        partials["sectional_cd", "alpha_star"] = at.dcd_dalpha
        partials["sectional_cd", "reynolds"] = at.dcd_dreynolds - low.dcd_dreynolds
        partials["sectional_cd", "mach"] = at.dcd_dmach - low.dcd_dmach
