"""Circulation of the vortex rings: the VLM linear system as an implicit component."""

import warnings

import numpy as np
import openmdao.api as om
import scipy.linalg

#: Smallest accepted abs(U_kk) / max abs(U_kk) of the LU factors before the AIC counts as singular.
SINGULAR_RCOND = 1.0e-13


class VLMCirculationComp(om.ImplicitComponent):
    """
    Ring circulations Gamma from the residual of paper eq. 10, one dense system per node.

    The residual of node n is

        R[n] = A[n] Gamma[n] + v_coll[n] . n'[n] = 0

    (docs theory/aerodynamics 'Circulation system'; v_coll is the relative wind at the collocation
    points, n' the boundary normals). ``solve_nonlinear`` LU-factorises A[n] (scipy ``lu_factor``)
    and back-substitutes; ``linearize`` gives the exact partials
    (dR/dGamma = A, dR/dA = Gamma, dR/dv = n', dR/dn' = v) and keeps the factors, which
    ``solve_linear`` reuses in forward (A x = b) and reverse (A^T x = b) mode. A group holding
    this component therefore needs no linear solver of its own (the default LinearRunOnce is
    exact). A singular or non-finite A raises om.AnalysisError.

    Inputs
    ------
    aic : float, (nn, np, np), 1/m
    collocation_velocities : float, (nn, np, 3), m/s
    boundary_normals : float, (nn, np, 3)

    Outputs
    -------
    circulation : float, (nn, np), m**2/s
        Ring circulations (positive for lift on a wing, with the rings' p1->p2 along +y).

    Options
    -------
    num_nodes : int
    num_panels : int
    """

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )
        self.options.declare("num_panels", types=int, lower=1, desc="number of lattice panels")

    def setup(self):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        self.add_input("aic", np.zeros((nn, npn, npn)), units="1/m", desc="AIC matrix")
        self.add_input(
            "collocation_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="relative wind at the collocation points",
        )
        self.add_input(
            "boundary_normals",
            np.zeros((nn, npn, 3)),
            units=None,
            desc="boundary-condition unit normals",
        )
        self.add_output(
            "circulation",
            np.zeros((nn, npn)),
            units="m**2/s",
            desc="circulation of each vortex ring",
        )

        n_i, i_i, j_i = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(npn), indexing="ij")
        )
        self.declare_partials(
            "circulation", "circulation", rows=n_i * npn + i_i, cols=n_i * npn + j_i
        )
        self.declare_partials(
            "circulation", "aic", rows=n_i * npn + i_i, cols=np.arange(nn * npn * npn)
        )
        rows3 = np.repeat(np.arange(nn * npn), 3)
        cols3 = np.arange(nn * npn * 3)
        self.declare_partials(
            "circulation", ["collocation_velocities", "boundary_normals"], rows=rows3, cols=cols3
        )
        self._lu = None

    def apply_nonlinear(self, inputs, outputs, residuals):
        gamma = outputs["circulation"]
        residuals["circulation"] = np.einsum("nij,nj->ni", inputs["aic"], gamma) + np.einsum(
            "nic,nic->ni", inputs["collocation_velocities"], inputs["boundary_normals"]
        )

    def _factor(self, aic):
        if not np.all(np.isfinite(aic)):
            raise om.AnalysisError(
                f"{self.msginfo}: the AIC matrix has non-finite entries "
                "(a collocation point on a vortex line or a degenerate mesh)."
            )
        factors = []
        for n in range(aic.shape[0]):
            with warnings.catch_warnings():  # a singular matrix is reported below instead
                warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)
                lu, piv = scipy.linalg.lu_factor(aic[n], check_finite=False)
            diag = np.diag(lu).real
            scale = np.max(np.abs(diag))
            if scale == 0.0 or np.min(np.abs(diag)) < SINGULAR_RCOND * scale:
                raise om.AnalysisError(
                    f"{self.msginfo}: the AIC matrix of node {n} is singular "
                    f"(min/max |U_kk| = {np.min(np.abs(diag)) / max(scale, 1e-300):.3e} < "
                    f"{SINGULAR_RCOND}); check the meshes for zero-area or coincident panels."
                )
            factors.append((lu, piv))
        return factors

    def solve_nonlinear(self, inputs, outputs):
        aic = inputs["aic"]
        rhs = -np.einsum(
            "nic,nic->ni", inputs["collocation_velocities"], inputs["boundary_normals"]
        )
        factors = self._factor(aic)
        outputs["circulation"] = np.stack(
            [scipy.linalg.lu_solve(f, rhs[n], check_finite=False) for n, f in enumerate(factors)]
        )

    def linearize(self, inputs, outputs, partials):
        aic = inputs["aic"]
        npn = self.options["num_panels"]
        partials["circulation", "circulation"] = aic.ravel()
        gamma = outputs["circulation"]
        partials["circulation", "aic"] = np.broadcast_to(
            gamma[:, None, :], (gamma.shape[0], npn, npn)
        ).ravel()
        partials["circulation", "collocation_velocities"] = inputs["boundary_normals"].ravel()
        partials["circulation", "boundary_normals"] = inputs["collocation_velocities"].ravel()
        if not self.under_complex_step:
            self._lu = self._factor(aic)

    def solve_linear(self, d_outputs, d_residuals, mode):
        if self._lu is None:
            raise om.AnalysisError(f"{self.msginfo}: solve_linear called before linearize.")
        if mode == "fwd":
            rhs = d_residuals["circulation"]
            d_outputs["circulation"] = np.stack(
                [scipy.linalg.lu_solve(f, rhs[n], trans=0) for n, f in enumerate(self._lu)]
            )
        else:
            rhs = d_outputs["circulation"]
            d_residuals["circulation"] = np.stack(
                [scipy.linalg.lu_solve(f, rhs[n], trans=1) for n, f in enumerate(self._lu)]
            )
