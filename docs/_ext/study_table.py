"""Sphinx directive ``study-table``: a table of the study's stages, from :mod:`lpc_mdo.study_plan`.

Usage in a page::

    .. study-table:: problems

The argument names the table: ``problems`` (what each stage solves,
:func:`lpc_mdo.study_plan.stage_rows`), ``runs`` (optimizer, trim and hand-over,
:func:`lpc_mdo.study_plan.run_rows`) or ``settings`` (the optimizer settings,
:func:`lpc_mdo.study_plan.settings_rows`). The table is built from the module at each docs
build, so the page shows what the code runs.
"""

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

from lpc_mdo import study_plan

TABLES = {
    "problems": study_plan.stage_rows,
    "runs": study_plan.run_rows,
    "settings": study_plan.settings_rows,
}


def _row(cells, literal_first):
    row = nodes.row()
    for k, text in enumerate(cells):
        entry = nodes.entry()
        body = nodes.literal(text=text) if literal_first and k == 0 else nodes.Text(text)
        entry += nodes.paragraph("", "", body)
        row += entry
    return row


class StudyTable(SphinxDirective):
    """The directive: one table of :mod:`lpc_mdo.study_plan`, named by its argument."""

    required_arguments = 1
    has_content = False

    def run(self):
        """Return the table's nodes (a docutils table with a header row)."""
        which = self.arguments[0]
        if which not in TABLES:
            raise self.error(f"study-table: table {which!r}; allowed: {list(TABLES)}")
        header, rows = TABLES[which]()
        group = nodes.tgroup(cols=len(header))
        for _ in header:
            group += nodes.colspec(colwidth=1)
        head = nodes.thead()
        head += _row(header, literal_first=False)
        body = nodes.tbody()
        for cells in rows:
            body += _row(cells, literal_first=True)
        group += head
        group += body
        table = nodes.table(classes=["study-table"])
        table += group
        return [table]


def setup(app):
    """Register the directive with Sphinx."""
    app.add_directive("study-table", StudyTable)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
