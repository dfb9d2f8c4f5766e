"""Declared partial sparsity of an explicit component checked against its sensitivities."""

import numpy as np

# An entry counts as a dependence when the relative change of the output per relative change
# of the input (scaled by the output's and input's magnitudes) exceeds THRESHOLD. Central
# differences of relative step STEP carry a truncation error of order STEP**2 and a round-off
# error of order 1e-16/STEP, both far below it; a true dependence below it is not one a design
# could feel.
STEP = 1.0e-6
THRESHOLD = 1.0e-7


def _scaled_jacobian(prob, inputs, outputs):
    """Central-difference Jacobian of ``outputs`` wrt ``inputs``, in relative terms."""
    base = {name: np.array(prob.get_val(name), dtype=float) for name in inputs}
    y0 = np.concatenate([np.ravel(prob.get_val(name)) for name in outputs])
    y_scale = np.maximum(np.abs(y0), 1e-12 + 1e-6 * np.max(np.abs(y0)))
    columns = []
    for name in inputs:
        x = base[name]
        for k in range(x.size):
            h = STEP * max(abs(x.flat[k]), 1e-6)
            values = []
            for sign in (1.0, -1.0):
                xp = x.copy()
                xp.flat[k] += sign * h
                prob.set_val(name, xp)
                prob.run_model()
                values.append(np.concatenate([np.ravel(prob.get_val(o)) for o in outputs]))
            prob.set_val(name, x)
            derivative = (values[0] - values[1]) / (2.0 * h)
            columns.append(derivative * max(abs(x.flat[k]), 1e-6) / y_scale)
    prob.run_model()
    return np.abs(np.array(columns).T)


def _declared(prob, comp, inputs, outputs):
    """
    Return the declared pattern and the analytic values of the partials.

    Rows and columns are ordered as the Jacobian; the values are dense, zero where nothing is
    declared.
    """
    sizes = {name: np.size(prob.get_val(name)) for name in (*inputs, *outputs)}
    row0 = np.cumsum([0] + [sizes[o] for o in outputs])
    col0 = np.cumsum([0] + [sizes[i] for i in inputs])
    pattern = np.zeros((row0[-1], col0[-1]), dtype=bool)
    values = np.zeros(pattern.shape)
    data = prob.check_partials(includes=[comp.pathname], method="cs", out_stream=None)
    prefix = comp.pathname + "."
    for (of, wrt), meta in comp._subjacs_info.items():
        of, wrt = of.removeprefix(prefix), wrt.removeprefix(prefix)
        if of not in outputs or wrt not in inputs:
            continue
        i, j = outputs.index(of), inputs.index(wrt)
        block = (slice(row0[i], row0[i + 1]), slice(col0[j], col0[j + 1]))
        if meta.get("diagonal"):
            np.fill_diagonal(pattern[block], True)
        elif meta["rows"] is not None:
            pattern[block][meta["rows"], meta["cols"]] = True
        else:
            pattern[block] = True
        values[block] = data[comp.pathname][of, wrt]["J_fwd"]
    return pattern, values


def assert_sparsity_matches(prob, path):
    """
    Assert that the explicit component at ``path`` declares the entries its outputs depend on.

    Every entry they depend on must be declared, and no entry that is zero in the component's
    own partials and to central differences.

    The component must be the only system of ``prob``, its variables promoted. OpenMDAO's
    ``assert_sparsity_matches_fd`` calls any entry a forward difference leaves nonzero at two
    random points: an entry a few orders below the others then falls under round-off at some
    draws, and a quantity that does not depend on an input but is computed through it shows as
    a dependence. Here a dependence is a relative sensitivity above ``THRESHOLD``. An entry
    small at this point but not zero (a KS weight far from the maximum) may be declared.
    """
    comp = prob.model._get_subsystem(path)
    inputs = [meta["prom_name"] for _, meta in comp.list_inputs(out_stream=None, prom_name=True)]
    outputs = [meta["prom_name"] for _, meta in comp.list_outputs(out_stream=None, prom_name=True)]
    sensitive = _scaled_jacobian(prob, inputs, outputs) > THRESHOLD
    declared, values = _declared(prob, comp, inputs, outputs)
    missing = np.argwhere(sensitive & ~declared)
    superfluous = np.argwhere(declared & ~sensitive & (values == 0.0))
    assert missing.size == 0 and superfluous.size == 0, (
        f"{path}: (row, column) entries that depend but are not declared: {missing.tolist()}; "
        f"declared but zero: {superfluous.tolist()}"
    )
